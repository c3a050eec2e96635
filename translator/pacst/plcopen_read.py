"""Reads a PLCopen XML project (TC6, as CODESYS and TwinCAT export it, and as the project's own export
`pacexport` writes it) back into ST: one reader for the export's round trip and for pacst's user
programs (`pacst build --user project.xml`).

Declarations are rebuilt from the structured interface only (variable lists, types, initial values,
addresses), never from CODESYS's declaration text, so what is read is what every PLCopen importer reads.
Anything this reader does not know is an error, not a guess.
"""
import os
import re
from dataclasses import dataclass, field
from typing import Optional

from lxml import etree

from .errors import StError, StErrors
from .plcopen_names import (ATTRIBUTES, CODESYS, GLOBAL_VARS, MIXED_ATTRIBUTES, NS, POU_INHERITANCE, POU_KEYWORDS,
                            XHTML, q)

# CODESYS 3.5 and TwinCAT 3.1 write TC6 XML under the namespace of version 2.00 (pacexport too).
# A POU's TRANSITIONs (PLCopen's, or CODESYS's addData): the step conditions of an SFC chart, which pacst does
# not read, so a TRANSITION has nothing to be called from.
_TRANSITION_REFUSED = ("its TRANSITIONs are not read: a TRANSITION is a step condition of an SFC chart, and pacst "
                       "reads no SFC; leave the POU out of the program tested")
# CODESYS's extensions of a POU that this reader refuses (its METHODs and PROPERTYs are read).
_POU_EXTENSIONS = {CODESYS + "action": "ACTIONs are not read from PLCopen XML yet: write a METHOD",
                   CODESYS + "transition": _TRANSITION_REFUSED}

# PLCopen's variable lists and the ST keyword that opens each.
SECTION_KEYWORDS = {"inputVars": "VAR_INPUT", "outputVars": "VAR_OUTPUT", "inOutVars": "VAR_IN_OUT",
                    "localVars": "VAR", "tempVars": "VAR_TEMP", "externalVars": "VAR_EXTERNAL",
                    "globalVars": "VAR_GLOBAL"}
_ELEMENTARY = {"BOOL", "BYTE", "WORD", "DWORD", "LWORD", "SINT", "INT", "DINT", "LINT", "USINT", "UINT",
               "UDINT", "ULINT", "REAL", "LREAL", "TIME", "DATE", "DT", "TOD"}


# The PLCopen XML's and TwinCAT's names of the bodies pacst does not read
_LANGUAGES = {"NWL": "a network list (LD, FBD or IL)", "LD": "LD", "FBD": "FBD", "IL": "IL", "SFC": "SFC",
              "CFC": "CFC"}


class PlcopenReadError(Exception):
    lineno = None  # the line of the XML element refused, where known
    errors = ()  # read_plcopen's: every object's refusal, this one first
    element = None  # the object refused: its pou, dataType or globalVars element, where known


def _at(read, element):
    """`read(element)`, a refusal given the element's line in the XML file and the object's name."""
    try:
        return read(element)
    except PlcopenReadError as exc:
        if exc.lineno is None:
            exc.lineno = element.sourceline
        exc.element = element  # the outermost: the object whose METHOD or body was refused
        name = element.get("name")
        if name and not str(exc).startswith(name):
            exc.args = (f"{name}: {exc}",)
        raise


@dataclass(frozen=True)
class StObject:
    kind: str  # dataType, interface, function, functionBlock, program or globalVars
    name: str
    declaration: str
    body: Optional[str]
    members: str = ""  # its METHODs and ACTIONs as ST, after it (user programs)
    # Where it stands in the XML file, for messages: not part of what the object is (compare=False), so the
    # same objects read from two layouts of one export compare equal.
    xml_line: int = field(default=0, compare=False)  # the object's element in the XML file
    body_xml_line: int = field(default=0, compare=False)  # the line where its ST body starts (0: none)
    # each member body's (first line in `members`, line where it starts in the XML file, its lines)
    member_lines: tuple = field(default=(), compare=False)
    # each variable's (line in `declaration`, line of its <variable> element in the XML file, its name)
    declaration_lines: tuple = field(default=(), compare=False)

    def st(self):
        """The object as the text of one ST file."""
        if self.body is None:
            return self.declaration
        keyword = POU_KEYWORDS[self.kind]
        return f"{self.declaration}{self.body.rstrip()}\nEND_{keyword}\n{self.members}"


