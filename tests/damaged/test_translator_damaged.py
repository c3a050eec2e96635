"""pacst on random and damaged Structured Text (Hypothesis): every input ends either in C that a C compiler
accepts, or in refusals, each `file:line:col: error: reason`. Never a Python traceback, never a hang.
Run by ctest as TranslatorDamagedInput (docs/testing.md); PAC_HYPOTHESIS_SEED repeats a run."""
import glob
import io
import os
import re
import signal
import subprocess
import sys
import tempfile
import unittest
from contextlib import redirect_stderr, redirect_stdout

from hypothesis import given, seed, strategies as st

from damaged_inputs import SEED, SETTINGS, mutated

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "translator"))
from pacst.cli import main as pacst_main  # noqa: E402

ACCEPT = sorted(glob.glob(os.path.join(REPO, "tests", "conformance", "accept", "*.st")))
SNIPPETS = [open(p, encoding="utf-8").read() for p in ACCEPT]
CC = os.environ.get("CC", "cc")
SECONDS_PER_INPUT = 30
REFUSAL = re.compile(r"^.+:\d+:\d+: error: .+$")

# Words and signs of the ST subset and some outside it, so random text sometimes parses.
VOCABULARY = ["FUNCTION_BLOCK", "END_FUNCTION_BLOCK", "FUNCTION", "END_FUNCTION", "PROGRAM", "END_PROGRAM",
              "VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR CONSTANT", "END_VAR", "TYPE", "END_TYPE",
              "STRUCT", "END_STRUCT", "IF", "THEN", "ELSIF", "ELSE", "END_IF", "CASE", "OF", "END_CASE", "FOR",
              "TO", "BY", "DO", "END_FOR", "WHILE", "END_WHILE", "REPEAT", "UNTIL", "END_REPEAT", "RETURN",
              "EXIT", "BOOL", "INT", "DINT", "UINT", "WORD", "DWORD", "REAL", "LREAL", "TIME", "STRING",
              "ARRAY", "[", "]", "..", "(", ")", ":", ";", ":=", "=>", "+", "-", "*", "/", "MOD", "AND", "OR",
              "XOR", "NOT", "<", ">", "<=", ">=", "=", "<>", ",", ".", "x", "y", "Fb", "T#1S", "T#0S", "16#FFFF",
              "WORD#16#8000", "1", "0", "-1", "32767", "2147483648", "1.5E38", "TRUE", "FALSE", "'a'", "(*", "*)",
              "//", "\n", " ", "\t", "#", "$", "@", "\u00e9", "\x00"]

junk = st.lists(st.sampled_from(VOCABULARY), min_size=1, max_size=6).map(" ".join) | st.text(max_size=8)
random_st = st.lists(st.sampled_from(VOCABULARY), max_size=60).map(" ".join)


class Hang(Exception):
    pass


def _alarm(signum, frame):
    raise Hang()


class TranslatorOnDamagedInput(unittest.TestCase):
    def check(self, text):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "damaged.st")
            with open(path, "w", encoding="utf-8", errors="surrogatepass") as f:
                f.write(text)
            out = os.path.join(tmp, "out")
            err = io.StringIO()
            signal.signal(signal.SIGALRM, _alarm)
            signal.alarm(SECONDS_PER_INPUT)
            try:
                with redirect_stderr(err), redirect_stdout(io.StringIO()):
                    code = pacst_main(["build", "--out", out, path])
            except Hang:
                self.fail(f"pacst took longer than {SECONDS_PER_INPUT} s on:\n{text!r}")
            except SystemExit as e:
                code = e.code
            finally:
                signal.alarm(0)
            # Any other exception propagates: a traceback is a failure with the input in Hypothesis' report.
            if code == 0:
                self.compiles(out, text)
            else:
                lines = [line for line in err.getvalue().splitlines() if line.strip()]
                self.assertEqual(code, 1, f"exit code {code} on:\n{text!r}")
                self.assertTrue(lines, f"refused without a reason:\n{text!r}")
                for line in lines:
                    self.assertRegex(line, REFUSAL, f"not file:line:col: error: reason, on:\n{text!r}")

    def compiles(self, out, text):
        for c_file in glob.glob(os.path.join(out, "*.c")):
            result = subprocess.run([CC, "-std=c99", "-fsyntax-only", "-I", out,
                                     "-I", os.path.join(REPO, "translator", "pacst", "include"), c_file],
                                    capture_output=True, text=True, timeout=60)
            self.assertEqual(result.returncode, 0, f"C that does not compile:\n{result.stderr}\nfrom:\n{text!r}")

    @seed(SEED)
    @SETTINGS
    @given(mutated(SNIPPETS, junk))
    def test_mutated_snippets(self, text):
        self.check(text)

    @seed(SEED)
    @SETTINGS
    @given(random_st)
    def test_random_token_soup(self, text):
        self.check(text)

    def test_the_snippets_themselves_translate(self):
        self.assertGreater(len(SNIPPETS), 10)
        for text in SNIPPETS[:3]:
            self.check(text)


if __name__ == "__main__":
    unittest.main()
