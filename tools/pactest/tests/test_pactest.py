"""pac-test's own tests (CTest PacTest.*): the example's run and what a user sees of its deliberate failure;
pac-test's own fixture project with a failure of every kind; shards; refusals of the wiring file.

Run with the venv of tools/pactest/requirements.txt (lxml, gcovr); PAC_BUILD names the project's build and
PACTEST_OUT a folder for the runs."""
import json
import os
import re
import shutil
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.dirname(HERE)
ROOT = os.path.dirname(os.path.dirname(TOOL))
sys.path.insert(0, TOOL)

from pactest import project  # noqa: E402
from pactest.cli import shard_of  # noqa: E402

PAC_BUILD = os.environ.get("PAC_BUILD", os.path.join(ROOT, "build"))


def _matiec_build(folder):
    """A MATIEC build (the matiec preset): pac-test compiles with iec2c and writes no coverage table."""
    try:
        with open(os.path.join(folder, "CMakeCache.txt"), encoding="utf-8") as f:
            return re.search(r"^PAC_ST_COMPILER:\w+=matiec$", f.read(), re.M) is not None
    except OSError:
        return False


MATIEC = _matiec_build(PAC_BUILD)
OUT = os.environ.get("PACTEST_OUT", os.path.join(PAC_BUILD, "pactest-tests"))
# One parse cache for every run: each parses the library, and a cold parse costs most of a run. The build
# tree's own (PACST_CACHE, set by CTest) already holds the library's trees and the parser from the build.
PARSE_CACHE = os.environ.get("PACST_CACHE") or os.path.join(OUT, "pacst-cache")
EXAMPLE_TESTS = ["FB_TestControllerRestart", "FB_TestLimitSwitchRecovery", "FB_TestNormalCycle",
                 "FB_TestShowsAFailure", "FB_TestStopInput"]
FIXTURE_TESTS = ["FB_TestBusByName", "FB_TestFails", "FB_TestNeverEnds", "FB_TestPasses", "FB_TestWaitFails"]
FAILURE = re.compile(r"^    (?P<file>\S+):(?P<line>\d+): test (?P<test>\w+), scan (?P<scan>\d+), "
                     r"t=(?P<t>[\d.]+) ms: (?P<msg>.*)$")


def pac_test(wiring, out, *args):
    env = dict(os.environ, PYTHONPATH=TOOL)
    return subprocess.run([sys.executable, "-m", "pactest", wiring, "--pac-build", PAC_BUILD, "--out", out,
                           "--parse-cache", PARSE_CACHE, *args],
                          capture_output=True, text=True, env=env, cwd=os.path.dirname(wiring))


def write_wiring(name, data):
    """`data` as the wiring file OUT/name/wiring.json; its path."""
    path = os.path.join(OUT, name, "wiring.json")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        json.dump(data, f)
    return path


def line_of(path, text):
    """The 1-based line of `path` holding `text` (once)."""
    with open(path, encoding="utf-8") as f:
        return line_in(f.read(), text, path)


def line_in(content, text, where="the text"):
    """The 1-based line of `content` holding `text` (once)."""
    lines = [n for n, line in enumerate(content.splitlines(), 1) if text in line]
    assert len(lines) == 1, f"{text!r} is on {len(lines)} lines of {where}"
    return lines[0]


def failures(stdout):
    return [m.groupdict() for m in map(FAILURE.match, stdout.splitlines()) if m]


def check_junit(case, path, tests, failed, skipped):
    from lxml import etree
    schema = etree.XMLSchema(etree.parse(os.path.join(HERE, "junit.xsd")))
    document = etree.parse(path)
    case.assertTrue(schema.validate(document), str(schema.error_log))
    suite = document.getroot()[0]
    case.assertEqual((int(suite.get("tests")), int(suite.get("failures")), int(suite.get("skipped"))),
                     (tests, failed, skipped))


