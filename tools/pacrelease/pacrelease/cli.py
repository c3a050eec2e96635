"""pacrelease cut VERSION: the release commit (CHANGELOG.md, st/library.json) and its annotated tag.
pacrelease archive [COMMIT]: the release folder and its .zip and .tar.gz, the same bytes from the same
commit. See docs/release.md."""
import argparse
import datetime
import os
import sys

from .archive import write_release
from .changelog import ChangelogError
from .cut import ReleaseError, cut_release

_REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


def main(argv=None):
    parser = argparse.ArgumentParser(prog="pacrelease", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repo", default=_REPO, help="the repository (default: the one pacrelease is in)")
    commands = parser.add_subparsers(dest="command", required=True)
    cut = commands.add_parser("cut", help="commit and tag the release VERSION")
    cut.add_argument("version", help="major.minor.patch, after the latest release of CHANGELOG.md")
    cut.add_argument("--date", default=datetime.datetime.now(datetime.timezone.utc).date().isoformat(),
                     help="the release date, YYYY-MM-DD (default: today, UTC)")
    arc = commands.add_parser("archive", help="write the release folder and archives of a commit")
    arc.add_argument("commit", nargs="?", default="HEAD",
                     help="a commit, a tag or a released version, 1.0.0 or v1.0.0, found without its tag too "
                          "(default: HEAD)")
    arc.add_argument("--out", required=True, help="folder for <name>-<version>/, .zip and .tar.gz")
    arc.add_argument("--python", help="the Python of pacexport's venv (default: build/venv-pacexport)")
    arc.add_argument("--cache", help="pacst's parse cache (a faster export, the same bytes)")
    args = parser.parse_args(argv)
    try:
        if args.command == "cut":
            print(cut_release(args.repo, args.version, args.date))
        else:
            python = args.python or os.path.join(args.repo, "build", "venv-pacexport", "bin", "python")
            print(write_release(args.repo, args.commit, args.out, python, args.cache))
    except (ReleaseError, ChangelogError) as exc:
        print(f"pacrelease: {exc}", file=sys.stderr)
        return 1
    return 0
