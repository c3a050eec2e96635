"""The wiring file (JSON, docs/user_tests.md#the-wiring-file): the user's sources, tasks, bus images, the
simulated controller (the scenario format's "timing" and "controller", read by the scenario loader in the
host) and the tests. Every key is checked here; a refusal names the JSONPath, as the scenario loader does."""
import glob
import json
import math
import os
import re


class WiringError(Exception):
    def __init__(self, path, reason):
        super().__init__(f"{path}: {reason}")


TOP_KEYS = {"name", "description", "sources", "libraries", "tasks", "bus", "timing", "controller", "tests", "signals"}
TEST_KEYS = {"prefix", "names", "task", "time_limit_ms", "faults", "expected_to_fail"}
FAULT_KEYS = {"at_ms", "fault", "link", "number", "input", "value", "note"}
# The scenario format's description, whose fault steps name the fault kinds the scenario loader knows.
SCENARIO_SCHEMA = os.path.join(os.path.dirname(__file__), "..", "..", "..", "scenario", "scenario.schema.json")


def fault_kinds():
    """The fault kinds of the scenario format ("power_cycle", ...), read from its schema: `--list` refuses a
    misspelt one as the run does, without building the host whose loader checks the rest of a fault."""
    with open(SCENARIO_SCHEMA, encoding="utf-8") as f:
        definitions = json.load(f).get("definitions", {})
    kinds = set()
    for definition in definitions.values():
        fault = definition.get("properties", {}).get("fault", {})
        kinds.update([fault["const"]] if "const" in fault else fault.get("enum", []))
    return sorted(kinds)


def _object(value, path, keys):
    if not isinstance(value, dict):
        raise WiringError(path, f"expected an object, got {type(value).__name__}")
    for key in value:
        if key not in keys:
            raise WiringError(f"{path}.{key}", f"unknown key \"{key}\" (known: {', '.join(sorted(keys))})")
    return value


def _int(value, path, low, high):
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        raise WiringError(path, f"expected an integer in {low}..{high}, got {json.dumps(value)}")
    return value


def _names(value, path):
    if not isinstance(value, list) or not all(isinstance(v, str) and v for v in value):
        raise WiringError(path, "expected an array of names")
    return value


class Module:
    """One bus module: where the user's program keeps its input image and its output image. Each is a
    variable's ST path (GVL_Bus.CmdIn) or a located address (%IB0, %QB0) where the module's bytes start."""

    def __init__(self, kind, number, value, path):
        _object(value, path, {"in", "out"})
        self.kind, self.number, self.where = kind, number, path
        for side, prefix in (("in", "%IB"), ("out", "%QB")):
            if side not in value or not isinstance(value[side], str):
                raise WiringError(f"{path}.{side}", "missing: the variable or located address of the image")
            text = value[side]
            if text.upper().startswith("%") and not (text.upper().startswith(prefix) and text[3:].isdigit()):
                raise WiringError(f"{path}.{side}", f"a located {side}put image starts at {prefix}n, not {text}")
        self.image_in, self.image_out = value["in"], value["out"]
        self.size = 12 if kind == "axis" else 8

    def offset(self):
        if self.kind == "cmd":
            return 0
        if self.kind == "ctrl":
            return 8
        return 16 + 12 * (self.number - 1)


