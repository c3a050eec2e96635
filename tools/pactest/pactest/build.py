"""Translating the user's ST with the library and the test vocabulary (pacst --user), generating the host and
compiling it against a build of the project. Objects are kept between runs and rebuilt only when their source
or flags change; ccache is used when it is on the PATH."""
import concurrent.futures
import hashlib
import json
import os
import shutil
import subprocess
import sys

from . import hostgen, project


class BuildError(Exception):
    pass


def _run(command, what, env=None, warnings=False):
    """`command`'s output; BuildError with all it said when it fails. `warnings`: what it says on stderr when it
    succeeds is shown (pacst's warnings), not dropped."""
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    if result.returncode != 0:
        raise BuildError(f"{what} failed:\n{result.stdout}{result.stderr}".rstrip())
    if warnings and result.stderr:
        sys.stderr.write(result.stderr)
    return result.stdout


def compile_to(command, obj, what, whole=False):
    """Runs the compiler `command` writing `obj`, through ccache where it is installed. `whole`: the object
    appears whole or not at all, for one that runs against the same build share (HostBuild._compile); not
    for an object with gcov's counters, whose notes and counters are named after the compiler's output."""
    launcher = [shutil.which("ccache")] if shutil.which("ccache") else []
    if not whole:
        _run(launcher + command + ["-o", obj], what)
        return
    partial = f"{obj}.{os.getpid()}.tmp"
    try:
        _run(launcher + command + ["-o", partial], what)
        os.replace(partial, obj)
    finally:
        if os.path.exists(partial):
            os.remove(partial)


def link(exe, objects, libraries, sanitize, coverage=False):
    """Links the host `exe` as the project's build was compiled (its sanitizers, the coverage counters)."""
    flags = (["--coverage"] if coverage else []) + (["-fsanitize=address,undefined"] if sanitize else [])
    _run([os.environ.get("CXX", "c++"), *flags, "-o", exe, *objects, *libraries, "-lm"], "linking the host")


