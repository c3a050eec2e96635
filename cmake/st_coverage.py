"""Line and branch coverage of the library's ST, per POU, from gcc's counters (through gcovr).

pacst's #line directives make gcov count each statement of the generated C on its .st line, so gcovr
reports on the .st files themselves. This prints one row per POU (file), writes an HTML report of the
annotated ST and a JSON summary, and checks the project's targets (docs/testing.md#st-coverage):
every line of the POUs (every folder of st/ but st/types and st/gvl) executed, or listed with the
reason no test can execute it, and at least 90 % of the branches taken. The exceptions file may give
reasons for lines with a branch never taken as well:

    st/cmd/FB_PAC_Cmd.st:90 | ToPac[6] := BYTE#16#99; | why no test can get there

The text between the bars must be the line's text (without leading and trailing blanks), so an
entry that no longer matches its line is reported instead of excusing another one.
"""
import argparse
import json
import os
import subprocess
import sys

BRANCH_TARGET = 90.0
# The POUs: every folder of st/ (the topic folders, st/fun) but the types and the global list.
UNCHECKED_FOLDERS = ("st/types/", "st/gvl/")


def reset(objects):
    for folder, _, files in os.walk(objects):
        for name in files:
            if name.endswith(".gcda"):
                os.remove(os.path.join(folder, name))


def run_gcovr(gcovr, root, objects, out):
    os.makedirs(out, exist_ok=True)
    detail = os.path.join(out, "gcovr.json")
    command = [gcovr, "--root", root, "--filter", os.path.join(root, "st", ""),
               "--json", detail, "--json-pretty",
               "--html-details", os.path.join(out, "index.html"), "--html-title", "PA-CONTROL library: ST coverage",
               objects]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    with open(detail, encoding="utf-8") as f:
        return json.load(f)["files"]


class FileCoverage:
    """One .st file: its executable lines and their branches."""

    def __init__(self, entry):
        self.path = entry["file"]
        self.pou = os.path.splitext(os.path.basename(self.path))[0]
        self.lines = {}  # line number -> (count, branches taken, branches)
        for line in entry["lines"]:
            number = line["line_number"]
            count, taken, total = self.lines.get(number, (0, 0, 0))
            branches = line.get("branches", [])
            self.lines[number] = (count + line["count"], taken + sum(1 for b in branches if b["count"] > 0),
                                  total + len(branches))

    def executed(self):
        return sum(1 for count, _, _ in self.lines.values() if count > 0)

    def branches(self):
        return (sum(taken for _, taken, _ in self.lines.values()), sum(total for _, _, total in self.lines.values()))

    def not_executed(self):
        return sorted(n for n, (count, _, _) in self.lines.items() if count == 0)

    def partly_taken(self):
        return sorted(n for n, (count, taken, total) in self.lines.items() if count > 0 and taken < total)


def ranges(numbers):
    out, start, last = [], None, None
    for n in numbers + [None]:
        if start is not None and (n is None or n != last + 1):
            out.append(str(start) if start == last else f"{start}-{last}")
            start = None
        if n is not None and start is None:
            start = n
        last = n
    return ",".join(out)


def percent(part, whole):
    return 100.0 * part / whole if whole else 100.0


def read_exceptions(path):
    """{(file, line): (text, reason)} from `file:line | text | reason` lines; # starts a comment."""
    exceptions = {}
    if not os.path.exists(path):
        return exceptions
    with open(path, encoding="utf-8") as f:
        for number, raw in enumerate(f, 1):
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            parts = [p.strip() for p in line.split("|", 2)]
            where = parts[0].rsplit(":", 1)
            if len(parts) != 3 or len(where) != 2 or not where[1].isdigit() or not parts[2]:
                raise SystemExit(f"{path}:{number}: expected 'st/...st:LINE | text of the line | reason'")
            exceptions[(where[0], int(where[1]))] = (parts[1], parts[2])
    return exceptions


