"""Why the fast parser declines what it declines: for each ST or TwinCAT file given, the text pacst parses (with
--user, as pac-test reads a user's program), the fast parser's Decline reason and the line it stopped at, then
the reasons counted. What to teach the fast parser next is the reason most files share (each of them costs
blark's Earley parser, 10 to 100 times slower).

    build/venv/bin/python tests/parser/decline_reasons.py --user tools/pactest/tests/dialect/*
"""
import argparse
import collections
import os
import sys

from tree_oracle import Oracle  # (puts the translator on the path)
from pacst import parsing  # noqa: E402
from pacst.fastparse import Decline  # noqa: E402


def reason(oracle, path, user):
    """(the reason, the line where the fast parser stopped, that line's text) or None when it parses the file."""
    try:
        text = parsing._read(path, user)[0]
        text = oracle.processed(text)
    except Exception as exc:  # pacst's reading (StError) or blark's comment pass, on damaged text
        return f"not read: {exc}", 0, ""
    try:
        oracle.fast.parse(text)
        return None
    except Decline as exc:
        pos = getattr(exc, "pos", 0)
        line = text.count("\n", 0, pos) + 1
        return str(exc), line, text.split("\n")[line - 1].strip()


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("files", nargs="+")
    ap.add_argument("--user", action="store_true", help="read the files as pac-test reads a user's program")
    args = ap.parse_args(argv)
    oracle = Oracle()
    counts = collections.Counter()
    files = [f for f in args.files if f.lower().endswith((".st",) + parsing.twincat.OBJECT_EXTENSIONS)]
    for path in files:
        found = reason(oracle, path, args.user)
        if found is None:
            continue
        why, line, code = found
        counts[why] += 1
        print(f"{os.path.relpath(path)}:{line}: {why}: {code}")
    print(f"\n{len(files) - sum(counts.values())} of {len(files)} files parsed fast, {sum(counts.values())} declined:")
    for why, n in counts.most_common():
        print(f"{n:5}  {why}")


if __name__ == "__main__":
    sys.exit(main())
