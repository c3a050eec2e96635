"""pac_scenario on damaged scenario files (Hypothesis): the demo and the example scenarios, mutated, end in
exit code 2 with a reason on stderr, or, where the damage left a valid scenario, in 0 or 1 as any run does.
Never a crash, another exit code or a hang. Run by ctest as ScenarioDamagedInput (docs/testing.md)."""
import glob
import os
import subprocess
import sys
import tempfile
import unittest

from hypothesis import given, seed, strategies as st

from damaged_inputs import SEED, SETTINGS, mutated

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PAC_SCENARIO = sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(REPO, "build", "scenario", "pac_scenario")
FILES = [os.path.join(REPO, "scenario", "demo.json")] + sorted(glob.glob(os.path.join(REPO, "scenario", "examples", "*.json")))
SCENARIOS = [open(p, encoding="utf-8").read() for p in FILES]
SECONDS_PER_RUN = 60

junk = st.sampled_from(['"', "{", "}", "[", "]", ",", ":", "null", "true", "-1", "1e309", "99999999999",
                        '"scans"', '"expect"', "0.5", "\\u0000", "\u00e9"]) | st.text(max_size=6)


class ScenarioOnDamagedFile(unittest.TestCase):
    @seed(SEED)
    @SETTINGS
    @given(mutated(SCENARIOS, junk))
    def test_damaged_scenario(self, text):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "damaged.json")
            with open(path, "w", encoding="utf-8", errors="surrogatepass") as f:
                f.write(text)
            try:
                result = subprocess.run([PAC_SCENARIO, path], capture_output=True, text=True, errors="replace",
                                        timeout=SECONDS_PER_RUN)
            except subprocess.TimeoutExpired:
                self.fail(f"pac_scenario ran longer than {SECONDS_PER_RUN} s on:\n{text!r}")
            self.assertIn(result.returncode, (0, 1, 2), f"exit code {result.returncode}:\n{result.stderr}\non:\n{text!r}")
            if result.returncode == 2:
                self.assertTrue(result.stderr.strip(), f"exit code 2 without a reason, on:\n{text!r}")


if __name__ == "__main__":
    unittest.main()
