"""The user-program mode's declarations (docs/translator.md, "User programs"): global variable lists,
located variables, VAR_EXTERNAL, sized STRINGs and inline arrays. The library's subset refuses all of
them; `pacst --user` accepts them on top of it for a PLC programmer's own machine program.

Every global becomes one C variable of MATIEC's wrapper type (`__IEC_<type>_t <LIST>__<NAME>`), defined
in the C file of the list's ST file and declared in POUS.h; each list has an init function
(`<LIST>__init__`). A located variable keeps its own storage: the host copies the process image into
it before a scan and out of it after (symbols.json gives its address).
"""
import os
import re
from types import SimpleNamespace

from . import types as T
from . import varlen
from .common import _cls, _name, pos
from .errors import StError, StErrors
from .names import C_KEYWORDS, C_MACROS, reserved_reason
from .order import mentioned_names

# The largest STRING of pacst's C (STR_MAX_LEN of pacst_iec.h): TwinCAT's T_MaxString, the longest string its
# string functions take. MATIEC's STRING holds 126: a longer STRING(n) or literal is dialect there.
STRING_CAPACITY = 255
# A STRING(n) or WSTRING(n) longer than STRING_CAPACITY is a type of its own (types.LongStringType), up to this n:
# TwinCAT and CODESYS name no largest n (docs/open_points.md); pacst takes what a WORD counts.
LONG_STRING_CAPACITY = 65535
MATIEC_STRING_CAPACITY = 126
# The namespaces of the standard library in TwinCAT (Tc2_Standard) and CODESYS (Standard): the standard FBs
# and functions may be written Tc2_Standard.TON, Standard.LEN in user programs.
STANDARD_NAMESPACES = {"TC2_STANDARD", "STANDARD"}
# Libraries of the vendors that user programs name and pac-test does not provide: named in the refusal.
_VENDOR_LIBRARY = re.compile(r"(TC[23]_\w+|SM3_\w+|SYS\w+|CAA_?\w+|UTIL|IOSTANDARD|CMPERRORS\w*)$", re.I)


# Names of vendor libraries pac-test provides in part that it leaves out on purpose: {(LIBRARY, NAME): why, and
# what to write instead}.
_LEFT_OUT = {
    ("TC2_SYSTEM", "PI"): "Beckhoff's documentation of Tc2_System gives PI no type and value, so pac-test does not "
                          "make one up: declare your own constant (VAR_GLOBAL CONSTANT PI : LREAL := "
                          "3.141592653589793; END_VAR) and write PI for Tc2_System.PI",
}


def left_out(library, name):
    """Why pac-test does not give the vendor library's `name`, and what to write instead; None for a name it
    has no such reason for."""
    return _LEFT_OUT.get((library.upper(), name.upper()))


def unknown_namespace(name, known):
    """The reason a program cannot name `name` as a library namespace; `known`: the namespaces it may write."""
    if _VENDOR_LIBRARY.match(name):
        return (f"pac-test does not provide the vendor library {name} (it provides PA_CONTROL, and the standard "
                "FBs and functions as Tc2_Standard or Standard); leave its calls out of the program tested")
    return (f"'{name}' is no library namespace ({', '.join(known)}); give pac-test a library of your own with the "
            f"namespace it is referenced under: --library {name}=PATH, or \"libraries\" in the wiring file")


def namespace_like(name):
    """Whether an undeclared `name` before a dot is a vendor library's namespace."""
    return _VENDOR_LIBRARY.match(name) is not None


_SIZE_BITS = {"X": 1, "B": 8, "W": 16, "D": 32, "L": 64}


class GlobalVar(T.Var):
    """A variable of a global list: `csym` is its C variable, `location` its parsed address or None."""

    def __init__(self, name, type_, init, node, constant, gvl, location, strlen):
        super().__init__(name, "global", type_, init, node, constant)
        self.gvl = gvl
        self.csym = f"{gvl.cname}__{name.upper()}"
        self.location = location
        self.strlen = strlen


