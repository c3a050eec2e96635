"""Command line: `pacst build` translates ST files to C; `pacst declare` writes only the declarations that
C++ code of a MATIEC build includes, and the check that MATIEC lays them out the same; `pacst check`
only checks; `pacst order` prints files in the declaration order the others need."""
import argparse
import io
import json
import os
import pickle
import re
import sys
import tempfile
import time
import types

from .compiler import Compiler
from . import checked, gvl, layout, libraries, matiec, plcopen_read, symbols, twincat
from .order import closed_under_uses, declaration_order, shadowed_library_files
from . import system, types as T
from .emit import ENUM_NAMES, Emitter, remove_outputs, remove_stale_c, write_outputs, _stem
from .errors import StError, StErrors
from .parsing import parse_files

SYMBOLS = "symbols.json"


def _parsed(results):
    """The SourceFiles of parse_files' `results`, or StErrors with every file's fault."""
    errors = [r for r in results if isinstance(r, StError)]
    if errors:
        raise StErrors(errors)
    return results


def translate(files, cache_dir=None, gvl_files=(), jobs=None, user=False, native=(), namespaces=None, kept=None,
              strict_narrowing=False):
    """Parse and compile `files` in declaration order and check the global constant lists `gvl_files`
    against them; returns (compiler, program, {gvl file: constants}) or raises StErrors. `user`: the
    user-program mode; `native`: files (among `files`) whose FUNCTIONs the host implements; `kept`: a library's
    checked state (checked.Kept, user mode), whose files are not parsed again; `strict_narrowing`: an implicit
    narrowing refused, not taken with a warning."""
    taken = kept.by_path if kept is not None else {}
    parsed = iter(parse_files([f for f in files if f not in taken] + list(gvl_files), cache_dir, jobs, user))
    file_results = [taken[f] if f in taken else next(parsed) for f in files]
    return _translate_parsed(file_results, list(parsed), user, native, namespaces, kept, strict_narrowing)


# What a refusal may owe to a declaration pacst could not read: left out beside a file's syntax error
_MAY_DEPEND = re.compile(r"undeclared|declaration was refused|cannot be used|before its declaration|"
                         r"has no (variable|member|METHOD|PROPERTY|value)", re.I)


def _translate_parsed(file_results, list_results, user=False, native=(), namespaces=None, kept=None,
                      strict_narrowing=False):
    # A fault in a POU file is reported before any in a global list.
    unread = [r for r in file_results if isinstance(r, StError)]
    if user and unread and len(unread) < len(file_results):
        # user mode: the files that were read are checked too, in the same run, but for the refusals that
        # may be owed to a declaration in a file that could not be read
        try:
            _translate_parsed([r for r in file_results if not isinstance(r, StError)], [], user, native,
                              namespaces, kept, strict_narrowing)
        except StErrors as e:
            unread += [err for err in e.errors if not _MAY_DEPEND.search(err.message)]
        raise StErrors(unread)
    sources = _parsed(file_results)
    lists = _parsed(list_results)
    if user:
        # The libraries first, checked on their own (or a copy of their checked state); then the program. A PLC
        # programmer's tool keeps no declaration order: pacst finds it (`pacst order`).
        left_out = {}
        library, rest = user_order(sources, native, namespaces, left_out)
        kept_used = kept is not None and kept.covers(library)
        if kept is not None:
            kept.used = kept_used
        if kept_used:  # the kept files first, then the other libraries' on top
            comp = kept.compiler(native, namespaces)
            ids = {id(src) for src in kept.sources}
            comp.declare([src for src in library if id(src) not in ids])
        else:
            comp = checked_library(library, native, namespaces)
        comp.strict_narrowing = strict_narrowing  # the program's, not the libraries' (checked without it)
        comp.left_out = left_out
        comp.declare(rest)
        program = comp.finish()
    else:
        comp = Compiler(user, native, namespaces)
        program = comp.compile(sources)
    constants = {}
    errors = []
    for src in lists:
        try:
            constants[src.path] = gvl.read_list(comp, src)
            gvl.check_pous(comp, program, constants[src.path])
        except StErrors as e:
            errors += e.errors
    if errors:
        raise StErrors(errors)
    return comp, program, constants


