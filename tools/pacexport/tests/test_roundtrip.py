"""ST -> PLCopen XML -> ST: the reader rebuilds every declaration from the structured interface alone,
and blark finds it and the body equal to the source."""
import unittest

from lxml import etree

from pacexport.compare import canonical_items, source_items
from pacexport.plcopen_names import PLAIN_TEXT, XHTML, q
from pacst.plcopen_read import read_plcopen
from tests import support


class RoundTrip(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.library = support.library()
        cls.data = support.plcopen_data()
        cls.read = read_plcopen(cls.data)

    def test_the_objects_come_back_in_order(self):
        self.assertEqual([(o.kind, o.name) for o in self.read],
                         [(o.source.kind, o.source.name) for o in self.library.objects()])

    def test_declarations_and_bodies_equal_the_source(self):
        cache = support.cache()
        for read, obj in zip(self.read, self.library.objects()):
            with self.subTest(read.name):
                back = canonical_items(cache, source_items(read.kind, read.name, read.declaration, read.body),
                                       f"{read.name} read from PLCopen")
                source = canonical_items(cache, source_items(obj.source.kind, obj.source.name,
                                                             obj.source.declaration, obj.source.body),
                                         obj.source.path)
                self.assertEqual(back, source)

    def test_the_global_lists_come_back_qualified_only(self):
        lists = [o for o in self.read if o.kind == "globalVars"]
        self.assertTrue(lists)
        for read in lists:
            self.assertTrue(read.declaration.startswith("{attribute 'qualified_only'}\nVAR_GLOBAL CONSTANT\n"))

    def test_the_declaration_text_is_not_needed(self):
        root = etree.fromstring(self.data)
        for data in root.iter(q("data")):
            if data.get("name") == PLAIN_TEXT:
                data.getparent().remove(data)
        self.assertEqual(read_plcopen(etree.tostring(root)), self.read)

    def test_the_declaration_text_is_the_source_with_its_comments(self):
        root = etree.fromstring(self.data)
        texts = ["".join(d.find(f"{q('InterfaceAsPlainText')}/{{{XHTML}}}xhtml").itertext())
                 for d in root.iter(q("data")) if d.get("name") == PLAIN_TEXT]
        expected = [o.declaration for o in self.library.objects()]
        self.assertEqual(sorted(texts), sorted(expected))


if __name__ == "__main__":
    unittest.main()