def check_vcd(case, path):
    """A VCD as IEEE 1364 writes it: definitions, then value changes at times that only grow."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    case.assertIn("$enddefinitions $end", text)
    times = [int(t) for t in re.findall(r"^#(\d+)$", text, re.M)]
    case.assertGreater(len(times), 10)
    case.assertEqual(times, sorted(set(times)))
    return text


def check_coverage(case, out, pous):
    """The coverage summary of a run in `out` names `pous`, and more than 80 % of the ST's lines ran."""
    with open(os.path.join(out, "coverage", "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    found = {p["pou"] for p in summary["pous"]}
    case.assertTrue(pous <= found, found)
    case.assertGreater(summary["lines_executed"], 0.8 * summary["lines"])


def run_example(name):
    """pac-test on examples/NAME: (its folder, the output folder, the run)."""
    folder, out = os.path.join(ROOT, "examples", name), os.path.join(OUT, name)
    return folder, out, pac_test(os.path.join(folder, "wiring.json"), out)


class ExampleTest(unittest.TestCase):
    """examples/pick_and_place: four tests pass, the deliberate failure fails as expected and shows its
    file:line, a VCD and a JUnit XML that validates; the coverage table of its ST is printed."""

    @classmethod
    def setUpClass(cls):
        cls.folder, cls.out, cls.result = run_example("pick_and_place")

    def test_passes_with_the_deliberate_failure_outside_the_count(self):
        self.assertEqual(self.result.returncode, 0, self.result.stdout + self.result.stderr)
        self.assertIn("5 tests: 4 passed, 0 failed, 1 failed as expected", self.result.stdout)

    def test_the_deliberate_failure_names_the_assert_line_scan_and_time(self):
        found = [f for f in failures(self.result.stdout) if f["test"] == "FB_TestShowsAFailure"]
        self.assertEqual(len(found), 1, self.result.stdout)
        source = [p for p in _files(self.folder) if os.path.basename(p).startswith("FB_TestShowsAFailure.")][0]
        self.assertEqual(os.path.realpath(os.path.join(self.folder, found[0]["file"])), os.path.realpath(source))
        self.assertEqual(int(found[0]["line"]), line_of(source, "AssertEquals_UDINT"))
        self.assertEqual(found[0]["msg"], "parts placed: expected 2, got 1")
        # the scan's time is the PLC cycle (2 ms) times the scan
        self.assertAlmostEqual(float(found[0]["t"]), 2.0 * int(found[0]["scan"]))

    def test_the_deliberate_failure_writes_a_vcd(self):
        text = check_vcd(self, os.path.join(self.out, "vcd", "FB_TestShowsAFailure.vcd"))
        for signal in ("Cycles", "State", "ToPac", "FromPac", "Position"):
            self.assertRegex(text, rf"\$var \w+ \d+ \S+ {signal}")
        self.assertEqual(sorted(os.listdir(os.path.join(self.out, "vcd"))), ["FB_TestShowsAFailure.vcd"])

    def test_junit_xml_validates(self):
        check_junit(self, os.path.join(self.out, "junit.xml"), tests=5, failed=0, skipped=1)

    @unittest.skipIf(MATIEC, "MATIEC's C: no coverage table of the user's ST")
    def test_coverage_table_of_the_machine_program(self):
        self.assertRegex(self.result.stdout, r"FB_PickAndPlace\s+\d+/\d+\s+\d+\.\d%")
        check_coverage(self, self.out, {"MAIN", "FB_PickAndPlace", "FB_ModeControl", "FB_InputPoll"})

    @unittest.skipIf(MATIEC, "the MATIEC preset's build keeps no checked library (no pactest_prepare)")
    def test_the_translation_takes_the_library_the_build_checked(self):
        # the run's pacst neither parses nor checks st/ again: it takes the state the build kept (prepare.py)
        from pactest import build
        from pactest.wiring import Wiring
        host = build.HostBuild(Wiring(os.path.join(self.folder, "wiring.json")), project.PacBuild(PAC_BUILD),
                               os.path.join(self.out, "checked-library"), parse_cache=PARSE_CACHE)
        said = host._pacst("build", *host.user_inputs(), "--out", host.st_out, "--gvl", project.gvl_pac(),
                           "--checked-library", host.checked_library, "-v")
        self.assertIn(f"{len(project.library_sources())} file(s) taken, not parsed or checked", said)


class SortingStationTest(unittest.TestCase):
    """examples/sorting_station, the object-oriented example (METHODs, PROPERTYs, two INTERFACEs in .TcIO files,
    FOR loops, a REFERENCE and a POINTER, the library under its namespace): its four tests pass, each assert
    counted, the restart test through the controller's power cycle; the coverage table names its FBs."""

    @classmethod
    def setUpClass(cls):
        cls.folder, cls.out, cls.result = run_example("sorting_station")

    def test_every_test_passes(self):
        self.assertEqual(self.result.returncode, 0, self.result.stdout + self.result.stderr)
        self.assertIn("4 tests: 4 passed, 0 failed", self.result.stdout)
        self.assertEqual(failures(self.result.stdout), [])
        check_junit(self, os.path.join(self.out, "junit.xml"), tests=4, failed=0, skipped=0)

    def test_the_asserts_ran(self):
        # the unit test's 14 asserts in one scan; the recipe's pusher check every scan the carriage travels
        counts = dict(re.findall(r"ok  (\w+)  \((\d+) asserts", self.result.stdout))
        self.assertEqual(counts.get("FB_TestLaneTable"), "14", self.result.stdout)
        self.assertGreater(int(counts.get("FB_TestSortsARecipe", 0)), 7 + 50, self.result.stdout)
        self.assertEqual(counts.get("FB_TestControllerRestart"), "5", self.result.stdout)

    @unittest.skipIf(MATIEC, "MATIEC's C: no coverage table of the user's ST")
    def test_coverage_of_methods_and_properties(self):
        check_coverage(self, self.out, {"MAIN", "FB_Sorter", "FB_LaneTable", "FB_RecipeFeeder"})


class TcUnitTest(unittest.TestCase):
    """tools/pactest/tests/tcunit: TcUnit suites as TcUnit's users write them (EXTENDS TcUnit.FB_TestSuite, a test
    per METHOD between TEST('...') and TEST_FINISHED(), the generic AssertEquals, FB instances in a METHOD's VAR,
    VAR_INST kept over cycles, TEST_ORDERED, PRG_TEST calling TcUnit.RUN()) run unchanged: each suite is one test, its failures
    name the TcUnit test."""

    @classmethod
    def setUpClass(cls):
        cls.folder = os.path.join(HERE, "tcunit")
        cls.out = os.path.join(OUT, "tcunit")
        cls.result = pac_test(os.path.join(cls.folder, "wiring.json"), cls.out, "--no-coverage")

    def test_each_suite_is_a_test(self):
        self.assertEqual(self.result.returncode, 0, self.result.stdout + self.result.stderr)
        self.assertIn("5 tests: 3 passed, 0 failed, 2 failed as expected", self.result.stdout)
        check_junit(self, os.path.join(self.out, "junit.xml"), tests=5, failed=0, skipped=2)

    def test_a_finished_test_counts_no_more_asserts_and_the_suite_ends_with_its_last_test(self):
        # 2 + 2 in the one-scan tests; 10 scans of the third, whose assert after TEST_FINISHED_NAMED is not counted
        self.assertRegex(self.result.stdout, r"ok  FB_CounterSuite  \(14 asserts")

    def test_an_ordered_test_runs_after_the_one_ordered_before_it(self):
        # the first test's assert in each of its three cycles, then the second's once, in the first's last cycle
        self.assertRegex(self.result.stdout, r"ok  FB_OrderedSuite  \(4 asserts")

    def test_a_failure_names_the_tcunit_test_and_its_line(self):
        found = [f for f in failures(self.result.stdout) if f["test"] == "FB_ShowsAFailureSuite"]
        source = os.path.join(self.folder, "FB_ShowsAFailureSuite.TcPOU")
        self.assertEqual([(f["test"], int(f["line"]), f["msg"]) for f in found],
                         [("FB_ShowsAFailureSuite", line_of(source, "one edge is not two"),
                           "FailsOnPurpose: one edge is not two: expected 2, got 1")])

    def test_the_asserts_of_the_64_bit_types_the_dates_wstring_and_arrays(self):
        # TcUnit's AssertEquals_LINT/ULINT/LWORD/LTIME/DATE/DATE_AND_TIME/TIME_OF_DAY/WSTRING, AssertArrayEquals_,
        # AssertArray2dEquals_, AssertArray3dEquals_, TCUNIT_ADSLOGSTR and IS_TEST_FINISHED
        self.assertRegex(self.result.stdout, r"ok  FB_TypesSuite  \(18 asserts")
        source = os.path.join(self.folder, "FB_TypesFailureSuite.TcPOU")
        found = [(int(f["line"]), f["msg"]) for f in failures(self.result.stdout)
                 if f["test"] == "FB_TypesFailureSuite"]
        expected = [("'LINT'", "expected -9000000000, got 9000000000"),
                    ("'LWORD'", "expected 16#00000000000000FF, got 16#0000000000000100"),
                    ("'DATE'", "expected D#2026-01-01, got D#2026-01-02"),
                    ("'DT'", "expected DT#2026-01-01-12:30:00, got DT#2026-01-01-12:30:01"),
                    ("'TOD'", "expected TOD#12:30:00.500, got TOD#12:30:00.000"),
                    ("'LTIME'", "expected LTIME#1000002000NS, got LTIME#1000000000NS"),
                    ("'WSTRING'", 'expected "axis Ω", got "axis Σ"')]
        # the array asserts (ST, recording through PacTestRecord) print the line of the user's call too
        arrays = [("'SIZE'", "SIZE, size of arrays not matching: expected SIZE = 3, got SIZE = 2"),
                  ("'INT'", "INT: expected ARRAY[2] = 2, got ARRAY[1] = 5"),
                  ("'BOOL'", "BOOL: expected ARRAY[2] = FALSE, got ARRAY[2] = TRUE"),
                  ("'LREAL'", "LREAL: expected ARRAY[2] = -1.25, got ARRAY[2] = -1.5"),
                  ("'SIZE2D'", "SIZE2D, size of arrays not matching: expected SIZE = 2 x 3, got SIZE = 3 x 2"),
                  ("'REAL3D'", "REAL3D: expected ARRAY[2, 1, 1] = 3, got ARRAY[2, 1, 1] = 3.5")]
        self.assertEqual(found, [(line_of(source, f"Message := {m})"), f"FailsOnPurpose: {m[1:-1]}: {text}")
                                 for m, text in expected] +
                         [(line_of(source, f"Message := {m})"), f"FailsOnPurpose: {text}") for m, text in arrays])


class CorpusTest(unittest.TestCase):
    """pac-test-corpus on a folder of TwinCAT files: each POU accepted, refused for a construct or by the parser,
    or depending on a refused declaration, and the reasons counted."""

    def test_counts_and_reasons(self):
        folder = os.path.join(OUT, "corpus", "Project")
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "Project.plcproj"), "w", encoding="utf-8") as f:
            f.write("<Project />\n")
        wrap = ('<?xml version="1.0" encoding="utf-8"?>\n<TcPlcObject Version="1.1.0.1">\n  <POU Name="{0}">\n'
                '    <Declaration><![CDATA[{1}]]></Declaration>\n'
                '    <Implementation>\n      <ST><![CDATA[{2}]]></ST>\n    </Implementation>\n  </POU>\n'
                '</TcPlcObject>\n')
        pous = {"FB_Good": ("FUNCTION_BLOCK FB_Good\nVAR\n  n : INT;\nEND_VAR\n", "n := n + 1;"),
                "FB_Loop": ("FUNCTION_BLOCK FB_Loop\nVAR\n  i : INT;\nEND_VAR\n", "FOR i := 1 TO 5 BY 0 DO\n  i := i;\nEND_FOR"),
                "FB_User": ("FUNCTION_BLOCK FB_User\nVAR\n  Loop : FB_Loop;\nEND_VAR\n", "Loop();"),
                "FB_Broken": ("FUNCTION_BLOCK FB_Broken\nVAR\n  n : INT;\nEND_VAR\n", "n := := 1;")}
        for name, (declaration, body) in pous.items():
            with open(os.path.join(folder, name + ".TcPOU"), "w", encoding="utf-8") as f:
                f.write(wrap.format(name, declaration, body))
        report = os.path.join(OUT, "corpus", "report.json")
        env = dict(os.environ, PYTHONPATH=TOOL)
        run = subprocess.run([sys.executable, "-m", "pactest.corpus", os.path.dirname(folder), "--json", report,
                              "--cache", PARSE_CACHE], capture_output=True, text=True, env=env)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn("total: 4 POUs, 1 accepted (25.0 %), 1 refused by the parser, 1 for a construct, "
                      "0 needing a vendor library, 1 depending on a refused declaration", run.stdout)
        with open(report, encoding="utf-8") as f:
            files = {os.path.basename(k): v for k, v in json.load(f)["projects"][0]["files"].items()}
        self.assertIsNone(files["FB_Good.TcPOU"])
        self.assertEqual(files["FB_Loop.TcPOU"][0], "refused construct")
        self.assertIn("never ends", files["FB_Loop.TcPOU"][1])
        self.assertEqual(files["FB_User.TcPOU"][0], "depends on a refused declaration")
        self.assertEqual(files["FB_Broken.TcPOU"][0], "syntax")

    def test_a_plcopen_export_is_a_project(self):
        """A PLCopen XML export (CODESYS's) is a project of its own: the POUs of types/pous and the application's
        under instances/.../resource are read by pac-test's PLCopen reader and translated, a POU in LD counts as a
        body not in ST, and a refusal is given at the XML file's line."""
        top = os.path.join(OUT, "corpus-plcopen")
        os.makedirs(top, exist_ok=True)

        def pou(name, kind, variables, body):
            declared = "".join(f'<variable name="{n}"><type><{t} /></type></variable>' for n, t in variables)
            return (f'<pou name="{name}" pouType="{kind}"><interface><localVars>{declared}</localVars></interface>\n'
                    f'<body>{body}</body></pou>\n')

        def st(text):
            return f'<ST><xhtml xmlns="http://www.w3.org/1999/xhtml">{text}</xhtml></ST>'
        loop = "i := 0;\nFOR i := 1 TO 5 BY 0 DO\n  i := i;\nEND_FOR;"
        xml = ('<?xml version="1.0" encoding="utf-8"?>\n<project xmlns="http://www.plcopen.org/xml/tc6_0200">\n'
               '<types><dataTypes /><pous>\n'
               + pou("FB_Good", "functionBlock", [("n", "INT")], st("n := n + 1;"))
               + pou("FB_Loop", "functionBlock", [("i", "INT")], st(loop))
               + pou("FB_Rung", "functionBlock", [("x", "BOOL")], '<LD><leftPowerRail localId="1" /></LD>')
               + '</pous></types>\n<instances><configurations><configuration name="Device"><resource name="App">'
               '<addData><data name="http://www.3s-software.com/plcopenxml/pou" handleUnknown="implementation">\n'
               + pou("PLC_PRG", "program", [("b", "INT")], st("b := b + 2;"))
               + '</data></addData></resource></configuration></configurations></instances>\n</project>\n')
        path = os.path.join(top, "Export.xml")
        with open(path, "w", encoding="utf-8") as f:
            f.write(xml)
        report = os.path.join(top, "report.json")
        run = subprocess.run([sys.executable, "-m", "pactest.corpus", top, "--json", report, "--cache", PARSE_CACHE],
                             capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=TOOL))
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn(f"{path}: 4 POUs, 2 accepted", run.stdout)
        self.assertIn("1 with a body not in ST (LD, FBD, SFC...)", run.stdout)
        with open(report, encoding="utf-8") as f:
            files = json.load(f)["projects"][0]["files"]
        self.assertIsNone(files[path + "#FB_Good"])
        self.assertIsNone(files[path + "#PLC_PRG"], "the application's PROGRAM under instances/.../resource")
        self.assertEqual(files[path + "#FB_Rung"][0], "body not in ST")
        self.assertIn("'FB_Rung' is implemented in LD", files[path + "#FB_Rung"][1])
        self.assertEqual(files[path + "#FB_Loop"][0], "refused construct")
        line = next(n for n, text in enumerate(xml.splitlines(), 1) if text.startswith("FOR i"))
        self.assertEqual(files[path + "#FB_Loop"][1].split(": ", 1)[0], str(line), "the XML file's line")

    def test_a_project_gets_the_libraries_it_references(self):
        """App's .plcproj references the library project Lib (by title and company) under the namespace Common:
        App is translated with Lib's files (but the F_GetVersion TwinCAT generates), as pac-test --library gives
        them; without Lib measured, App's use of the namespace counts as needing a library not measured. The version
        of Lib App was compiled with (its _Libraries folder) is reported when it is not Lib's. A POU first refused for
        a construct (FOR ... BY 0) is refused for a construct, whatever else of it names a vendor library. The vendor
        parts given only to sources that name them (Tc2_Utilities' WSTRNCPY) are given for a library's sources too, as
        pac-test gives them."""
        top = os.path.join(OUT, "corpus-libraries")
        import shutil
        shutil.rmtree(top, ignore_errors=True)
        wrap = ('<?xml version="1.0" encoding="utf-8"?>\n<TcPlcObject Version="1.1.0.1">\n  <POU Name="{0}">\n'
                '    <Declaration><![CDATA[{1}]]></Declaration>\n'
                '    <Implementation>\n      <ST><![CDATA[{2}]]></ST>\n    </Implementation>\n  </POU>\n'
                '</TcPlcObject>\n')
        projects = {
            "Lib": ('<Project xmlns="http://schemas.microsoft.com/developer/msbuild/2003"><PropertyGroup>'
                    '<Name>Lib</Name><Company>Example</Company><Title>Example Library</Title>'
                    '<DefaultNamespace>ExLib</DefaultNamespace><ProjectVersion>1.0.0</ProjectVersion></PropertyGroup>'
                    '<ItemGroup>'
                    '<Compile Include="FB_Tool.TcPOU" /><Compile Include="F_GetVersion.TcPOU"><SystemCall>true'
                    '</SystemCall></Compile></ItemGroup></Project>\n',
                    {"FB_Tool": ("FUNCTION_BLOCK FB_Tool\nVAR_OUTPUT\n  n : INT;\nEND_VAR\nVAR\n  a, b : WSTRING;\nEND_VAR\n",
                                 "n := n + 1;\nWSTRNCPY(ADR(a), ADR(b), SIZEOF(a));"),
                     "F_GetVersion": ("FUNCTION F_GetVersion : INT\n", "F_GetVersion := 1;")}),
            "App": ('<Project xmlns="http://schemas.microsoft.com/developer/msbuild/2003"><PropertyGroup>'
                    '<Name>App</Name></PropertyGroup><ItemGroup>'
                    '<PlaceholderReference Include="Example Library"><DefaultResolution>Example Library, * (Example)'
                    '</DefaultResolution><Namespace>Common</Namespace></PlaceholderReference>'
                    '<PlaceholderReference Include="TcUnit"><DefaultResolution>TcUnit, * (www.tcunit.org)'
                    '</DefaultResolution><Namespace>TcUnit</Namespace></PlaceholderReference>'
                    '</ItemGroup></Project>\n',
                    {"FB_UsesTool": ("FUNCTION_BLOCK FB_UsesTool\nVAR\n  Tool : Common.FB_Tool;\n  m : INT;\nEND_VAR\n",
                                     "Tool();\nm := Tool.n;"),
                     "F_GetVersion": ("FUNCTION F_GetVersion : INT\n", "F_GetVersion := 2;"),
                     "FB_ForByZero": ("FUNCTION_BLOCK FB_ForByZero\nVAR\n  a : INT;\n  b : INT;\nEND_VAR\n",
                                      "FOR a := 1 TO 3 BY 0 DO\n  b := a;\nEND_FOR;\na := Tc2_System.F_Nothing();")})}
        for name, (plcproj, pous) in projects.items():
            folder = os.path.join(top, name)
            os.makedirs(folder)
            with open(os.path.join(folder, name + ".plcproj"), "w", encoding="utf-8") as f:
                f.write(plcproj)
            for pou, (declaration, body) in pous.items():
                with open(os.path.join(folder, pou + ".TcPOU"), "w", encoding="utf-8") as f:
                    f.write(wrap.format(pou, declaration, body))
        # TwinCAT keeps the library App was compiled with: a later version than the library project measured
        os.makedirs(os.path.join(top, "App", "_Libraries", "example", "example library", "1.2.0"))
        env = dict(os.environ, PYTHONPATH=TOOL)

        def measure(*folders):
            report = os.path.join(top, "report.json")
            run = subprocess.run([sys.executable, "-m", "pactest.corpus", *folders, "--json", report,
                                  "--cache", os.path.join(OUT, "pacst-cache")], capture_output=True, text=True, env=env)
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            with open(report, encoding="utf-8") as f:
                found = {os.path.basename(p["folder"]): p for p in json.load(f)["projects"]}
            return run.stdout, found

        stdout, found = measure(os.path.join(top, "Lib"), os.path.join(top, "App"))
        app = {os.path.basename(k): v for k, v in found["App"]["files"].items()}
        self.assertEqual(found["App"]["libraries"], {"Common": os.path.join(top, "Lib")}, stdout)
        self.assertIsNone(app["FB_UsesTool.TcPOU"], stdout)
        # the library's generated Project Information POUs are not read with it: no clash with the program's own
        self.assertIsNone(app["F_GetVersion.TcPOU"], stdout)
        self.assertEqual(app["FB_ForByZero.TcPOU"][0], "refused construct")
        self.assertIn("BY 0", app["FB_ForByZero.TcPOU"][1])
        self.assertIn("built against Common 1.2.0 (its _Libraries folder), measured with Common 1.0.0", stdout)
        self.assertEqual(found["App"]["library_versions"], {"Common": {"built against": "1.2.0", "measured": "1.0.0"}})
        self.assertEqual(found["Lib"]["library_versions"], {})
        stdout, found = measure(os.path.join(top, "App"))
        app = {os.path.basename(k): v for k, v in found["App"]["files"].items()}
        self.assertEqual(app["FB_UsesTool.TcPOU"][0], "library not given", stdout)
        self.assertIn("1 needing a library of another project not measured", stdout)


