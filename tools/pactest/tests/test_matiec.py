"""pac-test's MATIEC check (CTest PacTest.Matiec, MATIEC preset only): the example's machine program and
pac-test's fixture program, with the library, compiled by MATIEC (`pacst matiec`, iec2c, the C compiler),
and the boundary that keeps their tests off MATIEC.

Run with pacst's venv; IEC2C and MATIEC_LIB name MATIEC, PACTEST_OUT a scratch folder."""
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.dirname(HERE)
ROOT = os.path.dirname(os.path.dirname(TOOL))
sys.path.insert(0, TOOL)

from pactest import build, matiec, project  # noqa: E402
from pactest.wiring import Wiring  # noqa: E402

OUT = os.environ.get("PACTEST_OUT", os.path.join(ROOT, "build", "matiec", "pactest-tests"))
EXAMPLE = os.path.join(ROOT, "examples", "pick_and_place", "wiring.json")
FIXTURE = os.path.join(HERE, "fixture", "wiring.json")


def program(wiring_path):
    wiring = Wiring(wiring_path)
    return matiec.MatiecProgram(wiring, os.path.join(OUT, wiring.name), os.environ["IEC2C"],
                                os.environ["MATIEC_LIB"], pacst_python=sys.executable,
                                parse_cache=os.path.join(OUT, "pacst-cache"))


class MatiecProgramTest(unittest.TestCase):
    def check(self, wiring_path, programs, tests):
        prog = program(wiring_path)
        files = [os.path.basename(f) for f in prog.program_files()]
        for name in tests:
            self.assertFalse([f for f in files if f.startswith(name + ".")], f"{name} went to MATIEC")
        objects = prog.compile(os.environ.get("CC", "cc"))
        self.assertEqual(len(objects), 2)
        with open(os.path.join(prog.c_dir, "PacResource.c"), encoding="utf-8") as f:
            resource = f.read().upper()
        for name in programs:  # each PROGRAM has its instance in the RESOURCE
            self.assertIn(f"INST_{name}".upper(), resource)

    def test_example(self):
        self.check(EXAMPLE, ["MAIN"], ["FB_TestNormalCycle", "FB_TestShowsAFailure"])

    def test_fixture(self):
        self.check(FIXTURE, ["PRG_Count", "PRG_Slow"], ["FB_TestPasses", "FB_TestBusByName"])

    def test_tasks(self):
        """The wiring's tasks as MATIEC's TASKs: the cycle the interval, the order the priority."""
        self.assertEqual(program(FIXTURE).tasks(),
                         {"PRG_Slow": {"task": "Slow", "interval": "T#10MS", "priority": 1},
                          "PRG_Count": {"task": "Fast", "interval": "T#2MS", "priority": 2}})


class MatiecBoundaryTest(unittest.TestCase):
    """What keeps the tests off MATIEC today (docs/user_tests.md, "On MATIEC"): when this fails, MATIEC
    (or pacst matiec) takes a test FB, and pac-test may run the tests on MATIEC."""

    def test_assert_as_statement_refused(self):
        prog = program(EXAMPLE)
        test = os.path.join(ROOT, "examples", "pick_and_place", "PickAndPlace", "Tests", "FB_TestShowsAFailure.TcPOU")
        files = project.vocabulary_sources() + prog.program_files()
        with self.assertRaises(build.BuildError) as refusal:
            prog.pacst("matiec", "--out", prog.st, *files, test)
        self.assertIn("FB_TestShowsAFailure.TcPOU:19:3: error: FUNCTION AssertEquals_UDINT called as a statement",
                      str(refusal.exception))


if __name__ == "__main__":
    unittest.main()
