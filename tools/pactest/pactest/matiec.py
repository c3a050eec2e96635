"""pac-test on a MATIEC build (docs/user_tests.md, "On MATIEC"): the library, the vocabulary's FBs and the user's
ST compiled by MATIEC's iec2c instead of pacst's C. `pacst matiec` writes them as one ST file with the
CONFIGURATION, RESOURCE and a TASK per task of the wiring file; iec2c compiles it with `-b` (a FUNCTION called
as a statement, as the asserts are), `-i` (a FUNCTION without inputs: TEST_FINISHED) and `-O p,l` (a C file per
POU, #line directives). The vocabulary's FUNCTIONs stay the host's C (pactest_natives.cpp): their C files are
left out and their headers pass the ST file and line of each call, as pacst's C does. The host binds MATIEC's
globals (PACCONFIG__NAME) and program instances (PACRESOURCE__INST_NAME); pacst's symbol table still names
the tests, programs and variables."""
import concurrent.futures
import json
import os
import re

from . import build, hostgen, project

CONFIG, RESOURCE = "PACCONFIG", "PACRESOURCE"  # pacst matiec's CONFIGURATION and RESOURCE, as MATIEC spells them
_LINE = re.compile(r'^#line (\d+) "([^"]*)"$')
# (iec2c writes its LOCATED_VARIABLES.h with the globals' names run together before the first entry)
_LOCATED = re.compile(r"__LOCATED_VAR\((\w+),(\w+),([IQM]),([XBWDL]),([\d,]+)\)")


