"""symbols.json: what a generated host needs to bind, run and inspect a user program (docs/translator.md,
"User programs"): every global with its C variable, type and address; every PROGRAM and FUNCTION_BLOCK
with its C type, functions and variables; every named type. Written by `pacst build --user`."""
import json

from . import types as T
from .body import program_instance
from .common import pos

FORMAT = 1
# sizeof of pacst_iec.h's elementary types (STRING: a length byte and STR_MAX_LEN bytes; WSTRING: a length word and
# STR_MAX_LEN words; TIME: two longs on the LP64 hosts the runtime targets).
_C_SIZES = {"BOOL": 1, "SINT": 1, "INT": 2, "DINT": 4, "USINT": 1, "UINT": 2, "UDINT": 4, "BYTE": 1,
            "WORD": 2, "DWORD": 4, "REAL": 4, "LREAL": 8, "TIME": 16, "STRING": 256,
            "LINT": 8, "ULINT": 8, "LWORD": 8, "WSTRING": 512}
_DIRECTIONS = {"input": "input", "output": "output", "inout": "in_out", "var": "var", "temp": "temp"}


def type_json(t):
    """A type as the host reads it: elementary types by name; arrays with bounds and element; others by
    name, described in `types`."""
    if t.is_array:
        return {"kind": "array", "name": t.name, "c_type": t.cname, "low": t.low, "high": t.high,
                "element": type_json(t.elem), "element_size": _C_SIZES.get(t.elem.cname)}
    if t.is_enum:
        return {"kind": "enum", "name": t.name, "c_type": t.cname}
    if t.is_struct:
        return {"kind": "struct", "name": t.name, "c_type": t.cname}
    if t.is_fb:
        return {"kind": "function_block", "name": t.name, "c_type": t.cname}
    if t.is_pointer:
        return {"kind": "pointer", "name": t.name, "c_type": t.cname, "target": type_json(t.target)}
    if t.kind == "interface":
        return {"kind": "interface", "name": t.name, "c_type": t.cname}
    if t.kind == "longstring":  # STRING(n) over 255: n units and the NUL
        return {"kind": "long_string", "name": t.name, "c_type": t.cname, "length": t.length,
                "size": (t.length + 1) * (2 if t.wide else 1)}
    if t.kind == "vla":  # an ARRAY [*]: the descriptor of the array an FB was last given
        return {"kind": "var_length_array", "name": t.name, "c_type": t.cname, "element": type_json(t.elem)}
    return {"kind": "elementary", "name": t.name, "c_type": t.cname, "size": _C_SIZES[t.cname]}


def _initial(comp, v):
    """The initial value as its ST literal, or None (the type's default)."""
    if v.init is None:
        return None
    return str(v.init)


def _variable(comp, v, path, c_name):
    entry = {"name": v.name, "path": path, "c_name": c_name, "wrapped": not v.type.is_fb,
             "type": type_json(v.type), "constant": bool(v.constant), "initial": _initial(comp, v),
             "location": v.location.as_json() if v.location is not None else None}
    if v.strlen is not None:
        entry["string_length"] = v.strlen
    if v.section in _DIRECTIONS:
        entry["direction"] = _DIRECTIONS[v.section]
    return entry


def _pou(comp, pou):
    entry = {"name": pou.name, "c_type": pou.cname, "init": f"{pou.cname}_init__", "body": f"{pou.cname}_body__",
             "file": pou.file, "line": pou.node.meta.line if pou.node.meta is not None else None,
             "variables": [_variable(comp, v, f"{pou.name}.{v.name}", v.cname) for v in pou.vars]}
    for v, variable in zip(pou.vars, entry["variables"]):
        if v.location is not None:  # where a located variable pac-test cannot copy is refused
            variable["line"] = pos(v.node)[0]
    entry["externals"] = [{"name": g.name, "global": f"{g.gvl.name}.{g.name}", "c_name": g.csym}
                          for g, _ in pou.externals.values()]
    if pou.program:
        entry["instance"] = program_instance(pou)
    if pou.base is not None:  # user mode: the FBs it EXTENDS, nearest first (pac-test finds TcUnit's suites)
        entry["extends"] = []
        base = pou.base
        while base is not None:
            entry["extends"].append(base.name)
            base = base.base
    return entry


def _type(t):
    entry = type_json(t)
    if t.is_struct:
        entry["members"] = [{"name": m.name, "c_name": m.cname, "type": type_json(m.type)} for m in t.members]
    if t.is_enum:
        entry["values"] = [{"name": v, "c_name": t.cvalue(v), "value": n} for v, n in zip(t.values, t.numbers)]
    return entry


def symbols(comp, program):
    """The symbol table of a compiled user program, as JSON text."""
    table = {"format": FORMAT, "global_lists": [], "globals": [], "programs": [], "function_blocks": [],
             "functions": [], "types": []}
    for kind, obj, file in program.items:
        if kind == "gvl":
            table["global_lists"].append({"name": obj.name, "file": obj.file, "init": f"{obj.cname}__init__"})
            for v in obj.vars:
                entry = _variable(comp, v, f"{obj.name}.{v.name}", v.csym)
                entry["list"] = obj.name
                entry["line"] = v.node.line
                table["globals"].append(entry)
        elif kind == "type" and not obj.name.startswith("ARRAY [") and obj.kind != "longstring":
            table["types"].append(_type(obj))
        elif kind == "pou" and obj.program:
            table["programs"].append(_pou(comp, obj))
        elif kind == "pou" and obj.kind == "fb":
            table["function_blocks"].append(_pou(comp, obj))
        elif kind == "pou" and obj.owner is None:  # a METHOD or ACTION is its FB's
            table["functions"].append({
                "name": obj.name, "c_name": obj.cname, "native": obj.native, "file": obj.file,
                "returns": type_json(obj.ret) if obj.ret is not None else None,
                "pins": [_variable(comp, v, f"{obj.name}.{v.name}", v.cname) for v in obj.vars
                         if v.section in ("input", "output", "inout")]})
    for fb in list(T.STANDARD_FBS.values()) + (list(T.USER_FBS.values()) if comp.user else []):
        table["function_blocks"].append({
            "name": fb.name, "c_type": fb.cname, "init": f"{fb.cname}_init__", "body": f"{fb.cname}_body__",
            "standard": True, "variables": [_variable(comp, v, f"{fb.name}.{v.name}", v.cname) for v in fb.vars]})
    return json.dumps(table, indent=1) + "\n"
