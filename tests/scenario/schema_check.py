"""scenario/scenario.schema.json against every scenario file of the tree and against the loader.

  schema_check.py --schema FILE --scenario-binary PAC_SCENARIO --repo REPO
      ScenarioSchema.EveryScenarioFileValidates: the schema is a valid draft-07 schema, and every scenario
      file of the tree (a *.json under scenario/ or tests/ whose top level has "steps") is valid under it
      and passes `pac_scenario --check`; the VS Code settings of docs/scenario.md name the schema.
      ScenarioSchema.RefusesWhatTheLoaderRefuses (--mutations): each file is damaged one place at a time,
      once per place of the format (the JSONPath without array indices): every key misspelt (an "x"
      appended) must be refused by both the schema and the loader, and every value replaced by one of
      another type (a string for a number or true/false, a number for a string, an array for an object and
      back) or by a number at or beyond the edge of a range (INTEGER_EDGES, REAL_EDGES) must be refused by
      both or accepted by both. The ranges that depend on other keys (CONTEXTUAL: a diagram's steps within
      the scenario's, an axis within modules.axes, the limit switches' order) are the loader's alone.
      The run prints the counts, and fails when a file or a damage disagrees.
The jsonschema package is pinned in requirements.txt (the venv of tests/scenario)."""
import argparse
import copy
import json
import os
import re
import subprocess
import sys
import tempfile

import jsonschema

# Places whose range depends on other keys (a diagram within the steps, axes steps within modules.axes,
# the negative switch below the positive one): the schema cannot say it, the loader does.
CONTEXTUAL = {"$.diagram.steps[]", "$.modules.axes", "$.steps[].axes[].axis", "$.steps[].automatic[].module",
              "$.controller.limit_switches[#].negative", "$.controller.limit_switches[#].positive"}


def scenario_files(repo):
    found = []
    for top in ("scenario", "tests"):
        for folder, dirs, files in os.walk(os.path.join(repo, top)):
            dirs[:] = sorted(d for d in dirs if not d.startswith("."))
            for name in sorted(files):
                if not name.endswith(".json") or name.endswith(".schema.json"):
                    continue
                path = os.path.join(folder, name)
                try:
                    with open(path, encoding="utf-8") as f:
                        document = json.load(f)
                except ValueError:
                    continue  # damaged on purpose (the loader's tests) or not JSON at all
                if isinstance(document, dict) and "steps" in document:
                    found.append(path)
    return found


def places(value, path="$", pattern="$"):
    """(path, pattern, container, key) of every key and array element below `value`; the pattern has no indices."""
    if isinstance(value, dict):
        for key in value:
            child = f"{path}[{json.dumps(key)}]"
            child_pattern = f"{pattern}.{key}" if not key.isdigit() else f"{pattern}[#]"
            yield child, child_pattern, value, key
            yield from places(value[key], child, child_pattern)
    elif isinstance(value, list):
        for i, item in enumerate(value):
            yield f"{path}[{i}]", f"{pattern}[]", value, i
            yield from places(item, f"{path}[{i}]", f"{pattern}[]")


# The edges of the format's integer ranges (the limits and one beyond) and a fraction; beyond a REAL.
INTEGER_EDGES = [0, 1, 8, 9, 255, 256, 999, 1000, 1001, 1024, 1025, 10000, 10001, 65535, 65536, 600000, 600001,
                 3600000, 3600001, -2147483648, -2147483649, 2147483647, 2147483648, 4294967295, 4294967296, 0.5]
REAL_EDGES = [3.5e38, -3.5e38]


def other_types(value):
    """Values of another type than `value`, and numbers at and beyond the edges of every range."""
    if isinstance(value, bool):
        return [json.dumps(value)]
    if isinstance(value, int):
        return [str(value), -1, 10**12] + INTEGER_EDGES
    if isinstance(value, float):
        return [str(value), -1, 10**12] + REAL_EDGES
    if isinstance(value, str):
        return [7]
    if isinstance(value, dict):
        return [[]]
    return [{}]


class Loader:
    """pac_scenario --check, given many documents in one call: one process start for all of them (a start of
    the sanitizer build costs more than the check itself)."""

    def __init__(self, binary, work):
        self.binary, self.work = binary, work

    def accepts(self, documents):
        """(accepted, the loader's reason or "") of each document, in order."""
        paths = []
        for i, document in enumerate(documents):
            paths.append(os.path.join(self.work, f"damaged-{i}.json"))
            with open(paths[-1], "w", encoding="utf-8") as f:
                json.dump(document, f)
        results = []
        for start in range(0, len(paths), 500):  # well within any command line's length
            results += self._check(paths[start:start + 500])
        return results

    def _check(self, paths):
        run = subprocess.run([self.binary, "--check", *paths], capture_output=True, text=True)
        if run.returncode not in (0, 2):
            raise SystemExit(f"pac_scenario --check exited {run.returncode}: {run.stderr}")
        valid = {line.partition(": valid scenario")[0] for line in run.stdout.splitlines()
                 if ": valid scenario" in line}
        reasons = {}
        for line in run.stderr.splitlines():
            for path in paths:
                if line.startswith(f"pac_scenario: invalid scenario {path}: ") or \
                        line.startswith(f"pac_scenario: warning: {path}: "):
                    reasons[path] = (reasons.get(path, "") + "\n" + line).strip()
                    break
        results = [(path in valid, reasons.get(path, "")) for path in paths]
        unreported = [path for path, (ok, why) in zip(paths, results) if not ok and "invalid scenario" not in why]
        if unreported:
            raise SystemExit(f"pac_scenario --check reported neither valid nor invalid: {unreported[0]}\n{run.stderr}")
        return results