def read_plcopen(data):
    """All objects of a PLCopen XML document (bytes), types first, then POUs, then global lists. A refusal is
    a PlcopenReadError at the refused element's line; where several objects are refused, the first, whose
    `errors` holds them all."""
    objects, errors = read_objects(data)
    if errors:
        errors[0].errors = errors
        raise errors[0]
    return objects


def read_objects(data):
    """(the objects read_plcopen reads of a PLCopen XML document, [a PlcopenReadError for each object refused]):
    what is read beside what is refused, for measuring how much of an export user mode takes (pac-test-corpus)."""
    root = etree.fromstring(data)
    if root.tag != q("project"):
        raise PlcopenReadError(f"root element is {root.tag}, not a TC6 project in {NS}")
    errors = []

    def read(reader, elements):
        found = []
        for element in elements:
            try:
                found.append(_at(reader, element))
            except PlcopenReadError as exc:
                errors.append(exc)
        return found

    # A CODESYS export of an application keeps its objects (PLC_PRG, its DUTs, its global lists) in the addData
    # of the configuration's resource, the project's own lists in the project's addData: all of them are read,
    # after the project's types and POUs (types/, first in the file).
    objects = read(_data_type, root.iter(q("dataType")))
    objects += read(_interface, [e for data in root.iter(q("data")) if data.get("name") == _INTERFACES for e in data
                                 if isinstance(e.tag, str)])
    objects += read(_pou, root.iter(q("pou")))
    lists = [e for data in root.iter(q("data")) if data.get("name") == GLOBAL_VARS
             for e in data.iterfind(q("globalVars"))]
    for holder in root.iterfind(f"{q('instances')}/{q('configurations')}/{q('configuration')}"):
        found = list(holder.iterfind(q("globalVars"))) + list(holder.iterfind(f"{q('resource')}/{q('globalVars')}"))
        lists += [e for e in found if e.get("name")]
    objects += read(_global_list, lists)
    return objects, errors


# CODESYS keeps each INTERFACE in an addData of the project, apart from the POUs
_INTERFACES = CODESYS + "interface"


# Where each ST file written by extract() came from: {ST path: (XML path, StObject)}
_ORIGINS = {}


def at_source(err):
    """A refusal in an ST file written from PLCopen XML, given at the XML file's line as CODESYS shows it: the
    body's line, a variable's <variable> element, or the object's element for the rest of its declaration and its
    members' declarations; other refusals unchanged."""
    origin = _ORIGINS.get(os.path.abspath(err.file))
    if origin is None:
        return err
    xml, obj = origin
    line, col = xml_position(xml, obj, err.line, err.col)
    return type(err)(xml, line, col, f"{err.message} (in {obj.name})")  # a warning stays one


def xml_position(xml, obj, st_line, col=1):
    """(line, column) in the XML file `xml` of line `st_line` of the ST file written from its object `obj`: the
    line in the body or in a METHOD's, ACTION's or PROPERTY accessor's body, a variable's <variable> element (of a
    POU's interface or a global list), else the object's element."""
    first = obj.declaration.count("\n") + 1  # the body's first line in the ST file
    spans = []
    if obj.body is not None:
        lines = obj.body.rstrip().count("\n") + 1
        spans.append((first, obj.body_xml_line, lines))
        members = first + lines + 1  # after END_<POU>
        spans += [(members + start - 1, xml_line, n) for start, xml_line, n in obj.member_lines]
    for start, xml_line, n in spans:
        if xml_line and start <= st_line < start + n:
            line = xml_line + st_line - start
            if st_line == start:  # a body's first line follows <xhtml ...> on its XML line
                try:
                    with open(xml, encoding="utf-8", errors="replace") as f:
                        text = f.read().splitlines()[line - 1]
                    col += text.index(">", text.index("<xhtml")) + 1
                except (OSError, IndexError, ValueError):
                    pass
            return line, col
    for decl_line, xml_line, name in obj.declaration_lines:  # a variable's declaration: its <variable> element
        if decl_line == st_line:
            try:
                with open(xml, encoding="utf-8", errors="replace") as f:
                    text = f.read().splitlines()[xml_line - 1]
                return xml_line, text.rindex("<", 0, text.index(f'name="{name}"')) + 1
            except (OSError, IndexError, ValueError):
                return xml_line, 1
    return obj.xml_line or 1, col


