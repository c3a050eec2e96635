"""The export's parts on inputs st/ does not hold today: it must stay right whatever st/ grows into."""
import os
import tempfile
import unittest

from lxml import etree

from pacexport.compare import canonical_items, source_items
from pacexport.cli import export
from pacexport.errors import ExportError
from pacexport.library import load_library
from pacexport.metadata import LibraryInfo
from pacst.plcopen_names import ENUM_VALUE_DOCUMENTATION, OBJECT_ID, PLAIN_TEXT, PROJECT_STRUCTURE, XHTML, q
from pacst.plcopen_read import read_plcopen
from pacexport.schema import load_schema, schema_errors
from pacexport.splitting import split_source
from pacexport.twincat import cdata, guid, relative_path
from pacexport.types import ArrayType, Derived, Elementary, StringType, parse_type, type_text
from tests import support

INFO = LibraryInfo("T_LIB", "Test library", "1.2.3", "2020-01-02", "Nobody", "MIT", "Shapes st/ does not use yet.")

SOURCES = {
    "T_Image.st": "TYPE T_Image : ARRAY[0..7, -1..1] OF BYTE;\nEND_TYPE\n",
    "S_Pair.st": "(* A pair. *)\nTYPE S_Pair :\nSTRUCT\n  a : INT := 3;  (* first *)\n  b, c : T_Image;\n"
                 "  s : STRING(20) := 'x';\nEND_STRUCT;\nEND_TYPE\n",
    "E_Valued.st": "TYPE E_Valued : (VAL_ONE := 1, VAL_TWO := 2) INT := VAL_TWO;\nEND_TYPE\n",
    "T_Name.st": "TYPE T_Name : STRING(10) := 'abc';\nEND_TYPE\n",
    "F_Pick.st": "FUNCTION F_Pick : STRING(20)\nVAR_INPUT\n  Which : BOOL;\nEND_VAR\n"
                 "IF Which THEN\n  F_Pick := 'END_VAR (* not a comment';\nELSE\n  F_Pick := '';\nEND_IF;\n"
                 "END_FUNCTION\n",
    "FB_Shapes.st": "(* Shapes. *)\nFUNCTION_BLOCK FB_Shapes\nVAR_INPUT\n  A, B : INT := -5;\n"
                    "  T : TIME := T#1S;\nEND_VAR\n"
                    "VAR_IN_OUT\n  Pair : S_Pair;\nEND_VAR\nVAR\n  Timer : TON;\nEND_VAR\n"
                    "VAR_TEMP\n  Sum : DINT;\nEND_VAR\n(* END_VAR in a comment *)\nSum := INT_TO_DINT(A + B);\n"
                    "Timer(IN := Sum > 0, PT := T);\nPair.a := A;\nEND_FUNCTION_BLOCK\n",
    "E_Commented.st": "(* Colours. *)\nTYPE E_Commented :\n(\n  RED,  (* stop *)\n  GREEN := 5,  (* go *)\n  BLUE\n);\n"
                      "END_TYPE\n",
    # A global list: the export adds its pragma.
    "GVL_Test.st": "VAR_GLOBAL CONSTANT\n  LIMIT : INT := 10;  (* the limit *)\n"
                   "  NAME : STRING := 'x';\nEND_VAR\n",
}


def _write_sources(directory):
    paths = {}
    for name, text in SOURCES.items():
        paths[name] = os.path.join(directory, name)
        with open(paths[name], "w", encoding="utf-8") as f:
            f.write(text)
    return paths


class Splitting(unittest.TestCase):
    def test_keywords_in_comments_and_strings_do_not_cut(self):
        source = split_source("F_Pick.st", SOURCES["F_Pick.st"])
        self.assertTrue(source.declaration.endswith("  Which : BOOL;\nEND_VAR\n"))
        self.assertTrue(source.body.startswith("IF Which THEN") and source.body.endswith("END_IF;"))

    def test_the_header_comment_is_the_documentation(self):
        self.assertEqual(split_source("S_Pair.st", SOURCES["S_Pair.st"]).doc, "A pair.")

    def test_two_objects_in_a_file_are_refused(self):
        with self.assertRaises(ExportError):
            split_source("x.st", SOURCES["T_Image.st"] + SOURCES["T_Name.st"])

    def test_the_translators_lexer_cuts_and_refuses(self):
        # One lexer (pacst.lexcheck): what the translator refuses, the export refuses, at the same place.
        with self.assertRaisesRegex(ExportError, r"x\.st: 3:3: '//' comment"):
            split_source("x.st", "FUNCTION_BLOCK FB_X\nVAR\n  // no\n  X : INT;\nEND_VAR\nX := 1;\nEND_FUNCTION_BLOCK\n")
        with self.assertRaisesRegex(ExportError, "pragma"):
            split_source("x.st", "{attribute 'hide'}\nTYPE T : INT;\nEND_TYPE\n")

    def test_a_pou_without_a_body_is_refused(self):
        with self.assertRaises(ExportError):
            split_source("x.st", "FUNCTION_BLOCK FB_Empty\nVAR\n  X : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n")


