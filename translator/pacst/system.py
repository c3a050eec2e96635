"""User mode: TwinCAT's operators starting with `__` (docs/user_dialect.md).

- `__SYSTEM.TYPE_CLASS`, the enumeration of the type classes (`__SYSTEM.TYPE_CLASS.TYPE_INT`), with the numbers
  of CODESYS's and TwinCAT's TypeClass (TYPE_BOOL 0 ... TYPE_LTIMEOFDAY 48, TYPE_INTERFACE 16#F000) and base type
  UDINT, as TwinCAT programs convert it (`UDINT_TO_INT(Class)`); `__SYSTEM.AnyType`, the struct of an ANY input
  (pValue, diSize, TypeClass). Both are declared in the program the first time a program names them.
  `IBaseLibrary.TypeClass` (the library Base Interfaces under its namespace) is `__SYSTEM.TYPE_CLASS`.
  `__SYSTEM.IQueryInterface`, TwinCAT's root INTERFACE, is one without METHODs.
- A VAR_INPUT of type ANY: a __SYSTEM.AnyType the call fills with the address, size and type class of what it
  gives.
- `p := __NEW(T)` and `p := __NEW(T, n)`: an instance (or n elements) of T from a bounded heap of the test
  runtime (pacst_iec.h: PACST_HEAP_BYTES), initialised as a variable of T is (an FB's initial values and its
  METHOD FB_init, given the arguments of `__NEW(FB_List(10))` as a declaration's); 0 when the heap has no room,
  as TwinCAT's router memory returns 0 when it is exhausted.
- `__DELETE(p)`: the FB's METHOD FB_exit first when p points to an FB that has one, then the memory freed and
  p set to 0; p = 0 does nothing; a pointer __NEW did not return stops the test with its ST line.
"""
from . import rewrite
from . import types as T
from .common import _cls, _name, pos
from .errors import StError

NAMESPACE = "__SYSTEM"
# The type classes in their order: each one's number is its index (CODESYS's library Base Interfaces, TypeClass).
_TYPE_CLASSES = (
    "TYPE_BOOL TYPE_BIT TYPE_BYTE TYPE_WORD TYPE_DWORD TYPE_LWORD TYPE_SINT TYPE_INT TYPE_DINT TYPE_LINT "
    "TYPE_USINT TYPE_UINT TYPE_UDINT TYPE_ULINT TYPE_REAL TYPE_LREAL TYPE_STRING TYPE_WSTRING TYPE_TIME TYPE_DATE "
    "TYPE_DATEANDTIME TYPE_TIMEOFDAY TYPE_POINTER TYPE_REFERENCE TYPE_SUBRANGE TYPE_ENUM TYPE_ARRAY TYPE_PARAMS "
    "TYPE_USERDEF TYPE_NONE TYPE_ANY TYPE_ANYBIT TYPE_ANYDATE TYPE_ANYINT TYPE_ANYNUM TYPE_ANYREAL TYPE_LAZY "
    "TYPE_LTIME TYPE_BITCONST TYPE_UXINT TYPE_XWORD TYPE_XINT TYPE_XSTRING TYPE_VARLENARRAY TYPE_ANYSTRING "
    "TYPE_VECTOR TYPE_LDATE TYPE_LDATEANDTIME TYPE_LTIMEOFDAY").split()
# and one value out of that order: TYPE_INTERFACE, which the library Base Interfaces keeps at 16#F000 for programs
# of CODESYS 3.1 (TcUnit's F_AnyToUnionValue names it as a CASE label)
_TYPE_CLASS_NUMBERS = list(range(len(_TYPE_CLASSES))) + [0xF000]
TYPES = ("TYPE_CLASS", "ANYTYPE", "IQUERYINTERFACE")


# CODESYS's library Base Interfaces, referenced under the namespace IBaseLibrary (as TcUnit references it), declares
# the type classes as TypeClass: `IBaseLibrary.TypeClass` is __SYSTEM.TYPE_CLASS here
BASE_INTERFACES = "IBASELIBRARY"


def canonical(parts):
    """The parts of a dotted name, `IBaseLibrary.TypeClass...` as `__SYSTEM.TYPE_CLASS...`."""
    if len(parts) >= 2 and parts[0].upper() == BASE_INTERFACES and parts[1].upper() == "TYPECLASS":
        return [NAMESPACE, "TYPE_CLASS"] + list(parts[2:])
    return list(parts)


def is_system(name):
    """Whether the dotted `name` starts with the namespace __SYSTEM (or is IBaseLibrary.TypeClass...)."""
    return canonical(name.split("."))[0].upper() == NAMESPACE