def mutations(document):
    """(what, damaged document, both must refuse) for each place of the format in `document`."""
    for path, pattern, container, key in places(document):
        if isinstance(key, str):
            damaged = copy.deepcopy(document)
            target = resolve(damaged, path)
            target[key + "x"] = target.pop(key)
            yield f"{path}: key misspelt", pattern + "/key", damaged, True
        for value in other_types(container[key]):
            damaged = copy.deepcopy(document)
            resolve(damaged, path)[key] = value
            # Once per place and kind of damage: each number, any string, array or object.
            kind = json.dumps(value) if isinstance(value, (int, float)) else type(value).__name__
            yield f"{path}: {json.dumps(value)}", f"{pattern}/{kind}", damaged, False


def resolve(document, path):
    """The container of the place `path` ($["steps"][2]["param"]) in `document`."""
    tokens = re.findall(r'\[("(?:[^"\\]|\\.)*"|\d+)\]', path)
    target = document
    for token in tokens[:-1]:
        target = target[json.loads(token)] if token.startswith('"') else target[int(token)]
    return target


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--schema", required=True)
    parser.add_argument("--scenario-binary", required=True)
    parser.add_argument("--repo", required=True)
    parser.add_argument("--mutations", action="store_true")
    args = parser.parse_args()
    with open(args.schema, encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    # docs/scenario.md's VS Code settings name this schema, relative to the repository (the workspace).
    with open(os.path.join(args.repo, "tests", "docs", "examples", "vscode_settings.json"), encoding="utf-8") as f:
        urls = [entry["url"] for entry in json.load(f)["json.schemas"]]
    failures = [f"vscode_settings.json: {url} is not {args.schema}" for url in urls
                if not os.path.samefile(os.path.join(args.repo, url), args.schema)]
    validator = jsonschema.Draft7Validator(schema)
    files = scenario_files(args.repo)
    with tempfile.TemporaryDirectory() as work:
        loader = Loader(args.scenario_binary, work)
        if not args.mutations:
            documents = []
            for path in files:
                rel = os.path.relpath(path, args.repo)
                with open(path, encoding="utf-8") as f:
                    documents.append(json.load(f))
                for error in validator.iter_errors(documents[-1]):
                    failures.append(f"{rel}: {error.json_path}: {error.message}")
            for path, (ok, why) in zip(files, loader.accepts(documents)):
                if not ok:
                    failures.append(f"{os.path.relpath(path, args.repo)}: pac_scenario --check refuses it: {why}")
        seen = set()
        damages = []  # (file, what, place, damaged, must refuse)
        for path in files if args.mutations else []:
            with open(path, encoding="utf-8") as f:
                document = json.load(f)
            for what, place, damaged, must_refuse in mutations(document):
                if place not in seen:
                    seen.add(place)
                    damages.append((os.path.relpath(path, args.repo), what, place, damaged, must_refuse))
        refused = agreed = 0
        verdicts = loader.accepts([damaged for _, _, _, damaged, _ in damages])
        for (rel, what, place, damaged, must_refuse), (loader_ok, why) in zip(damages, verdicts):
            schema_ok = validator.is_valid(damaged)
            contextual = any(place.startswith(c + "/") for c in CONTEXTUAL)
            if must_refuse and (schema_ok or loader_ok):
                failures.append(f"{rel}: {what}: the schema {'accepts' if schema_ok else 'refuses'}, "
                                f"the loader {'accepts' if loader_ok else 'refuses'} (both must refuse)")
            elif schema_ok != loader_ok and not (contextual and schema_ok):
                failures.append(f"{rel}: {what}: the schema {'accepts' if schema_ok else 'refuses'}, "
                                f"the loader {'accepts: ' if loader_ok else 'refuses: ' + why}")
            agreed += 1
            refused += not loader_ok
    for failure in failures[:40]:
        print("FAILED: " + failure)
    if args.mutations:
        print(f"{len(files)} scenario files, {agreed} damages (one per place of the format), {refused} refused by "
              f"the loader; {len(failures)} disagreement(s) with the schema")
        if agreed < 200 or refused < agreed // 2:
            print("FAILED: too few damages to say the schema and the loader agree")
            return 1
    else:
        print(f"{len(files)} scenario files: {len(failures)} failure(s)")
        if len(files) < 14:
            print("FAILED: fewer scenario files than the tree holds (scenario/demo.json, scenario/examples, tests)")
            return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