def _files(folder):
    return [os.path.join(d, n) for d, _, names in os.walk(folder) for n in names]


class FixtureTest(unittest.TestCase):
    """tools/pactest/tests/fixture: a failure of every kind, each at its line."""

    @classmethod
    def setUpClass(cls):
        cls.folder = os.path.join(HERE, "fixture")
        cls.out = os.path.join(OUT, "fixture")
        cls.result = pac_test(os.path.join(cls.folder, "wiring.json"), cls.out, "--no-coverage")
        cls.failures = failures(cls.result.stdout)

    def at(self, test, text):
        return line_of(os.path.join(self.folder, test + ".st"), text)

    def messages(self, test):
        return {int(f["line"]): f["msg"] for f in self.failures if f["test"] == test}

    def test_exit_code_and_counts(self):
        self.assertEqual(self.result.returncode, 1, self.result.stdout + self.result.stderr)
        self.assertIn("5 tests: 2 passed, 3 failed", self.result.stdout)
        check_junit(self, os.path.join(self.out, "junit.xml"), tests=5, failed=3, skipped=0)

    def test_every_assert_passes_where_it_should(self):
        self.assertNotIn("FB_TestPasses", {f["test"] for f in self.failures})
        self.assertRegex(self.result.stdout, r"ok  FB_TestPasses  \(15 asserts")

    def test_failed_asserts_print_expected_and_actual_at_their_lines(self):
        self.assertEqual(self.messages("FB_TestFails"), {
            self.at("FB_TestFails", "'DINT differs'"): "DINT differs: expected 11, got 10",
            self.at("FB_TestFails", "'STRING differs'"): "STRING differs: expected 'other', got 'counter'",
            self.at("FB_TestFails", "'REAL differs'"): "REAL differs: expected 1 +/- 0.1, got 5",
            self.at("FB_TestFails", "'WORD differs'"): "WORD differs: expected 16#00FF, got 16#0F00",
            self.at("FB_TestFails", "'FALSE expected'"): "FALSE expected: expected FALSE, got TRUE"})
        self.assertEqual({f["scan"] for f in self.failures if f["test"] == "FB_TestFails"}, {"10"})

    def test_a_wait_fails_at_the_line_that_calls_it_when_its_time_runs_out(self):
        self.assertEqual(self.messages("FB_TestWaitFails"),
                         {self.at("FB_TestWaitFails", "Wait(Execute"): "a negative count: not within the time limit"})
        t = [float(f["t"]) for f in self.failures if f["test"] == "FB_TestWaitFails"][0]
        self.assertTrue(50 <= t <= 54, t)  # T#50MS from the first call (2 ms), one scan to see it

    def test_a_test_that_never_finishes_fails_at_its_time_limit(self):
        self.assertEqual(self.messages("FB_TestNeverEnds"), {
            self.at("FB_TestNeverEnds", "FUNCTION_BLOCK FB_TestNeverEnds"):
                "the time limit of 300 ms ran out before TEST_FINISHED()"})

    def test_a_vcd_for_each_failing_test_only(self):
        self.assertEqual(sorted(os.listdir(os.path.join(self.out, "vcd"))),
                         ["FB_TestFails.vcd", "FB_TestNeverEnds.vcd", "FB_TestWaitFails.vcd"])

    def test_shards_split_the_tests_stably(self):
        names = []
        for i in range(1, 4):
            run = pac_test(os.path.join(self.folder, "wiring.json"), self.out, "--no-coverage", "--list",
                           "--shard", f"{i}/3")
            self.assertEqual(run.returncode, 0, run.stderr)
            shard = run.stdout.split()
            self.assertEqual(shard, [n for n in FIXTURE_TESTS if shard_of(n, 3) == i - 1])
            names += shard
        self.assertEqual(sorted(names), FIXTURE_TESTS)
        # a test's shard is a function of its name alone: the same in any project, for every count
        self.assertEqual([shard_of("FB_TestPasses", n) for n in (1, 2, 3, 4)],
                         [int(__import__("hashlib").sha256(b"FB_TESTPASSES").hexdigest()[:8], 16) % n
                          for n in (1, 2, 3, 4)])