def system_type(comp, name, node):
    """The type `__SYSTEM.<name>` (TYPE_CLASS, AnyType or IQueryInterface), declared in the program at its first
    use."""
    up = name.upper()
    if up not in TYPES:
        raise comp.err(node, f"'{NAMESPACE}.{name}': pacst provides {NAMESPACE}.TYPE_CLASS, {NAMESPACE}.AnyType and "
                             f"{NAMESPACE}.IQueryInterface of TwinCAT's __SYSTEM (not its exception codes)")
    comp.dialect(node, f"TwinCAT's {NAMESPACE}.{name}")
    key = f"{NAMESPACE}__{up}"
    t = comp.types.get(key)
    if t is not None:
        return t
    if up == "IQUERYINTERFACE":  # TwinCAT's root INTERFACE: no METHODs (FsCommon's T_QueryInterface, U_Pointer)
        t = T.InterfaceType(f"{NAMESPACE}.IQueryInterface")
    elif up == "TYPE_CLASS":
        t = T.EnumType(f"{NAMESPACE}.TYPE_CLASS", list(_TYPE_CLASSES) + ["TYPE_INTERFACE"], _TYPE_CLASS_NUMBERS,
                       T.ELEMENTARY["UDINT"])
    else:
        t = T.StructType(f"{NAMESPACE}.AnyType")
        t.members = [T.Var("pValue", "member", comp.pointer_to(T.ELEMENTARY["BYTE"]), None, None),
                     T.Var("diSize", "member", T.DINT, None, None),
                     T.Var("TypeClass", "member", system_type(comp, "TYPE_CLASS", node), None, None)]
    t.cname = key
    comp.types[key] = t
    comp.program.items.append(("type", t, comp.file))
    return t


def any_type(comp, node):
    """The type of a VAR_INPUT of type ANY (user mode): TwinCAT passes it as a __SYSTEM.AnyType, which the POU
    reads (`Value.TypeClass`, `Value.pValue`, `Value.diSize`) or assigns to one; a call gives any variable or value
    (any_argument)."""
    anytype = system_type(comp, "AnyType", node)
    t = comp.types.get(f"{NAMESPACE}__ANY")
    if t is None:
        t = T.StructType("ANY")
        t.members = anytype.members
        t.cname = anytype.cname  # the same C struct: declared once, as __SYSTEM.AnyType
        t.any = True
        comp.types[f"{NAMESPACE}__ANY"] = t
    comp.dialect(node, "ANY")
    return t


def same_struct(source, target):
    """Whether an ANY goes to a __SYSTEM.AnyType (or back) as it is: the same C struct."""
    return source.is_struct and target.is_struct and source.cname == target.cname == f"{NAMESPACE}__ANYTYPE"


# TYPE_CLASS of the elementary types an ANY input is given
_CLASS_OF = {"BOOL": "TYPE_BOOL", "BYTE": "TYPE_BYTE", "WORD": "TYPE_WORD", "DWORD": "TYPE_DWORD", "LWORD": "TYPE_LWORD",
             "SINT": "TYPE_SINT", "INT": "TYPE_INT", "DINT": "TYPE_DINT", "LINT": "TYPE_LINT", "USINT": "TYPE_USINT",
             "UINT": "TYPE_UINT", "UDINT": "TYPE_UDINT", "ULINT": "TYPE_ULINT", "REAL": "TYPE_REAL",
             "LREAL": "TYPE_LREAL", "STRING": "TYPE_STRING", "WSTRING": "TYPE_WSTRING", "TIME": "TYPE_TIME",
             "LTIME": "TYPE_LTIME", "DATE": "TYPE_DATE", "DATE_AND_TIME": "TYPE_DATEANDTIME",
             "TIME_OF_DAY": "TYPE_TIMEOFDAY"}


def _class_of(t):
    if t.is_pointer:
        return "TYPE_REFERENCE" if t.reference else "TYPE_POINTER"
    if t.is_enum:
        return "TYPE_ENUM"
    if t.is_array:
        return "TYPE_ARRAY"
    return _CLASS_OF.get(t.name, "TYPE_USERDEF")


def variable(ex, arg):
    """The Ref of the variable `arg` names, when it is one with an address (no PROPERTY, bit, enumeration value
    or constant of a type); else None, and the argument is a value."""
    if _cls(arg) not in ("SimpleVariable", "MultiElementVariable") or ex.body is None \
            or ex.body.property_target(arg) is not None or enum_value(ex.comp, arg) is not None:
        return None
    try:
        r = ex.body.ref(arg)
    except StError:
        return None  # an enumeration value, a named value: passed as a value
    return r if getattr(r, "whole", None) is None else None


