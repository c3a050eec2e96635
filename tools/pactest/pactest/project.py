"""Where pac-test finds the project's pieces: the library's ST, the test vocabulary, the translator, and a
configured build of the project holding the runtime, simulator and rig libraries the host links against."""
import glob
import os
import re
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
# The library's namespace in CODESYS and TwinCAT (docs/import.md): a program writes PA_CONTROL.MC_Power.
NAMESPACE = "PA_CONTROL"
VOCABULARY = os.path.join(ROOT, "tools", "pactest", "st")
HOST = os.path.join(ROOT, "tools", "pactest", "host")
# TcUnit's FB_TestSuite, RUN and RUN_IN_SEQUENCE, under the namespace TcUnit (docs/user_tests.md)
TCUNIT = os.path.join(ROOT, "tools", "pactest", "tcunit")

# The static libraries the host links, in link order, and where a build tree keeps them (not below:
# build/ holds the other presets' trees, build/debug...).
LIBRARIES = ["pac_scenario_lib", "pac_scenario_loader", "pac_names", "pac_rig", "pac_st", "pac_sim", "pac_runtime"]
LIBRARY_DIRS = {"pac_scenario_lib": "scenario", "pac_scenario_loader": "scenario", "pac_names": "runtime/names",
                "pac_rig": "rig", "pac_st": "st", "pac_sim": "sim", "pac_runtime": "runtime"}
INCLUDES = ["runtime/include", "sim/include", "rig/include", "runtime/names/include", "scenario",
            "translator/pacst/include"]


def translator():
    """The checkout's translator (PACTEST_TRANSLATOR: another checkout's) importable as `pacst`, as pac-test runs it."""
    path = os.environ.get("PACTEST_TRANSLATOR", os.path.join(ROOT, "translator"))
    if path not in sys.path:
        sys.path.insert(0, path)


def reserved_namespaces():
    """{upper namespace: what pac-test gives under it}: no library of the program's own may take one."""
    names = {NAMESPACE: "the PA-CONTROL library", "TC2_STANDARD": "the standard library", "STANDARD": "the standard "
             "library", "TCUNIT": "TcUnit's suite"}
    names.update((name.upper(), f"its part of the vendor library {name}") for name in vendor_libraries())
    return names


class LibraryError(Exception):
    """A library of the program's own that pac-test cannot take, with where it is given."""


def check_libraries(libraries):
    """A program's own libraries, [(namespace, path, where given)]: raises LibraryError, naming where the library
    is given, for a namespace pac-test gives itself, a namespace or a library given twice, a path that is no
    library."""
    translator()
    from pacst import libraries as pacst_libraries  # noqa: E402 (the checkout's translator)
    reserved = reserved_namespaces()
    for name, _, label in libraries:
        if name.upper() in reserved:
            raise LibraryError(f"{label}: the namespace {name} is pac-test's, for {reserved[name.upper()]}: "
                               "reference your library under another")
    try:
        pacst_libraries.check([(name, path) for name, path, _ in libraries], [label for _, _, label in libraries])
    except pacst_libraries.LibraryError as e:
        raise LibraryError(str(e)) from None


def library_folders(libraries, out):
    """The folders whose declarations the program's own libraries hold (a PLCopen XML library's: OUT/plcopen/NAME)."""
    translator()
    from pacst import libraries as pacst_libraries  # noqa: E402
    return [pacst_libraries.folder(name, path, os.path.join(out, "plcopen")) for name, path, _ in libraries]


def library_sources():
    """The library's ST files: every .st under st/ but the global constant list, which goes in --gvl."""
    files = sorted(glob.glob(os.path.join(ROOT, "st", "**", "*.st"), recursive=True))
    return [f for f in files if os.sep + "gvl" + os.sep not in f]


def gvl_pac():
    return os.path.join(ROOT, "st", "gvl", "GVL_PAC.st")


def vocabulary_sources():
    return sorted(glob.glob(os.path.join(VOCABULARY, "*.st")))


# TcUnit's array asserts: only for sources that call one. Their ARRAY [*] pins are read by blark's slow parser
# (about 11 s of CPU for the file when pacst's parse cache does not hold it yet), which other programs need not pay.
_ARRAY_ASSERTS = "AssertArrayEquals.st"
_ARRAY_ASSERT = re.compile(rb"\bAssertArray\w*Equals_", re.I)


# TcUnit's WRITE_PROTECTED_ functions: only for sources that call one.
_WRITE_PROTECTED = "WRITE_PROTECTED.st"
_WRITE_PROTECTED_CALL = re.compile(rb"\bWRITE_PROTECTED_\w+", re.I)
# TcUnit's FB_Test: only for sources that name it and do not declare an FB_Test of their own.
_RECORD = "FB_Test.st"
_RECORD_NAME = re.compile(rb"\bFB_Test\b", re.I)


