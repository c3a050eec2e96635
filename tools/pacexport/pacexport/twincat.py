"""Writes the library as TwinCAT 3 PLC files: a .TcDUT per type, a .TcPOU per POU, a .TcGVL per global
list, and a .plcproj that lists them.

The files have the form TwinCAT 3.1 writes (tests/ide_reference.json lists what real files carry):
a UTF-8 byte-order mark, the declaration and implementation as CDATA, CRLF line ends, the
ProductVersion of a real TwinCAT 3.1 build, and an object Id that is a UUID derived from the object's
name, so that the same object keeps its Id from build to build and from version to version (TwinCAT
matches objects by it). The .plcproj is a library project's: Title, DefaultNamespace PA_CONTROL (the
calls are PA_CONTROL.MC_Power, which cannot collide with Tc2_MC2), Author, a library category, the
GVLs linked always and the project options TwinCAT keeps in ProjectExtensions.
"""
import os
import uuid

from .splitting import folder_of
from xml.sax.saxutils import escape, quoteattr

OBJECT_VERSION = "1.1.0.1"  # the TcPlcObject format of TwinCAT 3.1
PRODUCT_VERSION = "3.1.4024.15"  # a released TwinCAT 3.1 build (4024.15) that writes this format
PROGRAM_VERSION = "3.1.4024.0"  # the .plcproj's ProgramVersion: the oldest build of the 4024 line it is for
BOM = "\ufeff"  # TwinCAT writes its XML files with a UTF-8 byte-order mark
_NAMESPACE = uuid.uuid5(uuid.NAMESPACE_URL, "urn:pa-control-plc:pacexport")

