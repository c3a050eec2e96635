"""What every program's first run against a build would make again, made by the build (`cmake --build`, the
target pactest_prepare): the host's object shared by the runs against it (build.py's HostBuild), pacst's user-mode
parses of the ST every program is translated with, the library, the vocabulary and the vendor libraries' parts, in
the build's parse cache, which a run reads beneath its own, and the library's checked state (`pacst library`). The
same object, parses and state a run would make, under the keys a run looks them up by.

    python -m pactest.prepare BUILD --stamp FILE
"""
import argparse
import os
import sys
import tempfile

from . import build, project


def parse_own_st(host_build):
    """pacst's user-mode parses of the library, the vocabulary and the vendor parts, stored in the build's parse
    cache (the library's from the build's own parses, which user mode's reading and lexical checks still pass)."""
    files = project.library_sources() + [project.gvl_pac()] + project.vocabulary_sources() + project.vendor_sources()
    translator = os.environ.get("PACTEST_TRANSLATOR", os.path.join(project.ROOT, "translator"))
    code = ("import sys\nfrom pacst import parsing\n"
            "bad = [r for r in parsing.parse_files(sys.argv[2:], sys.argv[1], user=True) if not isinstance(r, "
            "parsing.SourceFile)]\nsys.exit(f'pacst: {bad[0]}' if bad else 0)")
    build._run([host_build.pacst_python, "-c", code, host_build.pac.parse_cache, *files], "parsing pac-test's own ST",
               dict(os.environ, PYTHONPATH=translator))


def check_library(host_build):
    """The library's checked state (`pacst library`), which every run's translation takes instead of parsing and
    checking st/ again; the run's pacst falls back to them where the library or the translator changed since."""
    host_build._pacst("library", "--namespace", f"{project.NAMESPACE}={os.path.join(project.ROOT, 'st')}",
                      "--out", host_build.checked_library, *project.library_sources())


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m pactest.prepare", description=__doc__.split("\n\n")[0])
    parser.add_argument("build", help="the build of the project (its CMAKE_BINARY_DIR)")
    parser.add_argument("--stamp", required=True, help="written when all are made")
    args = parser.parse_args(argv)
    pac = project.PacBuild(args.build)
    try:
        with tempfile.TemporaryDirectory() as out:  # a run's folder; only the shared object is kept
            host_build = build.HostBuild(None, pac, out)
            if pac.parse_cache:
                parse_own_st(host_build)
            check_library(host_build)
            host_build.shared_host()
    except build.BuildError as e:
        print(f"pac-test: {e}", file=sys.stderr)
        return 1
    with open(args.stamp, "w", encoding="utf-8") as f:
        f.write("")
    return 0


if __name__ == "__main__":
    sys.exit(main())