def any_argument(ex, arg, pin):
    """C of the __SYSTEM.AnyType an ANY input `pin` is given for `arg`: the address of the variable (of a copy of
    a value, alive during the call), its size in bytes and its type class."""
    comp = ex.comp
    r = variable(ex, arg)
    if r is not None:
        if same_struct(r.type, pin.type):
            return r.read()  # an ANY passed on
        return _descriptor(comp, pin, f"&({r.read()})", r.type)
    te = ex.expr(arg, None)
    t = ex.default_type(te, None) if te.type.kind in ("anyint", "anyreal") else te.type
    if t.is_fb:
        raise comp.err(arg, f"an ANY input is given a variable or a value, not a {t.name} instance here")
    return _descriptor(comp, pin, f"(({t.cname}[]){{{ex.coerce(te, t, arg)}}})", t)


def _descriptor(comp, pin, address, t):
    cls = system_type(comp, "TYPE_CLASS", pin.node)
    return (f"(({pin.type.cname}){{(__PTR_BYTE)(void *)({address}), (DINT)sizeof({t.cname}), "
            f"{cls.cvalue(_class_of(t))}}})")


def enum_value(comp, node):
    """(EnumType, value) of `__SYSTEM.TYPE_CLASS.TYPE_INT` (a MultiElementVariable), or None for another name."""
    if _cls(node) != "MultiElementVariable" or node.name.dereferenced:
        return None
    names = [el for el in node.elements if _cls(el) == "FieldSelector" and _cls(el.field) == "SimpleVariable"]
    head = canonical([_name(node.name.name)] + [_name(el.field.name) for el in names[:1]])
    if head[0].upper() != NAMESPACE:
        return None
    if len(names) != len(node.elements) or len(names) != 2 or head[1].upper() != "TYPE_CLASS":
        raise comp.err(node, f"'{NAMESPACE}' names its TYPE_CLASS's values here: {NAMESPACE}.TYPE_CLASS.TYPE_INT")
    t = system_type(comp, "TYPE_CLASS", node)
    return t, comp.enum_value_of(t, _name(names[1].field.name), names[1].field)


def case_label(comp, parts, node):
    """(EnumType, value) of a CASE label written `__SYSTEM.TYPE_CLASS.TYPE_INT` (split at its dots), or None."""
    parts = canonical(parts)
    if not parts or parts[0].upper() != NAMESPACE:
        return None
    if len(parts) != 3 or parts[1].upper() != "TYPE_CLASS":
        raise comp.err(node, f"'{NAMESPACE}' names its TYPE_CLASS's values here: {NAMESPACE}.TYPE_CLASS.TYPE_INT")
    t = system_type(comp, "TYPE_CLASS", node)
    return t, comp.enum_value_of(t, parts[2], node)


def _where(comp, node):
    line, col = pos(node)
    return f"{comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")


def is_new(node):
    """Whether the expression `node` is a call of __NEW."""
    return _cls(node) == "FunctionCall" and _cls(node.name) == "SimpleVariable" \
        and _name(node.name.name).upper() == "__NEW"