def origins(xml_paths):
    """{name of the ST file extract() writes: (XML path, object)} of the PLCopen projects `xml_paths`, for
    pointing at the XML what names an extracted file (a test's failure); unreadable projects left out."""
    found = {}
    for path in xml_paths:
        try:
            with open(path, "rb") as f:
                objects = read_plcopen(f.read())
        except (OSError, etree.XMLSyntaxError, PlcopenReadError):
            continue
        found.update((obj.name + ".st", (path, obj)) for obj in objects)
    return found


def extract(path, out_dir):
    """Write each object of the PLCopen project `path` as `<out_dir>/<name>.st` (a global list's name is its
    file's, as pacst names lists); returns the paths in the project's order. Raises StError."""
    try:
        with open(path, "rb") as f:
            objects = read_plcopen(f.read())
    except (OSError, etree.XMLSyntaxError, PlcopenReadError) as exc:
        refused = [StError(path, getattr(e, "lineno", None) or 1, 1, f"cannot read the PLCopen project: {e}")
                   for e in (getattr(exc, "errors", ()) or [exc])]
        raise (refused[0] if len(refused) == 1 else StErrors(refused)) from None
    return write_objects(path, objects, out_dir)


def write_objects(path, objects, out_dir):
    """Write the `objects` read of the PLCopen project `path` as extract() writes them; returns their paths."""
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for obj in objects:
        target = os.path.join(out_dir, obj.name + ".st")
        text = obj.st()
        try:
            with open(target, encoding="utf-8") as f:
                unchanged = f.read() == text
        except OSError:
            unchanged = False
        if not unchanged:  # an unchanged file keeps its time, so a build recompiles nothing for it
            with open(target, "w", encoding="utf-8") as f:
                f.write(text)
        paths.append(target)
        _ORIGINS[os.path.abspath(target)] = (path, obj)
    return paths


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


def type_text(type_holder):
    """The ST spelling of the type a <type> (or <baseType>) element holds."""
    element = _only_child(type_holder, _local(type_holder))
    tag = _local(element)
    if tag in _ELEMENTARY:
        return tag
    if tag in ("string", "wstring"):
        length = element.get("length")
        return tag.upper() + (f"({length})" if length else "")
    if tag == "derived":
        return element.get("name")
    if tag == "array":
        dims = ", ".join(f"{d.get('lower')}..{d.get('upper')}" for d in element.iterfind(q("dimension")))
        return f"ARRAY[{dims}] OF {type_text(element.find(q('baseType')))}"
    if tag == "pointer":
        return f"POINTER TO {type_text(element.find(q('baseType')))}"
    if tag in ("subrangeSigned", "subrangeUnsigned"):
        bounds = element.find(q("range"))
        return f"{type_text(element.find(q('baseType')))}({bounds.get('lower')}..{bounds.get('upper')})"
    raise PlcopenReadError(f"type element <{tag}> has no ST form in this reader")


def _initial(element):
    holder = element.find(q("initialValue"))
    if holder is None:
        return None
    return _value(_only_child(holder, "initialValue"))


def _value(value):
    """The ST of a PLCopen value: a simpleValue's text, an arrayValue as `[1, 2(0)]`, a structValue as
    `(X := 1.0, Y := 2.0)`, as CODESYS exports a variable's initial value."""
    tag = _local(value)
    if tag == "simpleValue":
        return value.get("value")
    if tag == "arrayValue":
        items = []
        for item in value.iterfind(q("value")):
            text = _value(_only_child(item, "value"))
            repeat = item.get("repetitionValue")
            items.append(f"{repeat}({text})" if repeat and repeat != "1" else text)
        return f"[{', '.join(items)}]"
    if tag == "structValue":
        return "(" + ", ".join(f"{item.get('member')} := {_value(_only_child(item, 'value'))}"
                               for item in value.iterfind(q("value"))) + ")"
    raise PlcopenReadError(f"initial value <{tag}> is not read")


def _declaration(variable):
    initial = _initial(variable)
    address = variable.get("address")
    located = f" AT {address}" if address else ""
    text = f"{variable.get('name')}{located} : {type_text(variable.find(q('type')))}"
    return text if initial is None else f"{text} := {initial}"