class GlobalList:
    """One global variable list: a file's VAR_GLOBAL blocks, named like the file (TwinCAT's GVL name)."""

    def __init__(self, name, file, line):
        self.name = name
        self.cname = name.upper()
        self.file = file
        self.line = line
        self.qualified_only = False  # {attribute 'qualified_only'}: its variables written List.Name only
        self.vars = []
        self.refused = False  # a declaration was refused: a name it lacks may be one of those after it

    def var(self, name):
        return T.find_var(self.vars, name)


class Location:
    """A parsed `AT %...` address: area I, Q or M; size X, B, W, D; the dotted numbers; or `%I*`."""

    def __init__(self, text, area, size, numbers):
        self.text = text
        self.area = area
        self.size = size
        self.numbers = numbers  # [] for %I* / %Q*

    def as_json(self):
        return {"address": self.text, "area": self.area, "size": self.size, "numbers": self.numbers,
                "bits": _SIZE_BITS.get(self.size)}


def parse_location(comp, node, vtype):
    """The Location of a blark location node, checked against the variable's type."""
    text = str(node).replace("AT ", "").strip()
    if _cls(node) == "IncompleteLocation":
        return Location(text, text[1], None, [])
    area = node.location_prefix.value
    size = node.size_prefix.value if node.size_prefix is not None else "X"
    numbers = [int(str(node.location))] + [int(str(b)) for b in (node.bits or [])]
    if size == "L":
        raise comp.err(node, f"{text}: 64-bit located variables are outside pacst's user programs")
    if size == "X" and len(numbers) != 2:
        raise comp.err(node, f"{text}: a bit address names the byte and the bit (%IX0.3)")
    if size != "X" and len(numbers) != 1:
        raise comp.err(node, f"{text}: only bit addresses have a bit number")
    if size == "X" and not 0 <= numbers[1] <= 7:
        raise comp.err(node, f"{text}: bit {numbers[1]} of a byte (0..7)")
    elem = vtype.elem if vtype.is_array else vtype
    bits = _SIZE_BITS[size]
    fits = (elem.is_bool if bits == 1 else (elem.is_int or elem.is_bit) and elem.bits == bits)
    if not fits or (vtype.is_array and bits == 1):
        raise comp.err(node, f"{text} holds {bits} bit(s); {vtype.name} does not fit it (an elementary "
                             f"type or array of {bits}-bit elements)")
    return Location(text, area, size, numbers)


def string_type(comp, spec):
    """STRING or WSTRING (user mode, recorded as dialect) for a StringTypeSpecification, else None."""
    name = str(spec.type_name).upper()
    if name == "WSTRING":
        comp.dialect(spec, "WSTRING")
        return T.WSTRING
    return T.STRING if name == "STRING" else None


def sized_string(comp, tok):
    """(type, n or None) of a StringTypeSpecification with a length, as a variable, member, element or type name
    takes it: STRING or WSTRING with its n kept up to 255, the long string type of its own above."""
    n = string_length(comp, tok)
    short = string_type(comp, tok)
    if n <= STRING_CAPACITY:
        return short, n
    return long_string(comp, n, short is T.WSTRING), None


def long_string(comp, n, wide):
    """The LongStringType of STRING(n) or WSTRING(n), declared once a program (in the C of the first file)."""
    t = comp.long_strings.get((n, wide))
    if t is None:
        t = T.LongStringType(n, wide)
        comp.long_strings[(n, wide)] = t
        comp.program.items.append(("type", t, comp.file))
    return t