class MatiecHostBuild(build.HostBuild):
    """HostBuild with MATIEC's C: pacst still translates (its symbol table and the vocabulary's declarations for
    the natives' C++), then pacst matiec and iec2c compile what runs."""

    takes_dialect = False  # MATIEC compiles the portable subset: vendor stand-ins only where named, no TcUnit

    def __init__(self, wiring, pac_build, out, **kwargs):
        super().__init__(wiring, pac_build, out, coverage=False, **kwargs)
        self.mat = os.path.join(out, "matiec")
        self.c_dir = os.path.join(self.mat, "c")

    def _flags(self, cxx):
        # the natives' C++ and the host take MATIEC's STRING (126 characters), not pacst's (pacst_iec.h)
        return super()._flags(cxx) + ["-DPACST_MATIEC_STRING=1"]

    def tasks(self):
        """pacst matiec's task list: each PROGRAM in its task, the wiring's cycle as the TASK's interval and
        the task's place in the wiring file as its priority (the host calls the programs itself)."""
        return {program: {"task": task["name"], "interval": f"T#{task['cycle_ms']}MS", "priority": n}
                for n, task in enumerate(self.wiring.tasks, 1) for program in task["programs"]}

    def translate(self):
        symbols = super().translate()
        os.makedirs(self.c_dir, exist_ok=True)
        tasks, st, line_map = (os.path.join(self.mat, n) for n in ("tasks.json", "program.st", "lines.json"))
        with open(tasks, "w", encoding="utf-8") as f:
            json.dump(self.tasks(), f, indent=1)
        self._pacst("matiec", *self.user_inputs(), "--out", st, "--tasks", tasks, "--line-map", line_map)
        for name in os.listdir(self.c_dir):
            os.remove(os.path.join(self.c_dir, name))
        iec2c, lib = self.pac.matiec
        build._run([iec2c, "-b", "-i", "-O", "p,l", "-I", lib, "-T", self.c_dir, st], "iec2c")
        with open(line_map, encoding="utf-8") as f:
            self._fix_lines(json.load(f))
        self._natives()
        return symbols

    def _fix_lines(self, bodies):
        """#line directives name the user's ST file and line instead of program.st's (failures, addr2line), and
        are repeated before each C statement of the ST statement: iec2c writes one directive and then several C
        lines (an FB call sets each input on a line of its own), which would count on from the ST line."""
        starts = [b[0] for b in bodies]

        def where(line):
            i = max((k for k, s in enumerate(starts) if s <= line), default=None)
            if i is None:
                return None
            first, path, st_line = bodies[i]
            return f'#line {st_line + line - first} "{os.path.abspath(path)}"'
        for name in os.listdir(self.c_dir):
            if not name.endswith(".c"):
                continue
            path = os.path.join(self.c_dir, name)
            with open(path, encoding="utf-8") as f:
                lines = f.read().split("\n")
            out, directive, previous = [], None, ""
            for line in lines:
                match = _LINE.match(line)
                if match:
                    directive = where(int(match.group(1)))
                    out.append(directive or line)
                    continue
                # a new C statement (not a macro's argument on a line of its own) keeps the ST line
                if directive and line.strip() and previous.rstrip().endswith((";", "{", "}")):
                    out.append(directive)
                out.append(line)
                if line.strip():
                    previous = line
            with open(path, "w", encoding="utf-8") as f:
                f.write("\n".join(out))

    def _natives(self):
        """The vocabulary's FUNCTIONs: their C left out of POUS.c, each call given the file and line."""
        names = {os.path.splitext(os.path.basename(f))[0] for f in project.native_sources()}
        with open(os.path.join(self.c_dir, "POUS.c"), encoding="utf-8") as f:
            pous = [line for line in f if line.strip() not in {f'#include "{n}.c"' for n in names}]
        with open(os.path.join(self.c_dir, "POUS.c"), "w", encoding="utf-8") as f:
            f.writelines(pous)
        for stem in names:
            path, c_name = os.path.join(self.c_dir, stem + ".h"), stem.upper()
            with open(path, encoding="utf-8") as f:
                text = f.read()
            text = text.replace(f" {c_name}(\n", f" {c_name}(\n  const char *file__,\n  int line__,\n", 1)
            call = f"#define {c_name}(...) {c_name}(__FILE__, __LINE__, __VA_ARGS__)\n#endif"
            with open(path, "w", encoding="utf-8") as f:
                f.write(text[:text.rindex("#endif")] + call + text[text.rindex("#endif") + 6:])

    def build(self, symbols, tests):
        os.makedirs(self.obj, exist_ok=True)
        glue, project_cpp = generate(symbols, self.wiring, tests, self.c_dir)
        files = {os.path.join(self.mat, "pactest_glue.c"): glue,
                 os.path.join(self.out, "pactest_project.cpp"): project_cpp}
        for path, text in files.items():
            if not os.path.exists(path) or open(path, encoding="utf-8").read() != text:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(text)
        c_files = [os.path.join(self.c_dir, "PacResource.c"), os.path.join(self.c_dir, "PacConfig.c"),
                   os.path.join(self.mat, "pactest_glue.c")]
        cxx_files = [os.path.join(self.out, "pactest_project.cpp"), os.path.join(project.HOST, "pactest_host.cpp"),
                     os.path.join(project.HOST, "pactest_natives.cpp")]
        with concurrent.futures.ThreadPoolExecutor(self.jobs) as pool:
            objects = list(pool.map(self._compile_matiec, c_files)) + \
                list(pool.map(lambda c: self._compile(c, True), cxx_files))
        # not the build's pac_st: the library is MATIEC's C above, compiled with the program
        libraries = [lib for lib in self.pac.libraries if not lib.endswith("libpac_st.a")]
        build.link(self.exe, objects, libraries, self.pac.sanitize)
        return self.exe

    def _compile_matiec(self, source):
        compiler = os.environ.get("CC", "cc")
        obj = os.path.join(self.obj, os.path.splitext(os.path.basename(source))[0] + ".o")
        sanitize = ["-fsanitize=address,undefined", "-fno-sanitize-recover=undefined"] if self.pac.sanitize else []
        # MATIEC's C is GNU C (statement expressions); -w: it warns of much that is meant
        flags = ["-g", "-fno-omit-frame-pointer", *sanitize, "-std=gnu11", "-fwrapv", "-w", "-O1"]
        includes = ["-I", self.c_dir, "-I", os.path.join(self.pac.matiec[1], "C")]
        what = f"compiling MATIEC's {os.path.basename(source)}"
        build.compile_to([compiler, *flags, *includes, "-c", source], obj, what)
        return obj


