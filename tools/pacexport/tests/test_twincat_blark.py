"""blark, which reads TwinCAT's own files, reads the TwinCAT export back: the project lists every file,
and each file's declaration and implementation parse to what the source declares."""
import os
import unittest

from blark.solution import TwincatPlcProject
from lxml import etree

from pacexport.compare import canonical_items, flatten, parse_item, source_items
from pacexport.twincat import FILE_KINDS, guid
from tests import support


def _files_on_disk(root):
    found = set()
    for folder, _, names in os.walk(root):
        found |= {os.path.relpath(os.path.join(folder, n), root) for n in names}
    return found


class TwincatBlark(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.library = support.library()
        cls.root = support.twincat_dir()
        cls.project = TwincatPlcProject.from_filename(
            os.path.join(cls.root, f"{cls.library.info.name}.plcproj"))
        cls.sources = {s.saved_path.stem: s for s in cls.project.sources}

    def test_the_project_lists_every_file_of_the_folder(self):
        listed = {s.saved_path.as_posix() for s in self.project.sources}
        on_disk = _files_on_disk(self.root) - {f"{self.library.info.name}.plcproj"}
        self.assertEqual(listed, {p.replace(os.sep, "/") for p in on_disk})
        self.assertTrue(all(s.contents is not None for s in self.project.sources))

    def test_the_project_refers_to_the_standard_library(self):
        self.assertIn("Tc2_Standard", self.project.dependencies)
        self.assertEqual(self.project.properties["ProjectVersion"], self.library.info.ide_version)

    def test_every_object_parses_back_to_its_source(self):
        cache = support.cache()
        for obj in self.library.objects():
            name, kind = obj.source.name, obj.source.kind
            with self.subTest(name):
                read = self.sources[name].contents
                self.assertEqual(type(read).__name__, "Tc" + FILE_KINDS[kind][0])
                self.assertEqual(read.name, name)
                exported = canonical_items(cache, read.to_blark(), str(read.filename))
                source = canonical_items(cache, source_items(kind, name, obj.source.declaration, obj.source.body),
                                         obj.source.path)
                self.assertEqual(exported, source)
                self.assertEqual(len(exported), 1 if obj.source.body is None else 2)

    def test_the_global_lists_are_qualified_only(self):
        cache = support.cache()
        for global_list in self.library.global_lists:
            read = self.sources[global_list.source.name].contents
            (item,) = flatten(read.to_blark())
            (node,) = parse_item(cache, item, str(read.filename)).items(comments=True)
            self.assertEqual(node.attribute_pragmas, ["qualified_only"])

    def test_object_ids_follow_from_names_and_differ(self):
        ids = []
        for name, source in self.sources.items():
            element = etree.parse(str(source.local_path)).getroot()[0]
            self.assertEqual(element.get("Id"), guid(element.tag, name))
            ids.append(element.get("Id"))
        self.assertEqual(len(set(ids)), len(ids))

    def test_declarations_and_bodies_are_cdata_with_crlf(self):
        for source in self.sources.values():
            raw = source.raw_contents
            self.assertIn(b"<Declaration><![CDATA[", raw)
            self.assertEqual(raw.count(b"\n"), raw.count(b"\r\n"))
            if source.contents.decl.implementation is not None:
                self.assertIn(b"<ST><![CDATA[", raw)


if __name__ == "__main__":
    unittest.main()
