"""Reads TwinCAT 3 PLC files for user programs: a `.TcPOU`, `.TcGVL` or `.TcDUT` (XML, the declaration
and the ST body as CDATA) becomes ST text in which every character of the CDATA stands at the line and
column it has in the XML file and everything else is blank, so that errors, `#line` directives and
coverage name the TwinCAT file and the line in it. A `.plcproj` lists the object files of a project.
"""
import os
import re

from lxml import etree

from .errors import StError

# a .TcTLEO is an enumeration with a text list (TwinCAT's EnumerationTextList): its TYPE is read as a .TcDUT's
OBJECT_EXTENSIONS = (".tcpou", ".tcgvl", ".tcdut", ".tcio", ".tctleo")
_CDATA = re.compile(r"<!\[CDATA\[(.*?)\]\]>", re.S)
_COMMENTS = re.compile(r"\(\*.*?\*\)|//[^\n]*|\{[^}]*\}", re.S)
_POU_KEYWORD = re.compile(r"\b(FUNCTION_BLOCK|FUNCTION|PROGRAM)\b", re.I)
# Parts of a TwinCAT object that pacst does not translate (METHODs and ACTIONs it does: _members).
_REFUSED = {"Transition": "TRANSITION"}
# TwinCAT keeps LD, FBD and IL as a network list (NWL)
_LANGUAGES = {"NWL": "a network list (LD, FBD or IL)", "SFC": "SFC", "CFC": "CFC", "LD": "LD", "FBD": "FBD"}
_MEMBERS = {"Method": "METHOD", "Action": "ACTION", "Property": "PROPERTY"}
_PROPERTY = re.compile(r"PROPERTY\s+(?:(?:PUBLIC|PRIVATE|PROTECTED|INTERNAL|FINAL|ABSTRACT)\s+)*(\w+)\s*:\s*"
                       r"([^\r\n;]*?)\s*;?\s*$", re.I | re.M)
_OBJECTS = {"POU", "GVL", "DUT", "Itf", "EnumerationTextList"}


def is_object_file(path):
    return path.lower().endswith(OBJECT_EXTENSIONS)


def _xml(text, path):
    try:
        return etree.fromstring(text.encode("utf-8"), etree.XMLParser(resolve_entities=False))
    except etree.XMLSyntaxError as exc:
        line, col = exc.position if exc.position else (1, 1)
        raise StError(path, line or 1, (col or 0) + 1, f"not a well-formed TwinCAT file: {exc.msg}") from None


def _blank_outside_cdata(text):
    """`text` with every character outside its CDATA sections blank, line ends kept."""
    out, at = [], 0
    for m in _CDATA.finditer(text):
        out.append(re.sub(r"[^\n]", " ", text[at:m.start(1)]))
        out.append(m.group(1))
        at = m.end(1)
    out.append(re.sub(r"[^\n]", " ", text[at:]))
    return "".join(out)


def object_st(text, path):
    """The ST of one TwinCAT object file, positioned as in the file; raises StError on what pacst does not
    read (METHODs, ACTIONs, PROPERTYs, a body in another language than ST)."""
    root = _xml(text, path)
    objects = [e for e in root if isinstance(e.tag, str) and e.tag in _OBJECTS]
    if root.tag != "TcPlcObject" or len(objects) != 1:
        raise StError(path, root.sourceline or 1, 1, "not a TwinCAT object file: a TcPlcObject with one POU, "
                                                     "GVL, DUT or Itf is expected")
    obj = objects[0]
    for element in obj.iter():
        if isinstance(element.tag, str) and element.tag in _REFUSED:
            raise StError(path, element.sourceline, 1, f"{_REFUSED[element.tag]} {element.get('Name')} of "
                                                       f"{obj.get('Name')} is outside pacst's user programs "
                                                       "(docs/user_dialect.md)")
    parts = [e for e in obj if isinstance(e.tag, str) and e.tag in _MEMBERS]
    parts += [g for e in parts if e.tag == "Property" for g in e if isinstance(g.tag, str) and g.tag in ("Get", "Set")]
    for holder in [obj] + parts:
        implementation = holder.find("Implementation")
        if implementation is not None:
            languages = [e for e in implementation if isinstance(e.tag, str)]
            if len(languages) != 1 or languages[0].tag != "ST":
                at = languages[0] if languages else implementation
                language = _LANGUAGES.get(at.tag, at.tag) if languages else "nothing"
                raise StError(path, at.sourceline, 1, f"{holder.get('Name')} is implemented in {language}: pacst "
                                                      "reads ST only; write its body in ST, or leave the POU out of "
                                                      "the program tested")
    st = _blank_outside_cdata(text)
    if obj.tag == "Itf":  # a .TcIO: the INTERFACE, then its METHODs' and PROPERTYs' declarations
        if any(isinstance(e.tag, str) and e.tag in _MEMBERS for e in obj):
            return _members(text, st, "END_INTERFACE", path)
        return st + "\nEND_INTERFACE\n"
    if obj.tag == "POU":
        declaration = obj.findtext("Declaration") or ""
        m = _POU_KEYWORD.search(_COMMENTS.sub(" ", declaration))
        if m is None:
            raise StError(path, obj.sourceline, 1, f"{obj.get('Name')}: the declaration opens no FUNCTION_BLOCK, "
                                                   "FUNCTION or PROGRAM")
        end = f"END_{m.group(1).upper()}"
        if any(isinstance(e.tag, str) and e.tag in _MEMBERS for e in obj):
            return _members(text, st, end, path)
        # TwinCAT keeps the END_... keyword out of the file: it closes the text after the body.
        st += f"\n{end}\n"
    return st


