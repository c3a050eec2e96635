"""The exports against real files of CODESYS 3.5 and TwinCAT 3.1 (tests/ide_reference.json): every
element and attribute the real files carry is in the export, or listed with the reason it is not."""
import glob
import json
import os
import tempfile
import unittest

from pacexport.twincat import PRODUCT_VERSION, PROGRAM_VERSION
from tests import support
from tests.fixture_machine import NAME, write_machine
from tests.ide_paths import plcopen_paths, sln_paths, twincat_paths


def _read(path):
    with open(path, "rb") as f:
        return f.read()


def _reference():
    with open(os.path.join(os.path.dirname(__file__), "ide_reference.json"), encoding="utf-8") as f:
        return json.load(f)


class IdeReference(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.facts = _reference()["facts"]
        twincat = support.twincat_dir()
        objects = [p for p in glob.glob(os.path.join(twincat, "*", "*")) if not p.endswith(".plcproj")]
        cls.exported = {
            "plcopen": plcopen_paths(support.plcopen_data()),
            "twincat_object": set().union(*(twincat_paths(_read(p)) for p in objects)),
            "twincat_plcproj": twincat_paths(_read(os.path.join(twincat, f"{support.library().info.name}.plcproj"))),
        }
        with tempfile.TemporaryDirectory() as directory:
            sln = write_machine(directory)
            project = os.path.join(os.path.dirname(sln), NAME)
            cls.exported["twincat_tsproj"] = twincat_paths(_read(os.path.join(project, f"{NAME}.tsproj")))
            cls.exported["twincat_task"] = twincat_paths(_read(glob.glob(os.path.join(project, "*", "*.TcTTO"))[0]))
            cls.exported["twincat_sln"] = sln_paths(_read(sln))

    def test_every_kind_of_file_is_compared(self):
        self.assertEqual(set(self.facts), set(self.exported))
        self.assertEqual(set(_reference()["sources"]), set(self.facts))

    def test_the_versions_written_are_real_twincat_builds(self):
        builds = _reference()["real_builds"]
        self.assertIn(PRODUCT_VERSION, builds)  # the objects' ProductVersion and the .tsproj's TcVersion
        self.assertIn(PROGRAM_VERSION, builds)  # the .plcproj's ProgramVersion

    def test_what_real_files_carry_is_exported_or_has_a_reason(self):
        for kind, facts in self.facts.items():
            exported = self.exported[kind]
            for path, verdict in facts.items():
                with self.subTest(kind=kind, path=path):
                    if verdict == "exported":
                        self.assertIn(path, exported, "listed as exported but missing from the export")
                    else:
                        self.assertGreater(len(verdict.split()), 3, "a reason says why")
                        below = sorted(p for p in exported if p == path or p.startswith(path + "/"))
                        self.assertEqual(below, [], "exported now: list it as exported")


if __name__ == "__main__":
    unittest.main()