def check(files, root, exceptions):
    """The problems that break the targets: a line not executed without a reason, an entry that no longer
    matches its line. A line with a branch never taken may be listed with its reason, but need not be: the
    branch target is the total."""
    problems = []
    listed = set()
    for cov in files:
        if not cov.path.startswith("st/") or cov.path.startswith(UNCHECKED_FOLDERS):
            continue
        with open(os.path.join(root, cov.path), encoding="utf-8") as f:
            source = f.read().splitlines()
        for n in cov.not_executed() + cov.partly_taken():
            key = (cov.path, n)
            text = source[n - 1].strip() if n <= len(source) else ""
            if key not in exceptions:
                if cov.lines[n][0] == 0:
                    problems.append(f"{cov.path}:{n}: not executed, and no reason in the exceptions file: {text}")
                continue
            listed.add(key)
            if exceptions[key][0] != text:
                problems.append(f"{cov.path}:{n}: the exceptions file says '{exceptions[key][0]}', the line is '{text}'")
    for key in sorted(set(exceptions) - listed):
        problems.append(f"{key[0]}:{key[1]}: listed in the exceptions file, but fully covered now: remove it")
    return problems


def report(files, out):
    rows = []
    print(f"{'POU':<36} {'lines':>15} {'branches':>15}   lines not executed; lines with a branch never taken")
    for cov in files:
        lines, (taken, branches) = len(cov.lines), cov.branches()
        executed = cov.executed()
        branch_text = f"{taken}/{branches} {percent(taken, branches):5.1f}%" if branches else "-"
        print(f"{cov.pou:<36} {executed:>5}/{lines:<4}{percent(executed, lines):5.1f}% {branch_text:>15}   "
              f"{ranges(cov.not_executed())}{'; ' + ranges(cov.partly_taken()) if cov.partly_taken() else ''}")
        rows.append({"pou": cov.pou, "file": cov.path, "lines": lines, "lines_executed": executed,
                     "branches": branches, "branches_taken": taken, "not_executed": cov.not_executed(),
                     "branches_not_taken_on": cov.partly_taken()})
    total_lines = sum(r["lines"] for r in rows)
    total_executed = sum(r["lines_executed"] for r in rows)
    total_branches = sum(r["branches"] for r in rows)
    total_taken = sum(r["branches_taken"] for r in rows)
    print(f"{'total':<36} {total_executed:>5}/{total_lines:<5}{percent(total_executed, total_lines):5.1f}% "
          f"{total_taken:>5}/{total_branches:<5}{percent(total_taken, total_branches):5.1f}%")
    summary = {"lines": total_lines, "lines_executed": total_executed, "branches": total_branches,
               "branches_taken": total_taken, "pous": rows}
    with open(os.path.join(out, "summary.json"), "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1)
    print(f"annotated ST: {os.path.join(out, 'index.html')}; figures: {os.path.join(out, 'summary.json')}")
    return percent(total_taken, total_branches)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gcovr", required=True)
    parser.add_argument("--root", required=True, help="the source tree")
    parser.add_argument("--objects", required=True, help="where the instrumented objects and their counters are")
    parser.add_argument("--out", required=True, help="folder for the HTML report and summary.json")
    parser.add_argument("--exceptions", required=True, help="lines left out, each with its reason")
    parser.add_argument("--reset", action="store_true", help="only delete the counters")
    args = parser.parse_args()
    if args.reset:
        reset(args.objects)
        return 0
    files = sorted((FileCoverage(e) for e in run_gcovr(args.gcovr, args.root, args.objects, args.out)),
                   key=lambda c: c.path)
    if not files:
        print("no counters: run the tests of this build first", file=sys.stderr)
        return 1
    branch_percent = report(files, args.out)
    problems = check(files, args.root, read_exceptions(args.exceptions))
    if branch_percent < BRANCH_TARGET:
        problems.append(f"branches: {branch_percent:.1f} % taken, the target is {BRANCH_TARGET:.0f} %")
    for problem in problems:
        print("coverage target missed: " + problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