def _members(text, st, end, path):
    """The ST of a POU with METHODs and ACTIONs (their <Method> and <Action> elements after the POU's
    <Implementation>): the END_ keywords TwinCAT leaves out, and an ACTION's heading, written into blank
    space between the CDATA sections, so that every line keeps its place."""
    chars = list(st)
    members = list(re.finditer(r"<(Method|Action|Property)\b[^>]*>", text))
    _write(chars, _last_cdata_end(text, members[0].start()), members[0].end(), end, path, members[0].start())
    for i, m in enumerate(members):
        close = text.find(f"</{m.group(1)}>", m.end())
        if m.group(1) == "Property":
            _property(text, chars, m, close, path)
            continue
        if m.group(1) == "Action":
            name = re.search(r'\bName="([^"]*)"', m.group(0))
            _write(chars, m.start(), _next_cdata_start(text, m.end()), f"ACTION {name.group(1) if name else ''} :",
                   path, m.start())
        _write(chars, _last_cdata_end(text, close), close + len(m.group(1)) + 3, f"END_{_MEMBERS[m.group(1)]}",
               path, close)
    return "".join(chars)


def _property(text, chars, m, close, path):
    """A <Property>: its declaration closed with END_PROPERTY, and each <Get> and <Set> written as
    `PROPERTY Name.Get : T ... END_PROPERTY` (pacst's form of the accessors, docs/user_dialect.md)."""
    declaration = _CDATA.search(text, m.end(), close)
    found = _PROPERTY.search(declaration.group(1)) if declaration else None
    if found is None:
        line = text.count("\n", 0, m.start()) + 1
        raise StError(path, line, 1, "a PROPERTY's declaration is `PROPERTY Name : Type`")
    name, type_text = found.group(1), found.group(2)
    accessors = list(re.finditer(r"<(Get|Set)\b[^>]*>", text[:close]))
    accessors = [a for a in accessors if a.start() > m.end()]
    first = accessors[0].end() if accessors else close + len("</Property>")
    after = _write(chars, declaration.end(), first, "END_PROPERTY", path, declaration.end())
    for a in accessors:
        a_close = text.find(f"</{a.group(1)}>", a.end())
        heading = f"PROPERTY {name}.{a.group(1)} : {type_text}"
        try:
            _write(chars, a.start(), _next_cdata_start(text, a.end()), heading, path, a.start())
        except StError:  # a heading longer than the <Get> tag: the blanks before it too, after what was written
            _write(chars, max(after, text.rfind("\n", 0, a.start()) + 1), _next_cdata_start(text, a.end()), heading,
                   path, a.start())
        after = _write(chars, _last_cdata_end(text, a_close), a_close + len(a.group(1)) + 3, "END_PROPERTY", path,
                       a_close)


def _last_cdata_end(text, before):
    found = [m.end() for m in _CDATA.finditer(text, 0, before)]
    return found[-1] if found else 0


def _next_cdata_start(text, after):
    m = _CDATA.search(text, after)
    return m.start() if m else len(text)


def _write(chars, start, end, word, path, at):
    """`word` into a run of blanks of chars[start:end] on one line, a blank kept on both sides; the index after it."""
    need = len(word) + 2
    run = 0
    for i in range(start, end):
        run = run + 1 if chars[i] == " " else 0
        if run >= need:
            first = i - need + 2
            chars[first:first + len(word)] = word
            return first + len(word)
    line = "".join(chars[:at]).count("\n") + 1
    raise StError(path, line, 1, f"no room to close {word.split()[0]} in this TwinCAT file: put the element's "
                                 "tags on lines of their own")


def project_files(path, generated=True):
    """The TwinCAT object files a `.plcproj` compiles, in its order (absolute paths). Without `generated`, not
    the POUs TwinCAT generates into a library project (its "Project Information": F_GetVersion, F_GetTitle...,
    marked SystemCall), which every library project declares and a program calls under the library's namespace
    only: read as a library of the program, they would clash with the program's own or another library's."""
    with open(path, "rb") as f:
        data = f.read()
    try:
        root = etree.fromstring(data)
    except etree.XMLSyntaxError as exc:
        raise StError(path, 1, 1, f"not a well-formed TwinCAT project: {exc.msg}") from None
    folder = os.path.dirname(os.path.abspath(path))
    files = []
    for element in root.iter("{*}Compile"):
        include = element.get("Include", "").replace("\\", "/")
        system_call = (element.findtext("{*}SystemCall") or "").strip().lower() == "true"
        if is_object_file(include) and (generated or not system_call):
            files.append(os.path.normpath(os.path.join(folder, include)))
    return files