COUNTER = """(* SPDX-License-Identifier: MIT *)
(* Counts its calls. *)
FUNCTION_BLOCK FB_Counter
VAR_INPUT
{extra}  Step : DINT;  (* added per call *)
END_VAR
VAR_OUTPUT
  N : DINT;  (* the sum *)
END_VAR
N := N + Step;
END_FUNCTION_BLOCK
"""
COUNTER_TEST = """(* SPDX-License-Identifier: MIT *)
(* FB_Counter called from another file. *)
FUNCTION_BLOCK FB_TestCounter
VAR
  Count : FB_Counter;
END_VAR
Count(Step := 2);
IF GVL_Plant.Scans = DINT#3 THEN
  AssertEquals_DINT(Expected := 6, Actual := Count.N, Message := 'three calls of 2');
  TEST_FINISHED();
END_IF;
END_FUNCTION_BLOCK
"""


class RebuildTest(unittest.TestCase):
    """A second run after an FB's interface changed rebuilds its callers too, whose C text pacst leaves as
    it was: their objects would read the FB's old layout; and the first build's objects leave no lines in
    the coverage; a renamed file's old C is not linked beside its new one."""

    def test_an_interface_change_rebuilds_the_callers(self):
        shutil.rmtree(os.path.join(OUT, "rebuild"), ignore_errors=True)  # the renamed file of a run before
        folder = os.path.join(OUT, "rebuild", "src")
        os.makedirs(folder, exist_ok=True)
        for name in ("GVL_Plant.st", "PRG_Count.st", "PRG_Slow.st", "wiring.json"):
            with open(os.path.join(HERE, "fixture", name), encoding="utf-8") as f, \
                    open(os.path.join(folder, name), "w", encoding="utf-8") as g:
                g.write(f.read())
        with open(os.path.join(folder, "FB_TestCounter.st"), "w", encoding="utf-8") as f:
            f.write(COUNTER_TEST)
        body_lines = []
        for extra in ("", "  Spare1 : DINT;  (* moves Step and N *)\n  Spare2 : LREAL;  (* and more *)\n"):
            text = COUNTER.format(extra=extra)
            with open(os.path.join(folder, "FB_Counter.st"), "w", encoding="utf-8") as f:
                f.write(text)
            body_lines.append(text.splitlines().index("N := N + Step;") + 1)
            out = os.path.join(OUT, "rebuild", "out")
            run = pac_test(os.path.join(folder, "wiring.json"), out)
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            self.assertIn("ok  FB_TestCounter  (1 asserts", run.stdout)
        # the coverage counts the new build's lines only, not the first build's objects' as well
        with open(os.path.join(out, "coverage", "gcovr.json"), encoding="utf-8") as f:
            files = {os.path.basename(e["file"]): e for e in json.load(f)["files"]}
        lines = {line["line_number"] for line in files["FB_Counter.st"]["lines"]}
        self.assertIn(body_lines[1], lines)
        self.assertNotIn(body_lines[0], lines)
        # a renamed ST file: the C of its old name, from the run before, is not linked beside the new one
        os.rename(os.path.join(folder, "FB_Counter.st"), os.path.join(folder, "FB_CounterRenamed.st"))
        run = pac_test(os.path.join(folder, "wiring.json"), out)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn("ok  FB_TestCounter  (1 asserts", run.stdout)


class OutInsideTheProjectTest(unittest.TestCase):
    """pac-test run in the project's folder writes pac-test-out there (the default --out): the coverage
    counts the project's ST, not the C that pac-test translated it to inside pac-test-out."""

    def test_coverage_names_only_the_projects_st(self):
        folder = os.path.join(OUT, "out_inside", "project")
        os.makedirs(folder, exist_ok=True)
        for name in os.listdir(os.path.join(HERE, "fixture")):
            with open(os.path.join(HERE, "fixture", name), encoding="utf-8") as f, \
                    open(os.path.join(folder, name), "w", encoding="utf-8") as g:
                g.write(f.read())
        out = os.path.join(folder, "pac-test-out")
        run = pac_test(os.path.join(folder, "wiring.json"), out, "--filter", "FB_TestPasses")
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        with open(os.path.join(out, "coverage", "gcovr.json"), encoding="utf-8") as f:
            files = sorted(os.path.relpath(e["file"], folder) if os.path.isabs(e["file"]) else e["file"]
                           for e in json.load(f)["files"])
        self.assertTrue(files)
        self.assertEqual([f for f in files if not f.endswith(".st") or os.sep in f], [], run.stdout)


