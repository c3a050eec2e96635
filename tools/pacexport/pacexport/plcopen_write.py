"""Writes the library as one PLCopen XML project for CODESYS's and TwinCAT's PLCopenXML import.

Every object carries both forms of its declaration: the structured interface of TC6 XML (variable
lists with types, initial values and documentation), which any importer reads, and the declaration
as text (CODESYS's InterfaceAsPlainText), with which CODESYS and TwinCAT keep the source's comments
and layout. The rest is where CODESYS 3.5 puts it in its own exports (tests/ide_reference.json lists
what real exports carry): a POU's header comment in interface/documentation (the only structured
place besides the text, so an importer finds it once), an enumeration value's comment in
enumvaluedocumentation, global lists in the project's addData (a library has no configuration), the
st/ folders as projectstructure, the Standard library as the project's library reference.
"""
import re

from lxml import etree

from . import __version__
from .model import AliasShape, EnumShape, StructShape
from pacst.plcopen_names import (ATTRIBUTES, BUILD_PROPERTIES, DISCARDED, ENUM_VALUE_DOCUMENTATION, GLOBAL_VARS,
                            LIBRARIES, NS, OBJECT_ID, PLAIN_TEXT, PROJECT_INFORMATION, PROJECT_STRUCTURE, XHTML, q)
from .splitting import folder_of
from .twincat import guid
from .types import ArrayType, Derived, Elementary, StringType

BOM = b"\xef\xbb\xbf"
# The Library Manager is an object of the POUs view too: its identity, its place in the tree.
LIBRARY_MANAGER = "Library Manager"
# R_TRIG and TON: CODESYS's Standard library, as a new CODESYS project refers to it (placeholder, any version).
STANDARD_LIBRARY = {"Name": "#Standard", "Namespace": "Standard", "HideWhenReferencedAsDependency": "false",
                    "PublishSymbolsInContainer": "false", "SystemLibrary": "false", "LinkAllContent": "false",
                    "DefaultResolution": "Standard, * (System)"}
# The project information as CODESYS keeps it, property by property in name order: what a library's checklist
# asks for, so the namespace does not depend on the name a user gives the project, and qualified access a
# property of the library rather than a tick on each reference (LanguageModelAttribute).
QUALIFIED_ACCESS_ONLY = "qualified-access-only"
# One enumeration value and the comment on its line: PAC_X := 2,  (* why *)
_ENUM_VALUE_LINE = re.compile(r"^\s*([A-Za-z_]\w*)\s*(?::=\s*[^,(]*?)?\s*,?\s*\(\*(.*?)\*\)\s*$")


def plcopen_bytes(library):
    root = _project(library)
    etree.indent(root, space="  ")
    # The declaration as CODESYS writes it (lxml's own uses single quotes), after a byte-order mark as well.
    return BOM + b'<?xml version="1.0" encoding="utf-8"?>\n' + etree.tostring(root, encoding="utf-8",
                                                                             pretty_print=True)


def _el(parent, tag, **attrib):
    return etree.SubElement(parent, q(tag), {k: v for k, v in attrib.items() if v is not None})


def _xhtml(parent, tag, text):
    holder = _el(parent, tag)
    etree.SubElement(holder, f"{{{XHTML}}}xhtml", nsmap={None: XHTML}).text = text
    return holder


def _documentation(parent, text):
    if text:
        _xhtml(parent, "documentation", text)


def _add_data(parent, entries):
    """entries: (name, element-building function) in order; nothing when there are none."""
    if not entries:
        return
    add = _el(parent, "addData")
    for name, build in entries:
        build(_el(add, "data", name=name, handleUnknown="discard" if name in DISCARDED else "implementation"))


def object_id(kind, name):
    """The object's identity in CODESYS: the Id of the same object's TwinCAT file, without braces."""
    return guid(kind, name).strip("{}")


def _object_id(kind, name):
    return OBJECT_ID, lambda data: setattr(etree.SubElement(data, q("ObjectId")), "text", object_id(kind, name))