def string_length(comp, spec):
    """The n of STRING(n) / STRING[n]: a literal integer, or an integer constant as an array bound takes one
    (`STRING(PARAM_Constants.PATH_LENGTH)`), up to pacst's capacity (LONG_STRING_CAPACITY)."""
    expr = spec.length.length
    if _cls(expr) == "ParenthesizedExpression":  # STRING(n)
        expr = expr.expr
    elif _cls(expr) == "BracketedExpression":  # STRING[n]
        expr = expr.expression
    kind = "WSTRING" if str(spec.type_name).upper() == "WSTRING" else "STRING"
    if _cls(expr) == "Integer" and expr.type_name is None:
        return string_capacity(comp, spec, int(str(expr.value).replace("_", "")), kind)
    n = comp.constant_int(expr)
    if n is None:
        raise comp.err(spec, f"the length of a {kind} is an integer literal or an integer constant declared before "
                             "(a global list's, List.Name, or the POU's VAR CONSTANT) with + - *: write the number")
    comp.dialect(spec, f"a {kind} length that is a named constant")
    return string_capacity(comp, spec, n, kind)


def string_capacity(comp, spec, n, kind="STRING"):
    """`n`, when a STRING(n) (a `kind`(n)) holds it, up to LONG_STRING_CAPACITY (over STRING_CAPACITY a type of its
    own, types.LongStringType); else the refusal at `spec`."""
    if STRING_CAPACITY < n <= LONG_STRING_CAPACITY:
        comp.dialect(spec, f"{kind}(n) with n over {STRING_CAPACITY}")
        return n
    if not 1 <= n <= STRING_CAPACITY:
        raise comp.err(spec, f"{kind}({n}): pacst's {kind}(n) holds 1 to {LONG_STRING_CAPACITY} characters; "
                             f"declare {kind}({LONG_STRING_CAPACITY}) or shorter where the program's texts fit")
    if n > MATIEC_STRING_CAPACITY:
        comp.dialect(spec, f"STRING({n}) (MATIEC's STRING holds {MATIEC_STRING_CAPACITY} characters)")
    return n


def inline_array(comp, spec, file, in_out=False):
    """The type of an inline `ARRAY [lo..hi] OF T`: one per bounds and element type, named as MATIEC
    names it (`__ARRAY_OF_BYTE_8`; arrays of equal length share the C type). `ARRAY [*] OF T` in a VAR_IN_OUT
    (`in_out`): varlen.py."""
    if varlen.is_var_length(spec):
        return varlen.declare(comp, spec, file, in_out)
    elem = comp._spec_type(spec.type, allow_fb=True)
    if len(spec.subranges) > 1:  # ARRAY [0..2, 0..3] OF T: an array of rows, indexed [i, j] or [i][j]
        comp.dialect(spec, "a multi-dimensional array")
        for sub in reversed(spec.subranges[1:]):
            elem = _dimension(comp, sub, elem, file)
    sub = spec.subranges[0]
    low, high = comp._literal_int(sub.start), comp._literal_int(sub.stop)
    if low > high:
        raise comp.err(sub, f"array bounds {low}..{high}: the lower bound exceeds the upper")
    if elem.is_fb:
        comp.dialect(spec.type, f"an array of function block instances ({elem.name})")
    if elem.is_array and len(spec.subranges) == 1:
        raise comp.err(spec.type, "array of arrays: use an array of a STRUCT that holds the row")
    return _array_type(comp, low, high, elem, file)


def _dimension(comp, sub, elem, file):
    low, high = comp._literal_int(sub.start), comp._literal_int(sub.stop)
    if low > high:
        raise comp.err(sub, f"array bounds {low}..{high}: the lower bound exceeds the upper")
    return _array_type(comp, low, high, elem, file)


def _array_type(comp, low, high, elem, file):
    # by the element's name too: an ARRAY OF LTIME is not one OF TIME, though their C types are one, declared once
    key = (low, high, elem.cname, elem.name)
    t = comp.inline_arrays.get(key)
    if t is None:
        t = T.ArrayType(f"ARRAY [{low}..{high}] OF {elem.name}", low, high, elem)
        t.cname = f"__ARRAY_OF_{elem.cname}_{high - low + 1}"
        declared = any(k[:3] == key[:3] for k in comp.inline_arrays)
        comp.inline_arrays[key] = t
        if not declared:
            comp.program.items.append(("type", t, file))
    return t