class WiringOutsideTheSourcesTest(unittest.TestCase):
    """A wiring file in a folder of its own (ci/wiring.json naming ../src/*.st): the coverage counts the
    sources' ST, not the wiring file's folder, where it found nothing and printed 0/0 as 100 %."""

    def test_coverage_counts_the_sources_folder(self):
        base = os.path.join(OUT, "wiring_outside")
        src = os.path.join(base, "src")
        os.makedirs(src, exist_ok=True)
        for name in os.listdir(os.path.join(HERE, "fixture")):
            if name.endswith(".st"):
                with open(os.path.join(HERE, "fixture", name), encoding="utf-8") as f, \
                        open(os.path.join(src, name), "w", encoding="utf-8") as g:
                    g.write(f.read())
        with open(os.path.join(HERE, "fixture", "wiring.json"), encoding="utf-8") as f:
            data = json.load(f)
        data["sources"] = ["../src/*.st"]
        wiring = write_wiring(os.path.join("wiring_outside", "ci"), data)
        out = os.path.join(base, "out")
        run = pac_test(wiring, out, "--filter", "FB_TestPasses")
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertNotIn("filtered out", run.stdout + run.stderr)
        with open(os.path.join(out, "coverage", "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
        self.assertGreater(summary["lines"], 0, run.stdout)
        self.assertGreater(summary["lines_executed"], 0, run.stdout)
        self.assertIn("PRG_Count", {row["pou"] for row in summary["pous"]}, run.stdout)


class CliTest(unittest.TestCase):
    """pac-test's command line and wiring object, without a build."""

    def test_help_says_the_whole_description(self):
        run = subprocess.run([sys.executable, "-m", "pactest", "--help"], capture_output=True, text=True,
                             env=dict(os.environ, PYTHONPATH=TOOL))
        self.assertEqual(run.returncode, 0, run.stderr)
        text = " ".join(run.stdout.split())
        self.assertIn("runs each of its ST tests against the simulated PA-CONTROL (docs/user_tests.md).", text)
        self.assertIn("a VCD of each failing test and the coverage of the program's ST.", text)

    def test_each_test_has_its_own_step_paths(self):
        # The tests run in a thread pool: one test's scenario must not change the paths another test's
        # refusal is named by.
        from pactest.wiring import Wiring, wiring_path
        with open(os.path.join(HERE, "fixture", "wiring.json"), encoding="utf-8") as f:
            data = json.load(f)
        data["sources"] = [os.path.join(HERE, "fixture", "*.st")]
        data["tests"]["faults"] = {"FB_TestPasses": [{"at_ms": 0, "fault": "power_cycle"}],
                                   "FB_TestFails": [{"at_ms": 5, "fault": "system_error"},
                                                    {"at_ms": 9, "fault": "thaw_link"}]}
        wiring = Wiring(write_wiring("step_paths", data))
        passes = wiring.step_paths("FB_TestPasses")
        wiring.scenario("FB_TestFails")
        self.assertEqual(wiring_path("$.steps[0].fault: unknown", passes),
                         "$.tests.faults.FB_TestPasses[0].fault: unknown")
        fails = wiring.step_paths("FB_TestFails")
        self.assertEqual(wiring_path("$.steps[3].fault: unknown", fails),
                         "$.tests.faults.FB_TestFails[1].fault: unknown")
        self.assertEqual([s.get("fault") for s in wiring.scenario("FB_TestFails")["steps"]],
                         [None, "system_error", None, "thaw_link", None])


class WiringRefusalTest(unittest.TestCase):
    """A wiring file pac-test cannot use is refused with the JSONPath and the reason, exit code 2."""

    def refused(self, change, listing=True):
        with open(os.path.join(HERE, "fixture", "wiring.json"), encoding="utf-8") as f:
            data = json.load(f)
        change(data)
        data["sources"] = [os.path.join(HERE, "fixture", "*.st")]
        run = pac_test(write_wiring("refused", data), os.path.join(OUT, "refused"), "--no-coverage", *(["--list"] if listing else []))
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        return run.stderr

    def test_unknown_key(self):
        self.assertIn("$.taks: unknown key", self.refused(lambda d: d.update(taks=[])))

    def test_unknown_test_task(self):
        self.assertIn("$.tests.task: no task named \"Medium\"",
                      self.refused(lambda d: d["tests"].update(task="Medium")))

    def test_controller_settings_are_the_scenario_loaders(self):
        self.assertIn("$.controller.n_registers[\"2000\"]: out of range",
                      self.refused(lambda d: d.update(controller={"n_registers": {"2000": 1}}), listing=False))

    def test_a_fault_the_scenario_format_does_not_know(self):
        # --list exits as the run would (it once listed the tests and exited 0)
        for listing in (False, True):
            self.assertIn("$.tests.faults.FB_TestPasses[1].fault: unknown fault \"melt_down\"",
                          self.refused(lambda d: d["tests"].update(faults={"FB_TestPasses": [
                              {"at_ms": 10, "fault": "power_cycle"}, {"at_ms": 5, "fault": "melt_down"}]}),
                              listing=listing))

    def test_an_automatic_module_is_its_axis_modules_image(self):
        self.assertIn("$.bus.automatic[0]: module 1 has one image",
                      self.refused(lambda d: d.update(bus={"ctrl": {"in": "%IB8", "out": "%QB8"},
                                                           "axes": [{"in": "%IB16", "out": "%QB16"}],
                                                           "automatic": [{"in": "%IB40", "out": "%QB40"}]})))

    def test_unknown_program(self):
        self.assertIn("$.tasks[0].programs[0]: no PROGRAM PRG_Other",
                      self.refused(lambda d: d["tasks"][0].update(programs=["PRG_Other"])))

    def test_located_image_on_the_wrong_side(self):
        self.assertIn("$.bus.cmd.in: a located input image starts at %IBn",
                      self.refused(lambda d: d.update(bus={"cmd": {"in": "%QB0", "out": "%QB0"}})))

    def test_unknown_bus_variable(self):
        # --list exits as the run would
        self.assertIn("$.bus.cmd.in: no global variable GVL_Plant.CmdInn",
                      self.refused(lambda d: d["bus"]["cmd"].update({"in": "GVL_Plant.CmdInn"})))

    def test_axis_modules_need_the_ctrl_module(self):
        self.assertIn("$.bus.axes: axis modules need the CTRL module",
                      self.refused(lambda d: d.update(bus={"axes": [{"in": "%IB16", "out": "%QB16"}]})))


class ProgramRefusalTest(unittest.TestCase):
    """What pac-test cannot run in the program itself is named at its file and line, not as the wiring file's."""

    @staticmethod
    def listed(name, files):
        """pac-test --list on the fixture copied to OUT/name with `files` ({name: ST}) added: (run, folder)."""
        import shutil
        folder = os.path.join(OUT, name)
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(os.path.join(HERE, "fixture"), folder)
        for file, text in files.items():
            with open(os.path.join(folder, file), "w", encoding="utf-8") as f:
                f.write(text)
        run = pac_test(os.path.join(folder, "wiring.json"), os.path.join(folder, "out"), "--no-coverage", "--list")
        return run, folder

    def test_a_word_address(self):
        # in a global list and in a PROGRAM's VAR (as TwinCAT's MAIN declares its I/O), each at its line
        run, folder = self.listed("word-address", {
            "GVL_Word.st": "VAR_GLOBAL\n  Speed AT %IW64 : WORD;\nEND_VAR\n",
            "PRG_Word.st": "PROGRAM PRG_Word\nVAR\n  Count : INT;\n  Total AT %QD4 : DINT;\nEND_VAR\nTotal := Count;\n"
                           "END_PROGRAM\n"})
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        self.assertIn(f"pac-test: {os.path.join(folder, 'GVL_Word.st')}:2: GVL_Word.Speed located at %IW64: pac-test "
                      "copies byte", run.stderr)
        self.assertIn(f"pac-test: {os.path.join(folder, 'PRG_Word.st')}:4: PRG_Word.Total located at %QD4: pac-test "
                      "copies byte", run.stderr)
        self.assertNotIn("invalid wiring file", run.stderr)

    def refused_at(self, name, file, text, where, message):
        """The program of the one file `file` holding `text` is refused at `where` (line:column) with `message`."""
        run, folder = self.listed(name, {file: text})
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        self.assertIn(f"{os.path.join(folder, file)}:{where}: error: {message}", run.stderr)

    def test_a_name_of_a_vendor_library_pac_test_provides_in_part(self):
        self.refused_at("vendor-name", "FB_TaskIndex.st", "FUNCTION_BLOCK FB_TaskIndex\nVAR\n  Index : "
                        "Tc2_System.T_AmsNetId;\nEND_VAR\nEND_FUNCTION_BLOCK\n", "3:11",
                        "'Tc2_System.T_AmsNetId': the library Tc2_System has no type or POU 'T_AmsNetId': pac-test "
                        "provides part of the vendor library Tc2_System (docs/user_dialect.md, \"Vendor libraries\"); "
                        "keep the code that needs this name out of the program tested")

    def test_tc2_system_pi_is_refused_with_why_and_what_to_write(self):
        # Beckhoff's documentation of Tc2_System gives PI no type and value: the refusal says so and what to write
        self.refused_at("vendor-pi", "FB_Wave.st", "FUNCTION_BLOCK FB_Wave\nVAR\n  Angle : LREAL;\nEND_VAR\n"
                        "Angle := 2.0 * Tc2_System.PI;\nEND_FUNCTION_BLOCK\n", "5:27",
                        "the library Tc2_System has no declaration 'PI': Beckhoff's documentation of Tc2_System gives "
                        "PI no type and value, so pac-test does not make one up: declare your own constant "
                        "(VAR_GLOBAL CONSTANT PI : LREAL := 3.141592653589793; END_VAR) and write PI for "
                        "Tc2_System.PI")

    def test_a_call_of_a_refused_function_and_a_function_named_like_a_conversion(self):
        run, folder = self.listed("refused-function", {
            "F_Bad.st": "FUNCTION F_Bad : INT\nVAR_INPUT\n  X : NoSuchType;\nEND_VAR\nF_Bad := 1;\nEND_FUNCTION\n",
            "BIN_TO_BYTE.st": "FUNCTION BIN_TO_BYTE : BYTE\nVAR_INPUT\n  Bits : WORD;\nEND_VAR\n"
                              "BIN_TO_BYTE := WORD_TO_BYTE(Bits);\nEND_FUNCTION\n",
            "PRG_Calls.st": "PROGRAM PRG_Calls\nVAR\n  N : INT;\n  B : BYTE;\nEND_VAR\nN := F_Bad(X := 1);\n"
                            "B := BIN_TO_BYTE(16#0102);\nEND_PROGRAM\n"})
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        self.assertIn(f"{os.path.join(folder, 'F_Bad.st')}:3:7: error: undeclared type 'NoSuchType'", run.stderr)
        # the call names the refusal above, not an order of declarations
        self.assertIn(f"{os.path.join(folder, 'PRG_Calls.st')}:6:6: error: FUNCTION F_Bad cannot be called: its "
                      "declaration was refused (above)", run.stderr)
        self.assertNotIn("before its declaration", run.stderr)
        # a FUNCTION of the program's own named like a conversion is called as declared
        self.assertNotIn("BIN_TO_BYTE", run.stderr)
        self.assertNotIn("PRG_Calls.st:7:", run.stderr)


class VendorLibraryTest(unittest.TestCase):
    """The vendor libraries' parts pac-test gives a program (tools/pactest/vendor): all of them, but a part the
    program declares itself; the host implements only those it names."""

    def test_a_part_the_program_declares_is_left_out(self):
        import tempfile
        with tempfile.TemporaryDirectory() as folder:
            mine = os.path.join(folder, "FLOOR.TcPOU")
            with open(mine, "w", encoding="utf-8") as f:
                f.write("<TcPlcObject><POU Name=\"FLOOR\"><Declaration><![CDATA[FUNCTION FLOOR : INT\n")
            given = {os.path.basename(p) for p in project.vendor_sources([folder])}
            every = {os.path.basename(p) for p in project.vendor_sources()}
        self.assertIn("FLOOR.st", every)
        self.assertEqual(every - given, {"FLOOR.st"})

    def test_the_host_implements_the_named_natives_only(self):
        self.assertEqual([os.path.basename(p) for p in project.vendor_natives()],
                         ["F_GetSystemTime.st", "PacTestTaskCycleTime.st", "PacTestTaskCycles.st"])

    @staticmethod
    def given_for(text, name, parts):
        """The file names parts([path]) gives a program whose one source file `name` holds `text`."""
        import tempfile
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, name)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
            return {os.path.basename(p) for p in parts([path])}

    def test_tcunit_array_asserts_only_for_a_program_calling_one(self):
        # their file costs a cold parse of about 11 s: a TcUnit program that calls none is given the rest only
        for text, given in (("AssertEquals_INT(1, 1, 'x');", False), ("AssertArrayEquals_INT(A, B, 'x');", True),
                            ("TcUnit.AssertArray2dEquals_REAL(A, B, 0.1, 'x');", True)):
            names = self.given_for(text, "FB_Suite.st", project.tcunit_sources)
            self.assertEqual("AssertArrayEquals.st" in names, given, text)
            self.assertIn("TEST.st", names)

    def test_a_leaf_function_only_for_a_program_naming_it(self):
        # LREAL_TO_FMTSTR and WSTRNCPY, which no other part calls, cost every program CPU to translate and compile
        for text in ("s := CONCAT(s, 'x');", "s := LREAL_TO_FMTSTR(x, 2, TRUE);",
                     "ok := Tc2_Utilities.WSTRNCPY(ADR(a), ADR(b), SIZEOF(a));"):
            names = self.given_for(text, "MAIN.st", lambda sources: project.vendor_sources(sources, named_only=True))
            self.assertEqual("LREAL_TO_FMTSTR.st" in names, "LREAL_TO_FMTSTR" in text, text)
            self.assertEqual("WSTRNCPY.st" in names, "WSTRNCPY" in text, text)
            self.assertIn("STRNCPY.st", names)

    def test_a_program_naming_a_part_uses_the_vendor_libraries(self):
        import tempfile
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "MAIN.st")
            for text, uses in (("x := Tc2_Math.FLOOR(2.5);", True), ("s : T_MaxString;", True),
                               ("n := MAX_STRING_LENGTH;", True), ("n := LEN2(ADR(s));", True),
                               ("x := FLOORED;", False)):
                with open(path, "w", encoding="utf-8") as f:
                    f.write(text)
                self.assertEqual(project.uses_vendor([path]), uses, text)


