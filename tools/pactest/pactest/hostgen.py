"""The part of the host that knows the user's program, generated from pacst's symbol table (symbols.json)
and the wiring file: program and test instances, the tasks, the copies between the bus and the user's
images, the signals of the VCD. The rest of the host is fixed C++ (tools/pactest/host)."""
import re

from .wiring import WiringError

_ELEMENTARY_KINDS = {"BOOL": "kBool", "BYTE": "kUnsigned", "WORD": "kUnsigned", "DWORD": "kUnsigned",
                     "USINT": "kUnsigned", "UINT": "kUnsigned", "UDINT": "kUnsigned", "SINT": "kSigned",
                     "INT": "kSigned", "DINT": "kSigned", "REAL": "kReal", "LREAL": "kLreal", "TIME": "kTime"}


class ProgramError(Exception):
    """What pac-test cannot run in the user's program (not in the wiring file), with its file and line."""


class Symbols:
    def __init__(self, table):
        self.table = table
        self.globals = {g["path"].upper(): g for g in table["globals"]}
        self.programs = {p["name"].upper(): p for p in table["programs"]}
        self.fbs = {f["name"].upper(): f for f in table["function_blocks"] if not f.get("standard")}

    def global_var(self, path, where):
        found = self.globals.get(path.upper())
        if found is None:
            raise WiringError(where, f"no global variable {path} in the program (a GVL variable: LIST.NAME)")
        return found

    def located(self, area):
        """The located variables of `area` (I, Q): the globals', then the PROGRAMs' (TwinCAT's MAIN declares its
        I/O in its VAR), each with the C name of its storage and where it is declared."""
        files = {gl["name"]: gl["file"] for gl in self.table["global_lists"]}
        found = [dict(g, file=files.get(g.get("list"))) for g in self.table["globals"]
                 if g.get("location") and g["location"]["area"] == area]
        for p in self.table["programs"]:
            found += [dict(v, c_name=f"{p['instance']}.{v['c_name']}", file=p["file"], line=v.get("line") or p["line"])
                      for v in p["variables"] if v.get("location") and v["location"]["area"] == area]
        return found


def _location_byte(g):
    loc = g["location"]
    if not loc["numbers"]:
        return None
    return loc["numbers"][0]


def _memcpy(lines, side, ours, theirs, size):
    """`ours` (the program's storage) from `theirs` for an input, `theirs` from `ours` for an output."""
    destination, source = (ours, theirs) if side == "in" else (theirs, ours)
    lines.append(f"    std::memcpy({destination}, {source}, {size});")


def _copy_module(lines_in, lines_out, symbols, module):
    """The C++ lines that copy `module` between the bus image and the user's variable or located image."""
    offset, size = module.offset(), module.size
    for side, lines in (("in", lines_in), ("out", lines_out)):
        target = module.image_in if side == "in" else module.image_out
        bus = f"{'fromPac' if side == 'in' else 'toPac'} + {offset}"
        if target.startswith("%"):
            image = "inImage" if side == "in" else "outImage"
            _memcpy(lines, side, f"{image} + {int(target[3:])}", bus, size)
        else:
            g = symbols.global_var(target, f"{module.where}.{side}")
            lines.append(f"    static_assert(sizeof {g['c_name']}.value == {size}, "
                         f"\"{target} is not the {size} bytes of the {module.kind} module\");")
            _memcpy(lines, side, f"&{g['c_name']}.value", bus, size)


def _bytes_of(vtype):
    """The bytes of a located variable's type, where the symbol table gives them (elementary types and
    their arrays), else None."""
    if vtype.get("kind") == "array" and "element_size" in vtype:
        return (vtype["high"] - vtype["low"] + 1) * vtype["element_size"]
    return vtype.get("size")