def _plain_text(declaration):
    return PLAIN_TEXT, lambda data: _xhtml(data, "InterfaceAsPlainText", declaration)


def _attributes(names):
    def build(data):
        holder = _el(data, "Attributes")
        for name in names:
            _el(holder, "Attribute", Name=name, Value="")
    return ATTRIBUTES, build


def _project(library):
    info = library.info
    root = etree.Element(q("project"), nsmap={None: NS})
    _el(root, "fileHeader", companyName=info.company, productName="pacexport", productVersion=__version__,
        creationDateTime=info.timestamp, contentDescription=f"{info.title} {info.version} ({info.license_line})")
    header = _el(root, "contentHeader", name=info.name, version=info.version,
                 modificationDateTime=info.timestamp, organization=info.company, author=info.company, language="en")
    etree.SubElement(header, q("Comment")).text = (f"{info.title} {info.version}: {info.description}\n"
                                                   f"{info.license_line}")
    coordinates = _el(header, "coordinateInfo")
    for language in ("fbd", "ld", "sfc"):
        _el(_el(coordinates, language), "scaling", x="1", y="1")
    _add_data(header, [(PROJECT_INFORMATION, lambda data: _project_information(data, info))])
    types = _el(root, "types")
    data_types = _el(types, "dataTypes")
    for data_type in library.data_types:
        _data_type(data_types, data_type)
    pous = _el(types, "pous")
    for pou in library.pous:
        _pou(pous, pou)
    _el(_el(root, "instances"), "configurations")
    _add_data(root, [(GLOBAL_VARS, lambda data, g=g: _global_list(data, g)) for g in library.global_lists]
              + [(LIBRARIES, lambda data: _libraries(data, info.name)),
                 (PROJECT_STRUCTURE, lambda data: _project_structure(data, library))])
    _documentation(root, f"{info.title} {info.version} ({info.released}). {info.description} {info.license_line}")
    return root


def project_information(info):
    """[(name, type, value)] of the library's project information, in the order CODESYS writes them."""
    return sorted([("Author", "string", info.company), ("Company", "string", info.company),
                   ("DefaultNamespace", "string", info.name), ("Description", "string", info.description),
                   ("LanguageModelAttribute", "string", QUALIFIED_ACCESS_ONLY), ("Title", "string", info.name),
                   ("Version", "version", info.ide_version)])


def _project_information(data, info):
    holder = _el(data, "ProjectInformation")
    for name, kind, value in project_information(info):
        _el(holder, "property", name=name, type=kind).text = value


def _libraries(data, name):
    libraries = _el(data, "Libraries")
    _el(libraries, "Library", **STANDARD_LIBRARY)
    _add_data(libraries, [_object_id(LIBRARY_MANAGER, name)])


def _project_structure(data, library):
    """The st/ folders with their objects in declaration order, and the Library Manager, sorted by name
    as CODESYS lists them."""
    folders = {}
    for obj in library.objects():
        folders.setdefault(folder_of(obj.source), []).append(obj.source)
    structure = _el(data, "ProjectStructure")
    for name in sorted([*folders, LIBRARY_MANAGER], key=str.lower):
        if name == LIBRARY_MANAGER:
            _el(structure, "Object", Name=name, ObjectId=object_id(LIBRARY_MANAGER, library.info.name))
            continue
        folder = _el(structure, "Folder", Name=name)
        for source in folders[name]:
            _el(folder, "Object", Name=source.name, ObjectId=object_id(_id_kind(source.kind), source.name))


def _id_kind(kind):
    return {"dataType": "DUT", "globalVars": "GVL"}.get(kind, "POU")


