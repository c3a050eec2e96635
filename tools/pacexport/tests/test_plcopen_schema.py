"""The PLCopen export is valid TC6 XML (v2.01's schema, from plcrex) in the namespace CODESYS reads."""
import unittest

from lxml import etree

from pacst.plcopen_names import NS, SCHEMA_NS, q
from pacexport.schema import load_schema, schema_errors
from tests import support


class PlcopenSchema(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.schema = load_schema()
        cls.data = support.plcopen_data()

    def test_the_export_is_valid_against_the_schema(self):
        self.assertEqual(schema_errors(self.schema, self.data), [])

    def test_the_root_is_a_project_in_the_namespace_codesys_and_twincat_write(self):
        self.assertEqual(etree.fromstring(self.data).tag, f"{{{NS}}}project")

    def test_the_schema_rejects_a_pou_without_its_type(self):
        root = etree.fromstring(self.data)
        root.find(f".//{q('pou')}").attrib.pop("pouType")
        errors = schema_errors(self.schema, etree.tostring(root))
        self.assertTrue(any("pouType" in e for e in errors), errors)

    def test_the_schema_rejects_a_variable_without_a_type(self):
        root = etree.fromstring(self.data)
        variable = root.find(f".//{q('inputVars')}/{q('variable')}")
        variable.remove(variable.find(q("type")))
        self.assertNotEqual(schema_errors(self.schema, etree.tostring(root)), [])

    def test_a_document_in_the_v201_namespace_is_not_what_the_schema_was_retargeted_to(self):
        retargeted = self.data.replace(NS.encode(), SCHEMA_NS.encode())
        self.assertNotEqual(schema_errors(self.schema, retargeted), [])


if __name__ == "__main__":
    unittest.main()
