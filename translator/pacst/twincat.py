"""Reads TwinCAT 3 PLC files for user programs: a `.TcPOU`, `.TcGVL` or `.TcDUT` (XML, the declaration
and the ST body as CDATA) becomes ST text in which every character of the CDATA stands at the line and
column it has in the XML file and everything else is blank, so that errors, `#line` directives and
coverage name the TwinCAT file and the line in it. A `.plcproj` lists the object files of a project.
"""
import os
import re

from lxml import etree

from .errors import StError

OBJECT_EXTENSIONS = (".tcpou", ".tcgvl", ".tcdut")
_CDATA = re.compile(r"<!\[CDATA\[(.*?)\]\]>", re.S)
_COMMENTS = re.compile(r"\(\*.*?\*\)|//[^\n]*|\{[^}]*\}", re.S)
_POU_KEYWORD = re.compile(r"\b(FUNCTION_BLOCK|FUNCTION|PROGRAM)\b", re.I)
# Parts of a TwinCAT object that the portable subset has no place for.
_REFUSED = {"Method": "METHOD", "Action": "ACTION", "Property": "PROPERTY", "Transition": "TRANSITION"}
_OBJECTS = {"POU", "GVL", "DUT"}


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
                                                     "GVL or DUT is expected")
    obj = objects[0]
    for element in obj.iter():
        if isinstance(element.tag, str) and element.tag in _REFUSED:
            raise StError(path, element.sourceline, 1, f"{_REFUSED[element.tag]} {element.get('Name')} of "
                                                       f"{obj.get('Name')} is outside pacst's user programs: "
                                                       "write a FUNCTION_BLOCK or FUNCTION")
    implementation = obj.find("Implementation")
    if implementation is not None:
        languages = [e for e in implementation if isinstance(e.tag, str)]
        if len(languages) != 1 or languages[0].tag != "ST":
            at = languages[0] if languages else implementation
            raise StError(path, at.sourceline, 1, f"{obj.get('Name')} is implemented in "
                                                  f"{at.tag if languages else 'nothing'}: pacst reads ST only")
    st = _blank_outside_cdata(text)
    if obj.tag == "POU":
        declaration = obj.findtext("Declaration") or ""
        m = _POU_KEYWORD.search(_COMMENTS.sub(" ", declaration))
        if m is None:
            raise StError(path, obj.sourceline, 1, f"{obj.get('Name')}: the declaration opens no FUNCTION_BLOCK, "
                                                   "FUNCTION or PROGRAM")
        # TwinCAT keeps the END_... keyword out of the file: it closes the text after the body.
        st += f"\nEND_{m.group(1).upper()}\n"
    return st


def project_files(path):
    """The TwinCAT object files a `.plcproj` compiles, in its order (absolute paths)."""
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
        if is_object_file(include):
            files.append(os.path.normpath(os.path.join(folder, include)))
    return files