class HostBuild:
    takes_dialect = True  # pacst's C: the vendor libraries' parts and TcUnit's suite come with the program

    def __init__(self, wiring, pac_build, out, coverage=True, jobs=None, pacst_python=None, parse_cache=None,
                 strict_narrowing=False):
        self.wiring, self.pac, self.out, self.parse_cache = wiring, pac_build, out, parse_cache
        self.strict_narrowing = strict_narrowing  # pacst build --strict-narrowing
        self.coverage, self.jobs = coverage, jobs or os.cpu_count() or 1
        venv_python = os.path.join(project.ROOT, "build", "venv", "bin", "python")
        self.pacst_python = pacst_python or (venv_python if os.path.exists(venv_python) else sys.executable)
        self.st_out = os.path.join(out, "st-c")
        self.obj = os.path.join(out, "obj")
        # pactest_host.cpp sees the library only (the rig, the scenario loader), as the build's libraries do:
        # compiled once per build of the project and shared by every run against it, not once per program.
        self.shared_obj = os.path.join(pac_build.folder, "pactest-host")
        self.exe = os.path.join(out, "pactest_host")
        # the library's checked state, kept by the build (prepare.py): pacst neither parses nor checks st/ again
        self.checked_library = os.path.join(self.shared_obj, "checked-library.pickle")

    def _pacst(self, *args):
        # PACTEST_TRANSLATOR: another checkout's translator folder (to try a translator change on a project)
        translator = os.environ.get("PACTEST_TRANSLATOR", os.path.join(project.ROOT, "translator"))
        env = dict(os.environ, PYTHONPATH=translator)
        cache = self.parse_cache or os.path.join(self.out, "pacst-cache")
        # the build's cache under the run's own, only read: it holds the library's parses and the parser's
        # facts, which a first run would otherwise make again (the library's text is parsed as the build parsed it)
        built = self.pac.parse_cache
        if built and os.path.isdir(built) and os.path.abspath(built) != os.path.abspath(cache):
            cache += os.pathsep + built
        return _run([self.pacst_python, "-m", "pacst", *args[:1], "--cache", cache, *args[1:]], "pacst", env,
                    warnings=True)

    def user_inputs(self):
        """pacst's arguments for the whole program, in any order (pacst --user finds the declaration order): the
        library, GVL_PAC (the program names its constants, PAC_CMD_PUT_INT_REG...), the vocabulary (its FUNCTIONs
        the host's) and the user's sources; a TwinCAT .plcproj stands for its objects, a PLCopen XML project for
        ST files written to OUT/plcopen."""
        # the vendor libraries' parts and TcUnit's suite are dialect: with MATIEC only for a program that names
        # them (which pacst matiec then refuses at its lines)
        theirs = self.wiring.sources + [path for _, path, _ in self.wiring.libraries]
        dialect = self.takes_dialect or project.uses_vendor(theirs)
        tcunit = self.takes_dialect and project.uses_tcunit(theirs)
        vendor = project.vendor_sources(theirs, named_only=True) if dialect else []
        files = project.library_sources() + [project.gvl_pac()] + project.vocabulary_sources() + vendor + \
            (project.tcunit_sources(theirs) if tcunit else []) + self.wiring.sources
        natives = [a for f in project.native_sources() + (project.vendor_natives(theirs) if dialect else []) +
                   (project.tcunit_natives() if tcunit else []) for a in ("--native", f)]
        # the library referenced with its namespace, as docs/import.md tells programmers to: PA_CONTROL.MC_Power
        namespaces = ["--namespace", f"{project.NAMESPACE}={os.path.join(project.ROOT, 'st')}"]
        for name, folder in project.vendor_libraries().items() if dialect else []:  # Tc2_System.T_MaxString
            namespaces += ["--namespace", f"{name}={folder}"]
        if tcunit:  # TcUnit's FB_TestSuite and RUN (docs/user_tests.md#tcunit-suites)
            namespaces += ["--namespace", f"TcUnit={project.TCUNIT}"]
        for name, path, _ in self.wiring.libraries:  # the program's own: FsCommon.I_Runnable
            namespaces += ["--library", f"{name}={path}"]
        return ["--user", *namespaces, "--sources", os.path.join(self.out, "plcopen"), *natives, *files]

    def translate(self):
        """pacst --user over the library, the vocabulary and the user's ST; returns the symbol table."""
        strict = ["--strict-narrowing"] if self.strict_narrowing else []
        self._pacst("build", *self.user_inputs(), "--line-directives", *strict, "--out", self.st_out,
                    "--gvl", project.gvl_pac(), "--checked-library", self.checked_library)
        with open(os.path.join(self.st_out, "symbols.json"), encoding="utf-8") as f:
            return hostgen.Symbols(json.load(f))

    def tests(self, symbols):
        """The test FBs: the wiring's names, or every FUNCTION_BLOCK whose name starts with the prefix."""
        if self.wiring.test_names:
            found = []
            for i, name in enumerate(self.wiring.test_names):
                fb = symbols.fbs.get(name.upper())
                if fb is None:
                    raise BuildError(f"$.tests.names[{i}]: no FUNCTION_BLOCK {name} in the sources")
                found.append(fb)
            return found
        theirs = (os.path.join(project.ROOT, "st", ""), project.VOCABULARY + os.sep, project.TCUNIT + os.sep,
                  project.VENDOR + os.sep, *(os.path.join(f, "") for f in project.library_folders(self.wiring.libraries,
                                                                                               self.out)))
        # a TcUnit suite (EXTENDS FB_TestSuite) is a test whatever its name
        return [fb for fb in symbols.table["function_blocks"]
                if not fb.get("standard") and (fb["name"].upper().startswith(self.wiring.prefix.upper())
                                               or "FB_TESTSUITE" in (b.upper() for b in fb.get("extends", [])))
                and not os.path.abspath(fb.get("file") or "").startswith(theirs)]

    def _flags(self, cxx):
        # the host's C++ with line tables only, as the debug preset compiles the project's (enough for a
        # sanitizer's stack trace; full debug information was a quarter of its compile time); the ST's C with all
        flags = ["-g1" if cxx else "-g", "-fno-omit-frame-pointer"]
        if self.pac.sanitize:
            flags += ["-fsanitize=address,undefined", "-fno-sanitize-recover=undefined"]
        if cxx:
            return flags + ["-std=c++17", "-O1", "-Wall", "-Wextra"]
        # the ST as the library's coverage build compiles it (cmake/PacCoverage.cmake)
        flags += ["-std=c99", "-fwrapv", "-w"]
        return flags + (["--coverage", "-O0", "-DPACST_NO_FORCING"] if self.coverage else ["-O1"])

    def _compile(self, source, cxx, shared=False, included=()):
        """`source`'s object, compiled unless one with the same command and POUS.h is newer than it (and than
        the files it `included`)."""
        compiler = os.environ.get("CXX" if cxx else "CC", "c++" if cxx else "cc")
        declared = self.pac.library_c if shared else self.st_out
        includes = ([] if shared else [self.st_out]) + [project.HOST] + self.pac.include_dirs() + [self.pac.library_c]
        command = [compiler, *self._flags(cxx), *[f"-I{d}" for d in includes], "-c", source]
        # Every file includes POUS.h, which changes with any interface (an FB's pins move every caller's
        # struct offsets) while pacst leaves the text of an unchanged caller's C alone: POUS.h is in the key.
        with open(os.path.join(declared, "POUS.h"), "rb") as f:
            declarations = f.read()
        key = hashlib.sha1(" ".join(command).encode() + declarations).hexdigest()[:10]
        folder = self.shared_obj if shared else self.obj
        os.makedirs(folder, exist_ok=True)
        obj = os.path.join(folder, f"{os.path.splitext(os.path.basename(source))[0]}-{key}.o")
        # the shared host object is also older than a rebuilt library (a rig header may have changed) or host header
        sources = [source, *included] + \
            ([os.path.join(project.HOST, "pactest_host.hpp")] + self.pac.libraries if shared else [])
        if os.path.exists(obj) and os.path.getmtime(obj) >= max(os.path.getmtime(f) for f in sources):
            return obj
        compile_to(command, obj, f"compiling {os.path.basename(source)}", whole=shared)
        return obj

    def _unit(self, name, files, what):
        """OUT/`name`, which includes `files`, compiled as one unit: OUT/pactest_st.c, the C of every ST file of the
        program, as the build compiles the library (PAC_ST_UNITY), reads POUS.h and compiles pacst_iec.h's helpers
        once, not once per file (half the compiler's time), the #line directives still naming each statement's ST
        line, and a line outside them its own C file; OUT/pactest_cxx.cpp, the generated project part and the
        natives, reads POUS.h and the host's header once (a third of their compile time). Written only when the
        list changes, so an unchanged program is not compiled again."""
        unit = os.path.join(self.out, name)
        text = f"/* pac-test: {what} as one unit */\n" + "".join(f'#include "{c}"\n' for c in files)
        if not os.path.exists(unit) or open(unit, encoding="utf-8").read() != text:
            with open(unit, "w", encoding="utf-8") as f:
                f.write(text)
        return unit

    def shared_host(self):
        """pactest_host.cpp's object, shared by every run against this build (and made by its pactest_prepare)."""
        return self._compile(os.path.join(project.HOST, "pactest_host.cpp"), True, True)

    def build(self, symbols, tests):
        os.makedirs(self.obj, exist_ok=True)
        generated = os.path.join(self.out, "pactest_project.cpp")
        text = hostgen.generate(symbols, self.wiring, tests)
        if not os.path.exists(generated) or open(generated, encoding="utf-8").read() != text:
            with open(generated, "w", encoding="utf-8") as f:
                f.write(text)
        library = self.pac.library_stems()
        c_files = [os.path.join(self.st_out, n) for n in sorted(os.listdir(self.st_out))
                   if n.endswith(".c") and os.path.splitext(n)[0] not in library]
        cxx_files = [generated, os.path.join(project.HOST, "pactest_natives.cpp")]
        unit = self._unit("pactest_st.c", c_files, "the program's C")
        cxx_unit = self._unit("pactest_cxx.cpp", cxx_files, "the host's project part and natives")
        with concurrent.futures.ThreadPoolExecutor(self.jobs) as pool:
            shared = pool.submit(self.shared_host)
            program = pool.submit(self._compile, unit, False, False, c_files)
            objects = [self._compile(cxx_unit, True, False, cxx_files), program.result(), shared.result()]
        # An earlier build's objects (another key) would add their old lines to the coverage counts.
        keep = {os.path.splitext(o)[0] for o in objects}
        for name in os.listdir(self.obj):
            if os.path.splitext(os.path.join(self.obj, name))[0] not in keep:
                os.remove(os.path.join(self.obj, name))
        link(self.exe, objects, self.pac.libraries, self.pac.sanitize, self.coverage or self.pac.coverage)
        return self.exe