class Types(unittest.TestCase):
    def test_st_spellings_round_trip(self):
        cases = {"UINT": Elementary("UINT"), "STRING(20)": StringType(False, "20"), "WSTRING": StringType(True, None),
                 "TON": Derived("TON"), "ARRAY[0..7, -1..1] OF BYTE":
                     ArrayType((("0", "7"), ("-1", "1")), Elementary("BYTE"))}
        for text, ref in cases.items():
            self.assertEqual(parse_type(text), ref)
            self.assertEqual(type_text(ref), text)
        self.assertEqual(parse_type("TIME_OF_DAY"), Elementary("TOD"))

    def test_types_without_plcopen_form_are_refused(self):
        for text in ("POINTER TO INT", "ARRAY[0..] OF INT", "(A, B)"):
            with self.assertRaises(ValueError, msg=text):
                parse_type(text)


class TwincatText(unittest.TestCase):
    def test_cdata_keeps_a_closing_bracket_sequence(self):
        text = "IF a[b[1]]>0 THEN\n  x := 1;\nEND_IF;"
        element = etree.fromstring(f"<ST>{cdata(text)}</ST>")
        self.assertEqual(element.text, text)

    def test_object_ids_are_stable_and_distinct(self):
        self.assertEqual(guid("POU", "FB_X"), guid("POU", "FB_X"))
        self.assertNotEqual(guid("POU", "FB_X"), guid("POU", "FB_Y"))
        self.assertNotEqual(guid("POU", "FB_X"), guid("DUT", "FB_X"))
        self.assertRegex(guid("POU", "FB_X"), r"^\{[0-9a-f]{8}(-[0-9a-f]{4}){3}-[0-9a-f]{12}\}$")


