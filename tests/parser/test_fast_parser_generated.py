"""The fast parser against blark's Earley parser on generated ST (Hypothesis): expressions of random
precedence and spacing, statement nests, whole POUs, and the damaged-input tests' mutated and random
texts. Whatever the fast parser does not decline must be Earley's tree exactly. Run by ctest as
FastParser.Generated; PAC_HYPOTHESIS_SEED repeats a run."""
import os
import sys
import unittest

from hypothesis import example, given, seed, strategies as st

from tree_oracle import REPO, Oracle
import st_strategies

sys.path.insert(0, os.path.join(REPO, "tests", "damaged"))
from damaged_inputs import SEED, SETTINGS, mutated  # noqa: E402
import test_translator_damaged as damaged  # noqa: E402

ORACLE = Oracle()
EXPRESSIONS = st_strategies.expressions()
COUNTS = {}


def _check(case, kind, source):
    verdict, what = ORACLE.compare(source)
    COUNTS.setdefault(kind, {"same": 0, "declined": 0, "different": 0})[verdict] += 1
    case.assertNotEqual(verdict, "different", f"{what}\n--- input ---\n{source}")


@seed(SEED)
class Generated(unittest.TestCase):
    @classmethod
    def tearDownClass(cls):
        for kind, counts in sorted(COUNTS.items()):
            print(f"{kind}: {counts['same']} parsed fast and equal, {counts['declined']} declined",
                  file=sys.stderr)

    @SETTINGS
    @given(EXPRESSIONS)
    def test_expression(self, expr):
        _check(self, "expressions", f"FUNCTION F_X : INT\nVAR_INPUT a : INT; END_VAR\nF_X := {expr};\nEND_FUNCTION\n")

    @SETTINGS
    @given(st_strategies.statements(EXPRESSIONS))
    def test_statement(self, stmt):
        _check(self, "statements", f"FUNCTION_BLOCK FB_X\nVAR a : INT; END_VAR\n{stmt}\nEND_FUNCTION_BLOCK\n")

    @SETTINGS
    @given(st_strategies.pous(EXPRESSIONS))
    # Found by the mutations: a block closed by another block's keyword, a keyword as an enum value,
    # a date type blark names DATE_TYPE_NAME.
    @example("FUNCTION_BLOCK FB_X\nVAR a : INT; END_VAR\na := 1;\nEND_FUNCTION\n")
    @example("TYPE E_X : (A, END_TYPE); END_TYPE\n")
    @example("FUNCTION_BLOCK FB_X\nVAR a : DT; END_VAR\na := 1;\nEND_FUNCTION_BLOCK\n")
    def test_pou(self, source):
        _check(self, "POUs", source)

    @SETTINGS
    @given(mutated(damaged.SNIPPETS, damaged.junk))
    def test_mutated_conformance_file(self, source):
        _check(self, "mutated files", source)

    @SETTINGS
    @given(damaged.random_st)
    def test_random_words(self, source):
        _check(self, "random words", source)

    def test_the_generators_reach_the_fast_path(self):
        """Most generated expressions must be parsed fast, or the comparison above tests little."""
        same = sum(ORACLE.compare(f"FUNCTION F_X : INT\nF_X := {e};\nEND_FUNCTION\n")[0] == "same"
                   for e in ("a + 1", "-1 * (b - 2)", "NOT a AND b OR c XOR d", "f(x := 1, Q => b)",
                             "T#1m30s", "WORD#16#FF", "a.b[1, 2].c <= 3.0"))
        self.assertEqual(same, 7)


if __name__ == "__main__":
    unittest.main(verbosity=2)