class _CheckedLibraries:
    """User mode: the libraries' checked state, kept in this process for the next program translated with the same
    parsed library files, natives and namespaces (the dialect page's check, pac-test's corpus). A library is kept
    the second time it is met, so that one translation pays nothing for it; each program then gets a copy of the
    state (pickled once, unpickled for each), sharing with it what the translator never changes: the parsed trees
    (the compiler keys its notes by their identity), the elementary and standard types (compared by identity) and
    the POUs' C lines."""

    def __init__(self):
        self.met = {}  # key -> the library's SourceFiles (kept alive, so that their ids stay theirs)
        self.kept = {}  # key -> (the library's SourceFiles, the checked Compiler pickled, the objects it shares)

    def get(self, key, library, fresh):
        """A Compiler with `library` declared: `fresh()`'s, or a copy of the one kept for `key`."""
        kept = self.kept.get(key)
        if kept is not None and all(a is b for a, b in zip(kept[0], library)):
            return _copy(kept[1], kept[2])
        if key not in self.met or any(a is not b for a, b in zip(self.met[key], library)):
            if len(self.met) >= 8:
                self.met.clear()
            self.met[key] = list(library)
            return fresh()
        comp = fresh()
        if len(self.kept) >= 4:
            self.kept.clear()
        shared = _shared_objects([library, T, system])
        # and each POU's C lines, made once in its declaration and only read after
        shared.update((id(obj.body_c), obj.body_c) for kind, obj, _ in comp.program.items if kind == "pou")
        state = io.BytesIO()
        _Sharing(state, shared).dump(comp)
        self.kept[key] = (list(library), state.getvalue(), shared)
        return _copy(state.getvalue(), shared)


class _Sharing(pickle.Pickler):
    """A Pickler that writes each object of `shared` ({id: object}) as its id, for _copy to take it as it is."""

    def __init__(self, file, shared):
        super().__init__(file, protocol=pickle.HIGHEST_PROTOCOL)
        self.shared = shared

    def persistent_id(self, obj):
        return id(obj) if id(obj) in self.shared else None


def _copy(state, shared):
    """The Compiler pickled in `state` by _Sharing, with the objects of `shared` in it as they are."""
    unpickler = pickle.Unpickler(io.BytesIO(state))
    unpickler.persistent_load = shared.__getitem__
    return unpickler.load()


_CHECKED = _CheckedLibraries()


def _shared_objects(roots):
    """{id: object} of every object reachable from `roots` (lists, the parsed files, modules' globals): the objects
    _copy does not copy."""
    code = (types.FunctionType, types.BuiltinFunctionType, types.MethodType, types.ModuleType, type)
    found = {}
    stack = []
    for root in roots:
        stack += [v for v in vars(root).values() if not isinstance(v, code)] if isinstance(root, types.ModuleType) \
            else [root]
    while stack:
        obj = stack.pop()
        if id(obj) in found or type(obj) in (int, float, bool, str, bytes, type(None)) or isinstance(obj, code):
            continue
        found[id(obj)] = obj
        if isinstance(obj, dict):
            stack += list(obj.keys()) + list(obj.values())
        elif isinstance(obj, (list, tuple, set, frozenset)):
            stack += list(obj)
        elif not isinstance(obj, str):
            stack += list(getattr(obj, "__dict__", {}).values())
            stack += [getattr(obj, name) for name in getattr(type(obj), "__slots__", ()) if hasattr(obj, name)]
    return found


def user_order(sources, native=(), namespaces=None, left_out=None):
    """User mode: (the library files among `sources`, the rest), each in its declaration order. A library file is
    one in the folder of a namespace (--namespace, --library) that uses no name of the program's files
    (order.closed_under_uses): these are declared before the program, which may use them but not the reverse, as
    a library is compiled before the programs that reference it. A library file the program's declarations shadow
    is in neither (order.shadowed_library_files; `left_out`, a dict, gets them)."""
    probe = Compiler(True, native, namespaces)
    shadowed, sources = shadowed_library_files(sources, probe.library_of)
    if left_out is not None:
        left_out.update(shadowed)
    closed = closed_under_uses(sources, [src.path for src in sources if probe.library_of(src.path)])
    by_path = {src.path: src for src in sources}
    return tuple([by_path[path] for path in declaration_order([src for src in sources if (src.path in closed) == first],
                                                              user=True)] for first in (True, False))


