"""pac-test WIRING.json: translates a machine program in ST with the PA-CONTROL library, builds a host around
it and runs each of its ST tests against the simulated PA-CONTROL (docs/user_tests.md). Prints each failure
as FILE:LINE: test NAME, scan N, t=T ms: message; writes JUnit XML, a VCD of each failing test and the
coverage of the program's ST."""
import argparse
import concurrent.futures
import hashlib
import json
import os
import shutil
import subprocess
import sys
import time

from . import build, coverage, hostgen, junit, matiec, project
from .wiring import Wiring, WiringError, wiring_path

EXIT_PASSED, EXIT_FAILED, EXIT_REFUSED, EXIT_INTERNAL = 0, 1, 2, 3


def shard_of(name, count):
    """The shard (0-based) of a test: a hash of its name, so a test stays in its shard when others come."""
    return int(hashlib.sha256(name.upper().encode()).hexdigest()[:8], 16) % count


def _shard(text):
    try:
        index, count = (int(p) for p in text.split("/"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected i/n, e.g. 2/4, got {text}")
    if not 1 <= index <= count:
        raise argparse.ArgumentTypeError(f"shard {index} of {count}: i must be in 1..n")
    return index, count


class Result:
    def __init__(self, name, expected_to_fail):
        self.name, self.expected_to_fail = name, expected_to_fail
        self.outcome, self.lines, self.vcd, self.asserts, self.seconds = "error", [], None, 0, 0.0
        self.host_exit, self.host_error = None, ""
        self.end_ms = None  # the simulated time the test ended at


def _where(path):
    rel = os.path.relpath(path)
    return rel if not rel.startswith("..") else path


def _caller_location(failure):
    """For an assert inside the vocabulary's own FBs (FB_AssertWithin) or TcUnit's ST asserts (AssertArrayEquals_):
    the ST line of the user's test that called it, from the return address the host recorded (addr2line reads the
    #line directives' DWARF lines), or None."""
    own = os.path.abspath(failure["file"]) if "caller_module" in failure else ""
    if not own.startswith((project.VOCABULARY + os.sep, project.TCUNIT + os.sep)):
        return None
    try:
        text = subprocess.run(["addr2line", "-e", failure["caller_module"], hex(failure["caller_offset"] - 1)],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None
    where = text.split(" (")[0]
    path, _, line = where.rpartition(":")
    return (path, int(line)) if line.isdigit() and path and path != "??" else None


class _InXml:
    """Points what names an ST file pac-test extracted from a PLCopen XML source (OUT/plcopen/Name.st) at the
    XML file and the line of its object there, as CODESYS shows it (pacst's refusals are given so too)."""

    def __init__(self, sources, out):
        self.extracted = os.path.join(os.path.abspath(out), "plcopen")
        xml = [s for s in sources if s.lower().endswith(".xml")]
        self.origins = {}
        if xml:
            sys.path.insert(0, os.environ.get("PACTEST_TRANSLATOR", os.path.join(project.ROOT, "translator")))
            from pacst import plcopen_read  # noqa: E402 (the checkout's translator, as pac-test runs it)
            self.position = plcopen_read.xml_position
            self.origins = plcopen_read.origins(xml)

    def __call__(self, path, line):
        """(file, line) to print for `line` of `path`."""
        if not path or os.path.dirname(os.path.abspath(path)) != self.extracted:
            return path, line
        origin = self.origins.get(os.path.basename(path))
        if origin is None:
            return path, line
        xml, obj = origin
        return xml, self.position(xml, obj, int(line))[0]


def _run_one(host, wiring, fb, out, vcd_dir, time_limit_ms, vcd_all=False, in_xml=None):
    name = fb["name"]
    result = Result(name, name.upper() in wiring.expected_to_fail)
    scenario = os.path.join(out, "scenarios", name + ".json")
    with open(scenario, "w", encoding="utf-8") as f:
        json.dump(wiring.scenario(name), f, indent=1)
    step_paths = wiring.step_paths(name)
    result_file = os.path.join(out, "results", name + ".json")
    vcd = os.path.join(vcd_dir, name + ".vcd")
    for stale in (result_file, vcd):
        if os.path.exists(stale):
            os.remove(stale)
    start = time.monotonic()
    run = subprocess.run([host, "--scenario", scenario, "--test", name, "--result", result_file, "--vcd", vcd,
                          "--vcd-when", "always" if vcd_all else "failed", "--time-limit-ms", str(time_limit_ms)],
                         capture_output=True, text=True)
    result.seconds = time.monotonic() - start
    result.host_exit, result.host_error = run.returncode, wiring_path(run.stderr.strip(), step_paths)
    if run.returncode not in (0, 1) or not os.path.exists(result_file):
        result.lines = [f"{name}: the host stopped with exit code {run.returncode}: {run.stderr.strip()}"]
        return result
    with open(result_file, encoding="utf-8") as f:
        data = json.load(f)
    result.asserts = data["asserts"]
    result.end_ms = data["time_ms"]
    seen = {}
    for failure in data["failures"]:
        caller = _caller_location(failure)
        if caller:
            failure["file"], failure["line"] = caller
        if in_xml is not None:
            failure["file"], failure["line"] = in_xml(failure["file"], failure["line"])
        key = (failure["file"], failure["line"])
        if key in seen:
            seen[key][1] += 1
            continue
        seen[key] = [failure, 1]
    for failure, count in seen.values():
        again = f" (and {count - 1} more times)" if count > 1 else ""
        result.lines.append(f"{_where(failure['file'])}:{failure['line']}: test {name}, scan {failure['scan']}, "
                            f"t={failure['time_ms']:g} ms: {failure['message']}{again}")
    if data["timed_out"]:
        file, line = fb.get("file"), fb.get("line") or 0
        if in_xml is not None:
            file, line = in_xml(file, line)
        where = f"{_where(file or '?')}:{line}"
        result.lines.append(f"{where}: test {name}, scan {data['scans']}, "
                            f"t={data['time_ms']:g} ms: the time limit of {time_limit_ms} ms ran out before "
                            "TEST_FINISHED()")
    failed = bool(result.lines)
    if (failed or vcd_all) and os.path.exists(vcd):
        result.vcd = _where(vcd)
    if result.expected_to_fail:
        result.outcome = "failed as expected" if failed else "passed unexpectedly"
        if not failed:
            result.lines = [f"{name}: expected to fail (tests.expected_to_fail), but passed"]
    else:
        result.outcome = "failed" if failed else "passed"
    return result


def _library_option(item):
    """(namespace, path, where given) of a --library NAME=PATH (the path relative to the working folder)."""
    name, sep, path = item.partition("=")
    if not sep or not name.strip() or not path:
        raise project.LibraryError(f"--library {item}: write NAMESPACE=PATH (a .plcproj, a PLCopen XML file or a "
                                   "folder)")
    return name.strip(), os.path.abspath(path), f"--library {name.strip()}"


def main(argv=None):
    parser = argparse.ArgumentParser(prog="pac-test", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("wiring", help="the wiring file (JSON, docs/user_tests.md#the-wiring-file)")
    parser.add_argument("--pac-build", default=os.environ.get("PAC_BUILD", os.path.join(project.ROOT, "build")),
                        help="a build of the PA-CONTROL project (default: $PAC_BUILD, else build/ of this checkout)")
    parser.add_argument("--out", default="pac-test-out", help="folder for the build, results, VCDs, coverage")
    parser.add_argument("--junit", help="JUnit XML file (default: OUT/junit.xml)")
    parser.add_argument("--shard", type=_shard, default=(1, 1), metavar="I/N",
                        help="run only shard I of N (1-based), chosen by a hash of each test's name")
    parser.add_argument("--filter", default="", help="run only the tests whose name contains this text")
    parser.add_argument("--no-coverage", action="store_true", help="no instrumentation, no coverage table")
    parser.add_argument("--list", action="store_true", help="print the tests of this shard and stop")
    parser.add_argument("--vcd-all", action="store_true",
                        help="write the VCD of every test, passing ones too (OUT/vcd/NAME.vcd)")
    parser.add_argument("--library", action="append", default=[], metavar="NAME=PATH",
                        help="a library of your own that the program references under the namespace NAME (a .plcproj "
                             "or its folder, a PLCopen XML project, a folder of ST files); besides the wiring file's "
                             "\"libraries\"")
    parser.add_argument("--parse-cache", help="pacst's parse cache, shared by runs (default: OUT/pacst-cache); the build's is "
                        "read beneath it")
    parser.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1, help="compilers and tests at once")
    parser.add_argument("--strict-narrowing", action="store_true",
                        help="refuse an implicit narrowing (a DINT assigned to an INT) instead of taking it, as "
                             "TwinCAT and CODESYS do, with a warning")
    args = parser.parse_args(argv)
    started = time.monotonic()
    out = os.path.abspath(args.out)
    for sub in ("scenarios", "results", "vcd"):  # nothing of an earlier run's tests stays
        shutil.rmtree(os.path.join(out, sub), ignore_errors=True)
        os.makedirs(os.path.join(out, sub))
    try:
        wiring = Wiring(args.wiring)
        for warning in wiring.warnings():
            print(f"pac-test: warning: {args.wiring}: {warning}", file=sys.stderr)
        wiring.libraries += [_library_option(item) for item in args.library]
        project.check_libraries(wiring.libraries)
        pac = project.PacBuild(args.pac_build)
        if pac.matiec:  # MATIEC's C has no coverage table of the user's ST (docs/user_tests.md, "On MATIEC")
            args.no_coverage = True
            host_build = matiec.MatiecHostBuild(wiring, pac, out, jobs=args.jobs, parse_cache=args.parse_cache,
                                                strict_narrowing=args.strict_narrowing)
        else:
            host_build = build.HostBuild(wiring, pac, out, coverage=not args.no_coverage, jobs=args.jobs,
                                         parse_cache=args.parse_cache, strict_narrowing=args.strict_narrowing)
        symbols = host_build.translate()
        hostgen.programs_of(symbols, wiring)
        hostgen.check_module_images(symbols, wiring)
        tests = host_build.tests(symbols)
        if not tests:
            raise WiringError("$.tests", f"no test: no FUNCTION_BLOCK of the sources starts with {wiring.prefix}")
        for name in wiring.expected_to_fail | set(wiring.faults):
            if name not in {t["name"].upper() for t in tests}:
                raise WiringError("$.tests", f"{name} is named in the wiring file but is not a test")
        index, count = args.shard
        tests = sorted(tests, key=lambda t: t["name"].upper())
        selected = [t for t in tests if shard_of(t["name"], count) == index - 1 and args.filter in t["name"]]
        if args.list:
            hostgen.generate(symbols, wiring, tests)  # the bus images' variables and addresses, as a run checks them
            print("\n".join(t["name"] for t in selected))
            return EXIT_PASSED
        host = host_build.build(symbols, tests)
    except WiringError as e:
        print(f"pac-test: invalid wiring file {args.wiring}: {e}", file=sys.stderr)
        return EXIT_REFUSED
    except hostgen.ProgramError as e:  # one line each, at its file and line
        print("\n".join(f"pac-test: {line}" for line in str(e).splitlines()), file=sys.stderr)
        return EXIT_REFUSED
    except (build.BuildError, project.LibraryError) as e:
        print(f"pac-test: {e}", file=sys.stderr)
        return EXIT_REFUSED
    built = time.monotonic()
    if not args.no_coverage:
        coverage.reset(host_build.obj)
    vcd_dir = os.path.join(out, "vcd")
    in_xml = _InXml(wiring.sources, out)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda fb: _run_one(host, wiring, fb, out, vcd_dir, wiring.time_limit_ms,
                                                    args.vcd_all, in_xml), selected))
    ran = time.monotonic()
    refused = [r for r in results if r.host_exit == 2]
    if refused:  # the scenario loader refused the wiring file's timing, controller or faults
        print(f"pac-test: invalid wiring file {args.wiring}: {refused[0].host_error}", file=sys.stderr)
        return EXIT_REFUSED
    for r in results:
        late = [at for at, _ in wiring.faults.get(r.name.upper(), []) if r.end_ms is not None and at > r.end_ms]
        if late:  # a fault the test never saw: the test ended before it (its time in the wiring file is off)
            print(f"pac-test: warning: {args.wiring}: $.tests.faults.{r.name}: the fault at {min(late)} ms comes after "
                  f"the test ended at {r.end_ms:g} ms; it never happened", file=sys.stderr)
    for r in results:
        mark = {"passed": "ok", "failed": "FAILED", "error": "ERROR", "failed as expected": "failed (expected)",
                "passed unexpectedly": "FAILED (expected to fail)"}[r.outcome]
        print(f"{mark:>18}  {r.name}  ({r.asserts} asserts, {r.seconds * 1000:.0f} ms)")
        for line in r.lines:
            print(f"    {line}")
        if r.vcd:
            print(f"    VCD: {r.vcd}")
    junit_path = args.junit or os.path.join(out, "junit.xml")
    junit.write(junit_path, wiring.name, results, ran - built)
    if not args.no_coverage:
        coverage.report(host_build.obj, wiring.sources, _where(os.path.join(out, "coverage")),
                        extracted=os.path.join(out, "plcopen"),
                        libraries=project.library_folders(wiring.libraries, out))
    bad = [r for r in results if r.outcome in ("failed", "error", "passed unexpectedly")]
    expected = sum(1 for r in results if r.outcome == "failed as expected")
    shard = f", shard {index}/{count}" if count > 1 else ""
    print(f"pac-test: {len(results)} tests{shard}: {len(results) - len(bad) - expected} passed, {len(bad)} failed"
          f"{f', {expected} failed as expected' if expected else ''}; build {built - started:.1f} s, "
          f"tests {ran - built:.1f} s; JUnit XML: {_where(junit_path)}")
    return EXIT_FAILED if bad else EXIT_PASSED


if __name__ == "__main__":
    sys.exit(main())
