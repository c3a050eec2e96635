"""Global constant lists (st/gvl/GVL_PAC.st): checked like the library's POUs, and the one source of the
constants that POUs repeat as VAR CONSTANT.

MATIEC has no global constants outside a CONFIGURATION, so a library POU cannot read GVL_PAC; it repeats
the constants it needs under the same names. `--gvl` makes pacst check the list itself (one
VAR_GLOBAL CONSTANT block of integer and bit-string constants with literal values that fit their
types) and refuse every POU constant that has a list constant's name but not its type and value. It
also writes the list as a table that C and C++ code reads by name (`<stem>.h`).
"""
import os

from . import literals
from .common import _cls, _name, pos
from .errors import StError, StErrors
from .expressions import ExprCompiler


class Constant:
    def __init__(self, name, type_, value, code, file, line):
        self.name = name
        self.type = type_
        self.value = value  # the integer it stands for
        self.code = code  # its C spelling, for comparisons
        self.file = file
        self.line = line


def _value(comp, node, t):
    """The integer a literal initial value stands for, checked against its type."""
    te = comp.literal_te(node, t)
    code = ExprCompiler(comp, None).coerce(te, t, node)
    negative = _cls(node) == "UnaryOperation"
    literal = node.expr if negative else node
    if _cls(literal) not in ("Integer", "HexInteger", "BinaryInteger", "OctalInteger", "BitString",
                             "HexBitString", "BinaryBitString", "OctalBitString"):
        raise comp.err(node, "a global constant's value is an integer literal")
    value = literals.int_value(literal)
    return (-value if negative else value), code


def read_list(comp, src):
    """The constants of one parsed global constant list, in order; raises StErrors."""
    comp.file = src.path
    errors = []
    items = src.tree.items
    if len(items) != 1 or _cls(items[0]) != "GlobalVariableDeclarations":
        at = items[0] if items else None
        raise StErrors([comp.err(at, "a global constant list holds one VAR_GLOBAL CONSTANT block and nothing else")])
    block = items[0]
    if block.attrs is None or str(block.attrs).upper() != "CONSTANT":
        raise StErrors([comp.err(block, "VAR_GLOBAL without CONSTANT: the library's list holds constants only")])
    constants, seen = [], {}
    for item in block.items:
        try:
            init = item.init
            if _cls(init) != "TypeInitialization":
                raise comp.err(item, f"{_cls(init)} is outside the portable subset")
            t = comp._spec_type(init.spec, allow_fb=False)
            if not (t.is_int or t.is_bit):
                raise comp.err(init.spec, f"global constant of type {t.name}: the list holds integers and bit "
                                          "strings (the tables C++ code reads are integers)")
            if init.value is None:
                raise comp.err(item, "a global constant needs a value")
            value, code = _value(comp, init.value, t)
            for token in item.variables:
                name = _name(token.name if hasattr(token, "name") else token)
                comp._check_ident(token, "constant")
                if name.upper() in seen:
                    raise comp.err(token, f"constant '{name}' is declared twice (line {seen[name.upper()]})")
                line = pos(token)[0]
                seen[name.upper()] = line
                constants.append(Constant(name, t, value, code, src.path, line))
        except StError as e:
            errors.append(e)
    if errors:
        raise StErrors(errors)
    return constants


def check_pous(comp, program, constants):
    """POU constants named like a list constant must have its type and value; raises StErrors."""
    by_name = {c.name.upper(): c for c in constants}
    errors = []
    for kind, pou, file in program.items:
        if kind != "pou":
            continue
        for v in pou.vars:
            c = by_name.get(v.cname)
            if not v.constant or c is None:
                continue
            comp.file = file
            where = f"{os.path.basename(c.file)}:{c.line}"
            if v.type is not c.type:
                errors.append(comp.err(v.node, f"constant {v.name} is {v.type.name} here but {c.type.name} in "
                                               f"{where}: repeat the list's constant unchanged"))
                continue
            _, code = _value(comp, v.init, v.type)
            if code != c.code:
                shown = f"16#{c.value:0{c.type.bits // 4}X}" if c.type.is_bit else str(c.value)
                errors.append(comp.err(v.node, f"constant {v.name} differs from {where} "
                                               f"({c.type.name}#{shown}): repeat the list's constant unchanged"))
    if errors:
        raise StErrors(errors)


def table_header(stem, constants):
    """`<stem>.h`: the list as a name/type/value table for C and C++ code."""
    guard = f"PACST_{stem.upper()}_H"
    out = [f"/* Generated by pacst from {stem}.st: its constants by name, for C and C++ code. Do not edit. */",
           f"#ifndef {guard}", f"#define {guard}", "",
           "#ifndef PACST_CONSTANT_DEFINED", "#define PACST_CONSTANT_DEFINED",
           "typedef struct {", "  const char *name;", "  const char *type;", "  long long value;",
           "} PACST_CONSTANT;", "#endif", "",
           f"static const PACST_CONSTANT {stem.upper()}[] = {{"]
    out += [f'  {{"{c.name}", "{c.type.name}", {c.value}LL}},' for c in constants]
    out += ["};", f"#define {stem.upper()}_COUNT {len(constants)}", "", f"#endif /* {guard} */", ""]
    return "\n".join(out)