def check_module_images(symbols, wiring):
    """Refuses a module at a located address that cuts through a located image of the program: the program
    would read and write the module's bytes shifted."""
    for module in wiring.modules:
        for side in ("in", "out"):
            target = module.image_in if side == "in" else module.image_out
            if not target.startswith("%"):
                continue
            area, start = target[1], int(target[3:])
            end = start + module.size - 1
            for g in symbols.located(area):
                first, size = _location_byte(g), _bytes_of(g["type"])
                if first is None or size is None or g["location"]["size"] != "B":
                    continue
                last = first + size - 1
                inside = first <= start and end <= last or start <= first and last <= end
                if not inside and start <= last and first <= end:
                    raise WiringError(f"{module.where}.{side}",
                                      f"%{area}B{start}..%{area}B{end}, the {module.kind} module's {module.size} "
                                      f"bytes, cut through {g['path']} at %{area}B{first}..%{area}B{last}: start "
                                      f"the module where the image starts")


def bus_input_bytes(wiring):
    """The %IB bytes the simulated PA-CONTROL's modules write (the wiring's located `in` images)."""
    found = set()
    for module in wiring.modules if wiring is not None else []:
        if module.image_in.startswith("%"):
            start = int(module.image_in[3:])
            found.update(range(start, start + module.size))
    return found


def input_from_bus(g, bus_bytes):
    """Whether the located input `g` lies on bytes the bus writes: then every scan copies it from the bus
    image; any other located input is the tests' to set (docs/user_tests.md, "Inputs a test drives")."""
    first = _location_byte(g)
    size = 1 if g["location"]["size"] == "X" else (_bytes_of(g["type"]) or 1)
    return any(b in bus_bytes for b in range(first, first + size))


def located_copies(symbols, copy_in, copy_out, wiring=None):
    """Every located variable to and from the host's image of %I and %Q (little-endian, as the PLCs the
    project runs on: TwinCAT and CODESYS on x86 and ARM); an input the bus does not write is left to the
    tests (input_from_bus)."""
    bus_bytes = bus_input_bytes(wiring)
    refused = []
    for area, side, lines in (("I", "in", copy_in), ("Q", "out", copy_out)):
        image = "inImage" if area == "I" else "outImage"
        for g in symbols.located(area):
            byte = _location_byte(g)
            if byte is None:
                continue
            loc, var = g["location"], f"{g['c_name']}.value"
            if area == "I" and loc["size"] in ("X", "B") and not input_from_bus(g, bus_bytes):
                continue
            if loc["size"] == "X":
                bit = loc["numbers"][1] if len(loc["numbers"]) > 1 else 0
                if area == "I":
                    lines.append(f"    {var} = (inImage[{byte}] >> {bit}) & 1;")
                else:
                    lines.append(f"    outImage[{byte}] = (outImage[{byte}] & ~(1u << {bit})) | "
                                 f"(({var} & 1u) << {bit});")
                continue
            if loc["size"] != "B":
                # CODESYS numbers %IW and %ID by word and double word, TwinCAT by byte: rather than guess
                # which the program was written for, pac-test asks for byte addresses.
                refused.append(f"{g.get('file') or g['path']}:{g.get('line') or 1}: {g['path']} located at "
                               f"{loc['address']}: pac-test copies byte (%IB, %QB) and bit (%IX, %QX) addresses only; "
                               "declare the image as bytes")
                continue
            lines.append(f"    static_assert({byte} + sizeof {var} <= 256, \"{g['path']} beyond %{area}B255\");")
            _memcpy(lines, side, f"&{var}", f"{image} + {byte}", f"sizeof {var}")
    if refused:
        raise ProgramError("\n".join(refused))


def signal_entries(symbols, wanted):
    """The VCD's signals as (path, C expression, Signal kind): the globals and the programs' variables of
    elementary type (or those `wanted` names, globs with *)."""
    patterns = [re.compile("^" + re.escape(w).replace("\\*", ".*") + "$", re.I) for w in wanted]
    out = []

    def add(path, expr, vtype):
        if vtype.get("kind") == "enum":  # as its value's number
            kind = "kUnsigned"
        elif vtype.get("kind") == "elementary" and vtype["name"] in _ELEMENTARY_KINDS:
            kind = _ELEMENTARY_KINDS[vtype["name"]]
        else:
            return
        if patterns and not any(p.match(path) for p in patterns):
            return
        out.append((path, expr, kind))

    for g in symbols.table["globals"]:
        if not g.get("constant"):
            add(g["path"], f"{g['c_name']}.value", g["type"])
    for name, p in symbols.programs.items():
        for v in p["variables"]:
            if v.get("wrapped", True):
                add(f"{p['name']}.{v['name']}", f"program_{p['c_type']}.{v['c_name']}.value", v["type"])
    return out


