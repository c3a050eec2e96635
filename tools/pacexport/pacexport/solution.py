"""Writes a TwinCAT 3.1 solution around a PLC project, so that a machine program opens in TwinCAT XAE
as it is: the .sln, the TwinCAT project (.tsproj) with its real-time task, and a copy of the PLC
project with the task object (PlcTask.TcTTO) that calls the program each cycle. Without a program
(a library project) there is no task: the solution only opens the project, as TcUnit's does.

The files have the form TwinCAT 4024 writes (tests/ide_reference.json lists what real files carry):
the PLC project inline in the .tsproj, not in a separate .xti; every Id a UUID derived from the
solution's and the PLC project's names, so the same input gives the same bytes. No target system is
set: TwinCAT uses the local one until the user chooses another (docs/import.md).
"""
import os
import shutil
import uuid

from lxml import etree

from .errors import ExportError
from .twincat import BOM, OBJECT_VERSION, PRODUCT_VERSION

MSBUILD = "http://schemas.microsoft.com/developer/msbuild/2003"
TASK_FILE = "PlcTask.TcTTO"
TASK_NAME = "PlcTask"
TASK_PRIORITY = 20
PLC_AMS_PORT = 851  # the first PLC runtime
TASK_AMS_PORT = 350  # the first real-time task
_TSPROJ_TYPE = "{B1E792BE-AA5F-4E3C-8C82-674BF9C0715B}"  # Visual Studio's project type of a .tsproj
# The target platforms a new TwinCAT 3.1 solution offers.
_PLATFORMS = ("TwinCAT CE7 (ARMV7)", "TwinCAT OS (ARMT2)", "TwinCAT RT (x64)", "TwinCAT RT (x86)")
_NAMESPACE = uuid.uuid5(uuid.NAMESPACE_URL, "urn:pa-control-plc:pacexport:solution")


def _guid(*parts):
    return "{" + str(uuid.uuid5(_NAMESPACE, ":".join(parts))).upper() + "}"


def _crlf_file(path, text):
    with open(path, "w", encoding="utf-8", newline="\r\n") as f:
        f.write(text)


def _plc_project(plc_dir):
    """The one .plcproj of plc_dir: (file name, name, ProjectGuid)."""
    found = sorted(n for n in os.listdir(plc_dir) if n.lower().endswith(".plcproj"))
    if len(found) != 1:
        raise ExportError(plc_dir, f"holds {len(found)} .plcproj files, not one")
    root = etree.parse(os.path.join(plc_dir, found[0])).getroot()
    guid = root.findtext(f"{{{MSBUILD}}}PropertyGroup/{{{MSBUILD}}}ProjectGuid")
    name = root.findtext(f"{{{MSBUILD}}}PropertyGroup/{{{MSBUILD}}}Name") or os.path.splitext(found[0])[0]
    if not guid:
        raise ExportError(os.path.join(plc_dir, found[0]), "has no ProjectGuid")
    return found[0], name, guid.upper()


def task_object(plc_name, program, cycle_ms):
    """PlcTask.TcTTO: the task of the PLC project, which calls `program` every cycle_ms."""
    ids = {key: "{" + _guid(plc_name, "task", key).strip("{}").lower() + "}"
           for key in ("Id", "TaskFBGuid", "Fb_init", "Fb_exit", "CycleUpdate", "PostCycleUpdate")}
    lines = [BOM + '<?xml version="1.0" encoding="utf-8"?>',
             f'<TcPlcObject Version="{OBJECT_VERSION}" ProductVersion="{PRODUCT_VERSION}">',
             f'  <Task Name="{TASK_NAME}" Id="{ids["Id"]}">', "    <!--CycleTime in micro seconds.-->",
             f"    <CycleTime>{cycle_ms * 1000}</CycleTime>", f"    <Priority>{TASK_PRIORITY}</Priority>",
             "    <PouCall>", f"      <Name>{program}</Name>", "    </PouCall>"]
    lines += [f"    <{key}>{ids[key]}</{key}>" for key in ("TaskFBGuid", "Fb_init", "Fb_exit", "CycleUpdate",
                                                          "PostCycleUpdate")]
    return "\n".join(lines + ["  </Task>", "</TcPlcObject>"]) + "\n"


def _add_task_to_plcproj(path):
    """Lists PlcTask.TcTTO in the .plcproj (once), keeping everything else as it is."""
    with open(path, "rb") as f:
        text = f.read().decode("utf-8-sig").replace("\r\n", "\n")
    if f'Include="{TASK_FILE}"' in text:
        return
    entry = f'    <Compile Include="{TASK_FILE}">\n      <SubType>Code</SubType>\n    </Compile>\n'
    at = text.find("    <Compile Include=")
    if at < 0:
        at = text.find("  <ItemGroup>")
        if at < 0:
            raise ExportError(path, "has no ItemGroup to list the task in")
        entry = "  <ItemGroup>\n" + entry + "  </ItemGroup>\n"
    _crlf_file(path, BOM + text[:at] + entry + text[at:])


