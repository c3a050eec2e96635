"""Reads a PLCopen XML project back into ST: the round trip that shows the export loses nothing.

Declarations are rebuilt from the structured interface only (variable lists, types, initial
values), never from CODESYS's declaration text, so the round trip checks what every PLCopen
importer reads. Anything this reader does not know is an error, not a guess.
"""
from dataclasses import dataclass
from typing import Optional

from lxml import etree

from .model import SECTION_KEYWORDS
from .plcopen_names import ATTRIBUTES, GLOBAL_VARS, NS, POU_KEYWORDS, XHTML, q
from .types import ELEMENTARY, ArrayType, Derived, Elementary, StringType, type_text


class PlcopenReadError(Exception):
    pass


@dataclass(frozen=True)
class StObject:
    kind: str  # as splitting.SourceObject.kind
    name: str
    declaration: str
    body: Optional[str]


def read_plcopen(data):
    """All objects of a PLCopen XML document (bytes), types first, then POUs, then global lists."""
    root = etree.fromstring(data)
    if root.tag != q("project"):
        raise PlcopenReadError(f"root element is {root.tag}, not a TC6 project in {NS}")
    objects = [_data_type(e) for e in root.iterfind(f"{q('types')}/{q('dataTypes')}/{q('dataType')}")]
    objects += [_pou(e) for e in root.iterfind(f"{q('types')}/{q('pous')}/{q('pou')}")]
    for data in root.iterfind(f"{q('addData')}/{q('data')}"):
        if data.get("name") == GLOBAL_VARS:
            objects += [_global_list(e) for e in data.iterfind(q("globalVars"))]
    return objects


def _local(element):
    return etree.QName(element).localname


def _only_child(element, what):
    children = [c for c in element if isinstance(c.tag, str)]
    if len(children) != 1:
        raise PlcopenReadError(f"{what} holds {len(children)} elements, not one")
    return children[0]


def _xhtml_text(holder):
    xhtml = holder.find(f"{{{XHTML}}}xhtml")
    if xhtml is None:
        raise PlcopenReadError(f"{_local(holder)} without an xhtml element")
    return "".join(xhtml.itertext())


def type_ref(type_holder):
    element = _only_child(type_holder, _local(type_holder))
    tag = _local(element)
    if tag in ELEMENTARY:
        return Elementary(tag)
    if tag in ("string", "wstring"):
        return StringType(tag == "wstring", element.get("length"))
    if tag == "derived":
        return Derived(element.get("name"))
    if tag == "array":
        dims = tuple((d.get("lower"), d.get("upper")) for d in element.iterfind(q("dimension")))
        return ArrayType(dims, type_ref(element.find(q("baseType"))))
    raise PlcopenReadError(f"type element <{tag}> has no ST form in this reader")


def _initial(element):
    holder = element.find(q("initialValue"))
    if holder is None:
        return None
    value = _only_child(holder, "initialValue")
    if _local(value) != "simpleValue":
        raise PlcopenReadError(f"initial value <{_local(value)}> is not a simpleValue")
    return value.get("value")


def _declaration(variable):
    initial = _initial(variable)
    text = f"{variable.get('name')} : {type_text(type_ref(variable.find(q('type'))))}"
    return text if initial is None else f"{text} := {initial}"


def _var_list(element, keyword):
    opener = keyword + (" CONSTANT" if element.get("constant") == "true" else "")
    lines = [opener] + [f"  {_declaration(v)};" for v in element.iterfind(q("variable"))] + ["END_VAR"]
    return "\n".join(lines) + "\n"


def _pou(element):
    name, kind = element.get("name"), element.get("pouType")
    header = f"{POU_KEYWORDS[kind]} {name}"
    interface = element.find(q("interface"))
    blocks = []
    for child in interface:
        tag = _local(child)
        if tag == "returnType":
            header += f" : {type_text(type_ref(child))}"
        elif tag in SECTION_KEYWORDS:
            blocks.append(_var_list(child, SECTION_KEYWORDS[tag]))
        elif tag not in ("addData", "documentation"):
            raise PlcopenReadError(f"{name}: interface element <{tag}> is not read")
    st = element.find(f"{q('body')}/{q('ST')}")
    if st is None:
        raise PlcopenReadError(f"{name}: no ST body")
    return StObject(kind, name, header + "\n" + "".join(blocks), _xhtml_text(st))


def _data_type(element):
    name = element.get("name")
    base = _only_child(element.find(q("baseType")), f"{name}'s baseType")
    tag = _local(base)
    initial = _initial(element)
    suffix = "" if initial is None else f" := {initial}"
    if tag == "enum":
        values = ", ".join(v.get("name") + ("" if v.get("value") is None else f" := {v.get('value')}")
                           for v in base.iterfind(f"{q('values')}/{q('value')}"))
        enum_base = base.find(q("baseType"))
        typed = "" if enum_base is None else f" {type_text(type_ref(enum_base))}"
        text = f"TYPE {name} : ({values}){typed}{suffix};\nEND_TYPE\n"
    elif tag == "struct":
        members = "".join(f"  {_declaration(v)};\n" for v in base.iterfind(q("variable")))
        text = f"TYPE {name} :\nSTRUCT\n{members}END_STRUCT\nEND_TYPE\n"
    else:
        text = f"TYPE {name} : {type_text(type_ref(element.find(q('baseType'))))}{suffix};\nEND_TYPE\n"
    return StObject("dataType", name, text, None)


def _global_list(element):
    pragmas = []
    for data in element.iterfind(f"{q('addData')}/{q('data')}"):
        if data.get("name") == ATTRIBUTES:
            pragmas += [_pragma(a.get("Name"), a.get("Value")) for a in data.iter(q("Attribute"))]
    text = "".join(pragmas) + _var_list(element, "VAR_GLOBAL")
    return StObject("globalVars", element.get("name"), text, None)


def _pragma(name, value):
    return f"{{attribute '{name}' := '{value}'}}\n" if value else f"{{attribute '{name}'}}\n"