def _var_list(element, keyword):
    """The ST blocks of a variable list: one, or where CODESYS wrote a VAR_IN_OUT's ARRAY[*] into it, the runs of
    the list's variables around it and a VAR_IN_OUT block for it, in the list's order."""
    opener = keyword + "".join(f" {a.upper()}" for a in ("constant", "retain", "persistent")
                               if element.get(a) == "true")
    runs = []
    for v in element.iterfind(q("variable")):
        varlen = _variable_length_array(v)
        block, text = ("VAR_IN_OUT", f"{v.get('name')} : {varlen}") if varlen else (opener, _declaration(v))
        if not runs or runs[-1][0] != block:
            runs.append((block, []))
        runs[-1][1].append(f"  {text};")
    return "".join("\n".join([block, *lines, "END_VAR"]) + "\n" for block, lines in runs or [(opener, [])])


# CODESYS's export of a VAR_IN_OUT `ARRAY[*] OF T`: a POINTER TO T whose attributes keep the array's type and the
# list it was declared in ("Inout"), and which the export writes among the inputs. One declared in a VAR_INPUT
# ("Input") is exported the same way, a pointer to the caller's array: read as a VAR_IN_OUT too (open_points.md)
_VARLEN_SCOPES = {"Inout", "Input"}


def _variable_length_array(variable):
    """The `ARRAY[*] OF T` CODESYS exported as a pointer in `variable`'s attributes, or None."""
    found = {a.get("Name"): a.get("Value") for data in variable.iterfind(f"{q('addData')}/{q('data')}")
             if data.get("name") == ATTRIBUTES for a in data.iter(q("Attribute"))}
    varlen = found.get("variable_length_array")
    if varlen is None:
        return None
    scope = found.get("variable_length_array_original_scope")
    if scope not in _VARLEN_SCOPES:
        exc = PlcopenReadError(f"{variable.get('name')}: an {varlen} in the list CODESYS calls '{scope}' is not "
                               "read: pacst takes an ARRAY[*] in VAR_IN_OUT (or VAR_INPUT) only; declare it there")
        exc.lineno = variable.sourceline
        raise exc
    return varlen


def _interface(element):
    """An INTERFACE of CODESYS's export (an <Interface> with its <Methods>: each METHOD's interface, no body) as
    ST, the INTERFACE and then its METHODs, as an INTERFACE's ST file holds them. What else an <Interface> holds
    (a PROPERTY, a base INTERFACE) is refused at its line: no export of one has shown its form."""
    if _local(element) != "Interface":
        raise PlcopenReadError(f"<{_local(element)}> in CODESYS's INTERFACE data is not read")
    name = element.get("name")
    text, lines = f"INTERFACE {name}\nEND_INTERFACE\n", []
    for child in element:
        if not isinstance(child.tag, str) or _local(child) == "documentation":
            continue
        if _local(child) == "Methods":
            for method in (m for m in child if isinstance(m.tag, str)):
                method_text, method_lines = _interface_method(method, name)
                lines += [(text.count("\n") + line, xml_line, what) for line, xml_line, what in method_lines]
                text += method_text
        elif _local(child) == "addData":
            for data in (d for d in child if isinstance(d.tag, str) and d.get("handleUnknown") != "discard"):
                _refuse_in_interface(data, f"the data {data.get('name')}")
        else:
            _refuse_in_interface(child, f"<{_local(child)}>")
    return StObject("interface", name, text, None, xml_line=element.sourceline or 0, declaration_lines=tuple(lines))


def _interface_method(element, interface):
    """(an INTERFACE's METHOD as ST, after an empty line, [(line in that text, line in the XML file, name)] of its
    heading, at its <Method> element, and of its variables, at their <variable> elements)."""
    if _local(element) != "Method":
        _refuse_in_interface(element, f"<{_local(element)}> among its METHODs")
    name = element.get("name")
    header, blocks = _interface_text(element, f"METHOD {name}", interface)
    text = f"\n{header}\n{''.join(blocks)}END_METHOD\n"
    holder = element.find(q("interface"))
    variables = [v for section in (holder if holder is not None else []) if _local(section) in SECTION_KEYWORDS
                 for v in section.iterfind(q("variable"))]
    return text, [(2, element.sourceline, name), *_variable_lines(text, variables)]


def _refuse_in_interface(element, what):
    exc = PlcopenReadError(f"{what} of an INTERFACE is not read from PLCopen XML (its METHODs are): give this "
                           "INTERFACE to pac-test as an ST file of its own")
    exc.lineno = element.sourceline
    raise exc


