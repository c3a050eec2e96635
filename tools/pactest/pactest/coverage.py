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


def report(objects, folder, out, extracted=None):
    """Prints the table of the ST files under `folder` and of those extracted from a PLCopen XML project into
    `extracted` (under OUT); returns False when gcovr is missing."""
    gcovr = gcovr_command()
    if gcovr is None:
        print("pac-test: no coverage table: gcovr is not installed (pip install gcovr)")
        return False
    st = _st_coverage()
    os.makedirs(out, exist_ok=True)
    detail = os.path.join(out, "gcovr.json")
    # The host's build (OUT/st-c, the C of the ST) lies under the project's folder when OUT does (the
    # default pac-test-out, run in the project): its files are no ST of the project.
    built = os.path.join(os.path.abspath(os.path.dirname(objects.rstrip(os.sep))), "")
    keep = ""
    filters = ["--filter", os.path.join(os.path.abspath(folder), "")]
    if extracted is not None and os.path.isdir(extracted):  # the ST of a PLCopen XML project lies under OUT
        extracted = os.path.join(os.path.abspath(extracted), "")
        filters += ["--filter", re.escape(extracted)]
        if extracted.startswith(built):
            keep = f"(?!{re.escape(extracted[len(built):])})"
    subprocess.run([gcovr, "--root", folder, *filters,
                    "--exclude", re.escape(built) + keep + ".*", "--json", detail, "--html-details", os.path.join(out, "index.html"),
                    "--html-title", "pac-test: coverage of the machine program", objects],
                   check=True, stdout=subprocess.DEVNULL)
    import json
    with open(detail, encoding="utf-8") as f:
        files = sorted((st.FileCoverage(e) for e in json.load(f)["files"]), key=lambda c: c.path)
    print("coverage of the machine program's ST (lines executed, branches taken):")
    st.report(files, out)
    return True
