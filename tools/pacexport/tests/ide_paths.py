"""The structure of an XML file as the IDE comparison records it (tests/ide_reference.json): one
path per element and per attribute, from the root, in local names. What depends only on the content
of a library (which types its variables have, how deep its folders nest) is folded, so that the
paths name what a tool writes, not what one project holds:

- `data` of an addData is written data[<last part of its name>] (data[objectid]);
- the variable lists of an interface are one `varList`; a type (`type`, `returnType`, `initialValue`,
  an alias type's `baseType`) ends its path, with its children left out;
- the folders and objects of CODESYS's ProjectStructure are one level deep;
- TwinCAT's option tree in a .plcproj (ProjectExtensions) is cut after the root's own children;
- `#bom` stands for a UTF-8 byte-order mark at the start of the file.

A solution (.sln) is text, not XML: its paths are its header lines, its top-level settings, the type
of each project, and the entries of each global section by kind (the configurations by name).
"""
import re

from lxml import etree

_VAR_LISTS = {"inputVars", "outputVars", "inOutVars", "localVars", "tempVars", "externalVars"}
_TYPE_ENDS = {"type", "returnType", "initialValue"}
_BOM = b"\xef\xbb\xbf"


def _name(element):
    tag = etree.QName(element).localname
    if tag == "data" and element.get("name"):
        return f"data[{element.get('name').rstrip('/').split('/')[-1]}]"
    return "varList" if tag in _VAR_LISTS else tag


def _attributes(element, path):
    skip = {"name"} if path.endswith("]") else set()
    return {f"{path}/@{etree.QName(a).localname}" for a in element.attrib if etree.QName(a).localname not in skip}


def _walk(element, path, out, fold):
    out.add(path)
    out |= _attributes(element, path)
    for child in element:
        if isinstance(child.tag, str):
            child_path = fold(path, _name(child))
            if child_path is not None:
                _walk(child, child_path, out, fold)


def _plcopen_fold(path, name):
    parts = path.split("/")
    if parts[-1] in _TYPE_ENDS:
        return None
    if parts[-1] == "baseType" and parts[-2] == "dataType" and name not in ("enum", "struct"):
        return f"{path}/alias" if not path.endswith("alias") else None
    if path.endswith("/alias"):
        return None
    if "ProjectStructure" in parts and parts[-1] != "ProjectStructure":
        return f"{'/'.join(parts[:parts.index('ProjectStructure') + 1])}/{name}" if name != parts[-1] else path
    return f"{path}/{name}"


def _twincat_fold(path, name):
    parts = path.split("/")
    if "Data" in parts and len(parts) - parts.index("Data") > 2:
        return None
    return f"{path}/{name}"


def _paths(data, fold):
    root = etree.fromstring(data)
    out = {"#bom"} if data.startswith(_BOM) else set()
    _walk(root, _name(root), out, fold)
    return out


def plcopen_paths(data):
    """The folded paths of a PLCopen XML document (bytes)."""
    return _paths(data, _plcopen_fold)


def twincat_paths(data):
    """The folded paths of a TwinCAT file (bytes): an object file, a .plcproj, a .tsproj."""
    return _paths(data, _twincat_fold)


def sln_paths(data):
    """The folded paths of a Visual Studio solution (bytes)."""
    out = {"#bom"} if data.startswith(_BOM) else set()
    section = None
    for line in data.decode("utf-8-sig").splitlines():
        line = line.strip()
        project = re.match(r'Project\("(\{[^}]+\})"\)', line)
        opened = re.match(r"GlobalSection\((\w+)\)", line)
        if line.startswith(("Microsoft Visual Studio Solution File", "# ")):
            out.add(line.split(",")[0])
        elif project:
            out.add(f"Project({project.group(1).upper()})")
        elif opened:
            section = f"Global/GlobalSection({opened.group(1)})"
            out.add(section)
        elif line == "EndGlobalSection":
            section = None
        elif section and " = " in line:
            key = line.split(" = ")[0]
            if key.startswith("{"):  # {project}.<configuration>.ActiveCfg or .Build.0: its kind
                key = re.sub(r"^\{[^}]+\}\.[^|]+\|[^.]+\.", "", key)
            out.add(f"{section}/{key}")
        elif " = " in line:
            out.add(line.split(" = ")[0])
        elif line:
            out.add(line)
    return out
