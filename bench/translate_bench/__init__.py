"""Benchmark (not a test): seconds pacst needs to translate a set of ST files cold (in one process and
with one worker per core), unchanged, and after one file was touched (the largest file and one of
median size), printed as a table. Best of `--repeats` runs, each in fresh folders. Wall clock and CPU
time (user + system of pacst and its workers): on a machine shared with other work the CPU time is the
steadier figure, the wall clock what a user waits."""
import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time


def _cpu_of_children():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _run(pacst, files, out, cache, extra=()):
    """(wall seconds, CPU seconds) of one pacst build."""
    start, cpu = time.perf_counter(), _cpu_of_children()
    subprocess.run(pacst + ["build", "--out", out, "--cache", cache] + list(extra) + files, check=True)
    return time.perf_counter() - start, _cpu_of_children() - cpu


def _best(a, b):
    return (min(a[0], b[0]), min(a[1], b[1]))


def _lines(path):
    with open(path, encoding="utf-8") as f:
        return f.read().count("\n")


def _copy(files, tmp):
    root = os.path.commonpath(files) if len(files) > 1 else os.path.dirname(files[0])
    copies = []
    for f in files:
        dst = os.path.join(tmp, "src", os.path.relpath(f, root))
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copy(f, dst)
        copies.append(dst)
    return copies


def _touch(path):
    with open(path, "a", encoding="utf-8") as f:
        f.write("\n(* touched *)\n")


def _measure(pacst, label, files, repeats):
    by_size = sorted(range(len(files)), key=lambda i: _lines(files[i]))
    largest, median = by_size[-1], by_size[len(by_size) // 2]
    touched = [(f"touched: {os.path.basename(files[i])} ({_lines(files[i])} lines)", i) for i in (largest, median)]
    cases = ["cold, 1 process", "cold", "unchanged"] + [name for name, _ in touched]
    best = {case: (float("inf"), float("inf")) for case in cases}
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as tmp:
            copies = _copy(files, tmp)
            out = os.path.join(tmp, "out")
            best["cold, 1 process"] = _best(best["cold, 1 process"],
                                            _run(pacst, copies, out, os.path.join(tmp, "cache1"), ["-j", "1"]))
            cache = os.path.join(tmp, "cache")
            best["cold"] = _best(best["cold"], _run(pacst, copies, out, cache))
            best["unchanged"] = _best(best["unchanged"], _run(pacst, copies, out, cache))
            for name, i in touched:
                _touch(copies[i])
                best[name] = _best(best[name], _run(pacst, copies, out, cache))
    lines = sum(_lines(f) for f in files)
    return [(label, len(files), lines, case, best[case]) for case in cases]


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
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"Translation time (best of {args.repeats}, seconds; load average {load} at the end; "
          f"{len(os.sched_getaffinity(0))} cores)\n")
    print("| set | files | lines | case | wall clock | CPU (user + system) |\n|---|---:|---:|---|---:|---:|")
    for label, nfiles, lines, case, (wall, cpu) in rows:
        print(f"| {label} | {nfiles} | {lines} | {case} | {wall:.2f} | {cpu:.2f} |")
    sys.stdout.flush()
    return 0
