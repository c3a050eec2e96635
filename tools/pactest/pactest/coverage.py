"""Line and branch coverage of the user's ST: gcc's counters of the translated ST, whose #line directives
name the ST lines, read by gcovr and tabled per POU file as the library's report does (cmake/st_coverage.py)."""
import importlib.util
import os
import re
import shutil
import subprocess
import sys

from . import project


def _st_coverage():
    spec = importlib.util.spec_from_file_location("st_coverage", os.path.join(project.ROOT, "cmake", "st_coverage.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def gcovr_command():
    local = os.path.join(os.path.dirname(sys.executable), "gcovr")
    return local if os.path.exists(local) else shutil.which("gcovr")


def reset(objects):
    _st_coverage().reset(objects)


def source_folders(sources):
    """The folders of the wiring file's sources (a .plcproj's folder holds its objects), without one inside
    another: what the coverage counts, wherever the wiring file lies."""
    folders = sorted({os.path.dirname(os.path.abspath(s)) for s in sources})
    return [f for f in folders if not any(f.startswith(os.path.join(o, "")) for o in folders if o != f)]


def report(objects, sources, out, extracted=None, libraries=()):
    """Prints the table of the ST files in the folders of `sources` and of those extracted from a PLCopen XML
    project into `extracted` (under OUT), but the program's own libraries' (in the folders `libraries`); returns
    False when there is none (gcovr missing, or no line of those files measured)."""
    gcovr = gcovr_command()
    if gcovr is None:
        print("pac-test: no coverage table: gcovr is not installed (pip install gcovr)")
        return False
    st = _st_coverage()
    os.makedirs(out, exist_ok=True)
    detail = os.path.join(out, "gcovr.json")
    folders = source_folders(sources)
    # The host's build (OUT/st-c, the C of the ST) lies under the project's folder when OUT does (the
    # default pac-test-out, run in the project): its files are no ST of the project.
    built = os.path.join(os.path.abspath(os.path.dirname(objects.rstrip(os.sep))), "")
    keep = ""
    filters = [arg for folder in folders for arg in ("--filter", re.escape(os.path.join(folder, "")))]
    if extracted is not None and os.path.isdir(extracted):  # the ST of a PLCopen XML project lies under OUT
        extracted = os.path.join(os.path.abspath(extracted), "")
        filters += ["--filter", re.escape(extracted)]
        folders.append(extracted.rstrip(os.sep))
        if extracted.startswith(built):
            keep = f"(?!{re.escape(extracted[len(built):])})"
    run = subprocess.run([gcovr, "--root", os.path.commonpath(folders), *filters,
                          "--exclude", re.escape(built) + keep + ".*",
                          *[a for f in libraries for a in ("--exclude", re.escape(os.path.join(f, "")) + ".*")],
                          "--json", detail,
                          "--html-details", os.path.join(out, "index.html"),
                          "--html-title", "pac-test: coverage of the machine program", objects],
                         check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    import json
    with open(detail, encoding="utf-8") as f:
        files = sorted((st.FileCoverage(e) for e in json.load(f)["files"]), key=lambda c: c.path)
    if not any(c.lines for c in files):  # 0 of 0 lines is no coverage, not 100 %
        print(f"pac-test: no coverage table: no line of the sources was measured (in {', '.join(folders)})",
              file=sys.stderr)
        return False
    sys.stderr.write(run.stderr)
    print("coverage of the machine program's ST (lines executed, branches taken):")
    st.report(files, out)
    return True
