"""Writes the library as TwinCAT 3 PLC files: a .TcDUT per type, a .TcPOU per POU, a .TcGVL per global
list, and a .plcproj that lists them.

The files have the form TwinCAT writes: declaration and implementation as CDATA, CRLF line ends,
and an object Id that is a UUID derived from the object's name, so that the same object keeps its
Id from build to build and from version to version (TwinCAT matches objects by it).
"""
import os
import uuid
from xml.sax.saxutils import escape, quoteattr

OBJECT_VERSION = "1.1.0.1"  # the TcPlcObject format of TwinCAT 3.1
PRODUCT_VERSION = "3.1.4024.0"  # the oldest TwinCAT 3.1 build the files are meant for
_NAMESPACE = uuid.uuid5(uuid.NAMESPACE_URL, "urn:pa-control-plc:pacexport")

# Folder and file kind of each object kind; the folders are the ones a new TwinCAT PLC project has.
FILE_KINDS = {
    "dataType": ("DUTs", "DUT", ".TcDUT"),
    "function": ("POUs", "POU", ".TcPOU"),
    "functionBlock": ("POUs", "POU", ".TcPOU"),
    "program": ("POUs", "POU", ".TcPOU"),
    "globalVars": ("GVLs", "GVL", ".TcGVL"),
}
# R_TRIG, TON and the other standard function blocks.
LIBRARY_REFERENCES = ("Tc2_Standard",)


def guid(kind, name):
    return "{" + str(uuid.uuid5(_NAMESPACE, f"{kind}:{name}")) + "}"


def cdata(text):
    """A CDATA section holding text; a ']]>' in the text is split over two sections."""
    return "<![CDATA[" + text.replace("]]>", "]]]]><![CDATA[>") + "]]>"


def object_file(kind, name, declaration, body):
    """The text of one TwinCAT object file (LF line ends; write_twincat makes them CRLF)."""
    _, tag, _ = FILE_KINDS[kind]
    special = ' SpecialFunc="None"' if tag == "POU" else ""
    lines = ['<?xml version="1.0" encoding="utf-8"?>',
             f'<TcPlcObject Version="{OBJECT_VERSION}" ProductVersion="{PRODUCT_VERSION}">',
             f'  <{tag} Name={quoteattr(name)} Id="{guid(tag, name)}"{special}>',
             f"    <Declaration>{cdata(declaration)}</Declaration>"]
    if body is not None:
        lines += ["    <Implementation>", f"      <ST>{cdata(body)}</ST>", "    </Implementation>"]
    lines += [f"  </{tag}>", "</TcPlcObject>"]
    return "\n".join(lines) + "\n"


def relative_path(kind, name):
    folder, _, extension = FILE_KINDS[kind]
    return f"{folder}/{name}{extension}"


def project_file(library, paths):
    info = library.info
    ids = {key: guid("project", f"{info.name}:{key}") for key in (
        "ProjectGuid", "Application", "TypeSystem", "Implicit_Task_Info", "Implicit_KindOfTask",
        "Implicit_Jitter_Distribution", "LibraryReferences")}
    properties = [("FileVersion", "1.0.0.0"), ("SchemaVersion", "2.0"), ("ProjectGuid", ids["ProjectGuid"]),
                  ("SubObjectsSortedByName", "True"), ("DownloadApplicationInfo", "true"),
                  ("WriteProductVersion", "true"), ("GenerateTpy", "false"), ("Name", info.name),
                  ("ProgramVersion", PRODUCT_VERSION)]
    properties += [(k, v) for k, v in ids.items() if k != "ProjectGuid"]
    properties += [("Company", info.company), ("Title", info.name), ("ProjectVersion", info.ide_version),
                   ("Description", f"{info.title}: {info.description}")]
    lines = ['<?xml version="1.0" encoding="utf-8"?>',
             '<Project DefaultTargets="Build" xmlns="http://schemas.microsoft.com/developer/msbuild/2003">',
             "  <PropertyGroup>"]
    lines += [f"    <{k}>{escape(v)}</{k}>" for k, v in properties]
    lines += ["  </PropertyGroup>", "  <ItemGroup>"]
    for path in paths:
        lines += [f"    <Compile Include={quoteattr(path.replace('/', chr(92)))}>",
                  "      <SubType>Code</SubType>", "    </Compile>"]
    lines += ["  </ItemGroup>", "  <ItemGroup>"]
    lines += [f'    <Folder Include="{f}" />' for f in sorted({p.split("/")[0] for p in paths})]
    lines += ["  </ItemGroup>", "  <ItemGroup>"]
    for name in LIBRARY_REFERENCES:
        lines += [f'    <PlaceholderReference Include="{name}">',
                  f"      <DefaultResolution>{name}, * (Beckhoff Automation GmbH)</DefaultResolution>",
                  f"      <Namespace>{name}</Namespace>", "    </PlaceholderReference>"]
    lines += ["  </ItemGroup>", "</Project>"]
    return "\n".join(lines) + "\n"


def twincat_files(library):
    """{relative path: text} of every file of the TwinCAT export."""
    files = {}
    for obj in library.objects():
        source = obj.source
        files[relative_path(source.kind, source.name)] = object_file(source.kind, source.name, obj.declaration,
                                                                     source.body)
    files[f"{library.info.name}.plcproj"] = project_file(library, list(files))
    return files


def write_twincat(library, directory):
    for path, text in twincat_files(library).items():
        target = os.path.join(directory, *path.split("/"))
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "w", encoding="utf-8", newline="\r\n") as f:
            f.write(text)
