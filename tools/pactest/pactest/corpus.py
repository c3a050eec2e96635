"""pac-test-corpus: how much of real TwinCAT 3 and CODESYS projects pac-test's translator takes (docs/user_dialect.md).

For each project under the folders given (a folder holding a .plcproj, or a folder of TwinCAT files), every
.TcPOU, .TcDUT, .TcGVL and .TcIO is parsed and the parsed ones translated together by `pacst --user` with what
pac-test gives a program: its test vocabulary, the vendor libraries' parts it provides (Tc2_System's) and, for
sources that name it, TcUnit's FB_TestSuite (for a project that declares TcUnit itself, the vendor parts only). A file
is accepted when no refusal names it; a refused file is removed and the rest translated again, so that what
depends on it is counted as such. A project is translated with the libraries its .plcproj references that are
projects measured too (matched by title or name and company; pac-test-corpus A/Lib A/App gives App the library Lib
under the namespace its reference names), as `pac-test --library` gives them. A PLCopen XML export (CODESYS's) is a
project of its own, read by pac-test's PLCopen reader: each object it reads is translated so, each it refuses (a body
in LD, FBD or SFC...) counted with the reader's reason. Prints each project's counts and the
refusals by reason (the names in a reason replaced by '…'), and with --json writes them."""
import argparse
import collections
import json
import os
import re
import subprocess
import sys

from . import project

KINDS = {".tcpou": "POU", ".tcdut": "DUT", ".tcgvl": "GVL", ".tcio": "ITF", ".tctleo": "DUT"}
# a refusal caused by another file's refusal, not by the file's own ST
_DEPENDS = re.compile(r"declaration was refused|undeclared (type|name)|has no (variable|member|METHOD)|"
                      r"called before its declaration|cannot be used: (its declaration|a declaration of the global "
                      r"variable list)", re.I)
# a refusal for a vendor library: pac-test says so, or the name it quotes is one of a vendor library's
_VENDOR = re.compile(r"vendor library|'(Tc[23]_\w+|Sys\w+|SM3_\w+|CmpSys\w*|TwinCAT_\w+)\b")
# a name of a library missing because the library's own declaration of it was refused
_LIBRARY_LACKS = re.compile(r"the library (\w+) has no (?:type or POU|declaration) '(\w+)'")
# a refusal for a library of another project not given (an unknown namespace that is no vendor's), or, for a
# library given, a name it lacks (the library's version measured is not the one the project was written against)
_LIBRARY = re.compile(r"is no library namespace")
# an undeclared name before a dot: a library's namespace, unless it is the name of a file refused (and removed)
_UNDECLARED_HEAD = re.compile(r"undeclared name '(\w+)': no variable, global list, PROGRAM or library namespace")


def _translator():
    sys.path.insert(0, os.environ.get("PACTEST_TRANSLATOR", os.path.join(project.ROOT, "translator")))
    from pacst import cli, errors, parsing  # noqa: E402 (the checkout's translator)
    return cli, errors, parsing


def is_plcopen(path):
    """Whether `path` is a PLCopen XML export (TC6 2.00, as CODESYS 3.5 and TwinCAT 3 write it): its root element
    is a project in PLCopen's namespace."""
    try:
        with open(path, "rb") as f:
            head = f.read(4096)
    except OSError:
        return False
    return re.search(rb"<project\b[^>]*xmlns=\"http://www\.plcopen\.org/xml/tc6_0200\"", head) is not None


def projects(folders):
    """{project folder: [its TwinCAT files]}: a folder holding a .plcproj is a project with every TwinCAT file
    below it; TwinCAT files under no .plcproj belong to the folder given. A PLCopen XML export (a folder's, or
    a file given) is a project of its own: {its path: [its path]}."""
    found = collections.OrderedDict()
    for top in folders:
        if os.path.isfile(top):
            if is_plcopen(top):
                found[top] = [top]
            continue
        roots = sorted({d for d, _, names in os.walk(top) if any(n.lower().endswith(".plcproj") for n in names)})
        for d, _, names in sorted(os.walk(top)):
            for n in sorted(names):
                path = os.path.join(d, n)
                if n.lower().endswith(".xml") and is_plcopen(path):
                    found[path] = [path]
                if os.path.splitext(n)[1].lower() not in KINDS:
                    continue
                owner = max((r for r in roots if path.startswith(r + os.sep)), key=len, default=top)
                found.setdefault(owner, []).append(path)
    return found