def var_type(comp, init, allow_fb, in_out=False):
    """(type, STRING length or None) of a user variable's initialisation: inline arrays and sized
    STRINGs besides what the library's subset declares; ARRAY [*] in a VAR_IN_OUT (`in_out`)."""
    cls = _cls(init)
    if cls == "ArrayTypeInitialization":
        if init.indirection is not None:  # POINTER TO ARRAY [0..24] OF I_Logger
            return comp.pointer_type(init, inline_array(comp, init.spec, comp.file), init.indirection), None
        return inline_array(comp, init.spec, comp.file, in_out), None
    if cls == "InitializedStructure":  # p : ST_Point := (X := 1, Y := 2); Delay : TON := (PT := T#1S)
        return comp._resolve_type(init.name, allow_fb=allow_fb), None
    if cls == "StringTypeInitialization" or cls == "TypeInitialization":
        spec = init.spec
        tok = getattr(spec, "type", None) if _cls(spec) == "SimpleSpecification" else spec
        if _cls(tok) == "StringTypeSpecification" and string_type(comp, tok) is not None:
            return sized_string(comp, tok) if tok.length is not None else (string_type(comp, tok), None)
        if cls == "TypeInitialization":
            return comp._spec_type(spec, allow_fb=allow_fb), None
    if cls == "SubrangeTypeInitialization" and init.indirection is None and init.spec.subrange is not None:
        # UINT(1..MAX): the base type; its range is not checked, as TwinCAT checks it only with a CheckRange POU
        comp.dialect(init, "a subrange type")
        return comp._resolve_type(init.spec.type_name, allow_fb=False), None
    raise comp.err(init, f"{cls} is outside pacst's user programs")


def c_safe(comp, var):
    """`var` with a C name of its own where its name is a C keyword or macro (`Register`, `EOF`: __V_REGISTER),
    in user mode; `_check_ident` lets such a name through there and marks it dialect (MATIEC's C names it alone)."""
    up = var.name.upper()
    if comp.user and up in ("EN", "ENO"):
        raise comp.err(var.node, f"'{var.name}' is the name of the EN and ENO pins IEC 61131-3 gives every call: "
                                 "rename it")
    if comp.user and (up in C_KEYWORDS or up in C_MACROS):
        var.cname = T.c_safe_name(up)
    return var


def union_type(comp, decl):
    """User mode: TYPE U : UNION ... END_UNION END_TYPE, a C union: every member at offset 0, the memory zeroed
    when a variable of it is initialised (TwinCAT gives a UNION's members no initial values; a declaration's
    `(Member := value)` sets that member, as CODESYS does)."""
    comp._declare_global(decl.name, "type")
    comp.dialect(decl, "UNION")
    if decl.extends is not None:
        raise comp.err(decl.extends, "a UNION EXTENDS nothing: declare its members")
    t = T.StructType(_name(decl.name))
    t.union = True
    comp.types[t.cname] = t  # a member may point at the UNION itself (FsCommon's U_Pointer.pNested)
    try:
        _union_members(comp, t, decl)
    except (StError, StErrors):
        del comp.types[t.cname]
        raise
    return t


def _union_members(comp, t, decl):
    """The members of the UNION `t`."""
    seen = set()
    for el in decl.declarations:
        spec = el.spec
        if _cls(spec) == "ArraySpecification":
            mtype = inline_array(comp, spec, comp.file)
        else:
            mtype = comp._spec_type(spec, allow_fb=True)  # a function block is refused below, saying why
        if mtype is t or mtype.is_fb or (mtype.is_array and (mtype.elem is t or mtype.elem.is_fb)):
            fb = mtype.is_fb or (mtype.is_array and mtype.elem.is_fb)
            instead = ": declare the instance beside the UNION" if fb else ": write a POINTER TO it"
            raise comp.err(el, f"a member of the UNION {t.name} of the type {mtype.name}: a UNION holds data, "
                               f"not itself or a function block{instead}")
        comp._check_ident(el.name, "member", c_name=False)
        name = _name(el.name)
        if name.upper() in seen:
            raise comp.err(el.name, f"member '{name}' is declared twice")
        seen.add(name.upper())
        t.members.append(c_safe(comp, T.Var(name, "member", mtype, None, el.name)))