def type_element(parent, ref):
    if isinstance(ref, Elementary):
        return _el(parent, ref.name)
    if isinstance(ref, StringType):
        return _el(parent, "wstring" if ref.wide else "string", length=ref.length)
    if isinstance(ref, Derived):
        return _el(parent, "derived", name=ref.name)
    assert isinstance(ref, ArrayType)
    array = _el(parent, "array")
    for lower, upper in ref.dimensions:
        _el(array, "dimension", lower=lower, upper=upper)
    type_element(_el(array, "baseType"), ref.base)
    return array


def _initial_value(parent, text):
    if text is not None:
        _el(_el(parent, "initialValue"), "simpleValue", value=text)


def _variables(parent, variables):
    for variable in variables:
        element = _el(parent, "variable", name=variable.name, address=variable.address)
        type_element(_el(element, "type"), variable.type)
        _initial_value(element, variable.initial)
        _documentation(element, variable.doc)


def _var_list(parent, block, tag=None, name=None):
    element = _el(parent, tag or block.section, name=name, constant="true" if block.constant else None)
    _variables(element, block.variables)
    return element


def _data_type(parent, data_type):
    element = _el(parent, "dataType", name=data_type.source.name)
    base = _el(element, "baseType")
    shape = data_type.shape
    if isinstance(shape, EnumShape):
        enum = _el(base, "enum")
        values = _el(enum, "values")
        for name, value in shape.values:
            _el(values, "value", name=name, value=value)
        if shape.base is not None:
            type_element(_el(enum, "baseType"), shape.base)
    elif isinstance(shape, StructShape):
        _variables(_el(base, "struct"), shape.members)
    else:
        assert isinstance(shape, AliasShape)
        type_element(base, shape.type)
    _initial_value(element, data_type.initial)
    entries = []
    if isinstance(shape, EnumShape):
        docs = enum_value_docs(data_type.declaration, [name for name, _ in shape.values])
        if docs:
            entries.append((ENUM_VALUE_DOCUMENTATION, lambda data: _enum_value_documentation(data, docs)))
    name = data_type.source.name
    attributes = [_attributes(data_type.attributes)] if data_type.attributes else []
    _add_data(element, entries + attributes + [_plain_text(data_type.declaration), _object_id("DUT", name)])


def enum_value_docs(declaration, names):
    """[(value name, the comment on its line)] in declaration order."""
    docs = {}
    for line in declaration.splitlines():
        m = _ENUM_VALUE_LINE.match(line)
        if m and m.group(1) in names and m.group(2).strip():
            docs[m.group(1)] = m.group(2).strip()
    return [(n, docs[n]) for n in names if n in docs]


def _enum_value_documentation(data, docs):
    holder = _el(data, "EnumValueDocumentation")
    for name, doc in docs:
        value = _el(holder, "EnumValue")
        _el(value, "Name").text = name
        _xhtml(value, "Documentation", doc)


def _pou(parent, pou):
    source = pou.source
    element = _el(parent, "pou", name=source.name, pouType=source.kind)
    interface = _el(element, "interface")
    if pou.return_type is not None:
        type_element(_el(interface, "returnType"), pou.return_type)
    for block in pou.blocks:
        element_block = _var_list(interface, block)
        _documentation(element_block, block.doc)
    if pou.attributes:  # a POU's pragmas, where CODESYS writes them: in its interface, after the variables
        _add_data(interface, [_attributes(pou.attributes)])
    # The header comment: here, where CODESYS writes it, and not once more as the POU's documentation.
    _documentation(interface, source.doc)
    _xhtml(_el(element, "body"), "ST", source.body)
    _add_data(element, [_plain_text(pou.declaration), _object_id("POU", source.name)])


def _global_list(data, global_list):
    element = _var_list(data, global_list.block, tag="globalVars", name=global_list.source.name)
    _add_data(element, [_attributes(global_list.attributes), (BUILD_PROPERTIES, _link_always),
                        _plain_text(global_list.declaration), _object_id("GVL", global_list.source.name)])


def _link_always(data):
    """A library's global list is linked even where no POU refers to it, as CODESYS marks a GVL."""
    _el(_el(data, "BuildProperties"), "LinkAlways").text = "true"