def reason(message):
    """A refusal's message without the names it quotes, so that refusals count by construct."""
    text = re.sub(r"'[^']*'", "'…'", message)
    return re.sub(r"\b\d+\b", "n", text)


def _given(files, theirs=()):
    """What pac-test translates with a project's `files` and its libraries' files `theirs`: (extra files, native
    files, namespaces); the vendor parts given on demand are given for the libraries' sources too, as pac-test
    gives them (build.py)."""
    names = {os.path.splitext(os.path.basename(f))[0].upper() for f in files}
    namespaces = {name.upper(): (name, folder) for name, folder in project.vendor_libraries().items()}
    every = list(files) + list(theirs)
    if names & {"FB_TESTSUITE", "TEST", "TEST_FINISHED"}:  # TcUnit itself: its own names, Tc2_System's parts
        return project.vendor_sources(every, named_only=True), project.vendor_natives(every), namespaces
    extra = project.vocabulary_sources() + project.vendor_sources(every, named_only=True)
    native = project.native_sources() + project.vendor_natives(every)
    if not project.uses_tcunit(files):
        return extra, native, namespaces
    namespaces["TCUNIT"] = ("TcUnit", project.TCUNIT)
    return extra + project.tcunit_sources(files), native + project.tcunit_natives(), namespaces


def _plcproj(root):
    """The .plcproj of a project folder, or None."""
    found = sorted(n for n in os.listdir(root) if n.lower().endswith(".plcproj")) if os.path.isdir(root) else []
    return os.path.join(root, found[0]) if found else None


def _project_info(root):
    """(the names a reference may give the project's library by, its default namespace, [(referenced library's
    name, company, namespace or None)]) of the .plcproj in `root`; nothing for a folder without one."""
    path = _plcproj(root)
    if path is None:
        return set(), None, []
    from lxml import etree  # the translator's venv's
    try:
        tree = etree.parse(path)
    except etree.XMLSyntaxError:
        return set(), None, []

    def text(element, tag):
        found = element.find(f"{{*}}{tag}") if element is not None else None
        return found.text.strip() if found is not None and found.text else None
    group = tree.getroot().find("{*}PropertyGroup")
    company = text(group, "Company")
    names = {(n, company) for n in (text(group, "Title"), text(group, "Name")) if n}
    namespace = text(group, "DefaultNamespace") or text(group, "Title")
    references = []
    for ref in list(tree.iter("{*}PlaceholderReference")) + list(tree.iter("{*}LibraryReference")):
        resolution = text(ref, "DefaultResolution") or ref.get("Include", "")
        m = re.match(r"\s*([^,]+?)\s*,.*?\(([^)]*)\)\s*$", resolution)
        name, by = (m.group(1), m.group(2)) if m else (ref.get("Include", "").split(",")[0], None)
        references.append((name, by, text(ref, "Namespace")))
    return names, namespace, references


def dependencies(roots):
    """{project folder: [(namespace, library's project folder)]}: each library a project references that is one of
    the projects measured (matched by its title or name and its company), under the reference's namespace or the
    library's default one, with the libraries those reference in turn; a library pac-test gives itself (TcUnit,
    Tc2_Standard...) is left to pac-test's own."""
    info = {root: _project_info(root) for root in roots}
    reserved = project.reserved_namespaces()
    found = {}
    for root in roots:
        deps, todo = [], [root]
        while todo:
            for name, company, namespace in info[todo.pop()][2]:
                library = next((r for r in roots if r != root and any(
                    n == name and (company is None or c in (None, company)) for n, c in info[r][0])), None)
                if library is None:
                    continue
                namespace = namespace or info[library][1] or name
                if namespace.upper() in reserved or any(f == library for _, f in deps):
                    continue
                deps.append((namespace, library))
                todo.append(library)
        found[root] = deps
    return found


def _version(root):
    """The ProjectVersion of the .plcproj in `root`, or None."""
    path = _plcproj(root)
    if path is None:
        return None
    with open(path, encoding="utf-8-sig", errors="replace") as f:
        m = re.search(r"<ProjectVersion>\s*([^<\s]+)\s*</ProjectVersion>", f.read())
    return m.group(1) if m else None