def tcunit_sources(sources=None):
    """TcUnit's part pac-test gives a program that names its suite; the array asserts and the WRITE_PROTECTED_
    functions only when the program's `sources` call one, FB_Test only when they name it and declare none (None:
    every part)."""
    every = sorted(glob.glob(os.path.join(TCUNIT, "*.st")))
    if sources is None:
        return every
    texts = _texts(sources)
    left = set() if any(_ARRAY_ASSERT.search(t) for t in texts) else {_ARRAY_ASSERTS}
    if not any(_WRITE_PROTECTED_CALL.search(t) for t in texts):
        left.add(_WRITE_PROTECTED)
    if not any(_RECORD_NAME.search(t) for t in texts) or "FB_TEST" in declared_names(sources):
        left.add(_RECORD)
    return [f for f in every if os.path.basename(f) not in left]


VENDOR = os.path.join(ROOT, "tools", "pactest", "vendor")
# The vendor FUNCTIONs the host implements (pactest_natives.cpp); the other parts are ST, run as they are.
VENDOR_NATIVES = {"F_GetSystemTime", "PacTestTaskCycles", "PacTestTaskCycleTime"}


def vendor_libraries():
    """{namespace: folder} of the vendor libraries' parts pac-test provides (docs/user_dialect.md)."""
    return {name: os.path.join(VENDOR, name) for name in sorted(os.listdir(VENDOR))
            if os.path.isdir(os.path.join(VENDOR, name))}


# Vendor parts given (named_only) only to a program whose sources name them, or whose other parts given name them:
# each part given costs every program CPU to translate and compile (the first two, 0.5 s of user CPU for
# examples/pick_and_place on 7 December 2026); and so every part of the libraries below.
_ON_DEMAND = ("LREAL_TO_FMTSTR", "WSTRNCPY", "F_GetTaskTime", "FB_MemRingBuffer", "F_ToLCase", "F_ToUCase",
              "BYTE_TO_HEXSTR", "WORD_TO_HEXSTR", "DWORD_TO_HEXSTR", "LWORD_TO_HEXSTR", "PacTestHexDigits",
              "FB_FormatString", "T_Arg", "E_ArgType", "FILETIME64_TO_SYSTEMTIME",
              "WORD_TO_DECSTR")
_ON_DEMAND_LIBRARIES = ("SysFile", "SysTypes", "SysDir", "CmpErrors", "SysMem")


def vendor_sources(sources=(), named_only=False):
    """The vendor parts' files, but those declaring a name the user's `sources` declare themselves (a program's
    own TIMESTRUCT or FLOOR stays the program's); `named_only`: and the parts on demand only where the sources, or
    the parts given, name them."""
    theirs = declared_names(sources)
    files = [f for folder in vendor_libraries().values() for f in sorted(glob.glob(os.path.join(folder, "*.st")))
             if os.path.splitext(os.path.basename(f))[0].upper() not in theirs]
    if not named_only:
        return files
    lazy = {f: _part_pattern(f) for f in files if os.path.splitext(os.path.basename(f))[0] in _ON_DEMAND
            or os.path.basename(os.path.dirname(f)) in _ON_DEMAND_LIBRARIES}
    given, texts = set(), _texts(sources)
    while texts:  # the parts the sources name, then those the parts given name
        found = {f for f, pattern in lazy.items() if f not in given and any(pattern.search(t) for t in texts)}
        given |= found
        texts = _texts(sorted(found))
    return [f for f in files if f not in lazy or f in given]


def _texts(sources):
    """The bytes of each of the user's source files (read once for every pattern)."""
    texts = []
    for path in _files(sources, (".tcpou", ".st")):
        try:
            with open(path, "rb") as f:
                texts.append(f.read())
        except OSError:
            continue
    return texts


def _part_pattern(path):
    """What names a vendor part on demand: its name (a global list: its variables' too)."""
    names = [re.escape(os.path.splitext(os.path.basename(path))[0])]
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if "VAR_GLOBAL" in text:
        names += [re.escape(n) for n in re.findall(r"^\s*(\w+)\s*:", text, re.M)]
    return re.compile(rb"\b(?:" + "|".join(names).encode() + rb")\b", re.I)


def vendor_natives(sources=()):
    """The vendor FUNCTIONs the host implements (F_GetSystemTime: the simulated clock; the running task's cycles)."""
    return [f for f in vendor_sources(sources) if os.path.splitext(os.path.basename(f))[0] in VENDOR_NATIVES]


def tcunit_natives():
    """TcUnit's FUNCTIONs the host implements: TEST, TEST_FINISHED_NAMED, IS_TEST_FINISHED, the asserts (not the
    array asserts: ST, each recording through PacTestRecord)."""
    return [f for f in tcunit_sources() if os.path.basename(f).startswith(("TEST", "IS_TEST", "Assert"))
            and not os.path.basename(f).startswith("AssertArray")]


_TCUNIT = re.compile(rb"\bTcUnit\s*\.|\bFB_TestSuite\b", re.I)


def uses_tcunit(sources):
    """Whether the user's sources (files, a .plcproj standing for the files below its folder) name TcUnit's
    suite: only then are TcUnit's names (TEST, RUN...) declared, which a program may use for its own."""
    return _names(sources, _TCUNIT)


