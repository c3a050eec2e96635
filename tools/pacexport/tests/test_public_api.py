"""The public API (docs/public_api.md): the page's list, the sources' internal markers and both exports
agree, every type a program needs to call a public block is public, and each row's page names its object."""
import os
import re
import unittest

from lxml import etree

from pacexport.model import INTERNAL_ATTRIBUTES, StructShape, AliasShape
from pacexport.twincat import relative_path
from pacexport.types import ArrayType, Derived
from pacst.plcopen_names import ATTRIBUTES, PLAIN_TEXT, XHTML, q
from tests import support

PAGE = ("docs", "public_api.md")
# A row of the page's tables: | `NAME` | kind | [title](page) |
ROW = re.compile(r"^\|\s*`([A-Za-z_]\w*)`\s*\|\s*([^|]+?)\s*\|\s*\[[^\]]*\]\(([^)#]+)(?:#[^)]*)?\)\s*\|\s*$")
KINDS = {"functionBlock": "function block", "function": "function", "dataType": "type",
         "globalVars": "constant list"}
PIN_SECTIONS = ("inputVars", "outputVars", "inOutVars")
HIDE = "{attribute 'hide'}"


def _type_names(ref):
    if isinstance(ref, Derived):
        return {ref.name}
    if isinstance(ref, ArrayType):
        return _type_names(ref.base)
    return set()


def _page_rows():
    rows = {}
    with open(support.repo_file(*PAGE), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = ROW.match(line.rstrip("\n"))
            if m:
                assert m.group(1) not in rows, f"{PAGE[1]}:{number}: {m.group(1)} listed twice"
                rows[m.group(1)] = (m.group(2), m.group(3), number)
    return rows


class PublicApi(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.library = support.library()
        cls.objects = {o.source.name: o for o in cls.library.objects()}
        cls.public = {n for n, o in cls.objects.items() if not o.source.internal}
        cls.rows = _page_rows()

    def test_the_page_lists_exactly_the_objects_not_marked_internal(self):
        self.assertEqual(sorted(set(self.rows) - self.public), [], "listed, but internal or not in the library")
        self.assertEqual(sorted(self.public - set(self.rows)), [], "public in the sources, missing from the page")

    def test_each_row_says_the_objects_kind(self):
        for name, (kind, _, number) in self.rows.items():
            with self.subTest(name):
                self.assertEqual(kind, KINDS[self.objects[name].source.kind], f"{PAGE[1]}:{number}")

    def test_each_row_links_a_page_that_names_its_object(self):
        for name, (_, link, number) in self.rows.items():
            with self.subTest(name):
                path = support.repo_file("docs", *link.split("/"))
                self.assertTrue(os.path.isfile(path), f"{PAGE[1]}:{number}: {link} does not exist")
                with open(path, encoding="utf-8") as f:
                    named = re.search(rf"\b{name}\b", f.read()) is not None
                self.assertTrue(named, f"{PAGE[1]}:{number}: {link} does not name {name}")

    def test_every_type_a_public_block_or_type_needs_is_public(self):
        """A program declares the types of the pins it wires and of their members: none may be hidden."""
        needed = {}
        for name in self.public:
            obj = self.objects[name]
            refs = []
            if hasattr(obj, "blocks"):
                refs = [v.type for b in obj.blocks if b.section in PIN_SECTIONS for v in b.variables]
                refs += [obj.return_type] if obj.return_type is not None else []
            elif isinstance(getattr(obj, "shape", None), StructShape):
                refs = [m.type for m in obj.shape.members]
            elif isinstance(getattr(obj, "shape", None), AliasShape):
                refs = [obj.shape.type]
            for ref in refs:
                for type_name in _type_names(ref):
                    if type_name in self.objects:
                        needed.setdefault(type_name, set()).add(name)
        hidden = {t: sorted(users) for t, users in needed.items() if t not in self.public}
        self.assertEqual(hidden, {}, "internal types in the interface of public objects")

    def test_the_twincat_files_hide_exactly_the_internal_objects(self):
        twincat = support.twincat_dir()
        for name, obj in self.objects.items():
            with self.subTest(name):
                with open(os.path.join(twincat, *relative_path(obj.source).split("/")),
                          encoding="utf-8-sig") as f:
                    root = etree.fromstring(f.read().encode("utf-8"))
                declaration = root.find(".//Declaration").text
                self.assertEqual(HIDE in declaration, obj.source.internal)

    def test_the_plcopen_export_hides_exactly_the_internal_objects(self):
        root = etree.fromstring(support.plcopen_data())
        seen = set()
        for element in [*root.iter(q("pou")), *root.iter(q("dataType"))]:
            name = element.get("name")
            seen.add(name)
            with self.subTest(name):
                holder = element.find(q("interface")) if element.tag == q("pou") else element
                attributes = [a.get("Name") for d in holder.iterfind(f"{q('addData')}/{q('data')}")
                              if d.get("name") == ATTRIBUTES for a in d.iter(q("Attribute"))]
                internal = self.objects[name].source.internal
                self.assertEqual(attributes, list(INTERNAL_ATTRIBUTES) if internal else [])
                (text,) = ["".join(d.find(f"{q('InterfaceAsPlainText')}/{{{XHTML}}}xhtml").itertext())
                           for d in element.iterfind(f"{q('addData')}/{q('data')}") if d.get("name") == PLAIN_TEXT]
                self.assertEqual(HIDE in text, internal)
        self.assertEqual(seen, {n for n, o in self.objects.items() if o.source.kind != "globalVars"})

    def test_the_global_list_is_public(self):
        for obj in self.library.global_lists:
            self.assertIn(obj.source.name, self.public)


if __name__ == "__main__":
    unittest.main()