def new_assignment(body, target, node, ind):
    """C statements of `target := __NEW(T)` / `__NEW(T, n)`: the memory from the heap, each element initialised,
    then the pointer (NULL when the heap had no room) written to the target, a POINTER."""
    comp, ex = body.comp, body.ex
    comp.dialect(node, "TwinCAT's __NEW")
    args = [getattr(p, "value", p) for p in node.parameters]
    fb_init_args = None
    if len(args) == 1 and _cls(args[0]) == "FunctionCall" and _cls(args[0].name) == "SimpleVariable":
        # __NEW(FB_List(Initial_Capacity := 0)): the FB's FB_init given arguments, as in a declaration
        fb_init_args, args = list(args[0].parameters), [args[0].name]
    if not 1 <= len(args) <= 2 or any(a is None for a in args) or _cls(args[0]) != "SimpleVariable":
        raise comp.err(node, "__NEW takes a type and, for an elementary type, a number of elements: "
                             "__NEW(ST_Data), __NEW(BYTE, n), or an FB with FB_init arguments: __NEW(FB_List(10))")
    name = _name(args[0].name)
    if name.upper().startswith(rewrite.NEW_POINTER):  # __NEW(POINTER TO T, n), rewritten before parsing
        name = name[len(rewrite.NEW_POINTER):].lstrip("_")
        t = comp.pointer_to(comp._resolve_type(args[0].name.update(value=name), allow_fb=True))
    else:
        t = comp._resolve_type(args[0].name, allow_fb=True)
    if fb_init_args is not None and (not t.is_fb or comp._fb_init(t) is None):
        raise comp.err(node, f"__NEW({t.name}(...)): arguments go to an FB's METHOD FB_init, and {t.name} has none: "
                             f"write __NEW({t.name})")
    if len(args) == 2 and not t.is_elementary and not t.is_pointer:
        raise comp.err(args[1], f"__NEW({t.name}, n): the number of elements is for an elementary type, as in "
                                "TwinCAT; allocate an array type or one instance")
    if not target.type.is_pointer or target.type.reference:
        raise comp.err(node, f"__NEW returns a POINTER TO {t.name}: assign it to a POINTER, not a "
                             f"{target.type.name}")
    count = "1"
    if len(args) == 2:
        te = ex.expr(args[1], T.ELEMENTARY["UDINT"])
        if te.type is not T.ANY_INT and not (te.type.is_int or te.type.is_bit):
            raise comp.err(args[1], f"__NEW's number of elements is an integer, not {te.type.name}")
        count = str(te.value) if te.type is T.ANY_INT else te.code
    lines = [f"{ind}{{", f"{ind}  long long __n = (long long)({count});",
             f"{ind}  {t.cname} *__p = ({t.cname} *)__pacst_new(sizeof({t.cname}), __n);",
             f"{ind}  if (__p != NULL) {{", f"{ind}    long long __i;"]
    if t.is_fb:
        lines.append(f"{ind}    BOOL retain = FALSE;")
    element = T.Var("e", "member", t, None, node)
    element.fb_init_args = fb_init_args
    init = comp.init_code(element, "__p[__i]")
    lines.append(f"{ind}    for (__i = 0; __i < __n; __i++) {{")
    lines += [f"{ind}      {line}" for line in init]
    lines += [f"{ind}    }}", f"{ind}  }}",
              f"{ind}  {target.write(f'({target.type.cname})(void *)__p')}", f"{ind}}}"]
    return lines


def delete_statement(body, node, ind):
    """C statements of `__DELETE(p);`."""
    comp = body.comp
    comp.dialect(node, "TwinCAT's __DELETE")
    args = [getattr(p, "value", p) for p in node.parameters]
    if len(args) != 1 or args[0] is None:
        raise comp.err(node, "__DELETE takes one POINTER: __DELETE(p)")
    if _cls(args[0]) == "SimpleVariable" and not args[0].dereferenced and _name(args[0].name).upper() == "THIS" \
            and body.lookup("THIS") is None:  # the instance itself, made by __NEW (the collections' Dispose)
        return _delete_this(body, node, ind)
    r = body.ref(args[0], raw=True)
    if r.type.is_pointer and r.type.reference and r.type.target.is_pointer:  # a REFERENCE TO POINTER: the pointer
        r = body.ref(args[0])
    if not r.type.is_pointer or r.type.reference:
        raise comp.err(args[0], f"__DELETE's operand is a POINTER, not a {r.type.name} (TwinCAT refuses it too)")
    if not r.writable:
        raise comp.err(args[0], f"'{r.var.name}' cannot be written: {r.why_not}")
    lines = [f"{ind}if ({r.read()} != NULL) {{"] + _freed(comp, node, r.type.target, r.read(), ind + "  ")
    return lines + [f"{ind}  {r.write('NULL')}", f"{ind}}}"]


def _freed(comp, node, t, address, ind):
    """C statements that free the instance of `t` at `address`: its METHOD FB_exit first, when it has one."""
    lines = []
    fb_exit = t.pou.methods.get("FB_EXIT") if t.is_fb and getattr(t, "pou", None) is not None else None
    if fb_exit is not None:
        inputs = [v for v in fb_exit.vars if v.section == "input"]
        if len(inputs) != 1 or not inputs[0].type.is_bool or any(v.section in ("output", "inout")
                                                                  for v in fb_exit.vars):
            raise comp.err(node, f"the METHOD FB_exit of {t.name} is not TwinCAT's: its one input is bInCopyCode (BOOL)")
        lines.append(f"{ind}(void){fb_exit.cfunc}(__pacst_heap_block((void *){address}, \"{_where(comp, node)}\"),"
                     " TRUE, NULL, FALSE);")
    return lines + [f"{ind}__pacst_delete((void *){address}, \"{_where(comp, node)}\");"]


def _delete_this(body, node, ind):
    """C statements of `__DELETE(THIS);` in a METHOD: the instance's FB_exit, then its memory freed; an instance not
    made by __NEW stops the run at the ST line, as TwinCAT's statements after it would read freed memory."""
    arg = node.parameters[0]
    this = body.ex._this_instance(getattr(arg, "value", arg))  # its FB, whose METHOD's C function has it in data__
    return _freed(body.comp, node, this.type, "data__", ind)