def outcomes(stdout):
    """{test: (mark, asserts, [(scan, t, message)...])}: what a run found, without where it found it."""
    found = {}
    for line in stdout.splitlines():
        head = re.match(r"^\s*(ok|FAILED|failed \(expected\)|ERROR)  (\w+)  \((\d+) asserts", line)
        if head:
            found[head.group(2)] = (head.group(1), int(head.group(3)), [])
    for f in failures(stdout):
        found[f["test"]][2].append((f["scan"], f["t"], f["msg"]))
    return found


@unittest.skipUnless(MATIEC, "pac-test compiles with iec2c only on a MATIEC build")
class MatiecRefusalTest(unittest.TestCase):
    """On a MATIEC build, ST that MATIEC refuses stops the run with iec2c's own message (exit code 2): the
    fixture with a variable named Step, a keyword of SFC to MATIEC (pacst accepts it)."""

    def test_iec2c_refusal(self):
        import shutil
        folder = os.path.join(OUT, "matiec-refusal")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(os.path.join(HERE, "fixture"), folder)
        path = os.path.join(folder, "PRG_Count.st")
        with open(path, encoding="utf-8") as f:
            text = f.read()
        with open(path, "w", encoding="utf-8") as f:
            f.write(re.sub(r"\bIncrement\b", "Step", text))
        run = pac_test(os.path.join(folder, "wiring.json"), os.path.join(folder, "out"))
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        self.assertIn("iec2c failed", run.stderr)
        self.assertRegex(run.stderr, r"program\.st:\d+: error: invalid located variable declaration")


class DialectTest(unittest.TestCase):
    """tools/pactest/tests/dialect: a program in the TwinCAT 3 / CODESYS dialect (docs/user_dialect.md), with the
    library under its namespace (PA_CONTROL.MC_Power), a located input that a test presses, and tests that read
    the PROGRAM's variables (MAIN.Presses)."""

    @classmethod
    def setUpClass(cls):
        cls.folder = os.path.join(HERE, "dialect")
        cls.out = os.path.join(OUT, "dialect")
        cls.result = pac_test(os.path.join(cls.folder, "wiring.json"), cls.out, "--no-coverage", "--vcd-all")

    def test_every_test_passes(self):
        self.assertEqual(self.result.returncode, 0, self.result.stdout + self.result.stderr)
        tests = sorted(os.path.splitext(n)[0] for n in os.listdir(self.folder) if n.startswith("FB_Test"))
        self.assertIn(f"{len(tests)} tests: {len(tests)} passed, 0 failed", self.result.stdout)
        for name in tests:
            self.assertRegex(self.result.stdout, rf"\bok  {name}\b")

    def test_a_fault_after_the_end_of_its_test_is_warned_about(self):
        self.assertRegex(self.result.stderr, r"warning: .*wiring\.json: \$\.tests\.faults\.FB_TestStartButton: the fault at "
                                             r"150 ms comes after the test ended at \d+ ms; it never happened")

    def test_an_implicit_narrowing_is_warned_about_at_its_place(self):
        source = os.path.join(self.folder, "FB_TestNarrowing.st")
        line = line_of(source, "Unsigned := Wide;")
        self.assertIn(f"{source}:{line}:13: warning: implicit conversion of UDINT to UINT: a value outside UINT is cut "
                      "to its 16 bits, as TwinCAT and CODESYS cut it (their C0197); write UDINT_TO_UINT to say so",
                      self.result.stderr)
        line = line_of(source, "Totals(Start := 300, Total => Small);")
        self.assertIn(f"{source}:{line}:31: warning: implicit conversion of UDINT to USINT", self.result.stderr)

    def test_strict_narrowing_refuses_an_implicit_narrowing(self):
        run = pac_test(os.path.join(self.folder, "wiring.json"), os.path.join(OUT, "dialect-strict"), "--list",
                       "--strict-narrowing")
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        source = os.path.join(self.folder, "FB_TestNarrowing.st")
        line = line_of(source, "Unsigned := Wide;")
        self.assertIn(f"{source}:{line}:13: error: implicit narrowing of UDINT to UINT, refused by --strict-narrowing: "
                      "write UDINT_TO_UINT", run.stderr)

    def test_vcd_all_writes_the_vcd_of_passing_tests(self):
        vcd = os.path.join(self.out, "vcd", "FB_TestStartButton.vcd")
        self.assertTrue(os.path.exists(vcd), self.result.stdout)
        with open(vcd, encoding="utf-8") as f:
            self.assertRegex(f.read(), r"\$scope module GVL_Io \$end\n\$var wire 1 \S+ StartButton \$end")