def tsproj(name, plc_file, plc_name, plc_guid, cycle_ms, with_task):
    plc_path = f"{plc_name}\\{plc_file}"
    tmc = f"{plc_name}\\{plc_name}.tmc"
    lines = [
        '<?xml version="1.0"?>',
        '<TcSmProject xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" '
        'xsi:noNamespaceSchemaLocation="http://www.beckhoff.com/schemas/2012/07/TcSmProject" '
        f'TcSmVersion="1.0" TcVersion="{PRODUCT_VERSION}">',
        f'\t<Project ProjectGUID="{_guid(name, "tsproj")}" Target64Bit="true" ShowHideConfigurations="#x6">']
    if with_task:
        lines += [
            "\t\t<System>", "\t\t\t<Tasks>",
            f'\t\t\t\t<Task Id="3" Priority="{TASK_PRIORITY}" CycleTime="{cycle_ms * 10000}" '
            f'AmsPort="{TASK_AMS_PORT}" AdtTasks="true">',
            f"\t\t\t\t\t<Name>{TASK_NAME}</Name>", "\t\t\t\t</Task>", "\t\t\t</Tasks>", "\t\t</System>"]
    lines += [
        "\t\t<Plc>",
        f'\t\t\t<Project GUID="{plc_guid}" Name="{plc_name}" PrjFilePath="{plc_path}" TmcFilePath="{tmc}" '
        f'ReloadTmc="true" AmsPort="{PLC_AMS_PORT}" FileArchiveSettings="#x000e" SymbolicMapping="true">',
        '\t\t\t\t<Instance Id="#x08502000" TcSmClass="TComPlcObjDef" KeepUnrestoredLinks="2" '
        f'TmcPath="{tmc}">',
        f"\t\t\t\t\t<Name>{plc_name} Instance</Name>",
        '\t\t\t\t\t<CLSID ClassFactory="TcPlc30">{08500001-0000-0000-F000-000000000064}</CLSID>']
    if with_task:
        lines += [
            "\t\t\t\t\t<Contexts>", "\t\t\t\t\t\t<Context>", "\t\t\t\t\t\t\t<Id>0</Id>",
            f"\t\t\t\t\t\t\t<Name>{TASK_NAME}</Name>", "\t\t\t\t\t\t\t<ManualConfig>",
            "\t\t\t\t\t\t\t\t<OTCID>#x02010030</OTCID>", "\t\t\t\t\t\t\t</ManualConfig>",
            f"\t\t\t\t\t\t\t<Priority>{TASK_PRIORITY}</Priority>",
            f"\t\t\t\t\t\t\t<CycleTime>{cycle_ms * 1000000}</CycleTime>", "\t\t\t\t\t\t</Context>",
            "\t\t\t\t\t</Contexts>", "\t\t\t\t\t<TaskPouOids>",
            f'\t\t\t\t\t\t<TaskPouOid Prio="{TASK_PRIORITY}" OTCID="#x08502001"/>', "\t\t\t\t\t</TaskPouOids>"]
    lines += ["\t\t\t\t</Instance>", "\t\t\t</Project>", "\t\t</Plc>", "\t</Project>", "</TcSmProject>"]
    return "\n".join(lines) + "\n"


def sln(name, plc_guid):
    project_guid = _guid(name, "tsproj")
    configurations = [f"{c}|{p}" for c in ("Debug", "Release") for p in _PLATFORMS]
    lines = ["", "Microsoft Visual Studio Solution File, Format Version 12.00",
             "# TcXaeShell Solution File, Format Version 11.00", "VisualStudioVersion = 15.0.28307.1300",
             "MinimumVisualStudioVersion = 10.0.40219.1",
             f'Project("{_TSPROJ_TYPE}") = "{name}", "{name}\\{name}.tsproj", "{project_guid}"', "EndProject",
             "Global", "\tGlobalSection(SolutionConfigurationPlatforms) = preSolution"]
    lines += [f"\t\t{c} = {c}" for c in configurations]
    lines += ["\tEndGlobalSection", "\tGlobalSection(ProjectConfigurationPlatforms) = postSolution"]
    for guid in (project_guid, plc_guid):
        for c in configurations:
            lines += [f"\t\t{guid}.{c}.ActiveCfg = {c}", f"\t\t{guid}.{c}.Build.0 = {c}"]
    lines += ["\tEndGlobalSection", "\tGlobalSection(SolutionProperties) = preSolution",
              "\t\tHideSolutionNode = FALSE", "\tEndGlobalSection",
              "\tGlobalSection(ExtensibilityGlobals) = postSolution",
              f"\t\tSolutionGuid = {_guid(name, 'solution')}", "\tEndGlobalSection", "EndGlobal"]
    return BOM + "\n".join(lines) + "\n"


def write_solution(plc_dir, out, name, program, cycle_ms=10):
    """Writes <out>/<name>.sln, <out>/<name>/<name>.tsproj and <out>/<name>/<PLC project>/ (a copy of
    plc_dir, with the task object when there is a program to call), replacing what an earlier run left
    there."""
    if cycle_ms < 1:
        raise ExportError(plc_dir, f"cycle time {cycle_ms} ms is below TwinCAT's 1 ms base time")
    plc_file, plc_name, plc_guid = _plc_project(plc_dir)
    project_dir = os.path.join(out, name)
    shutil.rmtree(project_dir, ignore_errors=True)
    target = os.path.join(project_dir, plc_name)
    shutil.copytree(plc_dir, target)
    if program is not None:
        _crlf_file(os.path.join(target, TASK_FILE), task_object(plc_name, program, cycle_ms))
        _add_task_to_plcproj(os.path.join(target, plc_file))
    _crlf_file(os.path.join(project_dir, f"{name}.tsproj"),
               tsproj(name, plc_file, plc_name, plc_guid, cycle_ms, program is not None))
    _crlf_file(os.path.join(out, f"{name}.sln"), sln(name, plc_guid))
