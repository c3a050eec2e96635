"""The version and the licence of st/library.json reach both exports and CHANGELOG.md, and the licence every
ST file; docs/import.md names no version."""
import os
import unittest

from lxml import etree

from pacst.plcopen_names import XHTML, q
from pacexport.twincat import PRODUCT_VERSION
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

    def test_the_plcopen_project_information_names_the_library_and_asks_for_qualified_access(self):
        # CODESYS's project information: the namespace, title, version and company a library carries, and
        # qualified access as a property of the library (LanguageModelAttribute), so that an import needs
        # no tick and MC_Power cannot clash with SM3_Basic's.
        root = etree.fromstring(support.plcopen_data())
        holder = root.find(f"{q('contentHeader')}/{q('addData')}/{q('data')}/{q('ProjectInformation')}")
        self.assertIsNotNone(holder)
        properties = {p.get("name"): (p.get("type"), p.text) for p in holder.iter(q("property"))}
        self.assertEqual(properties, {
            "Author": ("string", self.info.company), "Company": ("string", self.info.company),
            "DefaultNamespace": ("string", self.info.name), "Description": ("string", self.info.description),
            "LanguageModelAttribute": ("string", "qualified-access-only"), "Title": ("string", self.info.name),
            "Version": ("version", self.info.version + ".0")})
        self.assertEqual(list(properties), sorted(properties))

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



class Licence(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.info = support.library().info
        cls.line = f"(* {cls.info.license_line} *)"

    def test_the_licence_file_is_the_one_named_and_the_readme_names_it(self):
        with open(support.repo_file("LICENSE"), encoding="utf-8") as f:
            self.assertEqual(f.readline().strip(), f"{self.info.license} License")
        with open(support.repo_file("README.md"), encoding="utf-8") as f:
            self.assertIn("[LICENSE](LICENSE)", f.read())

    def test_every_st_file_opens_with_the_licence(self):
        c = support.config()
        for path in [*c["sources"], *c["global_lists"]]:
            with self.subTest(path), open(path, encoding="utf-8") as f:
                self.assertEqual(f.readline().rstrip("\n"), self.line)

    def test_the_plcopen_metadata_names_the_licence(self):
        root = etree.fromstring(support.plcopen_data())
        self.assertIn(self.info.license_line, root.findtext(f"{q('contentHeader')}/{q('Comment')}"))
        self.assertIn(self.info.license_line, root.find(q("fileHeader")).get("contentDescription"))
        self.assertIn(self.info.license_line, root.findtext(f"{q('documentation')}/{{{XHTML}}}xhtml"))
        for pou in root.iter(q("pou")):
            with self.subTest(pou.get("name")):
                doc = pou.findtext(f"{q('interface')}/{q('documentation')}/{{{XHTML}}}xhtml")
                self.assertTrue(doc.startswith(self.info.license_line), doc)

    def test_the_twincat_files_name_the_licence(self):
        root = etree.parse(os.path.join(support.twincat_dir(), f"{self.info.name}.plcproj")).getroot()
        ns = {"m": "http://schemas.microsoft.com/developer/msbuild/2003"}
        self.assertIn(self.info.license_line, root.findtext("m:PropertyGroup/m:Description", namespaces=ns))
        for folder in sorted(os.listdir(support.twincat_dir())):
            if folder.endswith(".plcproj"):
                continue
            for name in os.listdir(os.path.join(support.twincat_dir(), folder)):
                with self.subTest(name):
                    element = etree.parse(os.path.join(support.twincat_dir(), folder, name)).getroot()
                    self.assertEqual(element.get("ProductVersion"), PRODUCT_VERSION)
                    self.assertTrue(element[0].findtext("Declaration").startswith(self.line))


if __name__ == "__main__":
    unittest.main()