def checked_library(library, native=(), namespaces=None):
    """User mode: a Compiler with the `library` files (user_order's first list) declared and checked."""
    comp = Compiler(True, native, namespaces)
    if not library:
        return comp
    key = (tuple(id(src) for src in library), tuple(sorted(native)), tuple(sorted(comp.namespaces.items())))

    def fresh():
        comp.declare(library)
        return comp
    return _CHECKED.get(key, library, fresh)


def _tables(constants):
    return {_stem(path) + ".h": gvl.table_header(_stem(path), items) for path, items in constants.items()}


def _user_files(args):
    """The files to compile: the native interfaces first (the user's POUs call them); in user mode a
    TwinCAT `.plcproj` stands for the object files it lists, a PLCopen XML project for the ST files of
    its objects (written to the `--sources` folder, or a temporary one)."""
    if (args.native or args.sources_dir or args.namespace or args.library) and not args.user:
        raise SystemExit("pacst: --native, --namespace, --library and --sources need --user")
    files = []
    for name, path in _libraries(args):
        files += libraries.files(name, path, _sources_dir(args))
    for path in args.files:
        if args.user and path.lower().endswith(".plcproj"):
            files += twincat.project_files(path)
        elif args.user and path.lower().endswith(".xml"):
            files += _without_libraries(args, path, plcopen_read.extract(path, _sources_dir(args)))
        else:
            files.append(path)
    return list(args.native) + [f for f in files if f not in args.native]


def _without_libraries(args, xml, extracted):
    """The ST files of the PLCopen project `xml` without the objects of a library given under its namespace,
    where the export holds at least half of that library: CODESYS's export "into an application" carries the
    objects of the libraries the application references. One warning names them. A few objects named like a
    library's are the program's own, and are refused as declared twice, with advice."""
    own = {_stem(f).upper() for f in extracted}
    for name, (_, folder) in _namespaces(args).items():
        objects = {os.path.splitext(n)[0].upper(): os.path.splitext(n)[0] for _, _, names in os.walk(folder)
                   for n in names if n.lower().endswith(libraries.SOURCE_EXTENSIONS)}
        shared = sorted(objects[n] for n in own & set(objects))
        if shared and len(shared) * 2 >= len(objects):
            listed = ", ".join(shared[:5]) + (", ..." if len(shared) > 5 else "")
            print(f"pacst: warning: {xml}: the export holds {len(shared)} of the {len(objects)} objects of the library "
                  f"{name} ({listed}): CODESYS exports an application with the libraries it references; they are "
                  f"left out, and the library given as {name} is used", file=sys.stderr)
            extracted = [f for f in extracted if _stem(f).upper() not in {n.upper() for n in shared}]
    return extracted


def _namespaces(args):
    """--namespace NAME=DIR: {NAME: (NAME, DIR)}."""
    found = {}
    for item in args.namespace:
        name, sep, folder = item.partition("=")
        if not sep or not name or not folder:
            raise SystemExit(f"pacst: --namespace {item}: write NAME=FOLDER")
        found[name] = (name, folder)
    for name, path in _libraries(args):
        if name.upper() in {n.upper() for n in found}:
            raise SystemExit(f"pacst: --library {name}={path}: the namespace {name} is given by --namespace too")
        found[name] = (name, libraries.folder(name, path, _sources_dir(args)))
    return found


def _libraries(args):
    """--library NAME=PATH: [(NAME, PATH)]."""
    try:
        return libraries.parse(args.library)
    except libraries.LibraryError as e:
        raise SystemExit(f"pacst: {e}") from None


def _sources_dir(args):
    if args.sources_dir is None:
        args.sources_dir = tempfile.mkdtemp(prefix="pacst-plcopen-")
    return args.sources_dir