def initial_value(init):
    """The initial value node of a declaration's initialisation, or None."""
    if _cls(init) == "InitializedStructure":
        return init.init
    return getattr(init, "value", None)


def check_string_init(comp, var):
    """A sized STRING's literal initial value fits its length."""
    if var.strlen is not None and var.init is not None and _cls(var.init) == "String":
        te = comp.literal_te(var.init, var.type)
        length = int(te.code.rsplit(",", 1)[1].strip(" )"))
        if length > var.strlen:
            raise comp.err(var.init, f"initial value of {length} characters for a {var.type.name}({var.strlen})")


def global_list(comp, block, src):
    """Declare one VAR_GLOBAL block of a user global list."""
    name = os.path.splitext(os.path.basename(src.path))[0]
    attrs = block.attrs
    flags = {a.name for a in type(attrs) if a in attrs} if attrs is not None else set()
    if flags - {"constant", "retain", "persistent", "non_retain"}:
        raise comp.err(block, f"VAR_GLOBAL {', '.join(sorted(flags))} is outside pacst's user programs")
    constant = "constant" in flags
    up = name.upper()
    gvl = comp.gvls.get(up)
    if gvl is None:
        why = reserved_reason(name, True)
        if why:
            raise comp.err(block, f"global variable list {why}")
        if up in comp.types or up in comp.pous or up in comp.enum_values:
            raise comp.err(block, f"global variable list '{name}' has the name of a type, POU or enumeration value")
        if up in comp.namespaces:
            raise comp.err(block, f"global variable list '{name}' has the name of the library namespace "
                                  f"{comp.namespaces[up][0]}: rename it (Name.x would name the library's x)")
        gvl = comp.gvls[up] = GlobalList(name, src.path, pos(block)[0])
        gvl.qualified_only = qualified_only(comp, pos(block)[0])
        comp.program.items.append(("gvl", gvl, src.path))
    elif gvl.file != src.path:
        raise comp.err(block, f"global variable list '{name}' is declared in {gvl.file} too")
    refused = []
    for item in block.items:  # every refused declaration is reported, not only the first
        try:
            global_items(comp, gvl, [item], constant)
        except (StError, StErrors) as e:
            refused += e.errors if isinstance(e, StErrors) else [e]
    if refused:
        gvl.refused = True
        raise StErrors(refused)


def global_items(comp, gvl, items, constant):
    """Declare the variables `items` of the global list `gvl`; an instance of a FUNCTION_BLOCK declared later waits
    for it (Compiler._pending_globals)."""
    comp.gvl_declaring = gvl
    try:
        _global_items(comp, gvl, items, constant)
    finally:
        comp.gvl_declaring = None


def _later_fb(comp, item):
    """The upper name of the FUNCTION_BLOCK of the program, not declared yet, that `item`'s type names, or None."""
    later = comp.later_fbs - set(comp.pous) - comp.refused
    if not later:
        return None
    found = mentioned_names(SimpleNamespace(items=[item.init])) & later
    return min(found) if found else None


