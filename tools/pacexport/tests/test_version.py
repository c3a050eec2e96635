"""The version of st/library.json reaches both exports and CHANGELOG.md; docs/import.md names none."""
import os
import unittest

from lxml import etree

from pacexport.plcopen_names import q
from tests import support


class Version(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.info = support.library().info

    def test_the_plcopen_header_names_the_version_and_its_date(self):
        root = etree.fromstring(support.plcopen_data())
        header = root.find(q("contentHeader"))
        self.assertEqual((header.get("name"), header.get("version")), (self.info.name, self.info.version))
        self.assertEqual(root.find(q("fileHeader")).get("creationDateTime"), f"{self.info.released}T00:00:00")

    def test_the_twincat_project_has_the_ide_version(self):
        path = os.path.join(support.twincat_dir(), f"{self.info.name}.plcproj")
        root = etree.parse(path).getroot()
        ns = {"m": "http://schemas.microsoft.com/developer/msbuild/2003"}
        version = root.findtext("m:PropertyGroup/m:ProjectVersion", namespaces=ns)
        self.assertEqual(version, self.info.version + ".0")
        self.assertRegex(version, r"^\d+\.\d+\.\d+\.\d+$")

    def test_docs_import_names_no_version_a_release_would_leave_stale(self):
        # import.md starts from a release archive, whatever its version (docs/release.md).
        with open(support.repo_file("docs", "import.md"), encoding="utf-8") as f:
            text = f.read()
        self.assertNotIn(f"version {self.info.version}", text)
        self.assertNotIn(f"`{self.info.ide_version}`", text)
        self.assertIn("pa_control-VERSION.zip", text)

    def test_the_changelog_has_the_version_with_its_date(self):
        with open(support.repo_file("CHANGELOG.md"), encoding="utf-8") as f:
            headings = [line.strip() for line in f if line.startswith("## ")]
        self.assertIn(f"## [{self.info.version}] - {self.info.released}", headings)


if __name__ == "__main__":
    unittest.main()