def uses_vendor(sources):
    """Whether the user's sources name what pac-test provides of a vendor library: a library's namespace
    (Tc2_System.), a part's name (T_MaxString) or a constant of its global lists (MAX_STRING_LENGTH)."""
    names = [re.escape(n) + r"\s*\." for n in vendor_libraries()]
    for path in vendor_sources(sources):
        names.append(re.escape(os.path.splitext(os.path.basename(path))[0]))
        if os.path.basename(path).startswith("GVL_"):
            with open(path, encoding="utf-8") as f:
                names += re.findall(r"^\s*(\w+)\s*:", f.read(), re.M)
    return _names(sources, re.compile(rb"\b(?:" + "|".join(names).encode() + rb")\b", re.I))


# a declaration's name in ST or a TwinCAT object (<Declaration><![CDATA[FUNCTION_BLOCK PUBLIC FB_X), TYPE T_X :
_DECLARATION = re.compile(rb"^(?:.*<!\[CDATA\[)?\s*(?:FUNCTION_BLOCK|FUNCTION|PROGRAM|INTERFACE|TYPE)\s+"
                          rb"(?:(?:PUBLIC|INTERNAL|ABSTRACT|FINAL)\s+)*(\w+)", re.I | re.M)


def declared_names(sources):
    """The upper-case names the user's sources declare (POUs, types, interfaces)."""
    found = set()
    for path in _files(sources, (".tcpou", ".tcdut", ".tcio", ".st")):
        try:
            with open(path, "rb") as f:
                found.update(m.group(1).decode("ascii", "replace").upper() for m in _DECLARATION.finditer(f.read()))
        except OSError:
            continue
    return found


def _files(sources, extensions):
    """The files of the user's sources (a .plcproj or a folder stands for the files below it)."""
    files = []
    for path in sources:
        if path.lower().endswith(".plcproj") or os.path.isdir(path):  # a library may be a folder
            top = path if os.path.isdir(path) else os.path.dirname(path)
            files += [os.path.join(d, n) for d, _, names in os.walk(top) for n in names
                      if n.lower().endswith(extensions)]
        else:
            files.append(path)
    return files


def _names(sources, pattern):
    """Whether `pattern` occurs in the user's sources."""
    for path in _files(sources, (".tcpou", ".st")):
        try:
            with open(path, "rb") as f:
                if pattern.search(f.read()):
                    return True
        except OSError:
            continue
    return False


def native_sources():
    """The vocabulary's FUNCTIONs, which the host implements (pactest_natives.cpp): every file but the
    global list and the FBs."""
    return [f for f in vocabulary_sources() if not os.path.basename(f).startswith(("FB_", "GVL_"))]


class PacBuild:
    """A configured and built tree of the project (cmake --preset default: build/)."""

    def __init__(self, folder):
        self.folder = os.path.abspath(folder)
        cache = os.path.join(self.folder, "CMakeCache.txt")
        if not os.path.exists(cache):
            raise SystemExit(f"pac-test: {self.folder} is not a build of the PA-CONTROL project "
                             "(configure and build it first: cmake --preset default && cmake --build build)")
        with open(cache, encoding="utf-8") as f:
            self.cache = dict(re.findall(r"^([A-Za-z_0-9]+):[A-Z]+=(.*)$", f.read(), re.M))
        # a MATIEC build: pac-test compiles the library and the user's ST with its iec2c (matiec.py)
        self.matiec = None
        if self.cache.get("PAC_ST_COMPILER", "pacst") == "matiec":
            self.matiec = (self.cache.get("IEC2C", ""), self.cache.get("MATIEC_LIB", ""))
        # the library's objects carry gcov's counters in a coverage build: the host links with --coverage
        self.coverage = self.cache.get("PAC_COVERAGE", "OFF").upper() in ("ON", "1", "TRUE", "YES")
        self.sanitize = self.cache.get("PAC_SANITIZE", "OFF").upper() in ("ON", "1", "TRUE", "YES")
        # pacst's parse cache of the build (the library's parses): pac-test reads it beneath a run's own
        self.parse_cache = self.cache.get("PACST_CACHE_DIR")
        self.libraries = []
        missing = []
        for name in LIBRARIES:
            path = os.path.join(self.folder, LIBRARY_DIRS[name], f"lib{name}.a")
            if os.path.exists(path):
                self.libraries.append(path)
            else:
                missing.append(name)
        if missing:
            raise SystemExit(f"pac-test: {self.folder} lacks {', '.join(missing)}: build them first "
                             f"(cmake --build {self.folder} --target pac_scenario_lib)")
        # pacst's declarations of the library (in a MATIEC build those C++ code includes)
        self.library_c = os.path.join(self.folder, "st", "pac_st.st-c", *(["decl"] if self.matiec else []))
        if not os.path.exists(os.path.join(self.library_c, "POUS.h")):
            raise SystemExit(f"pac-test: {self.folder} holds no translated library (pac_st.st-c): is it a pacst build?")

    def library_stems(self):
        """The stems of the library's C files in libpac_st.a: pac-test links those, not its own copies."""
        return {os.path.splitext(n)[0] for n in os.listdir(self.library_c) if n.endswith(".c")}

    def include_dirs(self):
        return [os.path.join(ROOT, d) for d in INCLUDES]
