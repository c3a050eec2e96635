"""A user program as one ST text that MATIEC's iec2c compiles (docs/translator.md, "User programs on
MATIEC"): what TwinCAT and CODESYS allow and MATIEC does not is spelled MATIEC's way.

- The global variable lists become the VAR_GLOBAL of one CONFIGURATION (MATIEC has globals only there),
  followed by a RESOURCE with the TASKs and PROGRAM instances the caller lists.
- Every POU gets a VAR_EXTERNAL for each global it uses, and `List.Name` loses its `List.` (MATIEC has
  neither implicit global access nor list names).
- Declarations are written again from what pacst compiled: located variables in VAR blocks of their own,
  `STRING(n)` as STRING (MATIEC's STRING[n] does not work), an inline array as a named type (a global
  and its VAR_EXTERNAL must share one type); bodies are copied as they are.
- A native FUNCTION (the host's C) is its interface only; where each body came from is returned beside
  the text, for the host to point iec2c's #line directives at the user's files.
"""
import json

from . import types as T
from .common import _cls
from .errors import StError

CONFIGURATION = "PacConfig"
RESOURCE = "PacResource"
DEFAULT_TASK = {"task": "PacTask", "interval": "T#10MS", "priority": 1}
_SECTION_KEYWORDS = {"input": "VAR_INPUT", "output": "VAR_OUTPUT", "inout": "VAR_IN_OUT", "var": "VAR",
                     "temp": "VAR_TEMP"}


def instance_name(program):
    """The name of a PROGRAM's instance in the RESOURCE (MATIEC refuses the program's own name)."""
    return f"Inst_{program}"


def array_type_name(t):
    """The named type an inline array becomes."""
    def bound(n):
        return f"M{-n}" if n < 0 else str(n)
    return f"T_PacArray_{t.elem.name}_{bound(t.low)}_{bound(t.high)}"


def _type(t):
    if t.is_array and t.name.startswith("ARRAY ["):
        return array_type_name(t)
    return t.name


def _decl(v, name=None):
    # MATIEC has no `AT %I*`: such a variable is a plain one there, which the host binds by name.
    located = f" AT {v.location.text}" if v.location is not None and v.location.numbers else ""
    init = f" := {v.init}" if v.init is not None else ""
    # STRING(n) is a plain STRING on MATIEC: it accepts STRING[n] in no VAR_EXTERNAL and then reports such
    # a variable undeclared wherever it is used (measured with iec2c).
    return f"  {name or v.name}{located} : {_type(v.type)}{init};"


def global_names(program):
    """{GlobalVar: its name in the CONFIGURATION}: its own, or `List_Name` where two lists declare it
    (MATIEC has one namespace of globals)."""
    lists = [obj for kind, obj, _ in program.items if kind == "gvl"]
    count = {}
    for gvl in lists:
        for g in gvl.vars:
            count[g.name.upper()] = count.get(g.name.upper(), 0) + 1
    return {g: (g.name if count[g.name.upper()] == 1 else f"{gvl.name}_{g.name}") for gvl in lists for g in gvl.vars}


def _type_decl(t):
    if t.is_enum:
        return [f"TYPE {t.name} : ({', '.join(t.values)});", "END_TYPE"]
    if t.is_array:
        name = array_type_name(t) if t.name.startswith("ARRAY [") else t.name
        return [f"TYPE {name} : ARRAY [{t.low}..{t.high}] OF {_type(t.elem)};", "END_TYPE"]
    return [f"TYPE {t.name} :", "STRUCT"] + [_decl(m) for m in t.members] + ["END_STRUCT;", "END_TYPE"]


def _blocks(pou, names):
    """The variable blocks of a POU, a located variable in a VAR block of its own (MATIEC)."""
    out = []
    for section in ("input", "output", "inout", "var", "temp"):
        for constant in (False, True):
            group = [v for v in pou.vars if v.section == section and v.constant == constant]
            located = [v for v in group if v.location is not None and v.location.numbers]
            plain = [v for v in group if v not in located]
            keyword = _SECTION_KEYWORDS[section] + (" CONSTANT" if constant else "")
            for group in (plain, located):
                if group:
                    out += [keyword] + [_decl(v) for v in group] + ["END_VAR"]
    used = {names[g]: (g, g.constant) for g, _ in pou.externals.values()}
    used.update({names[g]: (g, g.constant) for g in pou.globals_used.values()})
    for constant in (False, True):
        group = [g for g, c in used.values() if c == constant]
        if group:
            out += ["VAR_EXTERNAL" + (" CONSTANT" if constant else "")]
            out += [f"  {names[g]} : {_type(g.type)};" for g in group] + ["END_VAR"]
    return out


