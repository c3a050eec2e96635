"""The calling programs of docs/import.md parse and use the library as it is: its types, the pins of
its FBs (every in-out passed), the names of GVL_PAC and of its enumerations."""
import dataclasses
import re
import unittest

from pacst.parsing import parse_text

from pacexport.model import EnumShape
from pacexport.types import Derived, parse_type
from tests import support


def _walk(node):
    """Every node below node; a member after a dot (FieldSelector) is not a name of its own."""
    if dataclasses.is_dataclass(node):
        yield node
        if type(node).__name__ == "FieldSelector":
            return
        for field in dataclasses.fields(node):
            if field.name != "meta":
                yield from _walk(getattr(node, field.name))
    elif isinstance(node, (list, tuple)):
        for item in node:
            yield from _walk(item)


def _pins(pou):
    pins = {}
    for block in pou.blocks:
        for variable in block.variables:
            pins[variable.name.upper()] = block.section
    return pins


class DocsExamples(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(support.repo_file("docs", "import.md"), encoding="utf-8") as f:
            cls.blocks = re.findall(r"```iecst\n(.*?)```", f.read(), re.DOTALL)
        library = support.library()
        cls.fbs = {p.source.name.upper(): _pins(p) for p in library.pous}
        cls.types = {t.source.name.upper() for t in library.data_types} | set(cls.fbs) | {"TON", "R_TRIG"}
        cls.globals = {g.source.name.upper(): {v.name.upper() for v in g.block.variables}
                       for g in library.global_lists}
        cls.enum_values = {name.upper() for t in library.data_types if isinstance(t.shape, EnumShape)
                           for name, _ in t.shape.values}

    def _programs(self):
        for index, code in enumerate(self.blocks):
            for node in parse_text(code, f"docs/import.md example {index + 1}", support.cache()).items(False):
                yield node

    def test_there_are_examples_for_both_ides(self):
        names = [str(p.name) for p in self._programs()]
        self.assertIn("PLC_PRG", names)
        self.assertIn("MAIN", names)

    def test_the_examples_use_the_library_as_declared(self):
        for program in self._programs():
            with self.subTest(str(program.name)):
                instances = self._check_declarations(program)
                self._check_body(program, instances)

    def _check_declarations(self, program):
        instances = {}
        for block in program.declarations:
            for item in block.items:
                ref = parse_type(str(item.init.spec))
                if isinstance(ref, Derived):
                    self.assertIn(ref.name.upper(), self.types, f"unknown type in '{item}'")
                    for variable in item.variables:
                        instances[str(variable.variable.name).upper()] = ref.name.upper()
        return instances

    def _check_body(self, program, instances):
        declared = {str(v.variable.name).upper() for b in program.declarations for i in b.items
                    for v in i.variables}
        for node in _walk(program.body):
            kind = type(node).__name__
            if kind == "FunctionCallStatement" and instances.get(str(node.name).upper()) in self.fbs:
                pins = self.fbs[instances[str(node.name).upper()]]
                given = {str(p.name).upper() for p in node.parameters}
                self.assertEqual({g for g in given if pins.get(g) not in ("inputVars", "inOutVars")}, set(),
                                 f"not an input of {node.name}")
                self.assertLessEqual({p for p, s in pins.items() if s == "inOutVars"}, given,
                                     f"{node.name}: every VAR_IN_OUT must be passed")
            elif kind == "MultiElementVariable":
                owner, field = str(node.name).upper(), str(node.elements[0].field).upper()
                if owner in self.globals:
                    self.assertIn(field, self.globals[owner], f"{owner}.{field}")
                elif instances.get(owner) in self.fbs:
                    self.assertIn(self.fbs[instances[owner]].get(field), ("inputVars", "outputVars"),
                                  f"{owner}.{field}")
            elif kind == "SimpleVariable" and str(node.name).upper().startswith("PAC_"):
                self.assertIn(str(node.name).upper(), self.enum_values | declared, str(node.name))


if __name__ == "__main__":
    unittest.main()