class LibraryTest(unittest.TestCase):
    """tools/pactest/tests/library: a machine program and a library of its own (Common) that it references under
    that namespace, given in the wiring file's "libraries" or with --library: Common.FB_Counter, Common.GVL_Common.x,
    Common.E_Level.FULL, EXTENDS Common.FB_Counter, IMPLEMENTS Common.I_Runnable and the names without the namespace
    resolve; a library missing, given twice or under pac-test's own namespace, and a name the library lacks, are
    refused with where they are given."""

    folder = os.path.join(HERE, "library")

    def copy(self, name, libraries=None):
        """The project copied to OUT/name with the wiring file's "libraries" replaced (None: left out); its wiring
        file."""
        import shutil
        target = os.path.join(OUT, name)
        shutil.rmtree(target, ignore_errors=True)
        shutil.copytree(self.folder, target)
        path = os.path.join(target, "wiring.json")
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        data.pop("libraries")
        if libraries is not None:
            data["libraries"] = libraries
        with open(path, "w", encoding="utf-8") as f:
            json.dump(data, f)
        return path

    def test_every_test_passes(self):
        run = pac_test(os.path.join(self.folder, "wiring.json"), os.path.join(OUT, "library"), "--no-coverage")
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn("1 tests: 1 passed, 0 failed", run.stdout)
        self.assertRegex(run.stdout, r"ok  FB_TestLibrary  \(6 asserts")

    def test_the_library_given_as_an_option(self):
        wiring = self.copy("library-option")
        run = pac_test(wiring, os.path.join(OUT, "library-option"), "--no-coverage", "--list",
                       "--library", f"Common={os.path.join(os.path.dirname(wiring), 'Common')}")
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertEqual(run.stdout.split(), ["FB_TestLibrary"])

    def test_without_the_library_its_namespace_is_refused_at_its_line(self):
        wiring = self.copy("library-missing")
        run = pac_test(wiring, os.path.join(OUT, "library-missing", "out"), "--no-coverage", "--list")
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        source = os.path.join(os.path.dirname(wiring), "Machine", "FB_DoubleCounter.st")
        line = line_of(source, "EXTENDS Common.FB_Counter")
        with open(source, encoding="utf-8") as f:
            column = f.read().splitlines()[line - 1].index("Common.FB_Counter") + 1
        self.assertRegex(run.stderr, re.escape(f"{source}:{line}:{column}: error: 'Common.FB_Counter': 'Common' is no "
                                               "library namespace (PA_CONTROL, ") + r"[\w, ]*" +
                         re.escape("Standard); give pac-test a library of your own with the namespace it is referenced "
                                   "under: --library Common=PATH"))

    def test_a_library_given_twice(self):
        wiring = self.copy("library-twice", {"Common": "Common", "Again": "Common/"})
        run = pac_test(wiring, os.path.join(OUT, "library-twice", "out"), "--list")
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        common = os.path.join(os.path.dirname(wiring), "Common")
        self.assertIn(f"pac-test: $.libraries.Again: {common} is given twice, also by $.libraries.Common", run.stderr)
        wiring = self.copy("library-twice", {"Common": "Common"})
        run = pac_test(wiring, os.path.join(OUT, "library-twice", "out"), "--list", "--library", "common=Machine")
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        self.assertIn("pac-test: --library common: the namespace common is given twice, also by $.libraries.Common",
                      run.stderr)

    def test_a_namespace_of_pac_test_itself(self):
        wiring = self.copy("library-clash", {"PA_CONTROL": "Common"})
        run = pac_test(wiring, os.path.join(OUT, "library-clash", "out"), "--list")
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        self.assertIn("pac-test: $.libraries.PA_CONTROL: the namespace PA_CONTROL is pac-test's, for the PA-CONTROL "
                      "library: reference your library under another", run.stderr)

    def test_a_name_the_library_lacks(self):
        wiring = self.copy("library-lacks", {"Common": "Common"})
        source = os.path.join(os.path.dirname(wiring), "Machine", "MAIN.st")
        with open(source, encoding="utf-8") as f:
            text = f.read()
        with open(source, "w", encoding="utf-8") as f:
            f.write(text.replace("Parts : Common.FB_Counter;", "Parts : Common.FB_Count;"))
        run = pac_test(wiring, os.path.join(OUT, "library-lacks", "out"), "--list")
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        line = line_of(source, "Common.FB_Count;")
        self.assertIn(f"{source}:{line}:11: error: 'Common.FB_Count': the library Common has no type or POU "
                      "'FB_Count'", run.stderr)


class CodesysExportTest(unittest.TestCase):
    """tools/pactest/tests/codesys_export: a CODESYS PLCopen XML export whose INTERFACE (in the project's addData,
    its METHODs without bodies) an FB IMPLEMENTS and a test calls through a variable of the INTERFACE; what else
    an INTERFACE holds there is refused at its line."""

    folder = os.path.join(HERE, "codesys_export")

    def test_the_interface_is_implemented_and_called(self):
        run = pac_test(os.path.join(self.folder, "wiring.json"), os.path.join(OUT, "codesys_export"), "--no-coverage")
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn("1 tests: 1 passed, 0 failed", run.stdout)
        self.assertRegex(run.stdout, r"ok  FB_TestGaugeInterface  \(2 asserts")

    def test_a_property_of_an_interface_is_refused_at_its_line(self):
        export = os.path.join(OUT, "codesys_export-property", "Export.xml")
        with open(os.path.join(self.folder, "Export.xml"), encoding="utf-8") as f:
            text = f.read().replace("        </Methods>\n", "        </Methods>\n        <Properties />\n")
        self.assertIn(f"{export}:{line_in(text, '<Properties />')}:1: error: cannot read the PLCopen project: "
                      "I_Gauge: <Properties> of an INTERFACE is not read from PLCopen XML (its METHODs are): give "
                      "this INTERFACE to pac-test as an ST file of its own", self.refusal(export, text))

    def test_a_transition_is_refused_saying_why(self):
        export = os.path.join(OUT, "codesys_export-transition", "Export.xml")
        transition = ('        <transitions><transition name="T_Full"><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">'
                      'T_Full := Total > 5;</xhtml></ST></body></transition></transitions>\n')
        with open(os.path.join(self.folder, "Export.xml"), encoding="utf-8") as f:
            text = f.read().replace("        </interface>\n        <body>\n", "        </interface>\n" + transition
                                    + "        <body>\n", 1)
        self.assertIn(f"{export}:{line_in(text, '<transitions>')}:1: error: cannot read the PLCopen "
                      "project: FB_Gauge: its TRANSITIONs are not read: a TRANSITION is a step condition of an SFC "
                      "chart, and pacst reads no SFC; leave the POU out of the program tested",
                      self.refusal(export, text))

    def refusal(self, export, text):
        """pac-test's error output for the fixture with its Export.xml replaced by `text` (at `export`)."""
        import shutil
        target = os.path.dirname(export)
        shutil.rmtree(target, ignore_errors=True)
        shutil.copytree(self.folder, target)
        with open(export, "w", encoding="utf-8") as f:
            f.write(text)
        run = pac_test(os.path.join(target, "wiring.json"), os.path.join(target, "out"), "--list")
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        return run.stderr