def global_names(symbols):
    """{path: MATIEC's C name}: PACCONFIG__NAME, or PACCONFIG__LIST_NAME where two lists declare NAME
    (pacst matiec's one namespace of globals)."""
    count = {}
    for g in symbols.table["globals"]:
        count[g["name"].upper()] = count.get(g["name"].upper(), 0) + 1
    return {g["path"].upper(): f"{CONFIG}__" + (g["name"] if count[g["name"].upper()] == 1
                                                 else f"{g['list']}_{g['name']}").upper()
            for g in symbols.table["globals"]}


_BYTES = {"BOOL": 1, "BYTE": 1, "SINT": 1, "USINT": 1, "WORD": 2, "INT": 2, "UINT": 2, "DWORD": 4, "DINT": 4,
          "UDINT": 4, "REAL": 4}


def _located(c_dir):
    with open(os.path.join(c_dir, "LOCATED_VARIABLES.h"), encoding="utf-8") as f:
        return [m.groups() for m in _LOCATED.finditer(f.read())]


def generate(symbols, wiring, tests, c_dir):
    """(the C glue compiled with MATIEC's headers, the C++ Project): instances, tasks, copies, signals."""
    names = global_names(symbols)
    programs = hostgen.programs_of(symbols, wiring)
    hostgen.located_copies(symbols, [], [])  # the same refusals as on pacst's C (%IW, %ID)
    c = ["/* Generated by pac-test for MATIEC's C. Do not edit. */", "#include <stdint.h>", "#include <string.h>",
         '#include "iec_std_lib.h"', '#include "POUS.h"', "",
         "/* the located variables' storage, which a PLC runtime provides */"]
    located = _located(c_dir)
    c += [f"static {c_type} storage{name}; {c_type} *{name} = &storage{name};" for c_type, name, *_ in located]
    c += ["static uint8_t inImage[256], outImage[256];", "void config_init__(void);"]
    used = []
    for task in programs:
        used += [p for p in task if p not in used]
    for p in used:
        instance = f"{RESOURCE}__INST_{p['name'].upper()}"
        c += [f"extern {p['c_type']} {instance};",
              f"void pactest_run_{p['c_type']}(void) {{ {p['body']}(&{instance}); }}"]
    for t in tests:
        c += [f"static {t['c_type']} test_{t['c_type']};",
              f"void pactest_test_{t['c_type']}(void) {{ {t['body']}(&test_{t['c_type']}); }}"]
    c += ["void pactest_init(void) {", "  config_init__();"]
    c += [f"  {t['init']}(&test_{t['c_type']}, 0);" for t in tests] + ["}"]
    copy_in, copy_out, externs = [], [], set()
    for m in wiring.modules:
        for side, lines in (("in", copy_in), ("out", copy_out)):
            target = m.image_in if side == "in" else m.image_out
            bus = f"{'fromPac' if side == 'in' else 'toPac'} + {m.offset()}"
            if target.startswith("%"):
                ours = f"{'inImage' if side == 'in' else 'outImage'} + {int(target[3:])}"
            else:
                g = symbols.global_var(target, f"{m.where}.{side}")
                # a located global is MATIEC's pointer to its location's storage
                located_global = bool(g.get("location") and g["location"].get("numbers"))
                ours = f"{'' if located_global else '&'}{names[g['path'].upper()]}.value"
                externs.add(f"extern __IEC_{g['type']['c_type']}_{'p' if located_global else 't'} "
                            f"{names[g['path'].upper()]};")
            pair = (ours, bus) if side == "in" else (bus, ours)
            lines.append(f"  memcpy({pair[0]}, {pair[1]}, {m.size});")
    bus_bytes = hostgen.bus_input_bytes(wiring)
    for c_type, name, area, size, numbers in located:
        numbers = [int(n) for n in numbers.split(",")]
        image, lines = ("inImage", copy_in) if area == "I" else ("outImage", copy_out) if area == "Q" else (None, None)
        if image is None:
            continue
        nbytes = 1 if size == "X" else _BYTES.get(c_type)  # an array: copied as before
        if area == "I" and nbytes and not any(b in bus_bytes for b in range(numbers[0], numbers[0] + nbytes)):
            continue  # an input the bus does not write is the tests' to set, as on pacst's C
        byte, storage = numbers[0], f"storage{name}"
        if size == "X":
            bit = numbers[1] if len(numbers) > 1 else 0
            lines.append(f"  {storage} = ({image}[{byte}] >> {bit}) & 1;" if area == "I" else
                         f"  {image}[{byte}] = ({image}[{byte}] & ~(1u << {bit})) | (({storage} & 1u) << {bit});")
        elif size == "B":
            pair = (f"&{storage}", f"{image} + {byte}") if area == "I" else (f"{image} + {byte}", f"&{storage}")
            lines.append(f"  memcpy({pair[0]}, {pair[1]}, sizeof {storage});")
    # inputs: bus to images to variables; outputs: variables to images to bus (hostgen's order)
    located_in = [x for x in copy_in if "storage" in x]
    signals = _signals(symbols, wiring, names)
    for path, expr, _ in signals:
        g = symbols.globals.get(path.upper())
        if g is not None:
            externs.add(f"extern __IEC_{g['type']['c_type']}_t {expr[:-len('.value')]};")
    c += sorted(externs)
    c += ["void pactest_copy_in(const uint8_t *fromPac, size_t bytes) {", "  (void)bytes;"]
    c += [x for x in copy_in if x not in located_in] + located_in + ["}"]
    located_out = [x for x in copy_out if "storage" in x]
    c += ["void pactest_copy_out(uint8_t *toPac, size_t bytes) {", "  (void)bytes;"]
    c += located_out + [x for x in copy_out if x not in located_out] + ["}"]
    c += ["const void *const pactest_signal_data[] = {0" + "".join(f", &{e}" for _, e, _ in signals) + "};",
          "const int pactest_signal_bytes[] = {0" + "".join(f", (int)sizeof {e}" for _, e, _ in signals) + "};", ""]
    cpp = ["// Generated by pac-test for MATIEC's C. Do not edit.", "#include <cstddef>", "#include <cstdint>", "",
           '#include "pactest_host.hpp"', "", 'extern "C" {', "void pactest_init(void);",
           "void pactest_copy_in(const std::uint8_t* fromPac, std::size_t bytes);",
           "void pactest_copy_out(std::uint8_t* toPac, std::size_t bytes);",
           "extern const void* const pactest_signal_data[];", "extern const int pactest_signal_bytes[];"]
    cpp += [f"void pactest_run_{p['c_type']}(void);" for p in used]
    cpp += [f"void pactest_test_{t['c_type']}(void);" for t in tests] + ["}", "",
                                                                        "int main(int argc, char** argv) {",
                                                                        "    pactest::Project project;",
                                                                        "    project.tasks = {"]
    for task, progs in zip(wiring.tasks, programs):
        calls = ", ".join(f"pactest_run_{p['c_type']}" for p in progs)
        cpp.append(f"        {{\"{task['name']}\", {task['cycle_ms']}, {{{calls}}}}},")
    cpp += ["    };", "    project.tests = {"]
    cpp += [f"        {{\"{t['name']}\", \"{wiring.test_task}\", pactest_test_{t['c_type']}}}," for t in tests]
    cpp += ["    };", "    project.init = pactest_init;", "    project.copyIn = pactest_copy_in;",
            "    project.copyOut = pactest_copy_out;", "    project.signals = {"]
    cpp += [f"        {{\"{path}\", pactest_signal_data[{i}], pactest::Signal::Kind::{kind}, "
            f"pactest_signal_bytes[{i}]}}," for i, (path, _, kind) in enumerate(signals, 1)]
    cpp += ["    };", "    return pactest::Main(argc, argv, project);", "}", ""]
    return "\n".join(c), "\n".join(cpp)


def _signals(symbols, wiring, names):
    """(path, C expression, kind) of hostgen's signals, on MATIEC's globals and program instances."""
    out = []
    for line in hostgen.signal_entries(symbols, wiring.signals):
        path, expr, kind = line
        if expr.startswith("program_"):
            program, _, rest = expr[len("program_"):].partition(".")
            p = next(p for p in symbols.table["programs"] if p["c_type"] == program)
            expr = f"{RESOURCE}__INST_{p['name'].upper()}.{rest}"
        else:
            g = next(g for g in symbols.table["globals"] if g["path"] == path)
            if g.get("location") and g["location"].get("numbers"):
                continue  # MATIEC's located global is a pointer to its location's storage
            expr = f"{names[path.upper()]}.value"
        out.append((path, expr, kind))
    return out
