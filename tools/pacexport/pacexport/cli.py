"""pacexport export: the library as PLCopen XML and TwinCAT 3 files; pacexport validate: check PLCopen
XML files against the TC6 schema; pacexport solution: a TwinCAT solution around a PLC project. See
docs/import.md."""
import argparse
import os
import shutil
import sys

from .errors import ExportError
from .library import load_library
from .metadata import read_library_info
from .plcopen_write import plcopen_bytes
from .schema import SchemaUnavailable, load_schema, schema_errors
from .solution import write_solution
from .twincat import write_twincat


def plcopen_file_name(info):
    return info.name.lower() + ".xml"


def export(library, out):
    """Writes <out>/<name>.xml, <out>/twincat/ and <out>/twincat-solution/ (the TwinCAT files as a
    solution that opens as it is), replacing what an earlier export left there."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, plcopen_file_name(library.info)), "wb") as f:
        f.write(plcopen_bytes(library))
    twincat = os.path.join(out, "twincat")
    shutil.rmtree(twincat, ignore_errors=True)
    write_twincat(library, twincat)
    write_solution(twincat, os.path.join(out, "twincat-solution"), library.info.name, None)


def _export_command(args):
    info = read_library_info(args.library)
    library = load_library(info, args.sources, args.gvl, args.cache)
    export(library, args.out)
    if args.stamp:
        with open(args.stamp, "w", encoding="utf-8") as f:
            f.write(f"{info.name} {info.version}\n")
    return 0


def _solution_command(args):
    write_solution(args.plc, args.out, args.name, args.program, args.cycle_ms)
    return 0


def _validate_command(args):
    schema = load_schema()
    failed = 0
    for path in args.files:
        with open(path, "rb") as f:
            errors = schema_errors(schema, f.read())
        for error in errors:
            print(f"{path}: {error}", file=sys.stderr)
        failed += bool(errors)
    return 1 if failed else 0


def main(argv=None):
    parser = argparse.ArgumentParser(prog="pacexport", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    ex = commands.add_parser("export", help="write <out>/<name>.xml (PLCopen) and <out>/twincat/")
    ex.add_argument("--library", required=True, help="st/library.json: name and version")
    ex.add_argument("--out", required=True)
    ex.add_argument("--gvl", action="append", default=[], help="a global constant list (repeatable)")
    ex.add_argument("--cache", help="the translator's parse cache (pacst --cache), shared between runs")
    ex.add_argument("--stamp", help="file to write when the export succeeded")
    ex.add_argument("sources", nargs="+", help="the library's ST files in declaration order")
    va = commands.add_parser("validate", help="validate PLCopen XML files against TC6 XML v2.01")
    va.add_argument("files", nargs="+")
    so = commands.add_parser("solution", help="write <out>/<name>.sln and <out>/<name>/ around a PLC project")
    so.add_argument("--plc", required=True, help="the PLC project's folder (its .plcproj and files)")
    so.add_argument("--out", required=True)
    so.add_argument("--name", required=True, help="the solution's and the TwinCAT project's name")
    so.add_argument("--program", help="the PROGRAM the task calls; without it (a library) no task")
    so.add_argument("--cycle-ms", type=int, default=10, help="the task's cycle time in ms (default 10)")
    args = parser.parse_args(argv)
    commands_by_name = {"export": _export_command, "validate": _validate_command, "solution": _solution_command}
    try:
        return commands_by_name[args.command](args)
    except (ExportError, SchemaUnavailable) as exc:
        print(f"pacexport: {exc}", file=sys.stderr)
        return 1
