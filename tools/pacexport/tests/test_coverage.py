"""Every POU, type and global list of st/ is in both exports, and nothing else is."""
import glob
import os
import unittest

from lxml import etree

from pacst.plcopen_names import GLOBAL_VARS, q
from pacexport.splitting import read_source
from pacexport.twincat import relative_path
from tests import support


def _in_st():
    """(kind, name) of every object declared by an ST file under st/."""
    paths = glob.glob(os.path.join(support.config()["st_dir"], "**", "*.st"), recursive=True)
    return {(s.kind, s.name, relative_path(s)) for s in map(read_source, paths)}


class Coverage(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.expected = _in_st()

    def test_st_is_not_empty(self):
        kinds = {kind for kind, _, _ in self.expected}
        self.assertTrue({"dataType", "function", "functionBlock", "globalVars"} <= kinds, kinds)

    def test_every_file_of_st_is_exported(self):
        c = support.config()
        exported = {os.path.realpath(p) for p in c["sources"] + c["global_lists"]}
        in_st = {os.path.realpath(p)
                 for p in glob.glob(os.path.join(c["st_dir"], "**", "*.st"), recursive=True)}
        self.assertEqual(in_st - exported, set())

    def test_the_plcopen_file_holds_every_object(self):
        root = etree.fromstring(support.plcopen_data())
        found = {("dataType", e.get("name")) for e in root.iter(q("dataType"))}
        found |= {(e.get("pouType"), e.get("name")) for e in root.iter(q("pou"))}
        for data in root.iterfind(f"{q('addData')}/{q('data')}"):
            if data.get("name") == GLOBAL_VARS:
                found |= {("globalVars", e.get("name")) for e in data.iterfind(q("globalVars"))}
        self.assertEqual(found, {(kind, name) for kind, name, _ in self.expected})

    def test_the_twincat_folder_holds_every_object(self):
        root = support.twincat_dir()
        on_disk = {os.path.relpath(os.path.join(folder, n), root).replace(os.sep, "/")
                   for folder, _, names in os.walk(root) for n in names}
        wanted = {path for _, _, path in self.expected}
        self.assertEqual(on_disk, wanted | {f"{support.library().info.name}.plcproj"})


if __name__ == "__main__":
    unittest.main()