def version_mismatches(root, deps):
    """[(namespace, version built against, version measured)] of the libraries `deps` [(namespace, folder)] whose
    version in the project's _Libraries folder (TwinCAT keeps there the library the project was compiled with:
    _Libraries/<company>/<title>/<version>/) is not the version of the library project measured: the names the
    project uses that the measured version lacks are counted as a library not given, not as refusals."""
    found = []
    for namespace, folder in deps:
        measured = _version(folder)
        titles = {n.lower() for n, _ in _project_info(folder)[0]}
        built = sorted({os.path.basename(d) for d, _, _ in os.walk(root)
                        if os.path.basename(os.path.dirname(d)).lower() in titles
                        and "_libraries" in d.lower().split(os.sep)})
        if measured and built and measured not in built:
            found.append((namespace, built[-1], measured))
    return found


def _library_files(root, files):
    """The `files` of the project in `root` that pac-test reads of it as a library (pacst --library): without the
    POUs TwinCAT generates into a library project (F_GetVersion...)."""
    plcproj = _plcproj(root)
    if plcproj is None:
        return files
    _translator()
    from pacst import twincat  # noqa: E402 (the checkout's translator)
    kept = {os.path.abspath(f) for f in twincat.project_files(plcproj, generated=False)}
    generated = {os.path.abspath(f) for f in twincat.project_files(plcproj)} - kept
    return [f for f in files if os.path.abspath(f) not in generated]


def _namespace_of_nothing(message, removed):
    """Whether `message` refuses an undeclared name before a dot that no refused file had: a library's namespace."""
    m = _UNDECLARED_HEAD.search(message)
    return m is not None and m.group(1).upper() not in removed


_UNDECLARED_TYPE = re.compile(r"undeclared type '(\w+)'")


def _undeclared_of_a_library(message, removed):
    """Whether `message` refuses a type that no refused file declared: in a PLCopen XML export, which holds every
    object of the application, a type of a library it references."""
    m = _UNDECLARED_TYPE.search(message)
    return m is not None and m.group(1).upper() not in removed


_UNDECLARED_CALL = re.compile(r"undeclared function '(\w+)'|unknown conversion (\w+)")


def _calls_removed(message, removed):
    """Whether `message` refuses a call of a FUNCTION whose file was refused (and removed): a call that depends on
    that refusal, as `cannot be called: its declaration was refused` says where the file is kept."""
    m = _UNDECLARED_CALL.search(message)
    return m is not None and (m.group(1) or m.group(2)).upper() in removed


def _lacks_refused(message, gone):
    """Whether `message` says a library lacks a name whose file in it was refused."""
    m = _LIBRARY_LACKS.search(message)
    return m is not None and m.group(2).upper() in gone


