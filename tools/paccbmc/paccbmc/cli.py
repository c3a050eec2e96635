"""paccbmc run: one harness through CBMC, judged (properties hold, reachability checks reached), the
counterexample of each failure printed scan by scan and its free inputs written for the replay test."""
import argparse
import subprocess
import sys
import time
from pathlib import Path

from . import loops, results, timeline


SLICE = "--slice-formula"


def timeline_rerun_args(cbmc_args, failed):
    """CBMC's arguments for a second run that gives the failed properties' traces their timeline: --slice-formula
    drops the harness's tl_* assignments from a trace (the free inputs stay), so the failed properties alone are
    checked again without it. None when nothing is to be run again."""
    if SLICE not in cbmc_args or not failed:
        return None
    rerun, i = [], 0
    while i < len(cbmc_args):  # a part of a split run (--only) names its properties: only the failed ones now
        if cbmc_args[i] == "--property":
            i += 2
            continue
        if cbmc_args[i] != SLICE:
            rerun.append(cbmc_args[i])
        i += 1
    for prop in failed:
        rerun += ["--property", prop.name]
    return rerun


def _cbmc(args, cbmc_args):
    proc = subprocess.run([args.cbmc, *cbmc_args, "--json-ui", "--trace"], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    try:
        return proc, results.parse(proc.stdout)
    except ValueError as err:
        raise ValueError(f"{err}\n{proc.stderr}") from err


def only_args(cbmc, cbmc_args, only):
    """CBMC's arguments for one part of a run split in two (--only): the reachability checks ("reach") or the
    properties that must hold ("hold"), each as --property, read from `cbmc --show-properties` on the same
    program. Two CTest tests that run beside each other on two cores then share the run's cost; each part is
    the whole program, sliced to its own properties (docs/verification.md)."""
    proc = subprocess.run([cbmc, *cbmc_args, "--show-properties", "--json-ui"], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    try:
        names = results.selected(proc.stdout, only == "reach")
    except ValueError as err:
        raise ValueError(f"`cbmc --show-properties` failed (exit {proc.returncode}): {err}\n{proc.stderr[-2000:]}")
    if not names:
        raise ValueError(f"`cbmc --show-properties` lists no property for --only {only}")
    return [*cbmc_args, *(a for name in names for a in ("--property", name))]


def _run(args) -> int:
    problems = loops.verify(args.cbmc, args.cbmc_args, args.loop)
    if problems:
        for problem in problems:
            print(f"paccbmc: {args.name}: {problem}", file=sys.stderr)
        return 2
    if args.only:
        try:
            args.cbmc_args = only_args(args.cbmc, args.cbmc_args, args.only)
        except ValueError as err:
            print(f"paccbmc: {args.name}: {err}", file=sys.stderr)
            return 2
    start = time.monotonic()
    try:
        proc, props = _cbmc(args, args.cbmc_args)
    except ValueError as err:
        print(f"paccbmc: {args.name}: {err}", file=sys.stderr)
        return 2
    seconds = time.monotonic() - start
    if not props:
        print(f"paccbmc: {args.name}: CBMC reported no properties (exit {proc.returncode})\n{proc.stderr}"
              f"\n{proc.stdout[-4000:]}", file=sys.stderr)
        return 2
    verdict = results.judge(props, args.known_open)
    print(f"{args.name}: {verdict.held} properties hold, {verdict.reached} reachability checks reached, "
          f"{len(verdict.failed)} failed, {len(verdict.unreached)} unreached, "
          f"{len(verdict.known_open)} known open ({seconds:.1f} s)")
    # A known open failure keeps its sliced trace (its free inputs replay it; CI need not pay for the table).
    rerun = timeline_rerun_args(args.cbmc_args, [p for p in verdict.failed if not timeline.rows(p.trace)])
    if rerun:
        try:
            traces = {p.name: p.trace for p in _cbmc(args, rerun)[1] if p.status == "FAILURE"}
        except ValueError as err:
            print(f"paccbmc: {args.name}: the run for the timeline: {err}", file=sys.stderr)
            traces = {}
        for prop in verdict.failed:
            prop.trace = traces.get(prop.name, prop.trace)
    out_dir = Path(args.counterexamples) if args.counterexamples else None
    for kind, props_of_kind in (("FAILED", verdict.failed), ("KNOWN OPEN", verdict.known_open)):
        for prop in props_of_kind:
            print(f"\n{kind}: {prop.description} [{prop.name}]")
            if timeline.rows(prop.trace) or SLICE not in args.cbmc_args:
                print(timeline.table(prop.trace))
            else:
                print("(no timeline: --slice-formula dropped it; cbmc_replay_tests replays the free inputs below)")
            if out_dir:
                out_dir.mkdir(parents=True, exist_ok=True)
                path = out_dir / f"{args.name}.{prop.name}.inputs"
                values = " ".join(str(v) for v in timeline.nondet_values(prop.trace))
                path.write_text(f"# harness: {args.name}\n# property: {prop.description}\n# status: open\n"
                                f"{values}\n")
                print(f"free inputs for the replay: {path}")
    for prop in verdict.unreached:
        print(f"UNREACHED ({prop.status}): {prop.description} [{prop.name}]: a proof whose paths never get "
              "there proves nothing")
    return 0 if verdict.ok else 1


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="paccbmc", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    run = sub.add_parser("run", help="run one harness and judge it")
    run.add_argument("--cbmc", required=True, help="the cbmc program")
    run.add_argument("--name", required=True, help="the harness's name, for the report")
    run.add_argument("--known-open", action="append", default=[],
                     help="a property (description prefix) that is a known open defect: reported, not failed")
    run.add_argument("--loop", action="append", default=[], metavar="LOOP=TEXT",
                     help="a loop of --unwindset and a text of its source line: the run fails if the number moved")
    run.add_argument("--only", choices=("reach", "hold"),
                     help="one part of a run split in two: only the reachability checks, or only the properties "
                          "that must hold")
    run.add_argument("--counterexamples", help="folder for each counterexample's free inputs (the replay test)")
    run.add_argument("cbmc_args", nargs=argparse.REMAINDER, help="-- then CBMC's arguments")
    args = parser.parse_args(argv)
    if args.cbmc_args and args.cbmc_args[0] == "--":
        args.cbmc_args = args.cbmc_args[1:]
    return _run(args)