# Object tag and file extension of each object kind. The files go into the folders of st/ (cmd, axis, types...),
# as the PLCopen export's POUs view has them, so that a topic's helpers stay beside its blocks in TwinCAT too.
FILE_KINDS = {
    "dataType": ("DUT", ".TcDUT"),
    "function": ("POU", ".TcPOU"),
    "functionBlock": ("POU", ".TcPOU"),
    "program": ("POU", ".TcPOU"),
    "globalVars": ("GVL", ".TcGVL"),
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
    tag, _ = FILE_KINDS[kind]
    special = ' SpecialFunc="None"' if tag == "POU" else ""
    lines = [BOM + '<?xml version="1.0" encoding="utf-8"?>',
             f'<TcPlcObject Version="{OBJECT_VERSION}" ProductVersion="{PRODUCT_VERSION}">',
             f'  <{tag} Name={quoteattr(name)} Id="{guid(tag, name)}"{special}>',
             f"    <Declaration>{cdata(declaration)}</Declaration>"]
    if body is not None:
        lines += ["    <Implementation>", f"      <ST>{cdata(body)}</ST>", "    </Implementation>"]
    lines += [f"  </{tag}>", "</TcPlcObject>"]
    return "\n".join(lines) + "\n"


def relative_path(source):
    """The object's file in the export: its st/ folder and name."""
    _, extension = FILE_KINDS[source.kind]
    return f"{folder_of(source)}/{source.name}{extension}"


def project_file(library, paths):
    info = library.info
    ids = {key: guid("project", f"{info.name}:{key}") for key in (
        "ProjectGuid", "Application", "TypeSystem", "Implicit_Task_Info", "Implicit_KindOfTask",
        "Implicit_Jitter_Distribution", "LibraryReferences")}
    category = guid("category", info.company)
    properties = [("FileVersion", "1.0.0.0"), ("SchemaVersion", "2.0"), ("ProjectGuid", ids["ProjectGuid"]),
                  ("SubObjectsSortedByName", "True"), ("DownloadApplicationInfo", "true"),
                  ("WriteProductVersion", "true"), ("GenerateTpy", "false"), ("Name", info.name),
                  ("ProgramVersion", PROGRAM_VERSION)]
    properties += [(k, v) for k, v in ids.items() if k != "ProjectGuid"]
    properties += [("CombineIds", "true"), ("Company", info.company), ("Released", "false"), ("Title", info.name),
                   ("DefaultNamespace", info.name), ("ProjectVersion", info.ide_version), ("Author", info.company)]
    lines = [BOM + '<?xml version="1.0" encoding="utf-8"?>',
             '<Project DefaultTargets="Build" xmlns="http://schemas.microsoft.com/developer/msbuild/2003">',
             "  <PropertyGroup>"]
    lines += [f"    <{k}>{escape(v)}</{k}>" for k, v in properties]
    lines += ["    <LibraryCategories>", '      <LibraryCategory xmlns="">', f"        <Id>{category}</Id>",
              "        <Version>1.0.0.0</Version>", f"        <DefaultName>{escape(info.title)}</DefaultName>",
              "      </LibraryCategory>", "    </LibraryCategories>", "    <SelectedLibraryCategories>",
              f'      <Id xmlns="">{category}</Id>', "    </SelectedLibraryCategories>",
              f"    <Description>{escape(f'{info.title}: {info.description} {info.license_line}')}</Description>",
              "  </PropertyGroup>", "  <ItemGroup>"]
    lines += [f'    <Folder Include="{f}" />' for f in sorted({p.split("/")[0] for p in paths})]
    lines += ["  </ItemGroup>", "  <ItemGroup>"]
    for path in paths:
        lines += compile_item(path)
    lines += ["  </ItemGroup>", "  <ItemGroup>"]
    for name in LIBRARY_REFERENCES:
        lines += [f'    <PlaceholderReference Include="{name}">',
                  f"      <DefaultResolution>{name}, * (Beckhoff Automation GmbH)</DefaultResolution>",
                  f"      <Namespace>{name}</Namespace>", "    </PlaceholderReference>"]
    lines += ["  </ItemGroup>"] + project_extensions() + ["</Project>"]
    return "\n".join(lines) + "\n"


def compile_item(path):
    """A file's entry in the .plcproj; a global list is linked even where nothing refers to it."""
    lines = [f"    <Compile Include={quoteattr(path.replace('/', chr(92)))}>", "      <SubType>Code</SubType>"]
    if path.endswith(FILE_KINDS["globalVars"][1]):
        lines.append("      <LinkAlways>true</LinkAlways>")
    return lines + ["    </Compile>"]


def project_extensions():
    """The PLC project options as TwinCAT keeps them: the root of its option tree, with no option set
    (every option at its default), and the type list the tree names."""
    return ["  <ProjectExtensions>", "    <PlcProjectOptions>", "      <XmlArchive>", "        <Data>",
            '          <o xml:space="preserve" t="OptionKey">',
            '            <v n="Name">"&lt;ProjectRoot&gt;"</v>',
            '            <d n="SubKeys" t="Hashtable" />', '            <d n="Values" t="Hashtable" />',
            "          </o>", "        </Data>", "        <TypeList>",
            '          <Type n="Hashtable">System.Collections.Hashtable</Type>',
            '          <Type n="OptionKey">{54dd0eac-a6d8-46f2-8c27-2f43c7e49861}</Type>',
            '          <Type n="String">System.String</Type>', "        </TypeList>", "      </XmlArchive>",
            "    </PlcProjectOptions>", "  </ProjectExtensions>"]


def twincat_files(library):
    """{relative path: text} of every file of the TwinCAT export."""
    files = {}
    for obj in library.objects():
        source = obj.source
        files[relative_path(source)] = object_file(source.kind, source.name, obj.declaration,
                                                                     source.body)
    files[f"{library.info.name}.plcproj"] = project_file(library, list(files))
    return files


def write_twincat(library, directory):
    for path, text in twincat_files(library).items():
        target = os.path.join(directory, *path.split("/"))
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "w", encoding="utf-8", newline="\r\n") as f:
            f.write(text)