def measure(files, cache, jobs, libraries=(), refused_names=(), export=False):
    """{file: None (accepted) or (kind of refusal, first message)} for one project's `files`, translated with its
    `libraries` [(namespace, folder, files)] as pac-test translates a program with --library; `refused_names`: the
    names of the project's objects refused before (a PLCopen export's objects its reader refused); `export`: the
    files are a whole PLCopen export's, so a type none of them declares is a library's."""
    cli, errors, parsing = _translator()
    theirs = [f for _, _, library_files in libraries for f in library_files if f not in files]
    extra, native, namespaces = _given(files, theirs)
    for namespace, folder, _ in libraries:
        namespaces.setdefault(namespace.upper(), (namespace, folder))
    verdict = {}
    sources = []
    every = files + theirs + extra
    for path, result in zip(every, parsing.parse_files(every, cache, jobs, user=True)):
        if isinstance(result, errors.StError):
            verdict[path] = ("syntax", f"{result.line}: {result.message}")
        else:
            sources.append(result)
    gone = {os.path.splitext(os.path.basename(p))[0].upper() for p in theirs if p in verdict}  # libraries' refused
    removed = {os.path.splitext(os.path.basename(p))[0].upper() for p in verdict} | gone  # every file refused
    removed |= {name.upper() for name in refused_names}
    for _ in range(12):
        if not sources:
            break
        try:
            by_path = {s.path: s for s in sources}
            # as pacst --user translates: the libraries first (their checked state kept for the next round)
            cli._translate_parsed(sources, [], True, native, namespaces)
            break
        except errors.StErrors as e:
            refused = collections.OrderedDict()
            for err in e.errors:
                refused.setdefault(err.file, []).append(err)
        except errors.StError as err:
            refused = {err.file: [err]}
        if not any(p in refused for p in by_path if p not in extra):  # a refusal of no file: count every file as refused by it
            for p in by_path:
                verdict[p] = ("translation", str(next(iter(refused.values()))[0].message))
            sources = []
            break
        gone.update(os.path.splitext(os.path.basename(p))[0].upper() for p in refused if p in theirs)
        removed.update(os.path.splitext(os.path.basename(p))[0].upper() for p in refused)
        for path, errs in refused.items():
            own = [x for x in errs if (not _DEPENDS.search(x.message) or _namespace_of_nothing(x.message, removed)
                                       or export and _undeclared_of_a_library(x.message, removed))
                   and not _lacks_refused(x.message, gone) and not _calls_removed(x.message, removed)]
            first = (own or errs)[0]
            lacks = _LIBRARY_LACKS.search(first.message)
            kind = ("depends on a refused declaration" if not own
                    else "vendor library" if _VENDOR.search(first.message)
                    else "library not given" if _LIBRARY.search(first.message) or lacks and lacks.group(1).upper()
                    in {namespace.upper() for namespace, _, _ in libraries} or _namespace_of_nothing(first.message,
                                                                                                   removed)
                    or export and _undeclared_of_a_library(first.message, removed)
                    else "refused construct")
            verdict.setdefault(path, (kind, f"{first.line}: {first.message}"))
        sources = [s for s in sources if s.path not in refused]
    for s in sources:
        verdict.setdefault(s.path, None)
    return {f: verdict[f] for f in files}


# the kinds of a PLCopen object's refusal by pac-test's PLCopen reader, before any translation
BODY_NOT_ST = "body not in ST"
READER = "refused by the PLCopen reader"


def measure_plcopen(xml, cache, jobs):
    """({"XML#object": verdict} as measure() gives them, [the keys of its POUs]) of the PLCopen XML export `xml`,
    read by pac-test's PLCopen reader: each object it reads (types/pous, and the application's objects under
    instances/.../resource) translated as pac-test translates them, each it refuses counted with the reader's
    reason (a body in LD, FBD, SFC, IL or CFC as BODY_NOT_ST). Lines are the XML file's, as CODESYS shows them."""
    import tempfile
    _translator()
    from lxml import etree
    from pacst import plcopen_read  # noqa: E402 (the checkout's translator, as pac-test runs it)
    with open(xml, "rb") as f:
        data = f.read()
    try:
        objects, refused = plcopen_read.read_objects(data)
    except (etree.XMLSyntaxError, plcopen_read.PlcopenReadError) as exc:
        return {xml: (READER, f"{getattr(exc, 'lineno', None) or 1}: cannot read the PLCopen project: {exc}")}, [xml]
    verdict, pous, names = {}, [], []
    for exc in refused:
        element = exc.element
        name = element.get("name") if element is not None else None
        key = f"{xml}#{name or exc.lineno}"
        text = str(exc)
        if name and text.startswith(name):  # the name quoted, so that refusals count by reason
            text = f"'{name}'{text[len(name):]}"
        verdict[key] = (BODY_NOT_ST if " is implemented in " in text else READER, f"{exc.lineno or 1}: {text}")
        names.append(name or "")
        if element is not None and etree.QName(element).localname == "pou":
            pous.append(key)
    with tempfile.TemporaryDirectory(prefix="pac-test-corpus-") as out:
        paths = plcopen_read.write_objects(xml, objects, out)
        found = measure(paths, cache, jobs, refused_names=names, export=True)
    for path, obj in zip(paths, objects):
        key = f"{xml}#{obj.name}"
        result = found[path]
        if result is not None:  # the XML file's line of the ST line refused
            line, text = result[1].split(": ", 1)
            result = (result[0], f"{plcopen_read.xml_position(xml, obj, int(line))[0]}: {text}")
        verdict[key] = result
        if obj.kind in ("function", "functionBlock", "program"):
            pous.append(key)
    return verdict, pous