def _build(args):
    files = _user_files(args)
    names = ["POUS.h", "pacst_iec.h", ENUM_NAMES, SYMBOLS] + [_stem(f) + ".c" for f in files] + \
        [_stem(f) + ".h" for f in args.gvl]
    kept, why = _kept_library(args, files)
    try:
        comp, program, constants = translate(files, args.cache, args.gvl, args.jobs, args.user, args.native,
                                             _namespaces(args), kept, args.strict_narrowing)
    except StErrors as e:
        _say_kept(args, kept, why)
        remove_outputs(args.out, names + ([os.path.basename(args.stamp)] if args.stamp else []))
        if args.stamp and os.path.exists(args.stamp):
            os.remove(args.stamp)
        for err in e.errors:
            print(plcopen_read.at_source(err), file=sys.stderr)
        return 1
    _say_kept(args, kept, why)
    _print_warnings(comp)
    outputs = Emitter(comp, program, args.out if args.line_directives else None).outputs(files)
    outputs.update(_tables(constants))
    if args.user:
        outputs[SYMBOLS] = symbols.symbols(comp, program)
    written = write_outputs(args.out, outputs)
    if args.user:
        remove_stale_c(args.out, outputs)
    if args.stamp:
        with open(args.stamp, "w", encoding="utf-8") as f:
            f.write(f"{time.time()}\n")
    if args.verbose:
        print(f"pacst: {len(args.files)} file(s), rewrote {', '.join(written) or 'nothing'}")
    return 0


def _print_warnings(comp):
    """The warnings of a translation that succeeded, each once (a construct may be looked at twice), in source
    order, at the user's own file (a PLCopen XML project's line)."""
    unique = {str(w): w for w in comp.warnings}
    for warning in sorted(unique.values(), key=lambda w: (w.file, w.line, w.col)):
        print(plcopen_read.at_source(warning), file=sys.stderr)


def _kept_library(args, files):
    """build --checked-library FILE: (the state `pacst library` kept there where it stands for this run, else None;
    why not)."""
    if not args.checked_library:
        return None, None
    if not args.user:
        raise SystemExit("pacst: --checked-library needs --user")
    return checked.load(args.checked_library, files, args.native, _namespaces(args))


def _say_kept(args, kept, why):
    """--verbose: whether the checked library was taken."""
    if not args.verbose or not args.checked_library:
        return
    if kept is None:
        said = f"not taken, {why}"
    elif kept.used:
        said = f"{len(kept.sources)} file(s) taken, not parsed or checked"
    else:
        said = f"{len(kept.sources)} file(s) read from it and checked again: the program declares a name they use"
    print(f"pacst: the checked library {args.checked_library}: {said}")


def _library(args):
    """pacst library: the library files checked in user mode and their state kept in --out."""
    args.user = True
    try:
        files = _user_files(args)
        sources = _parsed(parse_files(files, args.cache, args.jobs, True))
        library, rest = user_order(sources, args.native, _namespaces(args))
        if rest:
            raise StErrors([StError(src.path, 1, 1, "not a library file: outside every --namespace folder, or it "
                                                    "uses a name declared outside them") for src in rest])
        comp = Compiler(True, args.native, _namespaces(args))
        comp.declare(library)
        comp.finish()
    except StErrors as e:
        for err in e.errors:
            print(plcopen_read.at_source(err), file=sys.stderr)
        return 1
    checked.save(args.out, library, comp)
    return 0


def _declare(args):
    names = ["POUS.h", "pacst_iec.h", ENUM_NAMES, "layout_probe.c"] + [_stem(f) + ".h" for f in args.gvl]
    check_name = os.path.join(args.check_out, "layout_check.c")
    try:
        comp, program, constants = translate(args.files, args.cache, args.gvl, args.jobs)
    except StErrors as e:
        remove_outputs(args.out, names)
        if os.path.exists(check_name):
            os.remove(check_name)
        for err in e.errors:
            print(plcopen_read.at_source(err), file=sys.stderr)
        return 1
    outputs = {name: text for name, text in Emitter(comp, program, by_reference=False).outputs(args.files).items()
               if name in names}
    outputs["layout_probe.c"] = layout.probe_source(program, args.files)
    outputs["pacst_iec.h"] = layout.matiec_header(outputs["pacst_iec.h"])
    outputs.update(_tables(constants))
    write_outputs(args.out, outputs)
    # Beside MATIEC's POUS.h: a quoted include looks in the including file's folder first.
    write_outputs(args.check_out, {"layout_check.c": layout.check_source(program, args.files)})
    if args.stamp:
        with open(args.stamp, "w", encoding="utf-8") as f:
            f.write(f"{time.time()}\n")
    return 0


