"""The same sources give the same bytes: no time stamp, no random Id; and the build's export is the
one the sources give now."""
import filecmp
import os
import tempfile
import unittest

from pacexport.cli import export
from tests import support


def _tree(root):
    found = {}
    for folder, _, names in os.walk(root):
        for name in names:
            path = os.path.join(folder, name)
            found[os.path.relpath(path, root)] = path
    return found


class Determinism(unittest.TestCase):
    def test_a_second_export_is_identical_to_the_build(self):
        built = {k: v for k, v in _tree(support.config()["out"]).items() if not k.endswith(".stamp")}
        with tempfile.TemporaryDirectory() as out:
            export(support.library(), out)
            again = _tree(out)
            self.assertEqual(sorted(again), sorted(built))
            for name, path in again.items():
                self.assertTrue(filecmp.cmp(path, built[name], shallow=False), name)


if __name__ == "__main__":
    unittest.main()