def _signals(symbols, wanted):
    return [f"        {{\"{path}\", &{expr}, pactest::Signal::Kind::{kind}, static_cast<int>(sizeof {expr})}},"
            for path, expr, kind in signal_entries(symbols, wanted)]


def programs_of(symbols, wiring):
    """Each task's programs (symbol table entries), in order; a name the sources lack is refused."""
    tasks = []
    for i, task in enumerate(wiring.tasks):
        programs = []
        for j, name in enumerate(task["programs"]):
            p = symbols.programs.get(name.upper())
            if p is None:
                raise WiringError(f"$.tasks[{i}].programs[{j}]", f"no PROGRAM {name} in the sources")
            programs.append(p)
        tasks.append(programs)
    return tasks


def generate(symbols, wiring, tests):
    """The C++ source of the Project for `tests` (symbol table entries of FBs)."""
    programs_used = []
    task_lines = []
    for task, programs in zip(wiring.tasks, programs_of(symbols, wiring)):
        calls = []
        for p in programs:
            if p not in programs_used:
                programs_used.append(p)
            calls.append(f"Run_{p['c_type']}")
        task_lines.append(f"        {{\"{task['name']}\", {task['cycle_ms']}, {{{', '.join(calls)}}}}},")
    copy_in, copy_out = [], []
    for m in wiring.modules:
        _copy_module(copy_in, copy_out, symbols, m)
    located_in, located_out = [], []
    located_copies(symbols, located_in, located_out, wiring)
    out = ["// Generated by pac-test from the symbol table and the wiring file. Do not edit.",
           "#include <cstdint>", "#include <cstring>", "", "#include \"POUS.h\"", "#include \"pactest_host.hpp\"",
           "", "namespace {", ""]
    # %IB0..%IB255 and %QB0..%QB255: the located images (the largest bus image is 112 bytes)
    out.append("std::uint8_t inImage[256];")
    out.append("std::uint8_t outImage[256];")
    # program_X / test_X: each instance, Run_X / Test_X: its body for a task, and its init
    instances = [("program", "Run", p) for p in programs_used] + [("test", "Test", t) for t in tests]
    for kind, runner, pou in instances:
        if pou.get("instance"):  # a PROGRAM's one instance, which other POUs may read (MAIN.x)
            out.append(f"{pou['c_type']}& {kind}_{pou['c_type']} = {pou['instance']};")
        else:
            out.append(f"{pou['c_type']} {kind}_{pou['c_type']};")
        out.append(f"void {runner}_{pou['c_type']}() {{ {pou['body']}(&{kind}_{pou['c_type']}); }}")
    out += ["", "void Init() {"]
    for gl in symbols.table["global_lists"]:
        out.append(f"    {gl['init']}();")
    for kind, _, pou in instances:
        out.append(f"    std::memset(&{kind}_{pou['c_type']}, 0, sizeof {kind}_{pou['c_type']});")
        out.append(f"    {pou['init']}(&{kind}_{pou['c_type']}, 0);")
    out += ["}", "",
            "void CopyIn(const std::uint8_t* fromPac, std::size_t bytes) {", "    (void)bytes;"] + copy_in + \
        located_in + ["}", "", "void CopyOut(std::uint8_t* toPac, std::size_t bytes) {", "    (void)bytes;"] + \
        located_out + copy_out + ["}", "", "}  // namespace", "",
                                  "int main(int argc, char** argv) {", "    pactest::Project project;",
                                  "    project.tasks = {"] + task_lines + ["    };", "    project.tests = {"]
    for t in tests:
        out.append(f"        {{\"{t['name']}\", \"{wiring.test_task}\", Test_{t['c_type']}}},")
    out += ["    };", "    project.init = Init;", "    project.copyIn = CopyIn;", "    project.copyOut = CopyOut;",
            "    project.signals = {"] + _signals(symbols, wiring.signals) + \
        ["    };", "    return pactest::Main(argc, argv, project);", "}", ""]
    return "\n".join(out)