def _check(args):
    # --separately: every file is a program of its own (the refusal snippets of the test suite). All
    # files are parsed first, in parallel; then each group is compiled on its own.
    files = _user_files(args)
    results = parse_files(files + args.gvl, args.cache, args.jobs, args.user)
    file_results, list_results = results[:len(files)], results[len(files):]
    natives = file_results[:len(args.native)]
    groups = [natives + [r] for r in file_results[len(natives):]] if args.separately else [file_results]
    failed = False
    for group in groups:
        try:
            _translate_parsed(group, list_results, args.user, args.native, _namespaces(args))
        except StErrors as e:
            failed = True
            for err in e.errors:
                print(plcopen_read.at_source(err), file=sys.stderr)
    return 1 if failed else 0


def _matiec(args):
    args.user = True
    try:
        files = _user_files(args)
        comp, program, _ = translate(files, args.cache, (), args.jobs, True, args.native, _namespaces(args))
        if comp.dialect_uses:  # each once, in source order (a construct may be looked at twice)
            unique = {str(e): e for e in comp.dialect_uses}
            raise StErrors(sorted(unique.values(), key=lambda e: (e.file, e.line, e.col)))
        text, lines = matiec.source_and_lines(comp, program, matiec.read_tasks(args.tasks))
    except StError as e:
        print(plcopen_read.at_source(e), file=sys.stderr)
        return 1
    except StErrors as e:
        for err in e.errors:
            print(plcopen_read.at_source(err), file=sys.stderr)
        return 1
    out_dir = os.path.dirname(os.path.abspath(args.out))
    write_outputs(out_dir, {os.path.basename(args.out): text})
    if args.line_map:
        with open(args.line_map, "w", encoding="utf-8") as f:
            json.dump(lines, f, indent=0)
    return 0


def _order(args):
    try:
        files = _user_files(args)
        sources = _parsed(parse_files(files, args.cache, args.jobs, args.user))
        order = [src.path for part in user_order(sources, args.native, _namespaces(args)) for src in part] \
            if args.user else declaration_order(sources)
    except StErrors as e:
        for err in e.errors:
            print(plcopen_read.at_source(err), file=sys.stderr)
        return 1
    print("\n".join(order))
    return 0


def _parse_options(parser):
    # The environment's default lets a test suite that starts pacst many times share one cache (and one
    # built parser) without naming it in every command.
    parser.add_argument("--cache", default=os.environ.get("PACST_CACHE") or None,
                        help="folder for the per-file parse cache (default: $PACST_CACHE, else none); several "
                             "joined by ':': the first is written, the others only read")
    parser.add_argument("-j", "--jobs", type=int,
                        help="processes that parse the files the cache lacks (default: one per core)")