class Wiring:
    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.folder = os.path.dirname(self.path)
        try:
            with open(path, encoding="utf-8") as f:
                data = json.load(f, object_pairs_hook=_no_duplicates)
        except OSError as e:
            raise WiringError("$", f"cannot read the file: {e.strerror}")
        except ValueError as e:
            raise WiringError("$", f"not valid JSON: {e}")
        _object(data, "$", TOP_KEYS)
        self.name = data.get("name", os.path.splitext(os.path.basename(path))[0])
        self.sources = self._sources(data.get("sources"), "$.sources")
        self.libraries = self._libraries(data.get("libraries", {}), "$.libraries")
        self.tasks = self._tasks(data.get("tasks"), "$.tasks")
        self.base_cycle_ms = math.gcd(*[t["cycle_ms"] for t in self.tasks])
        self.modules = self._bus(data.get("bus", {}), "$.bus")
        self.timing = dict(_object(data.get("timing", {}), "$.timing",
                                   {"pac_cycle_ms", "latency_cycles", "jitter_ms", "seed", "boot_ms"}))
        self.controller = data.get("controller", {})
        self.signals = _names(data.get("signals", []), "$.signals")
        tests = _object(data.get("tests", {}), "$.tests", TEST_KEYS)
        self.prefix = tests.get("prefix", "FB_Test")
        self.test_names = _names(tests.get("names", []), "$.tests.names")
        self.test_task = tests.get("task", self.tasks[0]["name"])
        if self.test_task not in [t["name"] for t in self.tasks]:
            raise WiringError("$.tests.task", f"no task named {json.dumps(self.test_task)} in $.tasks")
        self.time_limit_ms = _int(tests.get("time_limit_ms", 10000), "$.tests.time_limit_ms", 1, 3600000)
        expected = _names(tests.get("expected_to_fail", []), "$.tests.expected_to_fail")
        self.expected_to_fail = set(n.upper() for n in expected)
        self.faults = {}
        faults = _object(tests.get("faults", {}), "$.tests.faults", set(tests.get("faults", {})))
        for test, items in faults.items():
            where = f"$.tests.faults.{test}"
            if not isinstance(items, list):
                raise WiringError(where, "expected an array of faults")
            self.faults[test.upper()] = [self._fault(item, f"{where}[{i}]") for i, item in enumerate(items)]

    def _sources(self, value, path):
        if not isinstance(value, list) or not value:
            raise WiringError(path, "missing: the ST files (.st, .TcPOU, .TcGVL, .TcDUT, a .plcproj), globs allowed")
        files = []
        for i, pattern in enumerate(value):
            if not isinstance(pattern, str):
                raise WiringError(f"{path}[{i}]", "expected a file name or glob")
            found = sorted(glob.glob(os.path.join(self.folder, pattern), recursive=True))
            if not found:
                raise WiringError(f"{path}[{i}]", f"no file matches {pattern}")
            files += [f for f in found if f not in files]
        return files

    def _libraries(self, value, path):
        """[(namespace, path, where it is given)] of the program's own libraries:
        {"FsCommon": "lib/FsCommon.plcproj"}."""
        _object(value, path, set(value) if isinstance(value, dict) else set())
        found = []
        for name, where in value.items():
            if not isinstance(where, str) or not where:
                raise WiringError(f"{path}.{name}", "expected the library's path: a .plcproj, a PLCopen XML file or a "
                                                    "folder of ST or TwinCAT files")
            found.append((name, os.path.normpath(os.path.join(self.folder, where)), f"{path}.{name}"))
        return found

    def _tasks(self, value, path):
        if not isinstance(value, list) or not value:
            raise WiringError(path, "missing: at least one task with its cycle and programs")
        tasks = []
        for i, task in enumerate(value):
            where = f"{path}[{i}]"
            _object(task, where, {"name", "cycle_ms", "programs"})
            if not isinstance(task.get("name"), str):
                raise WiringError(f"{where}.name", "missing: the task's name")
            tasks.append({"name": task["name"], "cycle_ms": _int(task.get("cycle_ms"), f"{where}.cycle_ms", 1, 1000),
                          "programs": _names(task.get("programs", []), f"{where}.programs")})
        return tasks

    def _bus(self, value, path):
        _object(value, path, {"cmd", "ctrl", "axes", "automatic"})
        modules = []
        if "cmd" in value:
            modules.append(Module("cmd", 0, value["cmd"], f"{path}.cmd"))
        if "ctrl" in value:
            modules.append(Module("ctrl", 0, value["ctrl"], f"{path}.ctrl"))
        # Axis module k is also AUTOMATIC module k (manual 2.6): one image, which the library's axis FB and
        # FB_PAC_AutomaticModule share (AxisOwnsModule); `automatic` names it for a program in AUTOMATIC only.
        views = {}
        for kind in ("axes", "automatic"):
            items = value.get(kind, [])
            if not isinstance(items, list) or len(items) > 8:
                raise WiringError(f"{path}.{kind}", "expected an array of at most 8 modules")
            views[kind] = items
        count = max(len(views["axes"]), len(views["automatic"]))
        if count and "ctrl" not in value:
            raise WiringError(f"{path}.axes",
                              "axis modules need the CTRL module (they follow it on the bus, manual 2.3)")
        for k in range(1, count + 1):
            axis = views["axes"][k - 1] if k <= len(views["axes"]) else None
            auto = views["automatic"][k - 1] if k <= len(views["automatic"]) else None
            if axis is not None and auto is not None and axis != auto:
                raise WiringError(f"{path}.automatic[{k - 1}]", f"module {k} has one image: the same \"in\" and "
                                  f"\"out\" as $.bus.axes[{k - 1}], or leave one of them out")
            where = f"{path}.axes[{k - 1}]" if axis is not None else f"{path}.automatic[{k - 1}]"
            modules.append(Module("axis", k, axis if axis is not None else auto, where))
        return modules

    def warnings(self):
        """What makes the simulated controller ignore a start of ONLINE (manual 5.2.1.3), so that a program
        waits for it until its tests' time limit: as pac_scenario warns of it."""
        if not any(m.kind == "ctrl" for m in self.modules) or not isinstance(self.controller, dict):
            return []
        params = self.controller.get("system_parameters", {})
        inputs = self.controller.get("inputs", {})
        stop = params.get("4", 0) if isinstance(params, dict) else 0
        if stop == 0:
            return ["$.controller.system_parameters: system parameter 4 is 0: the PA-CONTROL will not start "
                    "ONLINE without an external stop input (manual 5.2.1.3); set it, e.g. "
                    "\"system_parameters\": {\"4\": 1}, \"inputs\": {\"1\": true}"]
        if isinstance(inputs, dict) and inputs.get(str(stop)) is not True:
            return [f"$.controller.inputs: input {stop} (system parameter 4) has no power: the PA-CONTROL will "
                    f"not start ONLINE while the external stop is open (manual 5.2.1.3); set "
                    f"\"inputs\": {{\"{stop}\": true}} (a test opens it with a set_input fault)"]
        return []

    def _fault(self, item, path):
        _object(item, path, FAULT_KEYS)
        at = _int(item.get("at_ms"), f"{path}.at_ms", 0, 3600000)
        kinds = fault_kinds()
        if item.get("fault") not in kinds:
            raise WiringError(f"{path}.fault", f"unknown fault {json.dumps(item.get('fault'))} (a fault is "
                                               f"{', '.join(json.dumps(k) for k in kinds)})")
        step = {k: v for k, v in item.items() if k != "at_ms"}
        return at, step

    def axes(self):
        return sum(1 for m in self.modules if m.kind == "axis")

    def _steps(self, test):
        """The scenario's steps for `test` and {step index: the fault's JSONPath in the wiring file}. Kept
        off the object: the tests run in a thread pool, each with its own."""
        steps, paths, now = [], {}, 0
        faults = self.faults.get(test.upper(), [])
        for i, (at, step) in sorted(enumerate(faults), key=lambda f: f[1][0]):
            if at > now:
                steps.append({"wait_ms": at - now})
                now = at
            paths[len(steps)] = f"$.tests.faults.{test}[{i}]"
            steps.append(step)
        steps.append({"wait_ms": 1})  # the format needs a step; the host ignores a last wait
        return steps, paths

    def scenario(self, test):
        """The scenario file the host reads for `test`: the simulated PLC and controller, and the test's
        faults as wait and fault steps (the scenario loader checks them)."""
        timing = dict(self.timing, plc_cycle_ms=self.base_cycle_ms)
        return {"name": test, "timing": timing, "controller": self.controller,
                "modules": {"ctrl": any(m.kind == "ctrl" for m in self.modules), "axes": self.axes()},
                "steps": self._steps(test)[0]}

    def step_paths(self, test):
        """{the scenario's step index: the JSONPath of the fault in the wiring file} of `test`."""
        return self._steps(test)[1]


def wiring_path(message, step_paths):
    """The scenario loader's refusal with the JSONPath of the wiring file: `$.steps[k]` is a test's fault."""
    match = re.match(r"\$\.steps\[(\d+)\]", message)
    if match and int(match.group(1)) in step_paths:
        return step_paths[int(match.group(1))] + message[match.end():]
    return message


def _no_duplicates(pairs):
    seen = {}
    for key, value in pairs:
        if key in seen:
            raise ValueError(f"duplicate key \"{key}\"")
        seen[key] = value
    return seen