class UnusedShapes(unittest.TestCase):
    """A small library with a struct, a string alias, a valued enumeration, multi-name declarations,
    VAR_TEMP and a function returning STRING(20), through both exports and back."""

    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.TemporaryDirectory()
        paths = _write_sources(cls.directory.name)
        cls.cache = support.config()["cache"]
        cls.image = paths["T_Image.st"]
        gvl = paths.pop("GVL_Test.st")
        cls.library = load_library(INFO, list(paths.values()), [gvl], cls.cache)
        cls.out = os.path.join(cls.directory.name, "out")
        export(cls.library, cls.out)
        with open(os.path.join(cls.out, "t_lib.xml"), "rb") as f:
            cls.data = f.read()

    @classmethod
    def tearDownClass(cls):
        cls.directory.cleanup()

    def test_the_plcopen_file_is_valid(self):
        self.assertEqual(schema_errors(load_schema(), self.data), [])

    def test_the_round_trip_gives_the_source(self):
        read = read_plcopen(self.data)
        self.assertEqual([r.name for r in read], [o.source.name for o in self.library.objects()])
        for back, obj in zip(read, self.library.objects()):
            with self.subTest(back.name):
                self.assertEqual(
                    canonical_items(self.cache, source_items(back.kind, back.name, back.declaration, back.body), "back"),
                    canonical_items(self.cache, source_items(obj.source.kind, obj.source.name, obj.source.declaration,
                                                             obj.source.body), obj.source.path))

    def test_multi_name_declarations_become_one_variable_each(self):
        root = etree.fromstring(self.data)
        names = [v.get("name") for v in root.iter("{*}variable")]
        self.assertEqual(names.count("A") + names.count("B") + names.count("b") + names.count("c"), 4)

    def test_initial_values_keep_their_spelling(self):
        root = etree.fromstring(self.data)
        values = {v.get("value") for v in root.iter("{*}simpleValue")}
        self.assertLessEqual({"T#1S", "-5", "'x'", "VAL_TWO", "'abc'", "3", "10"}, values)

    def test_the_parses_are_in_the_translators_cache(self):
        with tempfile.TemporaryDirectory() as cache:
            load_library(INFO, [self.image], [], cache)
            self.assertTrue(any(n.startswith("text-") and n.endswith(".pickle") for n in os.listdir(cache)))

    def _object(self, tag, name):
        (element,) = [e for e in etree.fromstring(self.data).iter(q(tag)) if e.get("name") == name]
        return element

    def _data(self, element, name):
        return [d for d in element.iterfind(f"{q('addData')}/{q('data')}") if d.get("name") == name]

    def test_enumeration_value_comments_are_enum_value_documentation(self):
        (data,) = self._data(self._object("dataType", "E_Commented"), ENUM_VALUE_DOCUMENTATION)
        docs = [(v.findtext(q("Name")), "".join(v.find(q("Documentation")).itertext()).strip())
                for v in data.iter(q("EnumValue"))]
        self.assertEqual(docs, [("RED", "stop"), ("GREEN", "go")])

    def test_the_pou_header_is_the_interface_documentation_and_nowhere_else(self):
        pou = self._object("pou", "FB_Shapes")
        self.assertEqual(pou.findtext(f"{q('interface')}/{q('documentation')}/{{{XHTML}}}xhtml"), "Shapes.")
        self.assertIsNone(pou.find(q("documentation")))
        (plain,) = self._data(pou, PLAIN_TEXT)
        self.assertEqual("".join(plain.itertext()).count("Shapes."), 1)

    def test_the_pragma_of_a_global_list_is_written_once(self):
        gvl = self._object("globalVars", "GVL_Test")
        (plain,) = self._data(gvl, PLAIN_TEXT)
        self.assertEqual("".join(plain.itertext()).count("{attribute 'qualified_only'}"), 1)
        self.assertEqual([a.get("Name") for a in gvl.iter(q("Attribute"))], ["qualified_only"])
        (source,) = [g.source for g in self.library.global_lists]
        with open(os.path.join(self.out, "twincat", *relative_path(source).split("/")), encoding="utf-8-sig") as f:
            self.assertEqual(f.read().count("{attribute 'qualified_only'}"), 1)

    def test_the_project_structure_holds_every_object_once_by_its_id(self):
        root = etree.fromstring(self.data)
        ids = {}
        for data in root.iter(q("data")):
            if data.get("name") == OBJECT_ID:
                owner = data.getparent().getparent()
                ids[owner.get("name") or "Library Manager"] = data.findtext(q("ObjectId"))
        (structure,) = [d for d in root.iter(q("data")) if d.get("name") == PROJECT_STRUCTURE]
        listed = {o.get("Name"): o.get("ObjectId") for o in structure.iter(q("Object"))}
        self.assertEqual(len(listed), len(list(structure.iter(q("Object")))))
        self.assertEqual(listed, ids)
        self.assertEqual(set(listed) - {"Library Manager"}, {o.source.name for o in self.library.objects()})
        self.assertEqual(listed["FB_Shapes"], guid("POU", "FB_Shapes").strip("{}"))

    def test_an_object_named_twice_is_refused(self):
        with self.assertRaises(ExportError):
            load_library(INFO, [self.image, self.image], [], self.cache)

    def test_an_initial_array_is_refused(self):
        path = os.path.join(self.directory.name, "FB_Init.st")
        with open(path, "w", encoding="utf-8") as f:
            f.write("FUNCTION_BLOCK FB_Init\nVAR\n  X : T_Image := [1, 2];\nEND_VAR\nX[0, 0] := 1;\n"
                    "END_FUNCTION_BLOCK\n")
        with self.assertRaises(ExportError):
            load_library(INFO, [path], [], self.cache)


class LocatedVariables(unittest.TestCase):
    """A machine program's located variables (pac-test's example, docs/user_tests.md) go out as PLCopen's
    address and come back as AT: the library has none, a program's bus images do."""

    def test_addresses_go_out_and_come_back(self):
        with tempfile.TemporaryDirectory() as directory:
            sources = {"GVL_Io.st": "VAR_GLOBAL\n  CmdIn AT %IB0 : ARRAY [0..7] OF BYTE;  (* the reply *)\n"
                                    "  Lamp AT %QX2.1 : BOOL;\n  Count : INT;\nEND_VAR\n",
                       "MAIN.st": "PROGRAM MAIN\nVAR\n  Button AT %IX0.3 : BOOL;\nEND_VAR\n"
                                  "Count := Count + 1;\nEND_PROGRAM\n"}
            paths = []
            for name, text in sources.items():
                paths.append(os.path.join(directory, name))
                with open(paths[-1], "w", encoding="utf-8") as f:
                    f.write(text)
            library = load_library(INFO, paths, [], support.config()["cache"])
            export(library, os.path.join(directory, "out"))
            with open(os.path.join(directory, "out", "t_lib.xml"), "rb") as f:
                data = f.read()
        self.assertEqual(schema_errors(load_schema(), data), [])
        addresses = {v.get("name"): v.get("address") for v in etree.fromstring(data).iter("{*}variable")}
        self.assertEqual(addresses, {"CmdIn": "%IB0", "Lamp": "%QX2.1", "Count": None, "Button": "%IX0.3"})
        back = "\n".join(obj.declaration for obj in read_plcopen(data))
        for declared in ("CmdIn AT %IB0 :", "Lamp AT %QX2.1 :", "Button AT %IX0.3 :"):
            self.assertIn(declared, back)


if __name__ == "__main__":
    unittest.main()
