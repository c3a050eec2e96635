"""The TwinCAT solution around a PLC project (pacexport solution): blark, which reads TwinCAT's
solutions, finds the project, its PLC project, the task object calling the program and every file;
the same input gives the same bytes."""
import filecmp
import os
import tempfile
import unittest

from blark.solution import Solution
from lxml import etree

from pacexport.errors import ExportError
from pacexport.solution import TASK_FILE, write_solution
from tests import support
from tests.fixture_machine import CYCLE_MS, INFO, NAME, write_machine


def _tree(root):
    return sorted(os.path.relpath(os.path.join(d, n), root) for d, _, names in os.walk(root) for n in names)


class SolutionFiles(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.TemporaryDirectory()
        cls.sln = write_machine(cls.directory.name)
        cls.solution = Solution.from_filename(cls.sln)

    @classmethod
    def tearDownClass(cls):
        cls.directory.cleanup()

    def test_blark_finds_the_plc_project_with_every_file(self):
        (project,) = self.solution.projects
        self.assertEqual(project.name, NAME)
        (plc,) = project.load().plcs
        self.assertEqual(plc.name, INFO.name)
        names = {s.saved_path.name for s in plc.sources}
        self.assertEqual(names, {TASK_FILE, "FB_Count.TcPOU", "MAIN.TcPOU"})
        self.assertTrue(all(s.contents is not None for s in plc.sources))

    def test_the_task_calls_the_program_every_cycle(self):
        task = os.path.join(os.path.dirname(self.sln), NAME, INFO.name, TASK_FILE)
        with open(task, "rb") as f:
            raw = f.read()
        self.assertTrue(raw.startswith(b"\xef\xbb\xbf"))
        self.assertEqual(raw.count(b"\n"), raw.count(b"\r\n"))
        root = etree.fromstring(raw)
        self.assertEqual(root.findtext("Task/PouCall/Name"), "MAIN")
        self.assertEqual(int(root.findtext("Task/CycleTime")), CYCLE_MS * 1000)  # microseconds
        tsproj = etree.parse(os.path.join(os.path.dirname(self.sln), NAME, f"{NAME}.tsproj")).getroot()
        (task_node,) = tsproj.iterfind("Project/System/Tasks/Task")
        self.assertEqual(int(task_node.get("CycleTime")), CYCLE_MS * 10000)  # 100 ns
        self.assertEqual(task_node.findtext("Name"), root.find("Task").get("Name"))

    def test_the_tsproj_names_the_plc_project_by_its_guid(self):
        ns = {"m": "http://schemas.microsoft.com/developer/msbuild/2003"}
        plc_dir = os.path.join(os.path.dirname(self.sln), NAME, INFO.name)
        plcproj = etree.parse(os.path.join(plc_dir, f"{INFO.name}.plcproj")).getroot()
        guid = plcproj.findtext("m:PropertyGroup/m:ProjectGuid", namespaces=ns)
        tsproj = etree.parse(os.path.join(os.path.dirname(self.sln), NAME, f"{NAME}.tsproj")).getroot()
        (plc,) = tsproj.iterfind("Project/Plc/Project")
        self.assertEqual(plc.get("GUID"), guid.upper())
        with open(self.sln, encoding="utf-8-sig") as f:
            self.assertIn(guid.upper(), f.read())

    def test_the_same_project_gives_the_same_bytes_and_one_task(self):
        with tempfile.TemporaryDirectory() as again:
            out = os.path.join(again, "solution")
            plc = os.path.join(self.directory.name, "plc")
            write_solution(plc, out, NAME, "MAIN", CYCLE_MS)
            write_solution(os.path.join(out, NAME, INFO.name), out + "2", NAME, "MAIN", CYCLE_MS)
            first = os.path.dirname(self.sln)
            self.assertEqual(_tree(out), _tree(first))
            for name in _tree(first):
                self.assertTrue(filecmp.cmp(os.path.join(out, name), os.path.join(first, name), shallow=False), name)
                self.assertTrue(filecmp.cmp(os.path.join(out + "2", name), os.path.join(first, name),
                                            shallow=False), name)

    def test_a_folder_without_a_plc_project_is_refused(self):
        with tempfile.TemporaryDirectory() as empty:
            with self.assertRaises(ExportError):
                write_solution(empty, os.path.join(empty, "out"), NAME, "MAIN", CYCLE_MS)



class LibrarySolution(unittest.TestCase):
    """The export's TwinCAT library project in a solution of its own: it opens as it is, without a task."""

    def test_blark_finds_the_library_project_with_every_object_and_no_task(self):
        name = support.library().info.name
        sln = os.path.join(support.config()["out"], "twincat-solution", f"{name}.sln")
        (project,) = Solution.from_filename(sln).projects
        (plc,) = project.load().plcs
        listed = {s.saved_path.name for s in plc.sources}
        exported = {os.path.basename(p) for p in _tree(support.twincat_dir())}
        self.assertEqual(listed, exported - {f"{name}.plcproj"})
        self.assertNotIn(TASK_FILE, listed)
        tsproj = etree.parse(os.path.join(os.path.dirname(sln), name, f"{name}.tsproj")).getroot()
        self.assertIsNone(tsproj.find("Project/System"))


if __name__ == "__main__":
    unittest.main()