def _global_items(comp, gvl, items, constant):
    for item in items:
        fb = _later_fb(comp, item)
        if fb is not None:
            comp.dialect(item, "a function block instance in a global list")
            comp.pending_globals.setdefault(fb, []).append((gvl, item, constant, comp.file))
            continue
        spec = item.spec
        vtype, strlen = var_type(comp, item.init, allow_fb=True)
        value = initial_value(item.init)
        if vtype.is_fb or vtype.is_array and vtype.elem.is_fb:
            comp.dialect(item, "a function block instance in a global list")
            if constant or spec.location is not None:
                raise comp.err(item, "a function block instance in a global list is neither CONSTANT nor located")
        location = parse_location(comp, spec.location, vtype) if spec.location is not None else None
        if constant and value is None:
            raise comp.err(item, "a global constant needs a value")
        if constant and location is not None:
            raise comp.err(spec.location, "a located variable cannot be CONSTANT")
        if value is not None and (vtype.is_array or vtype.is_struct):
            comp.dialect(value, "an initial value of an array or a struct")
        elif value is not None and not (vtype.is_elementary or vtype.is_enum):
            raise comp.err(value, "initial values are only for elementary and enumeration variables")
        for token in spec.variables:
            vname = _name(token)
            # C names it after its list (GVL_LIMITS__UINT_MAX): a C macro's name is free, as TwinCAT's
            # GVL_TypeValueLimits.UINT_MAX; MATIEC's C names it alone (_check_ident marks it dialect)
            comp._check_ident(token, "global variable", c_name=False)
            vup = vname.upper()
            if gvl.var(vname) is not None:
                raise comp.err(token, f"global variable '{vname}' is declared twice in {gvl.name}")
            # List.Name never means the value; a qualified_only enumeration's value alone is no value
            shadows_value = vup in comp.enum_values and not gvl.qualified_only \
                and not getattr(comp.enum_values[vup], "qualified_only", False)
            # in a qualified_only list the name alone never means the variable: TcUnit's GVL_TcUnit declares
            # GetCpuCounter : GETCPUCOUNTER (in C the variable is named after its list)
            shadows_type = (vup in comp.types or vup in comp.pous) and not gvl.qualified_only
            if shadows_type or shadows_value or vup in comp.gvls:
                raise comp.err(token, f"global variable '{vname}' has the name of a type, POU, enumeration "
                                      "value or global list")
            if vup in comp.enum_values:
                comp.dialect(token, "a global variable of a qualified_only list named like an enumeration value")
            if vup in comp.types or vup in comp.pous:
                comp.dialect(token, "a global variable of a qualified_only list named like a type or POU")
            v = GlobalVar(vname, vtype, value, token, constant, gvl, location, strlen)
            if value is not None:
                comp.init_code(v, "x")  # checks the initial value now
                check_string_init(comp, v)
            gvl.vars.append(v)
            comp.globals.setdefault(vup, []).append(v)


_QUALIFIED_ONLY = re.compile(r"\{\s*attribute\s+'qualified_only'\s*\}", re.I)
_STRICT = re.compile(r"\{\s*attribute\s+'strict'\s*\}", re.I)


def qualified_only(comp, line):
    """Whether TwinCAT's {attribute 'qualified_only'} stands before `line` of the file being compiled, after
    the declaration before it: its names are then written List.Name or Type.Value only, as the IDE demands."""
    return _attribute_before(comp, line, _QUALIFIED_ONLY)


def strict(comp, line):
    """Whether {attribute 'strict'} stands before the enumeration at `line`: no integer is assigned to it."""
    return _attribute_before(comp, line, _STRICT)


def _attribute_before(comp, line, attribute):
    src = next((s for s in comp.sources if s.path == comp.file), None)
    if src is None or not line:
        return False
    before = src.text.splitlines()[:line - 1]
    for i in range(len(before) - 1, -1, -1):
        text = before[i]
        if re.search(r"\bEND_(?:TYPE|VAR|STRUCT)\b", text, re.I):
            return False
        if attribute.search(text):
            return True
    return False


