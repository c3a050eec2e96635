"""paccbmc run: one harness through CBMC, judged (properties hold, reachability checks reached), the
counterexample of each failure printed scan by scan and its free inputs written for the replay test."""
import argparse
import subprocess
import sys
import time
from pathlib import Path

from . import results, timeline


def _run(args) -> int:
    cmd = [args.cbmc, *args.cbmc_args, "--json-ui", "--trace"]
    start = time.monotonic()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    seconds = time.monotonic() - start
    try:
        props = results.parse(proc.stdout)
    except ValueError as err:
        print(f"paccbmc: {args.name}: {err}\n{proc.stderr}", file=sys.stderr)
        return 2
    if not props:
        print(f"paccbmc: {args.name}: CBMC reported no properties (exit {proc.returncode})\n{proc.stderr}"
              f"\n{proc.stdout[-4000:]}", file=sys.stderr)
        return 2
    verdict = results.judge(props, args.known_open)
    print(f"{args.name}: {verdict.held} properties hold, {verdict.reached} reachability checks reached, "
          f"{len(verdict.failed)} failed, {len(verdict.unreached)} unreached, "
          f"{len(verdict.known_open)} known open ({seconds:.1f} s)")
    out_dir = Path(args.counterexamples) if args.counterexamples else None
    for kind, props_of_kind in (("FAILED", verdict.failed), ("KNOWN OPEN", verdict.known_open)):
        for prop in props_of_kind:
            print(f"\n{kind}: {prop.description} [{prop.name}]")
            print(timeline.table(prop.trace))
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
    run.add_argument("--counterexamples", help="folder for each counterexample's free inputs (the replay test)")
    run.add_argument("cbmc_args", nargs=argparse.REMAINDER, help="-- then CBMC's arguments")
    args = parser.parse_args(argv)
    if args.cbmc_args and args.cbmc_args[0] == "--":
        args.cbmc_args = args.cbmc_args[1:]
    return _run(args)