def _pou(element):
    name, kind = element.get("name"), element.get("pouType")
    transition = element.find(f"{q('transitions')}/{q('transition')}")
    if transition is not None:
        exc = PlcopenReadError(f"{name}: {_TRANSITION_REFUSED}")
        exc.lineno = transition.sourceline
        raise exc
    members, spans = [], []

    def add(read, member):
        text, found = _at(read, member)
        offset = sum(m.count("\n") for m in members)
        spans.extend((offset + start, xml_line, n) for start, xml_line, n in found)
        members.append(text)

    for action in element.iterfind(f"{q('actions')}/{q('action')}"):  # a user program's ACTIONs
        add(lambda a: _member_text(f"ACTION {a.get('name')} :", [], a, name, "END_ACTION"), action)
    for data in element.iterfind(f"{q('addData')}/{q('data')}"):
        if data.get("name") == CODESYS + "method":  # CODESYS keeps a POU's METHODs in its addData
            for m in data:
                if isinstance(m.tag, str):
                    add(_method, m)
        elif data.get("name") == CODESYS + "property":  # and its PROPERTYs, each with a Get and a Set
            for p in data:
                if isinstance(p.tag, str):
                    add(_property, p)
        elif data.get("name") in _POU_EXTENSIONS:
            raise PlcopenReadError(f"{name}: {_POU_EXTENSIONS[data.get('name')]}")
    header, blocks = _interface_text(element, f"{POU_KEYWORDS[kind]} {name}", name)
    xhtml = element.find(f"{q('body')}/{q('ST')}/{{{XHTML}}}xhtml")
    declaration = header + "\n" + "".join(blocks)
    interface = element.find(q("interface"))
    variables = [v for child in (interface if interface is not None else []) if _local(child) in SECTION_KEYWORDS
                 for v in child.iterfind(q("variable"))]
    return StObject(kind, name, declaration, _st_body(element, name), "".join(members),
                    element.sourceline or 0, xhtml.sourceline if xhtml is not None else 0, tuple(spans),
                    _variable_lines(declaration, variables))


def _variable_lines(text, variables):
    """((line of `text`, line of the XML file, name), ...): where each of the <variable> elements `variables` is
    declared in the ST `text` that _var_list wrote (a line `  Name : ...`), matched by its name."""
    where = {}
    for v in variables:
        if v.get("name") and v.sourceline:
            where.setdefault(v.get("name").upper(), (v.sourceline, v.get("name")))
    found = []
    for n, line in enumerate(text.split("\n"), 1):
        m = re.match(r"  (\w+)\b", line)
        if m and m.group(1).upper() in where:
            found.append((n, *where[m.group(1).upper()]))
    return tuple(found)


def _member_text(header, blocks, holder, name, end):
    """(the ST of a METHOD, ACTION or PROPERTY accessor whose ST body `holder` holds, [(its body's first line in
    that text, the line where the body starts in the XML file, its lines)])."""
    body = _st_body(holder, name).rstrip()
    text = f"{header}\n{''.join(blocks)}{body}\n{end}\n"
    xhtml = holder.find(f"{q('body')}/{q('ST')}/{{{XHTML}}}xhtml")
    first = header.count("\n") + "".join(blocks).count("\n") + 2
    return text, [(first, xhtml.sourceline, body.count("\n") + 1)] if xhtml is not None and xhtml.sourceline else []


def _method(element):
    """A METHOD of CODESYS's export (its own interface and ST body) as ST, and where its body is."""
    name = element.get("name") or element.get("Name")
    header, blocks = _interface_text(element, f"METHOD {name}", name)
    return _member_text(header, blocks, element, name, "END_METHOD")


def _property(element):
    """A PROPERTY of CODESYS's export (its type, and a GetAccessor and a SetAccessor with their own interface
    and ST body) as ST: the PROPERTY, then PROPERTY Name.Get and PROPERTY Name.Set."""
    name = element.get("name") or element.get("Name")
    header, blocks = _interface_text(element, f"PROPERTY {name}", name)
    text, spans = f"{header}\n{''.join(blocks)}END_PROPERTY\n", []
    result = header[len(f"PROPERTY {name}"):]  # ' : T'
    for tag, accessor in (("GetAccessor", "Get"), ("SetAccessor", "Set")):
        for part in element.iterfind(q(tag)):
            part_header, part_blocks = _interface_text(part, f"PROPERTY {name}.{accessor}{result}", name)
            part_text, found = _member_text(part_header, part_blocks, part, name, "END_PROPERTY")
            spans += [(text.count("\n") + start, xml_line, n) for start, xml_line, n in found]
            text += part_text
    return text, spans


