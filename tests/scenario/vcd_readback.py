"""Reads the VCD that `pac_scenario --vcd` writes back with pyvcd, a reader of IEEE 1364 that shares no
code with the writer, and checks it against what the same run printed in its timeline: every scan line
of the timeline (the CMD, CTRL and axis views) must show the values the VCD holds at that scan's time,
every step result must be where the VCD has the FB's final output rise, and every time stamp must be a
scan's time.

    vcd_readback.py --scenario-binary build/scenario/pac_scenario --scenario scenario/demo.json --work DIR
"""
import argparse
import os
import re
import subprocess
import sys
from bisect import bisect_right

from vcd.reader import TokenKind, tokenize

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


class Vcd:
    """The variables of a VCD by their full dotted name, each with its value changes in time order."""

    def __init__(self, path):
        self.timescale = None
        self.vars = {}  # name -> (size, [(time, value)])
        self.times = []
        codes = {}
        scopes = []
        time = None
        with open(path, "rb") as f:
            for token in tokenize(f):
                kind = token.kind
                if kind is TokenKind.TIMESCALE:
                    self.timescale = (int(token.timescale.magnitude), token.timescale.unit.value)
                elif kind is TokenKind.SCOPE:
                    scopes.append(token.scope.ident)
                elif kind is TokenKind.UPSCOPE:
                    scopes.pop()
                elif kind is TokenKind.VAR:
                    name = ".".join(scopes[1:] + [token.var.reference])  # below the top module
                    codes[token.var.id_code] = name
                    self.vars[name] = (token.var.size, [])
                elif kind is TokenKind.CHANGE_TIME:
                    time = token.time_change
                    self.times.append(time)
                elif kind in (TokenKind.CHANGE_SCALAR, TokenKind.CHANGE_VECTOR, TokenKind.CHANGE_REAL):
                    change = token.data
                    value = int(change.value) if kind is TokenKind.CHANGE_SCALAR else change.value
                    self.vars[codes[change.id_code]][1].append((time, value))

    def at(self, name, time):
        """The value of `name` at `time` (its last change at or before it)."""
        changes = self.vars[name][1]
        i = bisect_right([t for t, _ in changes], time)
        if i == 0:
            raise KeyError(f"{name} has no value at {time} ns")
        return changes[i - 1][1]


def hex_bytes(text):
    return int(text.replace(" ", ""), 16)


def number(text):
    """A timeline number: decimal, or an IEC literal 16#..."""
    return int(text[3:], 16) if text.startswith("16#") else int(text)


def ns(ms_text):
    whole, _, fraction = ms_text.partition(".")
    return int(whole) * 1_000_000 + int((fraction + "000000")[:6])


def check_cmd_line(vcd, fields, t):
    to_pac, from_pac, flags, pins = fields
    expect = {"cmd.ToPac": hex_bytes(to_pac), "cmd.FromPac": hex_bytes(from_pac)}
    send, rf, kf, bf, status = flags.split()
    expect.update({"cmd.SEND": int(send), "cmd.RF": int(rf), "cmd.KF": int(kf), "cmd.BF": int(bf),
                   "cmd.Status": int(status)})
    execute, busy, done, error, error_id, ack = pins.split()
    expect.update({"cmd.FB_PAC_Cmd.Execute": int(execute), "cmd.FB_PAC_Cmd.Busy": int(busy),
                   "cmd.FB_PAC_Cmd.Done": int(done), "cmd.FB_PAC_Cmd.Error": int(error),
                   "cmd.FB_PAC_Cmd.ErrorID": number(error_id), "cmd.FB_PAC_Cmd.AckData": number(ack)})
    return expect


def check_ctrl_line(vcd, fields, t):
    to_pac, from_pac, words, bits, pins = fields
    control, status, system_error = words.split()
    expect = {"ctrl.ToPac": hex_bytes(to_pac), "ctrl.FromPac": hex_bytes(from_pac), "ctrl.Control": number(control),
              "ctrl.Status": number(status), "ctrl.SystemErrorNumber": int(system_error)}
    names = ["Ready", "BatteryOk", "SystemError", "AutomaticActive", "AutomaticStopped", "OnlineActive",
             "OnlineStopped", "IntegerModeActive"]
    for name, bit in zip(names, bits.split()):
        expect["ctrl.status." + name] = int(bit)
    execute, busy, done, error, error_id = pins.split()
    expect.update({"ctrl.FB_PAC_Ctrl.Execute": int(execute), "ctrl.FB_PAC_Ctrl.Busy": int(busy),
                   "ctrl.FB_PAC_Ctrl.Done": int(done), "ctrl.FB_PAC_Ctrl.Error": int(error),
                   "ctrl.FB_PAC_Ctrl.ErrorID": number(error_id)})
    return expect