def _user_options(parser):
    parser.add_argument("--user", action="store_true",
                        help="user-program mode: PROGRAMs, global variable lists, located variables, VAR_EXTERNAL, "
                             "sized STRINGs and the string functions besides the library's subset")
    parser.add_argument("--native", action="append", default=[], metavar="FILE",
                        help="(--user) an ST file whose FUNCTIONs the host implements in C; each call passes "
                             "the ST file and line of the call")
    parser.add_argument("--namespace", action="append", default=[], metavar="NAME=DIR",
                        help="(--user) the declarations of the files under DIR may be written NAME.Decl (a library "
                             "referenced with its namespace: PA_CONTROL=st)")
    parser.add_argument("--library", action="append", default=[], metavar="NAME=PATH",
                        help="(--user) a library of the program's own, referenced under the namespace NAME: a "
                             ".plcproj (or its folder), a PLCopen XML project (its objects written to the --sources "
                             "folder's NAME/) or a folder of .st and TwinCAT files")
    parser.add_argument("--sources", dest="sources_dir", metavar="DIR",
                        help="(--user) folder for the ST files of a PLCopen XML project (default: a temporary one)")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="pacst", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    build = sub.add_parser("build", help="translate ST files (in declaration order) to C")
    build.add_argument("--out", required=True, help="folder for POUS.h, pacst_iec.h and one .c per ST file")
    _parse_options(build)
    build.add_argument("--gvl", action="append", default=[], metavar="FILE",
                       help="a global constant list: checked, checked against the POUs' constants, written as FILE.h")
    build.add_argument("--stamp", help="file written after a successful build, removed after a refusal")
    build.add_argument("--checked-library", metavar="FILE",
                       help="(--user) a library's checked state written by `pacst library`: its files are not parsed "
                            "or checked again where the file stands for them (else it is left alone)")
    build.add_argument("--line-directives", action="store_true",
                       help="precede each statement's C with #line naming its ST line (coverage, debuggers)")
    _user_options(build)
    build.add_argument("--strict-narrowing", action="store_true",
                       help="user mode: refuse an implicit narrowing (DINT to INT) instead of taking it with a warning")
    build.add_argument("-v", "--verbose", action="store_true")
    build.add_argument("files", nargs="+")
    build.set_defaults(run=_build)
    declare = sub.add_parser("declare", help="write POUS.h and the layout check for C++ code of a MATIEC build")
    declare.add_argument("--out", required=True, help="folder for POUS.h, pacst_iec.h and layout_probe.c")
    declare.add_argument("--check-out", required=True, help="folder of MATIEC's POUS.h, for layout_check.c")
    _parse_options(declare)
    declare.add_argument("--gvl", action="append", default=[], metavar="FILE",
                       help="a global constant list: checked, checked against the POUs' constants, written as FILE.h")
    declare.add_argument("--stamp", help="file written after success")
    declare.add_argument("files", nargs="+")
    declare.set_defaults(run=_declare)
    lib = sub.add_parser("library", help="check a library's files in user mode and keep their checked state in a "
                                          "file for `pacst build --user --checked-library`")
    lib.add_argument("--out", required=True, help="the file to write")
    _parse_options(lib)
    _user_options(lib)
    lib.add_argument("files", nargs="+")
    lib.set_defaults(run=_library)
    check = sub.add_parser("check", help="check ST files against the portable subset, generate nothing")
    _parse_options(check)
    check.add_argument("--gvl", action="append", default=[], metavar="FILE",
                       help="a global constant list: checked, and checked against the POUs' constants")
    check.add_argument("--separately", action="store_true", help="check each file as a program of its own")
    _user_options(check)
    check.add_argument("files", nargs="+")
    check.set_defaults(run=_check)
    mat = sub.add_parser("matiec", help="write a user program as one ST file for MATIEC's iec2c, with the "
                                         "CONFIGURATION, RESOURCE and TASKs it needs")
    mat.add_argument("--out", required=True, help="the ST file to write")
    mat.add_argument("--tasks", help="JSON: {\"PRG_Name\": {\"task\": \"Fast\", \"interval\": \"T#10MS\", "
                                     "\"priority\": 1}}; a PROGRAM not listed runs in PacTask every 10 ms")
    mat.add_argument("--line-map", help="JSON file: where each POU's body in the written file came from, "
                                        "[[line there, ST file, line in it], ...] (for #line directives)")
    _parse_options(mat)
    _user_options(mat)
    mat.add_argument("files", nargs="+")
    mat.set_defaults(run=_matiec)
    order = sub.add_parser("order", help="print ST files in declaration order: a type, enumeration or POU "
                                         "before every file that uses it, ties by file name")
    _parse_options(order)
    _user_options(order)
    order.add_argument("files", nargs="+")
    order.set_defaults(run=_order)
    args = parser.parse_args(argv)
    try:
        return args.run(args)
    except StError as e:  # a project file that cannot be read (.plcproj, PLCopen XML): no traceback
        print(e, file=sys.stderr)
        return 1
    except StErrors as e:  # a PLCopen XML project several of whose objects cannot be read
        print("\n".join(str(err) for err in e.errors), file=sys.stderr)
        return 1