def lookup_global(comp, token, at=None):
    """The global an unqualified name means in user mode, or None; several lists declaring it is an error, and
    so is the name alone of a list under {attribute 'qualified_only'} (at `at`, where `token` is a name only)."""
    found = comp.globals.get(_name(token).upper(), [])
    token = token if at is None else at
    if found and _name(token).upper() in comp.enum_values and all(v.gvl.qualified_only for v in found):
        return None  # ERR_OK alone is the enumeration value; GVL_Errors.ERR_OK the list's
    if len(found) > 1:
        raise comp.err(token, f"'{_name(token)}' is declared in the global lists "
                              f"{', '.join(v.gvl.name for v in found)}: qualify it (List.Name)")
    if found and found[0].gvl.qualified_only and found[0].gvl is comp.gvl_declaring:
        # the list's own initial values name its variables alone, as TwinCAT takes them (GVL_TypeValueLimits'
        # T_SIZE_MIN : T_Size := UDINT_MIN)
        comp.dialect(token, "a variable of a qualified_only list named alone in the list's own declarations")
    elif found and found[0].gvl.qualified_only:
        g = found[0]
        raise comp.err(token, f"'{_name(token)}' alone: the global list {g.gvl.name} has {{attribute "
                              f"'qualified_only'}}, as in TwinCAT write {g.gvl.name}.{g.name}")
    return found[0] if found else None


def external(comp, pou, block):
    """Declare VAR_EXTERNAL: each names a global of the same type."""
    constant = block.attrs is not None and "constant" in str(block.attrs).lower()
    for item in block.items:
        name = _name(item.name)
        g = lookup_global(comp, item.name)
        if g is None:
            raise comp.err(item.name, f"VAR_EXTERNAL '{name}' names no global variable")
        spec = item.spec
        if _cls(spec) == "ArraySpecification":
            t = inline_array(comp, spec, comp.file)
        elif _cls(spec) == "SimpleSpecification" and _cls(spec.type) == "StringTypeSpecification":
            t = string_type(comp, spec.type) or T.STRING
        else:
            t = comp._spec_type(spec, allow_fb=False)
        if t is not g.type:
            raise comp.err(item.name, f"VAR_EXTERNAL '{name}' is {t.name}, the global {g.gvl.name}.{g.name} is "
                                      f"{g.type.name}")
        if pou.var(name) is not None or name.upper() in pou.externals:
            raise comp.err(item.name, f"variable '{name}' is declared twice")
        if g.constant and not constant:
            raise comp.err(item.name, f"the global {g.gvl.name}.{g.name} is CONSTANT: declare VAR_EXTERNAL CONSTANT")
        pou.externals[name.upper()] = (g, constant)


def alias(comp, decl):
    """The type an alias `TYPE T_Type : __SYSTEM.TYPE_CLASS; END_TYPE` (or `: INT`, `: POINTER TO ST_Data`, `: E_Mode`)
    names: the alias is another name of it, as in TwinCAT (a value of the type and of the alias is the same). An
    alias with an initial value of its own, or that EXTENDS, is refused."""
    init = decl.init
    if decl.extends is not None:
        raise comp.err(decl, f"type alias {_name(decl.name)} with EXTENDS: extend a STRUCT or a FUNCTION_BLOCK")
    if getattr(init, "value", None) is not None:
        raise comp.err(init.value, f"type alias {_name(decl.name)} with an initial value of its own: pacst takes an "
                                   "alias as another name of its type; give the variables the initial value")
    t = comp._spec_type(init.spec, allow_fb=False)
    comp.dialect(decl, "a type alias")
    return t


def constant_aggregate(comp, node, t):
    """The initial value of the global CONSTANT array or struct of type `t` that the initial value `node` names
    (`GVL_Errors.ERR_NO_ERROR`, or the name alone), or None: the variable is given the same value, the constant's
    own initial value translated again where the variable is initialised."""
    g = None
    if _cls(node) == "SimpleVariable":
        g = lookup_global(comp, node.name)
    elif _cls(node) == "MultiElementVariable" and len(node.elements) == 1 and _cls(node.elements[0]) == "FieldSelector" \
            and _cls(node.elements[0].field) == "SimpleVariable" and _name(node.name.name).upper() in comp.gvls:
        g = comp.gvls[_name(node.name.name).upper()].var(_name(node.elements[0].field.name))
    if g is None or not g.constant or g.type is not t or g.init is None:
        return None
    return g.init