def _in_translator_venv(argv):
    """Runs this command again with the translator's Python (build/venv, which holds blark) when this one
    lacks it, as pac-test runs pacst; None when this Python will do."""
    try:
        import blark  # noqa: F401
        return None
    except ImportError:
        python = os.path.join(project.ROOT, "build", "venv", "bin", "python")
        if not os.path.exists(python):
            sys.exit("pac-test-corpus: no translator venv (build/venv): run cmake --preset default first")
        here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        env = dict(os.environ, PYTHONPATH=here + os.pathsep + os.environ.get("PYTHONPATH", ""))
        return subprocess.run([python, "-m", "pactest.corpus", *argv], env=env).returncode


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    code = _in_translator_venv(argv)
    if code is not None:
        return code
    parser = argparse.ArgumentParser(prog="pac-test-corpus", description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", help="folders of TwinCAT 3 projects and PLCopen XML exports, or "
                        "export files (checked out, never committed)")
    parser.add_argument("--cache", help="pacst's parse cache (a folder; makes a second run fast)")
    parser.add_argument("-j", "--jobs", type=int, default=None, help="parallel parses (default: one per core)")
    parser.add_argument("--json", help="write the counts and every refusal to this file")
    args = parser.parse_args(argv)
    totals = collections.Counter()
    reasons = collections.Counter()
    report = {"projects": []}
    found = projects(args.folders)
    libraries = dependencies(list(found))
    for root, files in found.items():
        if files == [root]:  # a PLCopen XML export
            verdict, pous = measure_plcopen(root, args.cache, args.jobs)
            files = list(verdict)
        else:
            given = [(namespace, folder, _library_files(folder, found[folder])) for namespace, folder in libraries[root]]
            verdict = measure(files, args.cache, args.jobs, given)
            pous = [f for f in files if f.lower().endswith(".tcpou")]
        counts = collections.Counter("accepted" if verdict[f] is None else verdict[f][0] for f in pous)
        totals.update(counts)
        totals["POUs"] += len(pous)
        for f in pous:
            if verdict[f] is not None and verdict[f][0] != "depends on a refused declaration":
                reasons[(verdict[f][0], reason(verdict[f][1].split(": ", 1)[1]))] += 1
        with_libraries = f" (with {', '.join(f'{n}: {f}' for n, f in libraries[root])})" if libraries[root] else ""
        print(f"{root}{with_libraries}: {len(pous)} POUs, {counts['accepted']} accepted; "
              + ", ".join(f"{n} {k}" for k, n in sorted(counts.items()) if k != "accepted"))
        mismatches = version_mismatches(root, libraries[root])
        for namespace, built, measured in mismatches:
            print(f"  built against {namespace} {built} (its _Libraries folder), measured with {namespace} {measured}: "
                  "the names that version lacks count as a library not given")
        report["projects"].append({"folder": root, "pous": len(pous), "counts": dict(counts),
                                   "libraries": {n: f for n, f in libraries[root]},
                                   "library_versions": {n: {"built against": b, "measured": m}
                                                        for n, b, m in mismatches},
                                   "files": {f: verdict[f] for f in files}})
    share = 100.0 * totals["accepted"] / totals["POUs"] if totals["POUs"] else 0.0
    print(f"total: {totals['POUs']} POUs, {totals['accepted']} accepted ({share:.1f} %), "
          f"{totals['syntax']} refused by the parser, {totals['refused construct']} for a construct, "
          f"{totals['vendor library']} needing a vendor library, "
          f"{totals['depends on a refused declaration']} depending on a refused declaration, "
          f"{totals['library not given']} needing a library of another project not measured (or a name the "
          f"library measured lacks), {totals[BODY_NOT_ST]} with a body not in ST (LD, FBD, SFC...), "
          f"{totals[READER]} refused by the PLCopen reader")
    print("refusals by reason (the POU's first):")
    for (kind, text), n in reasons.most_common():
        print(f"  {n:4d}  {kind}: {text}")
    report["totals"] = dict(totals)
    report["reasons"] = [{"kind": k, "reason": r, "pous": n} for (k, r), n in reasons.most_common()]
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(report, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
