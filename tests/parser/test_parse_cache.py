"""pacst's parse cache in layers (`--cache OWN:BASE`, as pac-test reads the build's cache beneath a run's own): a
user-mode translation takes the tree of a text the build parsed outside user mode instead of parsing it again,
writes only to its own folder, and still refuses what user mode's lexical checks refuse. Run by ctest as
FastParser.ParseCache."""
import os
import pickle
import sys
import tempfile
import unittest
from unittest import mock

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "translator"))
from pacst import parsing  # noqa: E402
from pacst.errors import StError  # noqa: E402

FB = """FUNCTION_BLOCK FB_Cached
VAR_INPUT
    Execute : BOOL; (* the edge that starts it *)
END_VAR
VAR
    Wait : TIME := T#1500MS;
END_VAR
IF Execute THEN
    Wait := T#2S;
END_IF;
END_FUNCTION_BLOCK
"""


def _entries(folder):
    return sorted(os.listdir(folder)) if os.path.isdir(folder) else []


class LayeredCacheTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.base = os.path.join(self.tmp.name, "build-cache")
        self.own = os.path.join(self.tmp.name, "run-cache")

    def tearDown(self):
        self.tmp.cleanup()

    def _file(self, text, name="FB_Cached.st"):
        path = os.path.join(self.tmp.name, name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        return path

    def _items(self, result):
        self.assertIsInstance(result, parsing.SourceFile)
        return pickle.dumps(result.tree.items)

    def test_a_user_parse_takes_the_builds_tree_and_writes_only_its_own_folder(self):
        path = self._file(FB)
        (built,) = parsing.parse_files([path], self.base, jobs=1)  # the build: outside user mode
        base_before = _entries(self.base)
        with mock.patch.object(parsing, "_parse_pickled", side_effect=AssertionError("parsed again")):
            (taken,) = parsing.parse_files([path], f"{self.own}{os.pathsep}{self.base}", jobs=1, user=True)
        self.assertEqual(self._items(taken), self._items(built))
        self.assertEqual(_entries(self.base), base_before)
        # the user-mode entry (and the file's user text) are kept in the run's own folder for its next run
        self.assertEqual(len([n for n in _entries(self.own) if not n.startswith("read-")]), 1)
        with mock.patch.object(parsing.lexcheck, "check", side_effect=AssertionError("checked again")):
            (again,) = parsing.parse_files([path], f"{self.own}{os.pathsep}{self.base}", jobs=1, user=True)
        self.assertEqual(self._items(again), self._items(built))

    def test_user_modes_lexical_checks_still_refuse_a_text_the_build_parsed(self):
        path = self._file(FB)
        (built,) = parsing.parse_files([path], self.base, jobs=1)
        self.assertIsInstance(built, parsing.SourceFile)
        # a text the build's stricter checks passed is checked in user mode all the same (no such text is known
        # to exist; the check's own refusal stands for one): the build's tree is no pass of user mode's checks
        refusal = StError(path, 6, 20, "user mode's refusal")
        checked = parsing.lexcheck.check

        def check(text, file, user=False):
            if user:
                raise refusal
            return checked(text, file, user)
        with mock.patch.object(parsing.lexcheck, "check", side_effect=check):
            (refused,) = parsing.parse_files([path], f"{self.own}{os.pathsep}{self.base}", jobs=1, user=True)
        self.assertIs(refused, refusal)
        self.assertEqual([n for n in _entries(self.own) if not n.startswith("read-")], [])

    def test_a_parse_outside_user_mode_never_takes_a_user_mode_tree(self):
        text = FB.replace("Wait : TIME", "Wait_ : TIME").replace("Wait :=", "Wait_ :=")  # user mode only
        path = self._file(text)
        (taken,) = parsing.parse_files([path], self.base, jobs=1, user=True)
        self.assertIsInstance(taken, parsing.SourceFile)
        (refused,) = parsing.parse_files([path], f"{self.own}{os.pathsep}{self.base}", jobs=1)
        self.assertIsInstance(refused, StError)
        self.assertIn("ends with '_'", refused.message)


if __name__ == "__main__":
    unittest.main()