@unittest.skipUnless(MATIEC, "pac-test compiles with iec2c only on a MATIEC build")
class MatiecDialectTest(unittest.TestCase):
    """On a MATIEC build, the dialect project is refused by pacst before iec2c, each construct at its line."""

    def test_each_dialect_construct_is_refused_at_its_line(self):
        folder = os.path.join(HERE, "dialect")
        run = pac_test(os.path.join(folder, "wiring.json"), os.path.join(OUT, "dialect-matiec"))
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        main = os.path.join(folder, "MAIN.st")
        self.assertIn(f"{main}:{line_of(main, 'PA_CONTROL.MC_Power')}:11: error: the namespace in "
                      "'PA_CONTROL.MC_Power': TwinCAT / CODESYS dialect that MATIEC does not compile", run.stderr)
        self.assertNotIn("iec2c failed", run.stderr)


class WiringWarningTest(unittest.TestCase):
    """A controller that will never start ONLINE is named before the tests run into their time limit."""

    def run_with(self, controller):
        with open(os.path.join(HERE, "fixture", "wiring.json"), encoding="utf-8") as f:
            data = json.load(f)
        data["bus"]["ctrl"] = {"in": "%IB8", "out": "%QB8"}
        data["controller"] = controller
        data["sources"] = [os.path.join(HERE, "fixture", "*.st")]
        run = pac_test(write_wiring("warned", data), os.path.join(OUT, "warned"), "--no-coverage", "--list")
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        return run.stderr

    def test_no_external_stop_input(self):
        stderr = self.run_with({})
        self.assertIn("pac-test: warning: ", stderr)
        self.assertIn("$.controller.system_parameters: system parameter 4 is 0: the PA-CONTROL will "
                      "not start ONLINE", stderr)

    def test_the_stop_input_without_power(self):
        self.assertIn("$.controller.inputs: input 1 (system parameter 4) has no power: the PA-CONTROL "
                      "will not start ONLINE", self.run_with({"system_parameters": {"4": 1}}))

    def test_a_controller_that_starts(self):
        self.assertNotIn("warning", self.run_with({"system_parameters": {"4": 1}, "inputs": {"1": True}}))


class ModuleImageTest(unittest.TestCase):
    """A module's address that cuts through a located image (a typing error: %IB17 for an image at %IB16)
    would hand the program shifted bytes: refused, naming both."""

    def test_a_module_straddling_a_located_image(self):
        example = os.path.join(ROOT, "examples", "pick_and_place")
        with open(os.path.join(example, "wiring.json"), encoding="utf-8") as f:
            data = json.load(f)
        data["sources"] = [os.path.join(example, "PickAndPlace", "PickAndPlace.plcproj")]
        data["bus"]["axes"][0]["in"] = "%IB17"
        run = pac_test(write_wiring("straddle", data), os.path.join(OUT, "straddle"), "--no-coverage", "--list")
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        self.assertIn("$.bus.axes[0].in: %IB17..%IB28, the axis module's 12 bytes, cut through GVL_Bus.XIn at "
                      "%IB16..%IB27", run.stderr)


class PlcopenRoundTripTest(unittest.TestCase):
    """A project exported as PLCopen XML by the project's own export (tools/pacexport), as CODESYS exports
    one, and read back by pac-test: the same tests end the same way, with the same failures in the same
    scans, named at the XML file's lines of the asserts."""

    def round_trip(self, name, folder, sources, expected, coverage=False):
        """Exports `sources` ({file name: ST text}), runs the wiring file of `folder` on the XML and on its
        own sources, and compares; with `coverage`, the XML's run tables the coverage of the ST it extracted."""
        out = os.path.join(OUT, "roundtrip", name)
        st = os.path.join(out, "st")
        os.makedirs(st, exist_ok=True)
        for file, text in sources.items():
            with open(os.path.join(st, file), "w", encoding="utf-8") as f:
                f.write(text)
        info = os.path.join(out, "library.json")
        with open(info, "w", encoding="utf-8") as f:
            json.dump({"name": name, "title": name, "version": "1.0.0", "released": "2026-12-02",
                       "company": "PA-CONTROL PLC library contributors", "license": "MIT",
                       "description": "exported for pac-test's round trip"}, f)
        python = os.path.join(PAC_BUILD, "venv-pacexport", "bin", "python")
        env = dict(os.environ, PYTHONPATH=os.pathsep.join([os.path.join(ROOT, "tools", "pacexport"),
                                                            os.path.join(ROOT, "translator")]))
        export = subprocess.run([python, "-m", "pacexport", "export", "--library", info, "--cache", PARSE_CACHE,
                                 "--out", os.path.join(out, "export"), *sorted(sources)], cwd=st, env=env,
                                capture_output=True, text=True)
        self.assertEqual(export.returncode, 0, export.stderr)
        with open(os.path.join(folder, "wiring.json"), encoding="utf-8") as f:
            wiring = json.load(f)
        wiring["sources"] = [f"export/{name.lower()}.xml"]
        with open(os.path.join(out, "wiring.json"), "w", encoding="utf-8") as f:
            json.dump(wiring, f)
        from_source = pac_test(os.path.join(folder, "wiring.json"), os.path.join(out, "source"), "--no-coverage")
        from_xml = pac_test(os.path.join(out, "wiring.json"), os.path.join(out, "xml"),
                            *([] if coverage else ["--no-coverage"]))
        self.assertEqual(from_xml.returncode, from_source.returncode, from_xml.stdout + from_xml.stderr)
        if coverage:  # the ST extracted from the XML lies under OUT, which coverage leaves out otherwise
            self.assertNotIn("total 0/0", from_xml.stdout)
            self.assertRegex(from_xml.stdout, r"(?m)^PRG_Count +\d+/\d+")
        found = outcomes(from_source.stdout)
        self.assertEqual(sorted(found), expected[0], from_source.stdout)
        self.assertEqual(sum(len(f) for _, _, f in found.values()), expected[1], from_source.stdout)
        self.assertEqual(outcomes(from_xml.stdout), found)
        for failure in failures(from_xml.stdout):  # at the XML file's line of the assert, as CODESYS shows it
            self.assertEqual(failure["file"], wiring["sources"][0], from_xml.stdout)
            with open(os.path.join(out, failure["file"]), encoding="utf-8") as f:
                text = f.read().splitlines()[int(failure["line"]) - 1]
            said = failure["msg"].split(": ")[0]  # the assert's Message, before what the assert adds
            self.assertTrue(f"'{said}'" in text or f'name="{failure["test"]}"' in text, (failure, text))

    def test_the_example_from_its_plcopen_export(self):
        sys.path.insert(0, os.path.join(ROOT, "translator"))
        from pacst import twincat  # the TwinCAT files as ST, as a CODESYS project would hold them
        folder = os.path.join(ROOT, "examples", "pick_and_place")
        sources = {}
        for path in twincat.project_files(os.path.join(folder, "PickAndPlace", "PickAndPlace.plcproj")):
            with open(path, encoding="utf-8-sig") as f:
                sources[os.path.splitext(os.path.basename(path))[0] + ".st"] = twincat.object_st(f.read(), path)
        self.round_trip("PickAndPlace", folder, sources, (EXAMPLE_TESTS, 1))

    def test_the_fixture_from_its_plcopen_export(self):
        folder = os.path.join(HERE, "fixture")
        sources = {}
        for file in sorted(n for n in os.listdir(folder) if n.endswith(".st")):
            with open(os.path.join(folder, file), encoding="utf-8") as f:
                sources[file] = f.read()
        self.round_trip("PacTestFixture", folder, sources, (FIXTURE_TESTS, 7), coverage=True)


class DocsCiJobsTest(unittest.TestCase):
    """The CI snippets of docs/user_tests.md call pac-test with options it has: each command line, with the
    CI system's shard variables filled in, lists the example's tests of that shard."""

    def test_every_pac_test_line_of_the_yaml_blocks_runs(self):
        with open(os.path.join(ROOT, "docs", "user_tests.md"), encoding="utf-8") as f:
            blocks = re.findall(r"^```yaml\n(.*?)^```", f.read(), re.S | re.M)
        commands = [line.split("pac-test", 1)[1] for block in blocks for line in block.splitlines()
                    if re.search(r"bin/pac-test ", line)]
        self.assertEqual(len(commands), 2, blocks)
        wiring = os.path.join(ROOT, "examples", "pick_and_place", "wiring.json")
        for command in commands:
            args = command.replace("$CI_NODE_INDEX/$CI_NODE_TOTAL", "1/4").replace("${{ matrix.shard }}", "1").split()
            self.assertEqual(args[0], "wiring.json")
            run = pac_test(wiring, os.path.join(OUT, "pick_and_place_docs"), *args[1:], "--list", "--no-coverage")
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            self.assertEqual(run.stdout.split(), [n for n in EXAMPLE_TESTS if shard_of(n, 4) == 0])


if __name__ == "__main__":
    unittest.main()