def check_axis_line(vcd, fields, t):
    axis, sent, received, pins = fields
    scope = f"axis{int(axis)}"
    control, acceleration, speed, target = sent.split()
    status, cmd_error, axis_error, position = received.split()
    expect = {scope + ".Control": number(control), scope + ".Acceleration": int(acceleration),
              scope + ".Speed": int(speed), scope + ".Status": number(status),
              scope + ".CmdErrorNumber": int(cmd_error), scope + ".AxisErrorNumber": int(axis_error)}
    for name, text in (("TargetPosition", target), ("Position", position)):
        check(abs(vcd.at(f"{scope}.{name}", t) - float(text)) <= 0.0005,
              f"{t} ns: {scope}.{name} is {vcd.at(f'{scope}.{name}', t)} in the VCD, {text} in the timeline")
    fb = scope + ".FB_PAC_Axis."
    for name, value in zip(["Enable", "Execute", "Busy", "Done", "Error", "CommandAborted"], pins.split()):
        expect[fb + name] = int(value)
    expect[fb + "ErrorID"] = number(pins.split()[6])
    return expect


VIEWS = {"ToPac (PLC -> PAC)": check_cmd_line, "CTRL ToPac": check_ctrl_line, "| axis |": check_axis_line}


def check_timeline(vcd, timeline, cycle_ns):
    view = None
    lines = 0
    outcomes = 0
    for line in timeline.splitlines():
        for marker, checker in VIEWS.items():
            if line.lstrip().startswith("t [ms]") and marker in line:
                view = checker
        scan = re.match(r"\s*(\d+(?:\.\d+)?)\s+(\d+) \| (.*)$", line)
        if scan and view:
            t = ns(scan.group(1))
            check(t == int(scan.group(2)) * cycle_ns, f"timeline: scan {scan.group(2)} at {scan.group(1)} ms")
            fields = [f.strip() for f in scan.group(3).split("|")]
            for name, value in view(vcd, fields, t).items():
                check(vcd.at(name, t) == value, f"{t} ns: {name} is {vcd.at(name, t)} in the VCD, {value} in the timeline")
            lines += 1
        # "=> Done in scan 34 (68 ms)" and "=> axis 1: Error in scan 86 (172 ms)": the final output rises there.
        result = re.match(r"\s*=> (?:axis (\d+): )?(Done|Error|CommandAborted) in scan (\d+) \((\S+) ms\)", line)
        if result and view:
            axis, output, _, ms = result.groups()
            t = ns(ms)
            if axis:
                name = f"axis{axis}.FB_PAC_Axis.{output}"
            elif view is check_ctrl_line:
                name = f"ctrl.FB_PAC_Ctrl.{output}"
            else:
                name = f"cmd.FB_PAC_Cmd.{output}"
            check(vcd.at(name, t) == 1, f"{name} is not 1 at {ms} ms, where the timeline reports it")
            check(vcd.at(name, t - cycle_ns) == 0, f"{name} is already 1 one scan before {ms} ms")
            outcomes += 1
    return lines, outcomes


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario-binary", required=True)
    parser.add_argument("--scenario", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    vcd_path = os.path.join(args.work, os.path.splitext(os.path.basename(args.scenario))[0] + ".vcd")
    run = subprocess.run([args.scenario_binary, "--vcd", vcd_path, args.scenario], capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout, run.stderr, sep="\n")
        print(f"pac_scenario exited with {run.returncode}")
        return 1
    cycle_ms = int(re.search(r"timing: PLC cycle (\d+) ms", run.stdout).group(1))
    cycle_ns = cycle_ms * 1_000_000
    vcd = Vcd(vcd_path)

    check(vcd.timescale == (1, "ns"), f"timescale {vcd.timescale}, expected 1 ns")
    check(vcd.times and vcd.times[0] == cycle_ns, "the first values are those of the first scan, one cycle in")
    check(all(t % cycle_ns == 0 for t in vcd.times), "a time stamp that is no scan's time")
    check(vcd.times == sorted(set(vcd.times)), "time stamps must increase")
    for scope in ("cmd.FB_PAC_Cmd.Execute", "ctrl.status.OnlineActive", "axis1.status.ACTIVE", "axis2.sim.Position"):
        check(scope in vcd.vars, f"no variable {scope} in the VCD")
    lines, outcomes = check_timeline(vcd, run.stdout, cycle_ns)
    check(lines > 50, f"only {lines} timeline lines checked")
    check(outcomes > 5, f"only {outcomes} step results checked")
    for failure in failures[:20]:
        print("FAILED: " + failure)
    print(f"{vcd_path}: {len(vcd.vars)} variables, {len(vcd.times)} time stamps; {lines} timeline lines and "
          f"{outcomes} step results agree" if not failures else f"{len(failures)} disagreements")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