def _st_body(element, name):
    st = element.find(f"{q('body')}/{q('ST')}")
    if st is None:
        body = element.find(q("body"))
        found = [e for e in body if isinstance(e.tag, str)] if body is not None else []
        if not found:
            raise PlcopenReadError(f"{name}: no ST body")
        language = found[0].tag.rsplit("}", 1)[-1]
        exc = PlcopenReadError(f"{name} is implemented in {_LANGUAGES.get(language, language)}: pacst reads ST "
                               "only; write its body in ST, or leave the POU out of the program tested")
        exc.lineno = found[0].sourceline
        raise exc
    return _xhtml_text(st)


def _interface_text(element, header, name):
    """(the heading with the result type, the variable blocks) of a POU's or METHOD's interface."""
    interface = element.find(q("interface"))
    blocks = []
    for child in interface if interface is not None else []:
        tag = _local(child)
        if tag == "returnType":
            header += f" : {type_text(child)}"
        elif tag in SECTION_KEYWORDS:
            blocks.append(_var_list(child, SECTION_KEYWORDS[tag]))
        elif tag == "addData":
            header += _inheritance(child)
        elif tag != "documentation":
            raise PlcopenReadError(f"{name}: interface element <{tag}> is not read")
    return header, blocks


def _inheritance(add_data):
    """` EXTENDS Base IMPLEMENTS I_A, I_B` of CODESYS's pouinheritance in an interface's addData, or ''."""
    text = ""
    for data in add_data.iterfind(q("data")):
        inheritance = data.find(q("Inheritance")) if data.get("name") == POU_INHERITANCE else None
        if inheritance is None:
            continue
        extends = [(e.text or "").strip() for e in inheritance.iterfind(q("Extends"))]
        implements = [(e.text or "").strip() for e in inheritance.iterfind(q("Implements"))]
        text += "".join(f" EXTENDS {e}" for e in extends if e)
        text += (" IMPLEMENTS " + ", ".join(i for i in implements if i)) if any(implements) else ""
    return text


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
        typed = "" if enum_base is None else f" {type_text(enum_base)}"
        text = f"TYPE {name} : ({values}){typed}{suffix};\nEND_TYPE\n"
    elif tag == "struct":
        members = "".join(f"  {_declaration(v)};\n" for v in base.iterfind(q("variable")))
        text = f"TYPE {name} :\nSTRUCT\n{members}END_STRUCT\nEND_TYPE\n"
    else:
        text = f"TYPE {name} : {type_text(element.find(q('baseType')))}{suffix};\nEND_TYPE\n"
    # the attributes pacst reads of a type (a CODESYS application's DUTs are qualified_only by default)
    pragmas = [_pragma(n, None) for n in _attribute_names(element) if n in ("qualified_only", "strict")]
    return StObject("dataType", name, "".join(pragmas) + text, None, xml_line=element.sourceline or 0)


def _attribute_names(element):
    return [a.get("Name") for data in element.iterfind(f"{q('addData')}/{q('data')}")
            if data.get("name") == ATTRIBUTES for a in data.iter(q("Attribute"))]


def _global_list(element):
    pragmas = []
    for data in element.iterfind(f"{q('addData')}/{q('data')}"):
        if data.get("name") == ATTRIBUTES:
            pragmas += [_pragma(a.get("Name"), a.get("Value")) for a in data.iter(q("Attribute"))]
    # CODESYS writes a list of several blocks (VAR_GLOBAL, VAR_GLOBAL CONSTANT, RETAIN) as one list of all its
    # variables, and the blocks, each with its attributes, in its MixedAttrsVarList
    blocks = [g for data in element.iterfind(f"{q('addData')}/{q('data')}") if data.get("name") == MIXED_ATTRIBUTES
              for g in data.iterfind(f"{q('MixedAttrsVarList')}/{q('globalVars')}")]
    text = "".join(pragmas) + "".join(_var_list(b, "VAR_GLOBAL") for b in blocks or [element])
    return StObject("globalVars", element.get("name"), text, None, xml_line=element.sourceline or 0,
                    declaration_lines=_variable_lines(text, element.iterfind(q("variable"))))


def _pragma(name, value):
    return f"{{attribute '{name}' := '{value}'}}\n" if value else f"{{attribute '{name}'}}\n"
