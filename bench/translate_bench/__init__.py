"""Benchmark (not a test): seconds pacst needs to translate the library cold, unchanged, and after
one file was touched, printed as a table."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time


def _run(pacst, files, out, cache):
    start = time.perf_counter()
    subprocess.run(pacst + ["build", "--out", out, "--cache", cache] + files, check=True)
    return time.perf_counter() - start


def _measure(pacst, label, files, repeats):
    """Best of `repeats` for each case, each in fresh folders so that 'cold' really has no cache."""
    best = {"cold": float("inf"), "unchanged": float("inf"), "one file touched": float("inf")}
    lines = sum(open(f, encoding="utf-8").read().count("\n") for f in files)
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as tmp:
            copies = []
            for f in files:
                dst = os.path.join(tmp, "src", os.path.relpath(f, os.path.commonpath(files) if len(files) > 1
                                                               else os.path.dirname(f)))
                os.makedirs(os.path.dirname(dst), exist_ok=True)
                shutil.copy(f, dst)
                copies.append(dst)
            out, cache = os.path.join(tmp, "out"), os.path.join(tmp, "cache")
            best["cold"] = min(best["cold"], _run(pacst, copies, out, cache))
            best["unchanged"] = min(best["unchanged"], _run(pacst, copies, out, cache))
            with open(copies[-1], "a", encoding="utf-8") as f:
                f.write("\n(* touched *)\n")
            best["one file touched"] = min(best["one file touched"], _run(pacst, copies, out, cache))
    return [(label, len(files), lines, case, seconds) for case, seconds in best.items()]


def main(argv=None):
    parser = argparse.ArgumentParser(prog="translate_bench", description=__doc__)
    parser.add_argument("--pacst", required=True, help="the translator command, e.g. 'python -m pacst'")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--set", nargs="+", action="append", metavar=("LABEL", "FILE"), required=True,
                        help="a label and the ST files of one set, in declaration order")
    args = parser.parse_args(argv)
    pacst = args.pacst.split()
    rows = []
    for label, *files in args.set:
        rows += _measure(pacst, label, files, args.repeats)
    print(f"{'set':<14} {'files':>5} {'lines':>6}  {'case':<17} {'seconds':>8}")
    for label, nfiles, lines, case, seconds in rows:
        print(f"{label:<14} {nfiles:>5} {lines:>6}  {case:<17} {seconds:>8.3f}")
    sys.stdout.flush()
    return 0