def _body(pou, text, names):
    """The POU's statements as written, every qualified global named as in the CONFIGURATION."""
    body = pou.node.body.meta
    start, end = body.start_pos, body.end_pos
    out, at = [], start
    for cut_start, cut_end, g in sorted(pou.qualifiers, key=lambda c: c[0]):
        out.append(text[at:cut_start])
        out.append(names[g][:-len(g.name)])  # `List.` becomes nothing, or `List_` where two lists share the name
        at = cut_end
    out.append(text[at:end])
    return "".join(out)


def _pou(pou, text, names):
    if pou.native:
        # the interface MATIEC checks the calls against; the host's C replaces the body (iec2c -O p writes it
        # to <name>.c, which the host leaves out), so the body only has to be one MATIEC accepts
        # (MATIEC parses no FUNCTION without a variable block: a local one keeps the C interface as it is)
        blocks = _blocks(pou, names) or ["VAR", "  PacUnused : BOOL;", "END_VAR"]
        return [f"FUNCTION {pou.name} : {_type(pou.ret)}"] + blocks + [f"{pou.name} := {pou.name};", "END_FUNCTION"]
    if pou.kind == "function" and (pou.globals_used or pou.externals):
        raise StError(pou.file, pou.node.meta.line, pou.node.meta.column,
                      f"FUNCTION {pou.name} uses global variables: MATIEC's FUNCTIONs have no VAR_EXTERNAL; "
                      "pass the value as an input")
    keyword = "PROGRAM" if pou.program else "FUNCTION_BLOCK" if pou.kind == "fb" else "FUNCTION"
    header = f"{keyword} {pou.name}" + (f" : {_type(pou.ret)}" if pou.kind == "function" else "")
    return [header] + _blocks(pou, names) + [_body(pou, text, names), f"END_{keyword}"]


def _tasks(program, tasks):
    """(task declarations, program instance lines) for every PROGRAM; `tasks` maps a program's name to
    {"task", "interval", "priority"} (defaults: DEFAULT_TASK)."""
    declared, instances = {}, []
    for kind, pou, _ in program.items:
        if kind != "pou" or not pou.program:
            continue
        entry = dict(DEFAULT_TASK, **{k.lower(): v for k, v in tasks.get(pou.name, {}).items()})
        line = f"    TASK {entry['task']}(INTERVAL := {entry['interval']}, PRIORITY := {entry['priority']});"
        if declared.setdefault(entry["task"].upper(), line) != line:
            raise StError(pou.file, 1, 1, f"task {entry['task']} is given two intervals or priorities")
        instances.append(f"    PROGRAM {instance_name(pou.name)} WITH {entry['task']} : {pou.name};")
    return list(declared.values()), instances


def source_and_lines(comp, program, tasks):
    """The one ST text iec2c compiles for a compiled user program (types, POUs, CONFIGURATION), and where
    each POU's body came from: [[first line of the body in the text, ST file, its line there], ...]; a body is
    copied line for line, so the lines after its first follow on."""
    texts = {src.path: src.text for src in comp.sources}
    out = ["(* Generated by pacst matiec from the user program. Do not edit. *)", ""]
    names = global_names(program)
    globals_, lines = [], []
    for kind, obj, _ in program.items:
        if kind == "type":
            out += _type_decl(obj) + [""]
        elif kind == "gvl":
            globals_ += obj.vars
        elif kind == "pou":
            pou = _pou(obj, texts[obj.file], names)
            if not obj.native:
                first = sum(part.count("\n") + 1 for part in out + pou[:-2]) + 1
                lines.append([first, obj.file, obj.node.body.meta.line])
            out += pou + [""]
    task_lines, instances = _tasks(program, tasks)
    out += [f"CONFIGURATION {CONFIGURATION}"]
    for constant in (False, True):
        group = [g for g in globals_ if g.constant == constant]
        if group:
            out += ["  VAR_GLOBAL" + (" CONSTANT" if constant else "")]
            out += ["  " + _decl(g, names[g]) for g in group] + ["  END_VAR"]
    out += [f"  RESOURCE {RESOURCE} ON PLC"] + task_lines + instances + ["  END_RESOURCE", "END_CONFIGURATION", ""]
    return "\n".join(out), lines


def read_tasks(path):
    """The task list: {"PRG_Name": {"task": "Fast", "interval": "T#10MS", "priority": 1}, ...}."""
    if path is None:
        return {}
    try:
        with open(path, encoding="utf-8") as f:
            tasks = json.load(f)
    except (OSError, ValueError) as exc:
        raise StError(path, 1, 1, f"cannot read the task list: {exc}") from None
    if not isinstance(tasks, dict) or not all(isinstance(v, dict) for v in tasks.values()):
        raise StError(path, 1, 1, "the task list maps each PROGRAM's name to {\"task\", \"interval\", \"priority\"}")
    return tasks
