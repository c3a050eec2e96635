"""Checks ST POUs against the portable subset and generates C with MATIEC's interface.

One pass does both: every expression is typed as it is translated, so the check mode and the build
mode refuse exactly the same programs. IEC semantics that C does not give by itself (wrap-around of
small types, truncating division, rounding conversions, TIME arithmetic) are spelled out in the
generated C; see docs/translator.md.

This module holds the driver and the declarations (types, POUs and their variables, initial values);
expressions.py types and translates expressions, body.py a POU's statements.
"""
import dataclasses
import difflib
import os
import re

from . import literals, rewrite
from . import types as T
from .body import BodyCompiler
from .common import TE, _BIT_LITERALS, _INT_LITERALS, _cls, _name, pos
from .errors import StError, StErrors, StWarning
from .expressions import ExprCompiler
from .names import STANDARD_FUNCTIONS, reserved_reason
from . import csizes, runinit, system, user, varlen



def _signature(pou):
    """What an INTERFACE's METHOD and its implementation must share: the result and the pins."""
    return pou.ret, [(v.section, v.type) for v in pou.vars if v.section in ("input", "output", "inout")]


def _address_of(node):
    """The operand of `ADR(x)` (user mode: a POINTER's initial value), or None; blark reads the initial value of a
    POINTER TO ARRAY as an array's `n(x)` with ADR for n."""
    if _cls(node) == "FunctionCall" and _cls(node.name) == "SimpleVariable" and _name(node.name.name).upper() == "ADR" \
            and len(node.parameters) == 1:
        return getattr(node.parameters[0], "value", node.parameters[0])
    if _cls(node) == "ArrayInitialization" and len(node.elements) == 1:
        count = getattr(node.elements[0], "count", None)
        if _cls(count) == "EnumeratedValue" and count.type_name is None and _name(count.name).upper() == "ADR":
            return node.elements[0].element
    return None


def _array_leaves(t, target):
    """(type, C lvalue) of each element that is no array of the array `t` at `target`, in TwinCAT's order."""
    for k in range(t.high - t.low + 1):
        if t.elem.is_array:
            yield from _array_leaves(t.elem, f"{target}.table[{k}]")
        else:
            yield t.elem, f"{target}.table[{k}]"


def _array_elements(node):
    """The elements of an array's initial value in order (blark nests the ones after the first, unbracketed)."""
    out = []
    for el in node.elements:
        if _cls(el.element) == "ArrayInitialization" and not el.element.brackets and el.count is None:
            out += _array_elements(el.element)
        else:
            out.append(el)
    return out


def _struct_elements(node):
    """(member name, value) of a struct's initial value. blark reads `(X := 1, Y := 2)` as X := [1, Y := 2]
    (an unbracketed array whose later elements are assignments): those are taken apart again."""
    out = []
    for el in node.elements:
        value = el.value
        if _cls(value) == "ArrayInitialization" and not value.brackets and all(
                _cls(e.element) == "BinaryOperation" and str(e.element.op) == ":=" and e.count is None
                for e in _array_elements(value)[1:]):
            rest = _array_elements(value)
            out.append((el.name, rest[0].element))
            out += [(e.element.left.name, e.element.right) for e in rest[1:]]
        else:
            out.append((el.name, value))
    return out


# Tc2_System's memory functions, which the translator provides itself (Tc2_System.MEMCPY is MEMCPY)
_TC2_SYSTEM_MEMORY = {"MEMCPY", "MEMMOVE", "MEMSET", "MEMCMP"}


class Pou:
    def __init__(self, kind, name, file, node):
        self.kind = kind  # "fb" or "function" (a user PROGRAM is an "fb" with `program` set)
        self.program = False
        self.action = False  # user mode: an ACTION (a method without interface)
        self.base = None  # user mode: the FUNCTION_BLOCK this one EXTENDS
        self.super_body = False  # user mode: the base's body as SUPER^() of a derived FB
        self.inherited_from = None  # user mode: the base FB whose METHOD, ACTION or body this is a copy of
        self.native = False  # a FUNCTION the host implements (user mode, --native)
        self.externals = {}  # upper name -> (GlobalVar, constant), from VAR_EXTERNAL (user mode)
        self.globals_used = {}  # C name -> GlobalVar the body names without VAR_EXTERNAL (user mode)
        self.qualifiers = []  # (start, end, GlobalVar): the offsets of each `List.` before a global in the body
        self.name = name
        self.cname = name.upper()
        self.cfunc = self.cname  # the C function of a FUNCTION (a method's is <FB>__<METHOD>)
        self.owner = None  # user mode: the FUNCTION_BLOCK or PROGRAM of a METHOD or ACTION
        self.methods = {}  # user mode: upper name -> the METHODs and ACTIONs of a FUNCTION_BLOCK or PROGRAM
        self.statics = []  # user mode: VAR_STAT, shared by every instance
        self.instance_vars = {}  # user mode: a METHOD's VAR_INST kept in its FB under another name (NAME -> Var)
        self.properties = {}  # user mode: upper name -> {"name", "type", "get": Pou, "set": Pou} of a FUNCTION_BLOCK
        self.accessor = None  # user mode: "get" or "set" for a PROPERTY's accessor
        self.interfaces = []  # user mode: the INTERFACEs a FUNCTION_BLOCK IMPLEMENTS (its base's too)
        self.file = file
        self.node = node
        self.vars = []
        self.ret = None
        self.fbtype = None
        self.body_c = []

    def var(self, name):
        return T.find_var(self.vars, name)


class Program:
    """Everything declared, in declaration order: what the emitter writes."""

    def __init__(self):
        self.items = []  # (kind, object, file): kind in type, pou


# A refusal in the body of an FB with METHODs, a base or interfaces that may owe to what they add (a METHOD or
# PROPERTY called, a variable inherited, THIS^ or SUPER^), when its declarations were refused and they are not
# declared: left out beside those refusals (Compiler._body_beside_refusals).
_MAY_OWE_MEMBERS = re.compile(r"undeclared|declaration was refused|cannot be used|before its declaration|METHOD|"
                              r"PROPERTY|ACTION|INTERFACE|IMPLEMENT|SUPER|THIS|has no (variable|member|value)", re.I)


class Compiler:
    """`user`: the user-program mode (docs/translator.md, "User programs"): PROGRAMs, global variable
    lists, located variables, VAR_EXTERNAL, sized STRINGs, inline arrays and the string functions are
    accepted on top of the library's subset. `native`: files whose FUNCTIONs the host implements."""

    def __init__(self, user=False, native=(), namespaces=None):
        self.user = user
        self.native_files = set(native)
        # user mode: upper namespace -> (its spelling, the folder whose declarations it holds), `--namespace`
        self.namespaces = {k.upper(): v for k, v in (namespaces or {}).items()}
        self.globals = {}  # upper name -> [GlobalVar] (one per list that declares the name)
        self.gvls = {}  # upper list name -> GlobalList
        self.gvl_declaring = None  # the GlobalList whose variables are being declared (user mode)
        self.later_fbs = set()  # upper names of the FUNCTION_BLOCKs of the files compiled (user mode)
        self.later_interfaces = set()  # upper names of the INTERFACEs of the files compiled (user mode)
        self.interface_members = False  # an INTERFACE's METHODs and PROPERTYs are being declared
        self.ahead = {}  # upper name of an INTERFACE named before its declaration -> the first (file, token)
        self.pending_globals = {}  # upper FB name -> [(GlobalList, item, CONSTANT, file)] waiting for that FB
        self.inline_arrays = {}  # (low, high, element cname and name) -> ArrayType of an inline ARRAY declaration
        self.long_strings = {}  # (n, wide) -> LongStringType of a STRING(n) or WSTRING(n) over 255 (user mode)
        self.pointer_types = {}  # (target cname, reference) -> PointerType (user mode)
        self.sizeof_checks = {}  # user mode: file -> {(type, C type, bytes)} of SIZEOF in a constant expression
        self.taken_from_library = {}  # user mode: (NAMESPACE, NAME) -> (file, line) of the program's declaration
        # user mode: {path: (namespace, names, (file, line) of the program's)} of library files the program shadows
        self.left_out = {}
        self.types = {}  # upper name -> Type
        self.pous = {}  # upper name -> Pou
        self.enum_values = {}  # upper value -> EnumType
        self.enum_shared = {}  # user mode: upper value -> the EnumTypes that share it (written E.A only)
        self.declared_at = {}  # upper name -> (file, line) for every global name, including later ones
        self.function_names = set()  # user mode: the upper names of the program's FUNCTIONs, later ones too
        self.program = Program()
        self.errors = []
        self.refused = set()  # upper names whose declaration was refused: later uses say so, not more
        self.file = None
        self.call_members = set()  # (file, line, column) of each member of a call's result (rewrite.CALL_MEMBER)
        # user mode: (file, line) of each FUNCTION's ARRAY result (rewrite.ARRAY_RESULT) -> (column of its ARRAY in
        # the parsed text, how far the rewrite moved it there)
        self.array_results = {}
        self.dialect_uses = []  # StErrors: the TwinCAT / CODESYS constructs used, which MATIEC cannot compile
        self.warnings = []  # StWarnings: what the vendors take with a warning and pacst takes too (user mode)
        self.strict_narrowing = False  # user mode: an implicit narrowing refused instead (--strict-narrowing)
        self.constant_inits = {}  # user mode: id(initial value node) -> its value, from named constants
        self.named_inits = {}  # user mode: id(initial value node) -> the initial value of the constant it names
        self.declaring = None  # user mode: the POU whose variable's initial value is being checked
        self.declaring_section = None  # user mode: that variable's section (runinit)
        self.computed_inits = {}  # user mode: id(node) -> TE of an initial value computed at run time (runinit)
        self.constant_blocks = None  # user mode: the declarations of the METHOD or POU being declared
        self.fb_call_sites = {}  # FB type cname -> the ST calls of its body in the program (an inline body: one)
        self.sources = []  # the SourceFiles declared, in order
        self.members = {}  # id of a FUNCTION_BLOCK or PROGRAM item -> its METHOD and ACTION items (user mode)

    def dialect(self, node, what):
        """Records a use of the TwinCAT / CODESYS dialect of user mode (docs/user_dialect.md): `pacst matiec`
        refuses each with its place, since MATIEC compiles only the portable subset's user programs."""
        self.dialect_at(self.file, *self.place(node), what)

    def dialect_at(self, file, line, col, what):
        self.dialect_uses.append(StError(file, line, col, f"{what}: TwinCAT / CODESYS dialect that MATIEC does "
                                                          "not compile (docs/user_dialect.md); run this program on "
                                                          "pacst's C"))

    def warn(self, node, message):
        """Records a warning at `node` in the file being compiled: shown with the build, the program still built."""
        self.warnings.append(StWarning(self.file, *self.place(node), message))

    # ------------------------------------------------------------------ errors
    def err(self, node, message):
        if self.user:  # the library's subset is not what a user program is held to: docs/user_dialect.md is
            message = message.replace("outside the portable subset", "outside pacst's user programs "
                                      "(docs/user_dialect.md)")
        return StError(self.file, *self.place(node), message)

    def place(self, node):
        """(line, column) of `node` in the user's own text of the file being compiled, for a refusal, a dialect use
        or a warning alike (1, 1 without a node)."""
        line, col = pos(node) if node is not None else (1, 1)
        return line, self.source_column(self.file, line, col)

    def source_column(self, file, line, col):
        """The column in the user's own line of `col` in the parsed text: on the heading of a FUNCTION's ARRAY
        result, where rewrite.py wrote the result's block, the array's declaration moved right."""
        found = self.array_results.get((file, line))
        return col - found[1] if found is not None and col >= found[0] else col

    # ------------------------------------------------------------------ driver
    def compile(self, sources):
        """Check and translate parsed files (in declaration order); raise StErrors on any refusal."""
        self.declare(sources)
        return self.finish()

    def declare(self, sources):
        """Check and translate parsed files (in declaration order) after those of any earlier call, collecting the
        refusals: user mode declares the libraries so, closed under their uses, before the program
        (cli.checked_library), whose files may use theirs but not the reverse."""
        self.sources = self.sources + list(sources)
        for src in sources:
            self.file = src.path
            for line, col, what, parsed_col in getattr(src, "rewrites", ()):  # rewrite.user_text's
                self.dialect_at(src.path, line, col, what)
                if what == rewrite.CALL_MEMBER:
                    self.call_members.add((src.path, line, parsed_col))
                elif what == rewrite.ARRAY_RESULT:
                    self.array_results[(src.path, line)] = (parsed_col, parsed_col - col)
            for item in src.tree.items:
                name = self._item_name(item) if _cls(item) not in ("Method", "Action", "Property") else None
                if name is not None and name.upper() not in self.declared_at:
                    self.declared_at[name.upper()] = (src.path, pos(item)[0])
                if name is not None and _cls(item) == "Function":
                    self.function_names.add(name.upper())
        attached = set()
        for src in sources if self.user else []:
            owner = None
            for item in src.tree.items:
                if _cls(item) in ("FunctionBlock", "Program", "Interface"):
                    owner = item
                elif _cls(item) in ("Method", "Action", "Property") and owner is not None:
                    self.members.setdefault(id(owner), []).append(item)
                    attached.add(id(item))
        if self.user:
            self.later_fbs |= {self._item_name(item).upper() for src in sources for item in src.tree.items
                               if _cls(item) == "FunctionBlock"}
            self.later_interfaces |= {self._item_name(item).upper() for src in sources for item in src.tree.items
                                      if _cls(item) == "Interface"}
        for src, item in self._in_order(sources):
            if id(item) in attached:
                continue  # declared with its FUNCTION_BLOCK or PROGRAM
            self.file = src.path
            try:
                self._item(item, src)
            except (StError, StErrors) as e:
                self.errors += e.errors if isinstance(e, StErrors) else [e]
                name = self._item_name(item)
                if name is not None:
                    self.refused.add(name.upper())

    def finish(self):
        """The Program of every file declared; StErrors with every refusal, in the order met."""
        for fb in list(self.pending_globals):  # their FB was refused: each says so
            self._pending_globals(fb)
        for up, (file, token) in self.ahead.items():  # named ahead in another INTERFACE, then refused
            if getattr(self.types.get(up), "ahead", False) or up not in self.types:
                file, self.file = self.file, file
                self.errors.append(self.err(token, f"INTERFACE {_name(token)} cannot be used: its declaration was "
                                                   "refused"))
                self.file = file
        if self.errors:
            raise StErrors(self.errors)
        return self.program

    def _pending_globals(self, fb):
        """User mode: declare the global variables that waited for the FUNCTION_BLOCK `fb` (instances of it in a
        global list, which TwinCAT declares in any order: Tc3_Event's GVL holds an FB_Message)."""
        file = self.file
        for gvl, item, constant, path in self.pending_globals.pop(fb, []):
            self.file = path
            try:
                user.global_items(self, gvl, [item], constant)
            except StError as e:
                self.errors.append(e)
                gvl.refused = True
        self.file = file

    def _in_order(self, sources):
        """(file, item) in the order they are declared: the files' order; in user mode every type and global
        list first (in the files' order, which declares a list before a type whose array bounds name its
        constants, as TcUnit's ST_TestSuiteResult names GVL_Param_TcUnit's), then the POUs, so that a POU may
        use a global of any list (TwinCAT and CODESYS have no declaration order)."""
        items = [(src, item) for src in sources for item in src.tree.items]
        if not self.user:
            return items
        rank = {"DataTypeDeclaration": 0, "GlobalVariableDeclarations": 0}
        return sorted(items, key=lambda pair: rank.get(_cls(pair[1]), 2))  # stable: file order within a rank

    @staticmethod
    def _item_name(item):
        if _cls(item) == "DataTypeDeclaration":
            return _name(getattr(item.declaration, "name", "")) or None
        name = getattr(item, "name", None)
        return _name(name) if name is not None else None

    def _item(self, item, src):
        cls = _cls(item)
        if cls == "DataTypeDeclaration":
            if item.access is not None:
                raise self.err(item, "access specifiers on types are outside the portable subset")
            self._type_decl(item.declaration)
        elif cls == "FunctionBlock":
            self._pou(item, "fb", src)
        elif cls == "Function":
            self._pou(item, "function", src)
        elif cls == "Program":
            if not self.user:
                raise self.err(item, "PROGRAM is outside the library's subset: write a FUNCTION_BLOCK "
                                     "(user programs: pacst --user)")
            self._pou(item, "program", src)
        elif cls == "GlobalVariableDeclarations":
            if self.user:
                return user.global_list(self, item, src)
            raise self.err(item, "VAR_GLOBAL is outside the subset: MATIEC allows globals only inside a "
                                 "CONFIGURATION (see docs/translator.md for library constants)")
        elif cls == "Interface" and self.user:
            self._interface(item)
        elif cls in ("Method", "Action") and self.user:
            raise self.err(item, f"{cls.upper()} {_name(item.name)} follows no FUNCTION_BLOCK or PROGRAM in its file")
        elif self.user:
            raise self.err(item, f"{cls.upper()} is not translated in user programs yet (docs/user_dialect.md)")
        else:
            raise self.err(item, f"{cls} is outside the portable subset (no METHOD, PROPERTY, ACTION, INTERFACE)")

    # ------------------------------------------------------------------ names
    def _check_ident(self, token, what, c_name=True):
        name = _name(token)
        why = reserved_reason(name, self.user, c_name)
        if why:
            raise self.err(token, f"{what} {why}")
        if not c_name and reserved_reason(name, self.user):  # MATIEC's C names it alone
            self.dialect(token, f"the {what} '{name}', a C keyword or macro")
        if self.user and ("__" in name or name.endswith("_")):
            self.dialect(token, f"the name '{name}' (MATIEC refuses '__' in names and a '_' at their end)")

    def _declare_global(self, token, what):
        name = _name(token)
        self._check_ident(token, what)
        up = name.upper()
        if up in self.types or up in self.pous:
            first = self.declared_at.get(up, (self.file, 1))
            owners = [self.library_of(first[0]), self.library_of(self.file)]
            if owners[0] and owners[1] and owners[0] != owners[1]:
                raise self.err(token, f"{what} '{name}' is declared by the library {owners[1]} and by the library "
                                      f"{owners[0]} ({first[0]}:{first[1]}): a program and its libraries share one "
                                      "set of names here; give pac-test one of the two libraries only")
            if owners[0] or owners[1]:  # a CODESYS export "into an application" carries the library's objects
                why = (f"{what} '{name}' is declared by the library {owners[0] or owners[1]} too: leave the "
                       "library's objects out of your sources (pac-test adds the library; export your application "
                       "without it), or rename yours: a program and its libraries share one set of names here")
                if first[0] != self.file and not owners[0]:
                    self.taken_from_library[(owners[1].upper(), up)] = first  # Lib.Name: refused, and says why
                    raise StError(first[0], first[1], 1, why)  # at the user's copy, not at the library's file
                raise self.err(token, why)
            raise self.err(token, f"{what} '{name}' is declared twice (names are case-insensitive)")
        if up in self.enum_values:
            raise self.err(token, f"{what} '{name}' has the name of an enumeration value")
        if up in self.namespaces:  # Name.x would name the library's x
            raise self.err(token, f"{what} '{name}' has the name of the library namespace {self.namespaces[up][0]}: "
                                  "rename it (Name.x would name the library's x)")

    def _resolve_type(self, token, allow_fb=True):
        name = _name(token)
        if self.user and system.is_system(name) and "." in name:  # __SYSTEM.TYPE_CLASS, __SYSTEM.AnyType
            return system.system_type(self, system.canonical(name.split("."))[1], token)
        if self.user and name.upper() == "ANY":  # a VAR_INPUT of any type: a __SYSTEM.AnyType
            return system.any_type(self, token)
        if self.user and "." in name:
            name = self.strip_namespace(name, token)
            self.dialect(token, f"the namespace in '{_name(token)}'")
        up = name.upper()
        if up in T.ELEMENTARY:
            return T.ELEMENTARY[up]
        if self.user and up in T.USER_ELEMENTARY:
            self.dialect(token, f"the 64-bit type {up}")
            return T.USER_ELEMENTARY[up]
        if self.user and up in T.PSEUDO_TYPES and (up.startswith("__") or up not in self.types):
            return self._pseudo_type(token, up)
        if self.user and up == "LTIME":
            self.dialect(token, "LTIME")
            return T.LTIME
        if self.user and up in T.USER_DATES:
            self.dialect(token, up)
            return T.USER_DATES[up]
        if self.user and up == "WSTRING":
            self.dialect(token, "WSTRING")
            return T.WSTRING
        if self.user and up == "BIT":  # TwinCAT packs a BIT member into its struct's bits: a BOOL here
            self.dialect(token, "BIT")
            return T.ELEMENTARY["BOOL"]
        if up in T.OUTSIDE_SUBSET:
            raise self.err(token, T.OUTSIDE_SUBSET[up])
        if self.user and up in T.USER_FBS:
            if not allow_fb:
                raise self.err(token, f"a function block ({up}) cannot be used here")
            self.dialect(token, f"{up} with the pin names of CODESYS and TwinCAT (MATIEC names them otherwise)")
            return T.USER_FBS[up]
        if up in T.NONPORTABLE_FBS:
            raise self.err(token, f"standard FB {up} has different pin names in MATIEC and CODESYS/TwinCAT: "
                                  "write that logic by hand")
        if up in T.STANDARD_FBS:
            if not allow_fb:
                raise self.err(token, f"a function block ({up}) cannot be used here")
            return T.STANDARD_FBS[up]
        if up in self.types and not (getattr(self.types[up], "ahead", False) and not self.interface_members):
            if self.types[up].kind == "interface":
                self.dialect(token, f"a variable of the INTERFACE {name}")
            return self.types[up]
        if up in self.pous:
            pou = self.pous[up]
            if pou.program:
                raise self.err(token, f"'{name}' is a PROGRAM: a task runs it, no POU declares an instance")
            if pou.kind == "fb":
                if not allow_fb:
                    raise self.err(token, f"a function block ({name}) cannot be used here")
                return pou.fbtype
            raise self.err(token, f"'{name}' is a FUNCTION, not a type")
        if up in self.refused:
            raise self.err(token, f"type '{name}' cannot be used: its declaration was refused (above)")
        if self.user and self.interface_members and up in self.later_interfaces:
            return self._interface_ahead(token, name)
        if up in self.declared_at:
            file, line = self.declared_at[up]
            raise self.err(token, f"type '{name}' is used before its declaration ({file}:{line}): "
                                  "declare before use (MATIEC)")
        raise self.err(token, f"undeclared type '{name}'")

    # ------------------------------------------------------------------ namespaces (user mode)
    def namespace(self, name):
        """'library' for a `--namespace` (PA_CONTROL), 'standard' for the standard library's (Tc2_Standard,
        Standard), None for any other name."""
        up = name.upper()
        if up in self.namespaces:
            return "library"
        if up in user.STANDARD_NAMESPACES:
            return "standard"
        return None

    def namespace_names(self):
        """The namespaces a program may write, as spelt where they were given: PA_CONTROL, the libraries', the
        standard library's."""
        return [spelling for spelling, _ in self.namespaces.values()] + ["Tc2_Standard", "Standard"]

    def in_namespace(self, namespace, name):
        """Whether `name` (a type, POU, global list or enumeration value) is declared in the namespace."""
        up = name.upper()
        kind = self.namespace(namespace)
        if kind == "standard":
            return up in T.STANDARD_FBS or up in T.NONPORTABLE_FBS or up in STANDARD_FUNCTIONS \
                or re.fullmatch(r"[A-Z]+_TO_[A-Z]+", up) is not None
        if kind == "library" and namespace.upper() == "TC2_SYSTEM" and up in _TC2_SYSTEM_MEMORY:
            return True  # Tc2_System.MEMCPY: the translator's own MEMCPY
        if up in self.enum_values and up not in self.declared_at:  # PA_CONTROL.PAC_AX_HOME: its type's
            up = self.enum_values[up].cname
        file = self.gvls[up].file if up in self.gvls else self.declared_at.get(up, (None,))[0]
        if file is None and up in self.globals:  # Tc2_System.ADSLOG_MSGTYPE_ERROR: a library's global variable
            return any(self._under(g.gvl.file, self.namespaces[namespace.upper()][1]) for g in self.globals[up])
        return self._under(file, self.namespaces[namespace.upper()][1])

    def library_of(self, path):
        """The namespace (as spelt where given) of the library whose folder holds the file `path`, or None."""
        return next((spelling for spelling, folder in self.namespaces.values() if self._under(path, folder)), None)

    @staticmethod
    def _under(path, folder):
        return bool(path) and os.path.abspath(path).startswith(os.path.join(os.path.abspath(folder), ""))

    def strip_namespace(self, dotted, node):
        """`Namespace.Name` (a type) as the plain name; an error for a name the namespace lacks or a
        namespace pac-test does not have."""
        first, _, rest = dotted.partition(".")
        if self.namespace(first) is None:
            raise self.err(node, f"'{dotted}': {user.unknown_namespace(first, self.namespace_names())}")
        inner = rest.partition(".")[0]
        if "." in rest and self.namespace(inner) == "library" and not self.in_namespace(first, inner):
            self.dialect(node, f"the namespace {inner} under {first}")  # SysFile.SysTypes.RTS_IEC_RESULT
            return self.strip_namespace(rest, node)
        if "." in rest or not self.in_namespace(first, rest):
            self.taken_by_program(first, rest, node)
            raise self.err(node, f"'{dotted}': the library {first} has no type or POU '{rest}'"
                                 f"{self._close_name(first, rest) or self._part_of(first, rest)}")
        return rest

    def _close_name(self, namespace, name):
        """': did you mean Namespace.Name?' for the type or POU of the library `namespace` closest to the one it
        lacks, `name` (a misspelling), or ''."""
        if "." in name or self.namespace(namespace) != "library":
            return ""
        folder = self.namespaces[namespace.upper()][1]
        spelt = {}
        for up, (file, _) in self.declared_at.items():
            decl = self.pous.get(up) or self.types.get(up)
            if decl is not None and self._under(file, folder):
                spelt[up] = decl.name
        close = difflib.get_close_matches(name.upper(), list(spelt), 1, 0.8)
        return f": did you mean {namespace}.{spelt[close[0]]}?" if close else ""

    def taken_by_program(self, namespace, name, node):
        """User mode: for `Namespace.Name` whose library declaration was refused or left out because the program
        declares Name too (refused: reported there, once), the error that says so, instead of one saying the library
        lacks Name."""
        for spelt, names, (file, line) in self.left_out.values():
            if spelt.upper() == namespace.upper() and name.upper() in {n.upper() for n in names}:
                raise self.err(node, f"'{namespace}.{name}': the program declares {name} too ({file}:{line}), which "
                                     f"TwinCAT and CODESYS keep apart from the library's; pac-test's C holds one "
                                     f"declaration of each name and takes the program's: rename the program's to use "
                                     f"the library's")
        first = self.taken_from_library.get((namespace.upper(), name.upper()))
        if first is not None:
            raise self.err(node, f"'{namespace}.{name}' cannot be used: its declaration was refused (above), as the "
                                 f"program declares {name} too ({first[0]}:{first[1]}): rename the program's")

    @staticmethod
    def _part_of(namespace, name):
        """What to write instead of a name `name` a vendor library pac-test provides in part lacks."""
        if not user.namespace_like(namespace):
            return ""
        why = user.left_out(namespace, name)
        if why is not None:
            return f": {why}"
        return (f": pac-test provides part of the vendor library {namespace} (docs/user_dialect.md, \"Vendor "
                "libraries\"); keep the code that needs this name out of the program tested")

    def declared_name(self, token):
        """User mode: the name of the declaration `token` names in a heading (EXTENDS, IMPLEMENTS), without the
        library namespace before it (`FsCommon.I_Runnable` is I_Runnable); an error for a namespace not given or a
        name its library lacks."""
        name = _name(token)
        if not self.user or "." not in name or system.is_system(name):
            return name
        name = self.strip_namespace(name, token)
        self.dialect(token, f"the namespace in '{_name(token)}'")
        return name

    def unqualify(self, node, local=None):
        """User mode: the variable or call name `node` without a namespace before it (PA_CONTROL.GVL_PAC.X is
        GVL_PAC.X, Tc2_Standard.LEN is LEN); `local(name)` tells whether a name is a variable, which keeps it."""
        if not self.user or _cls(node) != "MultiElementVariable" or node.name.dereferenced:
            return node
        first = _name(node.name.name)
        head = node.elements[0]
        if _cls(head) == "FieldSelector" and _cls(head.field) == "SimpleVariable" \
                and system.is_system(f"{first}.{_name(head.field.name)}"):  # __SYSTEM.x, IBaseLibrary.TypeClass
            return node
        if local is not None and self.namespace(first) is None and not local(first) and self._nothing_named(first):
            self._unknown_head(node.name, first)  # Other.F_X(), Other.GVL.x: no variable, list, POU or namespace
        if self.namespace(first) is None or (local is not None and local(first)):
            return node
        if _cls(head) != "FieldSelector" or _cls(head.field) != "SimpleVariable":
            raise self.err(head, f"{first} is a library namespace: name one of its declarations ({first}.Name)")
        inner = _name(head.field.name)
        if len(node.elements) > 1 and self.namespace(inner) == "library" and not self.in_namespace(first, inner) \
                and not head.dereferenced:  # SysDir.CmpErrors.Errors.ERR_OK: a library another one references
            self.dialect(node, f"the namespace {inner} under {first}")
            return self.unqualify(dataclasses.replace(node, name=head.field, elements=node.elements[1:]), local)
        if not self.in_namespace(first, _name(head.field.name)):
            self.taken_by_program(first, _name(head.field.name), head.field)
            raise self.err(head.field, f"the library {first} has no declaration '{_name(head.field.name)}'"
                                       f"{self._part_of(first, _name(head.field.name))}")
        self.dialect(node, f"the namespace in '{first}.{_name(head.field.name)}'")
        if len(node.elements) == 1:
            if not head.dereferenced and not node.dereferenced:
                return head.field
            return node  # a pointer: refused where it is read
        return dataclasses.replace(node, name=head.field, elements=node.elements[1:])

    def _nothing_named(self, name):
        """Whether no global declaration (a global variable, list, POU, type, enumeration value, TwinCAT's __SYSTEM)
        has the name `name`, not even a refused one."""
        up = name.upper()
        return not (up in self.globals or up in self.gvls or up in self.pous or up in self.types or up in
                    self.enum_values or up in self.declared_at or up in self.refused or system.is_system(name)
                    or up in ("THIS", "SUPER"))

    def refused_global(self, node, name):
        """User mode: refuses `name` at `node` when a global list declares it as an instance of a FUNCTION_BLOCK
        whose declaration was refused (the CNC machine's `fbCNC : FB_CNC;` in its GVL): the instance waits for its
        FB, which never comes."""
        up = name.upper()
        for fb, waiting in self.pending_globals.items() if self.user else ():
            for gvl, item, _, _ in waiting if fb in self.refused else ():
                if any(_name(token).upper() == up for token in item.spec.variables):
                    raise self.err(node, f"'{name}' of the global list {gvl.name} cannot be used: its function "
                                         "block's declaration was refused (above)")

    def _unknown_head(self, token, name):
        """The refusal of `name.x` where `name` is declared nowhere: a vendor library's namespace, or an undeclared
        name that would be a library's namespace if the library were given."""
        if user.namespace_like(name):
            raise self.err(token, f"'{name}': {user.unknown_namespace(name, self.namespace_names())}")
        self.refused_global(token, name)
        raise self.err(token, f"undeclared name '{name}': no variable, global list, PROGRAM or library namespace "
                              f"({', '.join(self.namespace_names())}) has that name; a library of your own is given "
                              f"to pac-test with the namespace it is referenced under: --library {name}=PATH")

    # ------------------------------------------------------------------ types
    def pointer_type(self, node, target, indirection):
        """User mode: the type of POINTER TO target / REFERENCE TO target (one per target, declared once)."""
        reference = bool(indirection.reference)
        depth = indirection.pointer_depth
        if reference and depth > 1 or target.is_pointer or depth > 2:
            raise self.err(node, "a REFERENCE TO POINTER TO POINTER, and a POINTER TO POINTER TO POINTER, are not "
                                 "translated")
        self.dialect(node, "REFERENCE TO" if reference else "POINTER TO")
        if reference and depth == 1:  # REFERENCE TO POINTER TO T (the collections' FB_Free)
            return self.pointer_to(self.pointer_to(target), reference)
        if depth == 2:  # POINTER TO POINTER TO T: an array of pointers from __NEW(POINTER TO T, n)
            return self.pointer_to(self.pointer_to(target))
        return self.pointer_to(target, reference)

    def pointer_to(self, target, reference=False):
        key = (T.PointerType(target, reference).cname, reference)
        t = self.pointer_types.get(key)
        if t is None:
            t = self.pointer_types[key] = T.PointerType(target, reference)
            self.program.items.append(("type", t, self.file))
        return t

    def _literal_int(self, node):
        """An array bound: a decimal literal, possibly negative."""
        if _cls(node) == "UnaryOperation" and str(node.op) == "-":
            return -self._literal_int(node.expr)
        if _cls(node) in _INT_LITERALS and node.type_name is None:
            return literals.int_value(node)
        if self.user:
            value = self.constant_int(node)
            if value is not None:
                self.dialect(node, "an array bound that is a named constant")
                return value
        if self.user:
            raise self.err(node, "array bounds must be integer literals or integer constants declared before (a "
                                 "global list's, List.Name, or the POU's VAR CONSTANT) and SIZEOF of a type (not of "
                                 "a function block) with + - *: write the number")
        raise self.err(node, "array bounds must be integer literals (no constants, MATIEC)")

    def constant_int(self, node, earlier=False):
        """User mode: the value of an integer constant expression of literals and named constants (a POU's
        VAR CONSTANT, a global constant, List.Name) with + - *, or None when `node` is none. `earlier`: an
        initial value, which may name a variable declared before it in its POU too (TwinCAT and CODESYS
        initialise in the order of declaration: that variable holds its own initial value then)."""
        cls = _cls(node)
        if cls in _INT_LITERALS | _BIT_LITERALS:
            return literals.int_value(node)
        if cls == "ParenthesizedExpression":
            return self.constant_int(node.expr, earlier)
        if cls == "UnaryOperation" and str(node.op) in ("-", "+"):
            inner = self.constant_int(node.expr, earlier)
            return -inner if inner is not None and str(node.op) == "-" else inner
        if cls == "BinaryOperation" and str(node.op) in ("+", "-", "*"):
            a, b = self.constant_int(node.left, earlier), self.constant_int(node.right, earlier)
            if a is None or b is None:
                return None
            return a + b if str(node.op) == "+" else a - b if str(node.op) == "-" else a * b
        if cls == "FunctionCall" and self.user and _name(node.name.name).upper() == "SIZEOF":
            return self._constant_sizeof(node)
        init = self.named_constant(node, earlier)
        return self.constant_int(init, earlier) if init is not None else None

    def _constant_sizeof(self, node):
        """User mode: SIZEOF(T) of a type T in a constant expression, its bytes in pacst's C (csizes), or None for
        an argument that is no type or a type whose size is not computed (a function block's)."""
        params = node.parameters
        arg = params[0].value if len(params) == 1 and _cls(params[0]) == "InputParameterAssignment" else None
        if _cls(arg) != "SimpleVariable":
            return None
        name = _name(arg.name)
        pou = getattr(self, "current_pou", None)
        if pou is not None and pou.var(name) is not None or name.upper() in self.globals:
            return None  # a variable: its size is C's, in code
        try:
            t = self._resolve_type(arg.name, allow_fb=True)
        except StError:
            return None
        size = csizes.size_align(t)
        if size is None:
            return None
        self.dialect(node, "SIZEOF of a type in a constant expression")
        self.sizeof_checks.setdefault(self.file, set()).add((name, t.cname, size[0]))
        return size[0]

    def named_constant(self, node, earlier=False):
        """User mode: the initial value of the constant `node` names (a POU's or METHOD's VAR CONSTANT, also one of a
        later block, a global constant, List.Name, Lib.List.Name), or, for an initial value (`earlier`), of a
        variable of the POU declared before; None when `node` names none of them."""
        if self.user and _cls(node) == "MultiElementVariable":
            node = self.unqualify(node)
        cls = _cls(node)
        var = None
        if cls == "SimpleVariable":
            declaring = self.declaring if earlier else None
            var = declaring.var(_name(node.name)) if declaring is not None else None
            if var is not None and not var.type.is_fb and var.init is not None:
                return var.init
            pou = getattr(self, "current_pou", None)
            var = pou.var(_name(node.name)) if pou is not None else None
            if var is None and _name(node.name).upper() in self.globals:
                var = user.lookup_global(self, node.name)
        elif cls == "MultiElementVariable" and len(node.elements) == 1 and _cls(node.elements[0]) == "FieldSelector" \
                and _name(node.name.name).upper() in self.gvls and _cls(node.elements[0].field) == "SimpleVariable":
            var = self.gvls[_name(node.name.name).upper()].var(_name(node.elements[0].field.name))
        if var is None and cls == "SimpleVariable" and self.user:
            return self._later_constant(_name(node.name))
        if var is None or not var.constant or var.init is None:
            return None
        return var.init

    def _later_constant(self, name):
        """User mode: the initial value of a VAR CONSTANT `name` of the METHOD or POU whose declarations are being
        read, declared in a block after the one that uses it (TwinCAT resolves a POU's constants before its
        variables), or None."""
        up = name.upper()
        for block in getattr(self, "constant_blocks", None) or ():
            attrs = getattr(block, "attrs", None)
            if attrs is None or str(getattr(attrs, "name", attrs)).lower() != "constant":
                continue
            for item in getattr(block, "items", ()):
                value = getattr(getattr(item, "init", None), "value", None)
                if value is not None and any(_name(getattr(v, "name", v)).upper() == up
                                             for v in getattr(item, "variables", ())):
                    return value
        return None

    def _result_string(self, spec, wide, length):
        """User mode: STRING(n) or WSTRING(n) (`wide`) that blark reads as a call (a result's type, POINTER TO
        STRING(n)): STRING or WSTRING, its n checked; over 255 the long string type of its length."""
        n = user.string_capacity(self, spec, literals.int_value(length), "WSTRING" if wide else "STRING")
        if n > user.STRING_CAPACITY:
            return user.long_string(self, n, wide)
        return T.WSTRING if wide else T.STRING

    def _pseudo_type(self, token, up):
        """User mode: __XINT, __UXINT, __XWORD (XINT, UXINT, XWORD) and PVOID, the register-wide types TwinCAT and
        CODESYS make LINT, ULINT, LWORD on a 64-bit target."""
        self.dialect(token, f"the pseudo type {up}, {T.PSEUDO_TYPES[up]} on a 64-bit target")
        return T.USER_ELEMENTARY[T.PSEUDO_TYPES[up]]

    def _spec_type(self, spec, allow_fb=True):
        cls = _cls(spec)
        if cls in ("SimpleSpecification", "DataType"):
            tok = spec.type if cls == "SimpleSpecification" else spec.type_name
            if _cls(tok) == "StringTypeSpecification":  # STRING[10], WSTRING
                if str(tok.type_name).upper() == "STRING" and tok.length is None:
                    return T.STRING
                if self.user and user.string_type(self, tok) is not None:
                    # A struct member, array element or result: a STRING, its length checked, not kept; over 255
                    # the long string type of its length.
                    if tok.length is not None:
                        return user.sized_string(self, tok)[0]
                    return user.string_type(self, tok)
                raise self.err(tok, T.OUTSIDE_SUBSET.get(str(tok.type_name).upper(), T.OUTSIDE_SUBSET["STRING"]))
            if cls == "DataType" and spec.indirection is not None and self.user:  # ARRAY [0..3] OF POINTER TO T
                return self.pointer_type(spec, self._resolve_type(tok, True), spec.indirection)
            if cls == "DataType" and spec.indirection is not None:
                raise self.err(spec, "pointers and references are outside the portable subset")
            return self._resolve_type(tok, allow_fb)
        if cls == "ArraySpecification":
            raise self.err(spec, "inline ARRAY declaration: declare a named array type (TYPE ... END_TYPE)")
        if cls == "StringTypeSpecification" and self.user and user.string_type(self, spec) is not None:
            if spec.length is not None:  # an array's element: a STRING, its length checked, not kept (over 255
                return user.sized_string(self, spec)[0]  # the long string type of its length)
            return user.string_type(self, spec)
        if cls in ("StringTypeSpecification", "StringSpecLength"):
            raise self.err(spec, T.OUTSIDE_SUBSET["STRING"])
        if cls == "IndirectSimpleSpecification":
            if self.user and spec.indirection is not None and spec.init_parameters is None:
                return self.pointer_type(spec, self._spec_type(spec.type, True), spec.indirection)
            length = [getattr(p, "value", p) for p in spec.init_parameters or ()]
            if self.user and spec.indirection is not None and len(length) == 1 and _cls(length[0]) == "Integer" \
                    and _cls(spec.type) == "SimpleSpecification" and _cls(spec.type.type) == "StringTypeSpecification":
                # POINTER TO STRING(255), which blark reads as a call: a POINTER TO STRING, its length checked (over
                # 255 a POINTER TO the long string type of its length)
                wide = str(spec.type.type.type_name).upper() == "WSTRING"
                return self.pointer_type(spec, self._result_string(spec, wide, length[0]), spec.indirection)
            if self.user and spec.indirection is None and spec.init_parameters is not None:
                length = [getattr(p, "value", p) for p in spec.init_parameters]
                if _name(spec.type).upper() in ("STRING", "WSTRING") and len(length) == 1 \
                        and _cls(length[0]) == "Integer":
                    # a FUNCTION's or METHOD's result STRING(80), which blark reads as a call
                    self.dialect(spec, f"a result of type {_name(spec.type).upper()}(n)")
                    return self._result_string(spec, _name(spec.type).upper() == "WSTRING", length[0])
                # TwinCAT's FB_init arguments: `Edge : R_TRIG();` is the instance alone; `List : FB_List(10);`
                # gives them to the FB's METHOD FB_init (_fb_init)
                t = self._spec_type(spec.type, allow_fb)
                if any(p is not None for p in spec.init_parameters) and self._fb_init(t) is None:
                    raise self.err(spec, f"FB_init arguments of '{_name(spec.type)}(...)': {t.name} has no METHOD "
                                         "FB_init to take them; declare the instance without them")
                self.dialect(spec, "FB_init arguments" if self._fb_init(t) else "an FB instance declared with ()")
                return t
            if spec.indirection is not None or spec.init_parameters is not None:
                raise self.err(spec, "pointers and references are outside the portable subset")
            return self._spec_type(spec.type, allow_fb)
        if cls in ("EnumeratedSpecification",):
            raise self.err(spec, "inline enumeration: declare a named enumeration type")
        if cls == "SubrangeSpecification":
            raise self.err(spec, "subrange types are outside the portable subset")
        raise self.err(spec, f"{cls} is outside the portable subset")

    def _type_decl(self, decl):
        cls = _cls(decl)
        if cls == "ArrayTypeDeclaration":
            self._declare_global(decl.name, "type")
            init = decl.init
            if init.indirection is not None:
                raise self.err(decl, "pointers and references are outside the portable subset")
            if init.value is not None:
                raise self.err(init.value, "array initial values are outside the portable subset: "
                                           "initialise in code")
            spec = init.spec
            if len(spec.subranges) != 1:
                raise self.err(decl, "multi-dimensional arrays are outside the portable subset: "
                                     "use an array of a named array type")
            sub = spec.subranges[0]
            if _cls(sub) != "PartialSubrange":
                raise self.err(decl, "ARRAY[*] is outside the portable subset: give literal bounds")
            low, high = self._literal_int(sub.start), self._literal_int(sub.stop)
            if low > high:
                raise self.err(sub, f"array bounds {low}..{high}: the lower bound exceeds the upper")
            if _cls(spec.type) != "DataType":
                raise self.err(spec.type, "inline array of array: declare the inner array as a named type")
            elem = self._spec_type(spec.type, allow_fb=True)
            if elem.is_fb:
                raise self.err(spec.type, f"array of function block instances ({elem.name}) is outside the "
                                          "portable subset: declare the instances one by one")
            if elem.is_array:
                raise self.err(spec.type, f"array of the array type {elem.name}: iec2c accepts it but writes C "
                                          "that does not compile; use an array of a STRUCT that holds the row")
            t = T.ArrayType(_name(decl.name), low, high, elem)
        elif cls == "StructureTypeDeclaration":
            self._declare_global(decl.name, "type")
            if decl.indirection is not None or (decl.extends is not None and not self.user):
                raise self.err(decl, "EXTENDS and pointers are outside the portable subset")
            t = T.StructType(_name(decl.name))
            if decl.extends is not None:  # user mode: STRUCT EXTENDS, the base's members first, as TwinCAT lays it out
                token = decl.extends.interfaces[0]
                base = self._resolve_type(token, allow_fb=False)
                if not base.is_struct or len(decl.extends.interfaces) != 1:
                    raise self.err(token, f"{t.name} EXTENDS {_name(token)}: a STRUCT extends one STRUCT")
                self.dialect(token, "STRUCT EXTENDS")
                t.members = list(base.members)
            if self.user:  # a member may point at the struct itself (a list's node): POINTER TO ST_Node
                self.types[t.cname] = t
                try:
                    self._struct_members(t, decl)
                except (StError, StErrors):
                    del self.types[t.cname]
                    raise
            else:
                self._struct_members(t, decl)
        elif cls == "EnumeratedTypeDeclaration":
            self._declare_global(decl.name, "type")
            init = decl.init
            if init.value is not None and not self.user:
                raise self.err(init.value, "a default value for an enumeration type is outside the portable "
                                           "subset: the first value is the default")
            spec = init.spec
            if _cls(spec) != "EnumeratedSpecification" or (spec.type_name is not None and not self.user):
                raise self.err(decl, "enumerations are plain value lists without base type (portable subset)")
            base = None
            if spec.type_name is not None:  # user mode: TwinCAT's and CODESYS's `(A := 1, B) INT`
                self.dialect(spec.type_name, "an enumeration's base type")
                base = self._resolve_type(spec.type_name, allow_fb=False)
                if not (base.is_int or base.is_bit) or base.bits > 32:
                    raise self.err(spec.type_name, f"an enumeration's base type is an integer type of up to 32 bits, "
                                                   f"not {base.name}")
            values, numbers, number = [], [], 0
            for ev in spec.values:
                if self.user and ev.type_name is None and ev.value is not None:
                    number = self._enum_number(ev.value, base)
                    self.dialect(ev, "an enumeration value with a number")
                if (ev.value is not None and not self.user) or ev.type_name is not None:
                    given = f"{_name(ev.name)} := {ev.value}" if ev.value is not None else _name(ev.name)
                    raise self.err(ev, f"'{given}': an enumeration value with an explicit "
                                       "number is outside the portable subset (user programs too): leave the "
                                       "numbers out, the values count from 0 in their order")
                vname = _name(ev.name)
                if "." in vname:
                    raise self.err(ev, "qualified enumeration value")
                self._check_ident(ev.name, "enumeration value", c_name=not self.user)  # Auto, Static, EOF
                up = vname.upper()
                shared = self.user and (up in self.enum_values or up in self.enum_shared)
                if not shared and (up in self.enum_values or up in self.types or up in self.pous):
                    raise self.err(ev, f"enumeration value '{vname}' is not globally unique: give it a prefix")
                if number in numbers:
                    twin = values[numbers.index(number)]
                    raise self.err(ev.value if ev.value is not None else ev,
                                   f"two values of {_name(decl.name)} have the number {number} ({twin} and {vname}): "
                                   "give each value its own number")
                values.append(vname)
                numbers.append(number)
                number += 1
            t = T.EnumType(_name(decl.name), values, numbers, base)
            t.qualified_only = self.user and user.qualified_only(self, pos(decl)[0])
            t.strict = self.user and user.strict(self, pos(decl)[0])
            if init.value is not None:  # user mode: the type's default value instead of the first
                dv = init.value
                self.dialect(dv, "an enumeration's default value")
                label = _name(dv.name) if _cls(dv) == "EnumeratedValue" and dv.type_name is None else ""
                label = label.split(".", 1)[1] if label.upper().startswith(t.name.upper() + ".") else label
                if label.upper() not in (v.upper() for v in values):
                    raise self.err(dv, f"the default of {t.name} is one of its values")
                t.default = self.enum_value_of(t, label, dv)
            for v in values:
                up = v.upper()
                if up in self.enum_values and self.user or up in self.enum_shared:
                    # TwinCAT's qualified_only types share names (E_Mode.IDLE, E_Step.IDLE): written E.A only; the
                    # name alone is the value of the one type among them without qualified_only, if there is one
                    # (a program's Static beside Tc2_System's E_TcMemoryArea.Static)
                    every = self.enum_shared[up] = (self.enum_shared.get(up) or [self.enum_values[up]]) + [t]
                    plain = [e for e in every if not getattr(e, "qualified_only", False)]
                    if len(plain) == 1:
                        self.enum_values[up] = plain[0]
                    else:
                        self.enum_values.pop(up, None)
                else:
                    self.enum_values[up] = t
        elif cls == "SimpleTypeDeclaration" and self.user:
            self._declare_global(decl.name, "type")
            self.types[_name(decl.name).upper()] = user.alias(self, decl)
            return
        elif cls == "SimpleTypeDeclaration":
            raise self.err(decl, "type aliases are outside the portable subset")
        elif cls == "StringTypeDeclaration" and self.user and user.string_type(self, decl.string_type) is not None \
                and decl.value is None:
            # TYPE T_Text : STRING(80); END_TYPE (TwinCAT's T_MaxString): another name of STRING, its length checked
            self._declare_global(decl.name, "type")
            t = user.string_type(self, decl.string_type)
            if decl.string_type.length is not None:  # over 255 the long string type of its length (FsCommon's T_Path)
                t = user.sized_string(self, decl.string_type)[0]
            self.dialect(decl, "a STRING type")
            self.types[_name(decl.name).upper()] = t
            return
        elif cls == "StringTypeDeclaration":
            raise self.err(decl, T.OUTSIDE_SUBSET["STRING"])
        elif cls == "UnionTypeDeclaration" and self.user:
            t = user.union_type(self, decl)
        elif cls == "UnionTypeDeclaration":
            raise self.err(decl, "UNION is outside the portable subset")
        elif cls == "SubrangeTypeDeclaration" and self.user and decl.init.indirection is None \
                and decl.init.value is None:
            # TYPE T_Capacity : DINT(1..100); END_TYPE: another name of its base type; the range is not checked, as
            # TwinCAT checks it only with a CheckRange POU
            self._declare_global(decl.name, "type")
            self.dialect(decl, "a subrange type")
            self.types[_name(decl.name).upper()] = self._resolve_type(decl.init.spec.type_name, allow_fb=False)
            return
        elif cls == "SubrangeTypeDeclaration":
            raise self.err(decl, "subrange types are outside the portable subset")
        else:
            raise self.err(decl, f"{cls} is outside the portable subset")
        self.types[t.cname] = t
        self.program.items.append(("type", t, self.file))

    def _struct_members(self, t, decl):
        """The members of the STRUCT `t`, from its declaration."""
        seen = {m.cname for m in t.members}  # a STRUCT EXTENDS: its base's members
        refused = []
        for el in decl.declarations:
            if not self.user:
                self._struct_member(t, el, seen)
                continue
            try:  # user mode: every refused member is reported, not only the first
                self._struct_member(t, el, seen)
            except (StError, StErrors) as e:
                refused += e.errors if isinstance(e, StErrors) else [e]
        if refused:
            raise StErrors(refused)

    def _struct_member(self, t, el, seen):
        if _cls(el) != "StructureElementDeclaration":
            raise self.err(el, f"{_cls(el)} in a STRUCT is outside the portable subset")
        init = el.init
        if self.user and _cls(init) in ("ArrayTypeInitialization", "SubrangeTypeInitialization"):
            mtype = user.var_type(self, init, allow_fb=True)[0]  # an inline array, UINT(0..N) (user mode)
        elif _cls(init) != "TypeInitialization":
            raise self.err(el, "a STRUCT member needs a plain type (named arrays, structs, enums)")
        else:
            mtype = self._spec_type(init.spec, allow_fb=self.user)
        if mtype.is_fb or (mtype.is_array and mtype.elem.is_fb):  # user mode: refused here, saying why
            raise self.err(el, f"a member of {t.name} of the type {mtype.name}: pacst's STRUCT holds data, not a "
                               "function block instance: declare the instance beside the STRUCT")
        if mtype is t or (mtype.is_array and mtype.elem is t):
            raise self.err(el, f"a member of {t.name} of the type {t.name} itself: a STRUCT holds a POINTER TO "
                               "itself, never itself")
        for dv in el.variables:
            name = self._decl_var_name(dv, "member")
            if name.upper() in seen:
                raise self.err(dv, f"member '{name}' is declared twice")
            seen.add(name.upper())
            v = user.c_safe(self, T.Var(name, "member", mtype, init.value, dv))
            if init.value is not None:
                self._init_code(v, "x")  # checks the initial value now
            t.members.append(v)

    def _enum_number(self, node, base):
        """User mode: the number an enumeration value is given (a literal, negative too), checked against the
        base type (DINT's range without one)."""
        negative = _cls(node) == "UnaryOperation" and str(node.op) == "-"
        inner = node.expr if negative else node
        if _cls(inner) not in _INT_LITERALS | _BIT_LITERALS:
            raise self.err(node, "an enumeration value's number is an integer literal")
        number = -literals.int_value(inner) if negative else literals.int_value(inner)
        lo, hi = (base or T.DINT).int_range()
        if not lo <= number <= hi:
            raise self.err(node, f"{number} does not fit the enumeration's base type {(base or T.DINT).name}")
        return number

    def _decl_var_name(self, dv, what):
        if _cls(dv) != "DeclaredVariable":
            raise self.err(dv, f"{_cls(dv)} is outside the portable subset")
        if dv.location is not None:
            raise self.err(dv, "located variables (AT %...) are outside the library's subset")
        token = dv.variable.name
        self._check_ident(token, what, c_name=not self.user)  # user mode: a C name of its own (user.c_safe)
        return _name(token)

    # ------------------------------------------------------------------ POUs
    _SECTIONS = {
        "InputDeclarations": "input",
        "OutputDeclarations": "output",
        "InputOutputDeclarations": "inout",
        "VariableDeclarations": "var",
        "FunctionVariableDeclarations": "var",
        "TemporaryVariableDeclarations": "temp",
    }

    def _pou(self, node, kind, src):
        what = {"fb": "function block", "program": "program"}.get(kind, "function")
        program = kind == "program"
        kind = "fb" if program else kind
        if getattr(node, "access", None) is not None:
            if not self.user:
                raise self.err(node, "access specifiers are outside the portable subset")
            # FINAL, ABSTRACT, PUBLIC, INTERNAL: what the IDE checks; the translation is the same
            self.dialect(node, f"the access specifier {str(node.access).upper()}")
        if kind == "fb" and not program and (node.extends is not None or node.implements is not None) \
                and not self.user:
            raise self.err(node, "EXTENDS and IMPLEMENTS are outside the portable subset")
        self._declare_global(node.name, what)
        if self.user and _name(node.name).upper() in self.globals:
            raise self.err(node.name, f"{what} '{_name(node.name)}' has the name of a global variable")
        pou = Pou(kind, _name(node.name), self.file, node)
        pou.program = program
        self.current_pou = pou  # its constants may give array bounds (user mode)
        base = self._extends(pou, node) if kind == "fb" and getattr(node, "extends", None) is not None else None
        pou.native = kind == "function" and self.file in self.native_files
        if kind == "fb":
            pou.fbtype = T.FbType(pou.name)
            pou.fbtype.pou = pou
        elif node.return_type is None and not pou.native and not self.user:
            raise self.err(node, "a FUNCTION needs a return type (MATIEC)")  # TwinCAT and CODESYS take one without
        refused = []
        declarations = node.declarations
        if kind == "function" and node.return_type is None and self._array_result(declarations):
            # FUNCTION F : ARRAY[...] OF T, which rewrite.py made a block `VAR F : ARRAY[...] OF T; END_VAR`
            declarations = declarations[1:]
            pou.ret = self._refusals(refused, self._result_type, node.declarations[0].items[0].init)
        elif kind != "fb" and node.return_type is not None:
            read = self._spec_type if _cls(node.return_type) != "Token" else self._resolve_type
            # user mode: a refused result hides no refusal of the pins
            pou.ret = self._refusals(refused, read, node.return_type, False) if self.user else \
                read(node.return_type, False)
        constant_block = None
        self.constant_blocks = declarations
        for block in declarations:
            attrs = getattr(block, "attrs", None)
            is_constant = attrs is not None and str(attrs.name).lower() == "constant"
            if kind == "function" and constant_block is not None and not is_constant \
                    and self._SECTIONS.get(_cls(block)) == "var":
                if not self.user:
                    raise self.err(block, "VAR after VAR CONSTANT in a FUNCTION: MATIEC then takes the VAR variables "
                                          "for constants too; put VAR CONSTANT last")
                # user mode: pacst's C keeps each block's own; MATIEC's would not (so it is dialect)
                self.dialect(block, "VAR after VAR CONSTANT in a FUNCTION (MATIEC takes its variables for constants)")
            if is_constant:
                constant_block = block
            if not self.user:
                self._var_block(pou, block)
            else:
                try:  # user mode: every refused declaration is reported, not only the first
                    self._var_block(pou, block)
                except (StError, StErrors) as e:
                    refused += e.errors if isinstance(e, StErrors) else [e]
            if kind == "function" and pou.ret is not None and pou.ret.is_struct and \
                    self._SECTIONS.get(_cls(block)) in ("output", "inout") and self.user:
                self.dialect(block, "a FUNCTION returning a STRUCT with a VAR_OUTPUT or VAR_IN_OUT")  # pacst's C has it
            elif kind == "function" and pou.ret is not None and pou.ret.is_struct and \
                    self._SECTIONS.get(_cls(block)) in ("output", "inout"):
                raise self.err(block, f"a FUNCTION returning the STRUCT {pou.ret.name} has no VAR_OUTPUT or "
                                      "VAR_IN_OUT: iec2c accepts it but writes C that does not compile; "
                                      "return the struct alone or use a FUNCTION_BLOCK")
        self.constant_blocks = None
        if refused:
            raise StErrors(refused + self._body_beside_refusals(pou, node, base))
        if kind == "fb":
            pou.fbtype.vars = pou.vars
        # Register before the body so that an error message can name it, but refuse recursion below.
        self.pous[pou.cname] = pou
        after = []  # the types its instances in global lists declare (an array of them): after the FB in POUS.h
        if kind == "fb" and self.user:  # its instances in global lists, which its body may use (Compiler.compile)
            mark = len(self.program.items)
            self._pending_globals(pou.cname)
            after = self.program.items[mark:]
            del self.program.items[mark:]
        if pou.native:  # the host implements it: its ST body (if any) is for the other tools
            self.program.items += [("pou", pou, self.file)] + after
            return
        members, refused = [], []
        for m in self.members.get(id(node), []) if self.user else []:
            try:  # every refused METHOD, ACTION or PROPERTY declaration is reported, not only the first
                members.append(self._member(pou, m))
            except (StError, StErrors) as e:
                refused += e.errors if isinstance(e, StErrors) else [e]
        if refused:
            raise StErrors(refused)
        members = [m for m in members if m is not None]  # a PROPERTY's declaration is no code of its own
        if base is not None:
            members += self._inherit(pou, base)
        if kind == "fb" and getattr(node, "implements", None) is not None:
            self._implements(pou, node.implements)
        try:
            errors = []
            for p in [pou] + members:  # the body's refusals and its METHODs' in one run
                try:
                    p.body_c = BodyCompiler(self, p).compile()
                except (StError, StErrors) as e:
                    if not self.user:
                        raise
                    errors += e.errors if isinstance(e, StErrors) else [e]
            if errors:
                raise StErrors(errors)
        except (StError, StErrors):
            del self.pous[pou.cname]
            raise
        self.program.items.append(("pou", pou, self.file))
        self.program.items += after
        self.program.items += [("pou", m, self.file) for m in members]

    def _array_result(self, declarations):
        """Whether the first of a FUNCTION's `declarations` is the block rewrite.py made of its ARRAY result."""
        if not declarations or not getattr(declarations[0], "items", None):
            return False
        line, col = pos(declarations[0].items[0])
        found = self.array_results.get((self.file, line))
        return found is not None and pos(getattr(declarations[0].items[0], "init", None)) == (line, found[0])

    def _body_beside_refusals(self, pou, node, base):
        """User mode: the refusals of the body of a POU some of whose declarations were refused, and of its METHODs',
        ACTIONs' and PROPERTYs' declarations and bodies, but those that name a variable not declared (its refusal
        above says it): as many refusals in one run as can be told apart. Of a POU with METHODs, a base or
        interfaces, not those either that may owe to what they add, which is not all declared then
        (_MAY_OWE_MEMBERS)."""
        if not self.user or pou.native:
            return []
        members = base is not None or getattr(node, "implements", None) is not None or bool(self.members.get(id(node)))
        if pou.kind == "fb":
            pou.fbtype.vars = pou.vars
        declared = {v.name.upper() for v in pou.vars}
        lost = {_name(dv.variable.name).upper() for block in node.declarations for item in block.items
                for dv in getattr(item, "variables", []) if _cls(dv) == "DeclaredVariable"} - declared
        if pou.kind == "function" and getattr(node, "return_type", None) is not None and pou.ret is None:
            lost.add(pou.name.upper())  # its result's type was refused
        self.pous[pou.cname] = pou
        found, declared_members, member_refusals = [], [], []
        try:
            for m in self.members.get(id(node), []):  # their declarations' refusals owe nothing to the POU's
                try:
                    declared_members.append(self._member(pou, m))
                except (StError, StErrors) as e:
                    member_refusals += e.errors if isinstance(e, StErrors) else [e]
            for p in [pou] + [m for m in declared_members if m is not None]:
                try:
                    BodyCompiler(self, p).compile()
                except (StError, StErrors) as e:
                    found += e.errors if isinstance(e, StErrors) else [e]
        finally:
            del self.pous[pou.cname]
        return member_refusals + [err for err in found
                                  if not lost & {n.upper() for n in re.findall(r"'(\w+)'", err.message)}
                                  and not (members and _MAY_OWE_MEMBERS.search(err.message))]

    def _implements(self, pou, implements):
        """User mode: each INTERFACE an FB IMPLEMENTS is declared, and the FB has each of its METHODs."""
        for token in implements.interfaces:
            if _name(token).upper() == f"{system.NAMESPACE}.IQUERYINTERFACE":  # TwinCAT's root: no METHODs
                self.dialect(token, f"IMPLEMENTS {_name(token)}")
                continue
            t = self.types.get(self.declared_name(token).upper())
            if t is None or t.kind != "interface":
                raise self.err(token, f"IMPLEMENTS {_name(token)}: no INTERFACE of that name")
            self.dialect(token, f"IMPLEMENTS {t.name}")
            missing = [m for m in t.methods if m.upper() not in pou.methods]
            if missing:
                raise self.err(token, f"{pou.name} IMPLEMENTS {t.name} but has no METHOD {', '.join(missing)}: "
                                      f"declare it in {pou.name}")
            for up, proto in t.protos.items():
                if proto.accessor is not None:  # a PROPERTY's Get or Set
                    own = pou.properties.get(proto.name.upper())
                    if own is None or own[proto.accessor] is None:
                        raise self.err(token, f"{pou.name} IMPLEMENTS {t.name} but has no PROPERTY {proto.name} with "
                                              f"a {proto.accessor.capitalize()}: declare it in {pou.name}")
                    if own["type"] is not t.properties[proto.name.upper()]["type"]:
                        raise self.err(token, f"{pou.name}.{proto.name} is a {own['type'].name}, "
                                              f"{t.name}.{proto.name} a {t.properties[proto.name.upper()]['type'].name}")
                elif _signature(pou.methods[up]) != _signature(proto):
                    raise self.err(token, f"{pou.name}.{proto.name} differs from {t.name}.{proto.name} in its result "
                                          "or its inputs, outputs and in-outs")
            for i in t.bases + [t]:  # the bases' tables first: the interface's table points to them
                if i not in pou.interfaces:
                    pou.interfaces.append(i)

    def _interface(self, node):
        """User mode: an INTERFACE: its METHODs' and PROPERTYs' prototypes, which an FB that IMPLEMENTS it must have
        with the same pins and types, its bases' (EXTENDS) first. A variable of the interface type refers to such an
        FB's instance: in C a struct of the instance's address and a table of its METHODs and PROPERTY accessors
        (`<FB>__<ITF>__VT`), through which a call goes; the table ends with the addresses of the FB's tables for
        the bases, so that the variable can be given to one of a base's type."""
        ahead = self.types.get(_name(node.name).upper())
        if getattr(ahead, "ahead", False):  # named ahead by an INTERFACE declared before: that type, completed
            del self.types[ahead.cname]
        self._declare_global(node.name, "interface")
        self.dialect(node, f"INTERFACE {_name(node.name)}")
        if node.declarations:
            raise self.err(node, "an INTERFACE declares METHODs and PROPERTYs, no variables")
        t = ahead if getattr(ahead, "ahead", False) else T.InterfaceType(_name(node.name))
        for token in node.extends.interfaces if node.extends is not None else []:
            if _name(token).upper() == f"{system.NAMESPACE}.IQUERYINTERFACE":  # TwinCAT's root: no METHODs
                self.dialect(token, f"EXTENDS {_name(token)}")
                continue
            up = self.declared_name(token).upper()
            base = self.types.get(up)
            if base is None or base.kind != "interface":
                raise self.err(token, f"INTERFACE {t.name} EXTENDS {_name(token)}: no INTERFACE of that name"
                                      + (" (declared later or refused)" if up in self.declared_at else ""))
            self.dialect(token, f"EXTENDS {base.name}")
            for b in base.bases + [base]:
                if b not in t.bases:
                    t.bases.append(b)
            for up, proto in base.protos.items():
                if up not in t.protos:
                    t.methods += [proto.name] if proto.accessor is None else []
                    t.protos[up] = proto
            for up, prop in base.properties.items():
                t.properties.setdefault(up, prop)
        self.types[t.cname] = t  # a METHOD may take or return the INTERFACE itself (I_List.Clone : I_List)
        self.interface_members = True
        try:
            self._interface_members(t, node)
        except (StError, StErrors):
            del self.types[t.cname]
            raise
        finally:
            self.interface_members = False
        if getattr(t, "ahead", False):
            t.ahead = False
            t.forward = True  # POUS.h declares its name before the types that name it
        self.program.items.append(("type", t, self.file))

    def _interface_ahead(self, token, name):
        """User mode: the INTERFACE `name` of the files compiled, named in the METHODs or PROPERTYs of an
        INTERFACE declared before it (the collections' I_Enumerable and I_Enumerator name each other): its type,
        completed when its own declaration comes; refused after all, the use is refused too (finish)."""
        up = name.upper()
        t = self.types.get(up)
        if t is None:
            t = self.types[up] = T.InterfaceType(name)
            t.ahead = True
            self.ahead[up] = (self.file, token)
        self.dialect(token, f"the INTERFACE {name}, named before its declaration in another INTERFACE")
        return t

    @staticmethod
    def _refusals(refused, declare, *args):
        """declare(*args); its refusals (user mode: every refused declaration is reported, not only the first) are
        added to `refused`."""
        try:
            return declare(*args)
        except (StError, StErrors) as e:
            refused += e.errors if isinstance(e, StErrors) else [e]
            return None

    def _result_type(self, rt):
        """The type of a METHOD's result `rt` (user mode: also a function block, returned by value, as TcUnit's
        FB_TestSuite.GetTestByPosition returns an FB_Test, and an ARRAY, returned by value as a struct is)."""
        if self.user and _cls(rt) == "ArrayTypeInitialization":
            if rt.value is not None:
                raise self.err(rt.value, "a result has no initial value: it starts from its type's initial values; "
                                         "assign the values in the body")
            self.dialect(rt, "an ARRAY result")
            return user.var_type(self, rt, allow_fb=False)[0]
        return self._spec_type(rt.spec, allow_fb=self.user) if _cls(rt) == "TypeInitialization" else \
            self._resolve_type(rt, allow_fb=self.user)

    def _interface_members(self, t, node):
        """The METHODs' and PROPERTYs' prototypes of the INTERFACE `t`; every refusal of a result, a pin or a
        PROPERTY is reported."""
        refused = []
        for m in self.members.get(id(node), []):
            if _cls(m) == "Property":
                self._refusals(refused, self._interface_property, t, m)
                continue
            if _cls(m) != "Method":
                refused.append(self.err(m, f"{_cls(m).upper()} in an INTERFACE: an INTERFACE declares METHODs and "
                                           "PROPERTYs"))
                continue
            proto = Pou("function", _name(m.name), self.file, m)
            if m.return_type is not None:
                proto.ret = self._refusals(refused, self._result_type, m.return_type)
            for block in m.declarations:
                self._refusals(refused, self._var_block, proto, block)
            if proto.cname in t.protos:
                refused.append(self.err(m.name, f"INTERFACE {t.name} has two METHODs {proto.name} (with its "
                                                "bases')"))
            t.methods.append(proto.name)
            t.protos[proto.cname] = proto
        if refused:
            raise StErrors(refused)

    def _interface_property(self, t, node):
        """User mode: a PROPERTY of an INTERFACE: `X` its type, `X.Get` and `X.Set` its accessors (TwinCAT's
        <Property> in a .TcIO and its <Get> and <Set>): a prototype for each accessor, a slot `X__GET` / `X__SET`
        of the table."""
        name, _, part = _name(node.name).partition(".")
        pt = self._property_type(node, name)
        up = name.upper()
        known = t.properties.setdefault(up, {"name": name, "type": pt, "get": None, "set": None})
        if known["type"] is not pt:
            raise self.err(node.return_type, f"PROPERTY {name} is a {known['type'].name}, not a {pt.name}")
        kinds = {"": [], "GET": ["get"], "SET": ["set"]}.get(part.upper())  # `X` alone: its type
        if kinds is None:
            raise self.err(node.name, f"PROPERTY {_name(node.name)}: the parts of a PROPERTY are Get and Set")
        for kind in kinds:
            proto = self._accessor(node, name, kind, pt)
            proto.cname = f"{up}__{kind.upper()}"
            known[kind] = proto
            t.protos[proto.cname] = proto

    def _extends(self, pou, node):
        """User mode: FUNCTION_BLOCK ... EXTENDS Base: the base's variables first, then its own; the base's
        METHODs and ACTIONs translated again for this FB unless it overrides them; SUPER^() is the base's
        body and SUPER^.M() the base's M, both on this instance."""
        token = node.extends.interfaces[0]
        name = self.declared_name(token).upper()  # TcUnit.FB_TestSuite: FB_TestSuite
        base = self.pous.get(name)
        if base is None or base.kind != "fb" or base.program:
            if name in self.declared_at and name not in self.pous:
                raise self.err(token, f"{_name(token)} cannot be extended: its declaration was refused or comes later")
            raise self.err(token, f"{_name(token)} is no FUNCTION_BLOCK to extend")
        self.dialect(node.extends, f"EXTENDS {base.name}")
        pou.base = base
        pou.vars = list(base.vars)
        pou.interfaces = list(base.interfaces)  # its METHODs' table is built from this FB's own
        return base

    def _inherit(self, pou, base):
        """The METHODs, ACTIONs and PROPERTYs of the base, and of its bases, that this FB does not override (the
        nearest base's first), and the base's body as SUPER^(), compiled for this FB's instance (from the base's
        text: their errors name the base's lines)."""
        members = []
        saved = self.file
        try:
            level = base
            while level is not None:  # the base's base's too: the nearest one's wins (user mode)
                own = set(pou.methods)
                own_properties = set(pou.properties)  # before the loop: a base's Get and Set are both inherited
                self.file = level.file
                start = len(members)
                for node in self.members.get(id(level.node), []):
                    if _cls(node) == "Property" and _name(node.name).split(".")[0].upper() not in own_properties \
                            or _cls(node) != "Property" and _name(node.name).upper() not in own:
                        members.append(self._member(pou, node, inherited=True))
                for m in members[start:]:
                    if m is not None:
                        m.inherited_from = level
                level = level.base
            self.file = base.file
            for node in self.members.get(id(base.node), []):
                if _cls(node) != "Property":
                    members.append(self._member(pou, node, inherited=True, prefix="SUPER__"))
            members = [m for m in members if m is not None]
            body = Pou("function", "SUPER__BODY", base.file, base.node)
            body.owner = pou
            body.cfunc = f"{pou.cname}__SUPER__BODY"
            body.super_body = True
            pou.methods["SUPER__BODY"] = body
            members.append(body)
        finally:
            self.file = saved
        for m in members:
            if m.inherited_from is None:
                m.inherited_from = base
        return members

    def _accessor(self, node, name, kind, t):
        """The Get (returning the PROPERTY's value) or the Set (taking it as its input) of the PROPERTY `name`."""
        m = Pou("function", name, self.file, node)
        m.accessor = kind
        if kind == "get":
            m.ret = t
        else:
            m.vars.append(T.Var(name, "input", t, None, node.name))
        return m

    def _property_type(self, node, name):
        """The type of the PROPERTY `name` whose declaration or accessor is `node`."""
        rt = node.return_type
        if rt is None:
            raise self.err(node, f"PROPERTY {name} needs its type")
        return self._spec_type(rt.spec, allow_fb=False) if _cls(rt) == "TypeInitialization" else \
            self._resolve_type(rt, allow_fb=False)

    def _property(self, owner, node, inherited):
        """User mode: a PROPERTY: `X` declares it (TwinCAT's <Property>), `X.Get` and `X.Set` are its accessors
        (a body of `X` alone is its Get): C functions `<FB>__<X>__GET(FB *, EN, ENO)` returning the value and
        `<FB>__<X>__SET(FB *, EN, ENO, X)`; `inst.X` reads through the one and `inst.X := v` writes through the
        other."""
        name, _, part = _name(node.name).partition(".")
        self.dialect(node, f"PROPERTY {name}")
        t = self._property_type(node, name)
        rt = node.return_type
        up = name.upper()
        known = owner.properties.get(up)
        if known is None:
            if owner.var(name) is not None or up in owner.methods:
                raise self.err(node.name, f"PROPERTY {name}: {owner.name} already has a variable or member of that name")
            known = owner.properties[up] = {"name": name, "type": t, "get": None, "set": None}
        elif known["type"] is not t:
            raise self.err(rt, f"PROPERTY {name} is a {known['type'].name}, not a {t.name}")
        kind = {"": "get" if node.body is not None else None, "GET": "get", "SET": "set"}.get(part.upper(), "?")
        if kind == "?":
            raise self.err(node.name, f"PROPERTY {_name(node.name)}: the parts of a PROPERTY are Get and Set")
        if kind is None:
            return None
        if known[kind] is not None and not inherited:
            raise self.err(node.name, f"PROPERTY {name} has two {kind.capitalize()}s")
        m = self._accessor(node, name, kind, t)
        m.owner = owner
        m.cfunc = f"{owner.cname}__{up}__{kind.upper()}"
        for block in node.declarations:
            if _cls(block) == "MethodInstanceVariableDeclarations":  # a Get's or Set's VAR_INST, as a METHOD's
                self._instance_vars(owner, m, block, inherited)
                continue
            self._var_block(m, block)
        known[kind] = m
        return m

    def _member(self, owner, node, inherited=False, prefix=""):
        if _cls(node) == "Property":
            return self._property(owner, node, inherited)
        """User mode: a METHOD or ACTION of `owner` (a FUNCTION_BLOCK or PROGRAM), declared before the owner's
        body (which may call it): a C function `<OWNER>__<NAME>(OWNER *data__, ...)` whose body reads and
        writes the owner's variables (docs/user_dialect.md)."""
        is_action = _cls(node) == "Action"
        name = _name(node.name)
        what = "ACTION" if is_action else "METHOD"
        self.dialect(node, f"{what} {name}")
        if "." in name:
            raise self.err(node.name, f"{what} {name}: write it after its FUNCTION_BLOCK, named without it")
        why = reserved_reason(name, True)
        # a C keyword upper-cased (Delete, Register) is no C word: the METHOD's C function is <OWNER>__DELETE and its
        # result a local DELETE; the elementary types' names (BOOL, INT) stay refused, C's typedefs
        up = name.upper()
        keyword = why and "C keyword" in why and up not in T.ELEMENTARY and up not in T.USER_ELEMENTARY
        if keyword:
            self.dialect(node.name, f"the {what} name '{name}', a C keyword upper-cased")
        elif why and "standard" not in why and "elementary type" not in why:  # MOVE, Reset: the FB's own names
            raise self.err(node.name, f"{what} {why}")
        if not inherited and (owner.var(name) is not None or name.upper() in owner.methods):
            raise self.err(node.name, f"{what} {name}: {owner.name} already has a variable or member of that name")
        m = Pou("function", name, self.file, node)
        m.owner = owner
        m.cfunc = f"{owner.cname}__{prefix}{name.upper()}"
        m.action = is_action
        refused = []  # every refusal of its result and pins is reported
        if not is_action and node.return_type is not None:
            m.ret = self._refusals(refused, self._result_type, node.return_type)
        self.constant_blocks = [] if is_action else node.declarations  # its own constants, then its FB's
        for block in ([] if is_action else node.declarations):
            if _cls(block) == "MethodInstanceVariableDeclarations":
                self._refusals(refused, self._instance_vars, owner, m, block, inherited)
            elif _cls(block) == "TemporaryVariableDeclarations":  # a METHOD's VAR_TEMP: locals of the call
                self._refusals(refused, self._method_temps, m, block)
            else:
                self._refusals(refused, self._var_block, m, block)
        self.constant_blocks = None
        if refused:
            raise StErrors(refused)
        owner.methods[prefix + name.upper()] = m
        return m

    def _method_temps(self, m, block):
        """A METHOD's VAR_TEMP: locals of its call."""
        for item in block.items:
            vtype = self._spec_type(item.init.spec, allow_fb=False)
            for dv in item.variables:
                self._declare_var(m, "var", False, vtype, item.init.value, dv)

    def _instance_vars(self, owner, method, block, inherited):
        """User mode: a METHOD's VAR_INST, kept from call to call: variables of its FUNCTION_BLOCK (FB instances
        too), which the METHOD reads by their names; a name the FB has already is refused."""
        self.dialect(block, "VAR_INST")
        if owner.kind != "fb" or owner.program:
            raise self.err(block, "VAR_INST belongs to a METHOD or PROPERTY of a FUNCTION_BLOCK")
        for item in block.items:
            names = [_name(dv.variable.name) for dv in item.variables]
            kept = [owner.var(self._instance_name(method, n)) for n in names]
            if inherited and all(k is not None or owner.var(n) is not None for k, n in zip(kept, names)):
                # the base's METHOD translated again for a derived FB: the variables came with the base's
                method.instance_vars.update((n.upper(), k) for k, n in zip(kept, names) if k is not None)
                continue
            if not any(owner.var(n) is not None for n in names):
                self._user_vars(owner, "var", False, item)
                continue
            # A name the FB has too (TcUnit's test METHODs keep an instance of the FB they test so): the METHOD's
            # variable is the FB's under the METHOD's name, which the METHOD reads by its own.
            before = len(method.vars)
            self._user_vars(method, "var", False, item)
            for v in method.vars[before:]:
                name, cname = v.name, self._instance_name(method, v.name)
                if owner.var(cname) is not None:
                    raise self.err(item, f"VAR_INST '{name}' of METHOD {method.name}: {owner.name} has a variable "
                                         f"'{cname}' already, where pacst keeps it; rename one")
                v.name, v.cname = f"{method.name}.{name}", cname
                owner.vars.append(v)
                method.instance_vars[name.upper()] = v
            del method.vars[before:]

    @staticmethod
    def _instance_name(method, name):
        """The name of a METHOD's VAR_INST among its FB's variables when the FB has its name too."""
        return f"{method.name}_{name}".upper()

    def _var_block(self, pou, block):
        cls = _cls(block)
        section = self._SECTIONS.get(cls)
        if self.user and cls == "ExternalVariableDeclarations" and pou.kind == "fb":
            return user.external(self, pou, block)
        if self.user and not block.items:  # an empty `VAR END_VAR` (TwinCAT's PROGRAM template)
            return None
        if self.user and cls == "StaticDeclarations":
            return self._statics(pou, block)
        if section is None:
            keyword = {"StaticDeclarations": "VAR_STAT", "MethodInstanceVariableDeclarations": "VAR_INST",
                       "ExternalVariableDeclarations": "VAR_EXTERNAL", "AccessDeclarations": "VAR_ACCESS"}.get(
                           cls, cls.replace("Declarations", " declarations"))
            raise self.err(block, f"{keyword} is outside the portable subset (VAR, VAR_INPUT, VAR_OUTPUT, "
                                  "VAR_IN_OUT, VAR CONSTANT, VAR_TEMP)")
        constant = False
        attrs = getattr(block, "attrs", None)
        if attrs is not None:
            if str(attrs.name).lower() == "constant" and section == "var":
                constant = True
            elif self.user and str(attrs.name).lower() == "constant" and section == "inout":
                self.dialect(block, "VAR_IN_OUT CONSTANT")  # read only; a call may pass a value (expressions.py)
                constant = True
            elif self.user and str(attrs.name).lower() == "constant" and section == "input":
                self.dialect(block, "VAR_INPUT CONSTANT")  # an input the POU only reads (TwinCAT, CODESYS)
                constant = True
            else:
                raise self.err(block, f"{str(attrs.name).upper()} variables are outside the portable subset")
        if section == "temp" and pou.kind == "function":
            raise self.err(block, "a FUNCTION has no VAR_TEMP in the portable subset: use VAR")
        refused = []
        for item in block.items:
            if self.user and _cls(item) in ("VariableOneInitDeclaration", "ArrayVariableInitDeclaration",
                                            "StructuredVariableInitDeclaration"):
                try:  # every refused line is reported
                    self._user_vars(pou, section, constant, item)
                except StError as e:
                    refused.append(e)
                continue
            if _cls(item) != "VariableOneInitDeclaration":
                if _cls(item) == "ArrayVariableInitDeclaration":
                    spec = getattr(item.init, "spec", None)
                    if any(_cls(sub) == "FullSubrange" for sub in getattr(spec, "subranges", [])):
                        raise self.err(item.init, "ARRAY[*] is outside the portable subset: declare a named "
                                                  "array type with literal bounds")
                    raise self.err(item.init, "inline ARRAY declaration: declare a named array type")
                if _cls(item) == "StructuredVariableInitDeclaration":
                    raise self.err(getattr(item.init, "init", item),
                                   "(member := value) initialisers are outside the portable subset: "
                                   "give defaults in the TYPE or in code")
                if _cls(item) == "EdgeDeclaration":
                    raise self.err(item, "R_EDGE/F_EDGE declarations are outside the portable subset")
                raise self.err(item, f"{_cls(item)} is outside the portable subset")
            init = item.init
            if _cls(init) != "TypeInitialization":
                if _cls(init) == "StringTypeInitialization":
                    raise self.err(item, T.OUTSIDE_SUBSET["STRING"])
                raise self.err(item, f"{_cls(init)} is outside the portable subset")
            vtype = self._spec_type(init.spec, allow_fb=(pou.kind == "fb"))
            self._check_section(pou, section, constant, vtype, item)
            for dv in item.variables:
                self._declare_var(pou, section, constant, vtype, init.value, dv)
        if refused:
            raise StErrors(refused)

    def _statics(self, pou, block):
        """User mode: VAR_STAT, variables every instance of the FUNCTION_BLOCK shares: each a C variable
        `<FB>__STAT__<NAME>` beside the FB's code, given its initial value when an instance is initialised
        (before the first scan, so a second instance finds it as the first left it only then). A FUNCTION's
        keep their values from one call to the next, as TwinCAT keeps them."""
        holder = pou.owner or pou  # a FUNCTION's: kept from call to call (emit.py initialises them in the first)
        self.dialect(block, "VAR_STAT" if pou.kind == "fb" or pou.owner is not None else "VAR_STAT in a FUNCTION")
        for item in block.items:
            # an FB instance too (FsCommon's F_GetCpuCycleCounter keeps its GETCPUCOUNTER so): one for every call
            # and instance
            vtype, strlen = user.var_type(self, item.init, allow_fb=True)
            if vtype.is_fb and getattr(getattr(item.init, "spec", None), "init_parameters", None):
                raise self.err(item, "FB_init arguments of an FB instance in VAR_STAT: declare it alone")
            for dv in item.variables:
                self._check_ident(dv.variable.name, "variable")
                name = _name(dv.variable.name)
                if pou.var(name) is not None or T.find_var(holder.statics, name) is not None:
                    raise self.err(dv, f"variable '{name}' is declared twice (names are case-insensitive)")
                v = T.Var(name, "stat", vtype, user.initial_value(item.init), dv)
                v.strlen = strlen
                v.csym = f"{holder.cname}__STAT__{name.upper()}"
                if v.init is not None or vtype.is_fb:
                    self.declaring, self.declaring_section = pou, "stat"  # runinit: literals, constants and calls
                    try:
                        self._init_code(v, "x")  # checks the initial value (an FB's FB_init) now
                    finally:
                        self.declaring = self.declaring_section = None
                holder.statics.append(v)

    def _check_section(self, pou, section, constant, vtype, item):
        """Whether a variable of type `vtype` may stand in this block of `pou`."""
        if getattr(vtype, "any", False) and section != "input":
            raise self.err(item, "ANY is the type of a VAR_INPUT only (as in TwinCAT); declare a __SYSTEM.AnyType to "
                                 "keep what one was given")
        if vtype.is_fb and section == "inout" and self.user and pou.kind != "fb":
            # TwinCAT passes an FB instance to a FUNCTION's or METHOD's VAR_IN_OUT (TcUnit's F_GetCpuCounterAs64bit)
            self.dialect(item, "an FB instance in a VAR_IN_OUT of a FUNCTION or METHOD")
            return
        if vtype.is_fb and section == "input" and self.user and pou.kind != "fb":
            # TwinCAT copies the caller's instance into a FUNCTION's or METHOD's VAR_INPUT (Tc3_Event's I_Logger.M_Log)
            self.dialect(item, "an FB instance in a VAR_INPUT of a FUNCTION or METHOD")
            return
        if vtype.is_fb and section == "temp" and self.user and pou.kind == "fb":
            # TwinCAT initialises an FB's VAR_TEMP in every call, an FB instance too (TcUnit's FB_TestResults)
            self.dialect(item, "an FB instance in a VAR_TEMP")
            return
        if vtype.is_fb and section != "var":
            raise self.err(item, "function block instances are only allowed in VAR")
        if vtype.is_fb and constant:
            raise self.err(item, "a function block instance cannot be CONSTANT")
        if vtype.kind == "vla":
            varlen.check_section(self, pou, item)
        if pou.kind == "function" and vtype.is_array and section in ("input", "output"):
            if not self.user:
                raise self.err(item, "arrays are passed to a FUNCTION only whole and as VAR_IN_OUT (MATIEC)")
            # TwinCAT and CODESYS pass it by value: the C struct of the array copied in (out)
            self.dialect(item, f"an ARRAY in a FUNCTION's VAR_{section.upper()}")

    def _user_vars(self, pou, section, constant, item):
        """One declaration line of a POU in user mode: inline arrays, sized STRINGs and located variables too."""
        # a METHOD's or FUNCTION's VAR may hold FB instances (TwinCAT and CODESYS): fresh in every call, like its
        # other VAR
        # (and an FB instance in a FUNCTION's or METHOD's VAR_IN_OUT: the caller's, as TwinCAT passes it)
        # (and in a FUNCTION's or METHOD's VAR_INPUT: a copy of the caller's instance, as TwinCAT passes it)
        vtype, strlen = user.var_type(self, item.init, allow_fb=(pou.kind == "fb" or section == "inout" or (
            section in ("var", "input") and (pou.owner is not None or pou.kind == "function"))),
            in_out=section == "inout")
        value = user.initial_value(item.init)
        spec = getattr(item.init, "spec", None)
        fb_init_args = getattr(spec, "init_parameters", None) if _cls(spec) == "IndirectSimpleSpecification" else None
        if vtype.is_fb and pou.kind == "function":
            self.dialect(item, "an FB instance in a FUNCTION")
        self._check_section(pou, section, constant, vtype, item)
        for dv in item.variables:
            location = None
            if dv.location is not None:
                # TwinCAT links an FB instance's `AT %I*` / `%Q*` variables one by one: the host binds them. In a
                # VAR_INPUT or VAR_OUTPUT too (TcUnit's FB_ProtectedVariables), where a caller passes them as pins.
                linked = _cls(dv.location) == "IncompleteLocation" and pou.kind == "fb" and not pou.program
                if not (pou.program and section == "var" or linked and section in ("var", "input", "output")) \
                        or constant:
                    # At the name: blark reads `AT %I*` as an enumeration value, which has no position.
                    raise self.err(dv, "located variables (AT %...) are declared in a global list or "
                                       "in a PROGRAM's VAR (MATIEC), AT %I* and %Q* in an FB's VAR, VAR_INPUT or "
                                       "VAR_OUTPUT too")
                if linked and section != "var":
                    self.dialect(dv, f"AT {user.parse_location(self, dv.location, vtype).text} in a "
                                     f"{'VAR_INPUT' if section == 'input' else 'VAR_OUTPUT'}")
                location = user.parse_location(self, dv.location, vtype)
            v = self._declare_var(pou, section, constant, vtype, value, dv, may_be_located=True)
            v.location = location
            v.strlen = strlen
            user.check_string_init(self, v)
            v.fb_init_args = fb_init_args
            v.fb_init_owner = pou
            if vtype.is_fb and self._fb_init(vtype) is not None:
                self.declaring = pou  # checks the FB_init arguments now, as an initial value
                try:
                    self._fb_init_call(v, "x")
                finally:
                    self.declaring = None

    def _declare_var(self, pou, section, constant, vtype, value, dv, may_be_located=False):
        """Check and add one variable of a POU."""
        if may_be_located and _cls(dv) == "DeclaredVariable":
            token = dv.variable.name
            self._check_ident(token, "variable", c_name=not self.user)  # user mode: user.c_safe
            name = _name(token)
        else:
            name = self._decl_var_name(dv, "variable")
        up = name.upper()
        if pou.var(name) is not None or up in pou.externals:
            raise self.err(dv, f"variable '{name}' is declared twice (names are case-insensitive)")
        # user mode: a FUNCTION without a result type may name a variable like itself (TcUnit's TEST: Test), and a
        # variable may have another FUNCTION's name (TEST_ORDERED's Test), which it hides inside this POU
        own = self.user and up == pou.cname and pou.kind == "function" and pou.ret is None and pou.owner is None
        hides = self.user and up != pou.cname and up in self.function_names and up not in self.types
        # user mode: an instance named like its function block (TcUnit's `GetCurTaskIndex : GETCURTASKINDEX;`), as
        # TwinCAT takes it: the name is the instance in this POU, the type where a type is written; C names it apart
        fb_named = self.user and up != pou.cname and up in self.pous and self.pous[up].kind == "fb" \
            and not self.pous[up].program
        if (up in self.types or up in self.pous or up in self.declared_at) and not (own or hides or fb_named):
            raise self.err(dv, f"variable '{name}' has the name of a type or POU (MATIEC refuses it)")
        if up in self.enum_values and not self.user:  # user mode: the variable shadows it; E.A names the value
            raise self.err(dv, f"variable '{name}' has the name of an enumeration value")
        if up == pou.cname and not own:
            raise self.err(dv, f"variable '{name}' has the name of its POU")
        if own or hides and (up in self.pous or up in self.declared_at):
            self.dialect(dv, f"a variable named like the FUNCTION {name}")
        v = user.c_safe(self, T.Var(name, section, vtype, value, dv, constant))
        if fb_named:
            self.dialect(dv, f"a variable named like the function block {name}")
            v.cname = T.c_safe_name(up)
        if constant and value is None and section not in ("inout", "input"):
            if not (self.user and (vtype.is_array or vtype.is_struct)):
                raise self.err(dv, f"constant '{name}' needs a value")
            # CODESYS: a VAR CONSTANT array or struct without a value holds its type's initial values
            self.dialect(dv, "a constant array or struct without a value")
        if value is not None:
            if self.user and (vtype.is_array or vtype.is_struct or vtype.is_fb):
                self.dialect(value, "an initial value of an array, a struct or an FB instance's inputs")
            elif vtype.is_fb or vtype.is_array or vtype.is_struct:
                raise self.err(value, "initial values are only for elementary and enumeration "
                                      "variables: give defaults in the TYPE or in code")
            if section == "inout":
                raise self.err(value, "a VAR_IN_OUT has no initial value")
            if section == "temp":
                raise self.err(value, "a VAR_TEMP variable has no initial value in MATIEC: it starts "
                                           "from zero in every call; assign it in the body")
            self.declaring = pou  # an initial value may name a variable declared before (user mode)
            self.declaring_section = section
            try:
                self._init_code(v, "x")
            finally:
                self.declaring = self.declaring_section = None
        pou.vars.append(v)
        return v

    # ------------------------------------------------------------------ initial values
    def qualified_enum_value(self, node):
        """User mode: (the EnumType, the value's spelling) of `E_Type.VALUE` (TwinCAT's qualified_only
        enumerations), or None when `node` is no such name; an unknown value of the type is an error."""
        if not self.user or _cls(node) != "MultiElementVariable" or len(node.elements) != 1:
            return None
        t = self.types.get(_name(node.name.name).upper())
        field = node.elements[0]
        if t is None or not t.is_enum or _cls(field) != "FieldSelector" or _cls(field.field) != "SimpleVariable":
            return None
        return t, self.enum_value_of(t, _name(field.field.name), field.field)

    def shared_enum_value(self, name, node):
        """User mode: refuses a value two enumerations share written without its type."""
        types = self.enum_shared.get(name.upper()) if self.user and name.upper() not in self.enum_values else None
        if types:
            names = sorted(t.name for t in types)
            raise self.err(node, f"'{name}' is a value of {' and '.join(names)}: qualify it ({names[0]}.{name})")

    def bare_enum_value(self, t, name, node):
        """User mode: an enumeration value written alone, refused where its type has {attribute 'qualified_only'}
        (TwinCAT's default for a new enumeration), as the IDE refuses it."""
        if getattr(t, "qualified_only", False):
            raise self.err(node, f"'{name}' alone: the enumeration {t.name} has {{attribute 'qualified_only'}}, as in "
                                 f"TwinCAT write {t.name}.{name}")

    def enum_value_of(self, t, name, node):
        """The spelling of the value `name` of the enumeration `t`; an error at `node` when it has none."""
        value = next((v for v in t.values if v.upper() == name.upper()), None)
        if value is None:
            raise self.err(node, f"{t.name} has no value '{name}'")
        return value

    def initial_constant(self, node):
        """User mode: the value of an initial value that is an integer expression of named constants
        (`[FLAG_ERROR, FLAG_WARNING]`, `MAX_COUNT * 2`), or None. Kept by node: the initial values are
        translated again outside their POU, where its own constants are out of reach."""
        if not self.user or _cls(node) in _INT_LITERALS | _BIT_LITERALS:
            return None
        if _cls(node) == "UnaryOperation" and str(node.op) == "-" and _cls(node.expr) in _INT_LITERALS:
            return None  # a negative literal (`INT := -1`) is portable, typed below as before
        if id(node) not in self.constant_inits:
            value = self.constant_int(node, earlier=True)
            if value is None:
                return None
            self.dialect(node, "an initial value from named constants or variables declared before")
            self.constant_inits[id(node)] = value
        return self.constant_inits[id(node)]

    def literal_te(self, node, want):
        """Type an initial value, which must be a literal or an enumeration value."""
        node = self.unqualify(node)
        cls = _cls(node)
        if self.initial_constant(node) is not None:
            return TE(T.ANY_INT, value=self.constant_inits[id(node)])
        if cls == "UnaryOperation" and str(node.op) == "-":
            inner = _cls(node.expr)
            if inner not in _INT_LITERALS | {"Real"}:
                raise self.err(node, "initial value must be a literal")
        elif cls not in _INT_LITERALS | _BIT_LITERALS | {"Real", "Boolean", "Duration", "String"} and \
                not (cls in ("Lduration", "Date", "DateTime", "TimeOfDay") and self.user):
            if cls == "SimpleVariable" and _name(node.name).upper() in self.enum_values:
                self.bare_enum_value(self.enum_values[_name(node.name).upper()], _name(node.name), node)
            elif self.qualified_enum_value(node) is not None:
                pass
            elif cls == "SimpleVariable" and self.shared_enum_value(_name(node.name), node):
                pass
            elif self.user:
                return self._user_initial_value(node, want)
            else:
                raise self.err(node, "initial value must be a literal (MATIEC, CODESYS and TwinCAT differ on "
                                     "constant expressions)")
        return ExprCompiler(self, None).expr(node, want)

    def _user_initial_value(self, node, want):
        """User mode: an initial value TwinCAT and CODESYS compute when they compile, beyond integer constant
        expressions: `+127`, and a named constant of any type (`Limit : LREAL := GVL_Limits.LREAL_MAX;`,
        `Lib.GVL.Name`), typed as its own initial value is."""
        if _cls(node) == "UnaryOperation" and str(node.op) == "+":
            self.dialect(node, "a unary + in an initial value")
            return self.literal_te(node.expr, want)
        if _cls(node) == "ParenthesizedExpression":
            return self.literal_te(node.expr, want)
        init = self.named_inits.get(id(node)) or self.named_constant(node, earlier=True)
        if init is None:
            te = runinit.computed(self, node, want)
            if te is not None:
                return te
            raise self.err(node, "initial value: pacst computes literals, named constants, variables declared before "
                                 "and integer expressions of them with + - * (and, in a VAR of a POU, calls and "
                                 "variables declared before when the variable is initialised; in a global list, "
                                 "expressions of literals, constants and calls); assign this one in code")
        self.dialect(node, "an initial value that is a named constant or a variable declared before")
        self.named_inits[id(node)] = init  # translated again outside its POU (initial_constant says why)
        return self.literal_te(init, want)

    def default_c(self, t):
        if t.is_pointer:
            return "NULL"
        if t.kind == "interface":
            return f"(({t.cname}){{NULL, NULL}})"
        if t.kind == "vla":  # user mode: an FB's ARRAY [*] before its first call
            return varlen.default_c(t)
        if t.kind == "longstring":  # user mode: STRING(n) over 255, empty
            return f"(({t.cname}){{{{0}}}})"
        if t is T.WSTRING:
            return "__pacst_wstring(NULL, 0)"
        if t.is_string:
            return '__pacst_string("", 0)'
        if t.is_time:
            return "__time_make(0L, 0L)"
        if t.is_enum:
            return t.cvalue(t.default)
        if t.is_real:
            return f"(({t.cname})0.0)"
        if t.is_bool:
            return "FALSE"
        return f"(({t.cname})0)"

    @staticmethod
    def _fb_init(t):
        """User mode: the METHOD FB_init of the FUNCTION_BLOCK type `t` (its base's too), or None."""
        pou = getattr(t, "pou", None) if t.is_fb else None
        return pou.methods.get("FB_INIT") if pou is not None else None

    def _fb_init_call(self, var, target):
        """User mode: the call of the instance's METHOD FB_init, as TwinCAT and CODESYS make it when the
        instance is initialised: bInitRetains and bInCopyCode FALSE, then the declaration's arguments
        (`List : FB_List(10);`), constants and literals, in the order of the METHOD's other inputs."""
        method = self._fb_init(var.type)
        inputs = [v for v in method.vars if v.section == "input"]
        extra = inputs[2:] if len(inputs) >= 2 and all(v.type.is_bool for v in inputs[:2]) else None
        if extra is None or any(v.section in ("output", "inout") for v in method.vars):
            raise self.err(var.node, f"the METHOD FB_init of {var.type.name} is not TwinCAT's: it begins with the "
                                     "inputs bInitRetains and bInCopyCode (BOOL) and has no outputs")
        params = [p for p in getattr(var, "fb_init_args", None) or [] if p is not None]
        if len(params) > len(extra):
            raise self.err(var.node, f"{len(params)} FB_init arguments for the {len(extra)} inputs of "
                                     f"{var.type.name}.FB_init after bInitRetains and bInCopyCode")
        given = {}  # the inputs' upper names -> the values given: by position, or by name (`tTn := LTIME#1S`)
        for v, p in zip(extra, params):
            name = getattr(p, "name", None)
            if name is not None:
                v = T.find_var(extra, _name(name))
            if v is None or v.cname in given:
                raise self.err(p, f"FB_init argument '{_name(name) if v is None else v.name}' of {var.type.name}: "
                                  + ("given twice" if v is not None else "FB_init has no such input after "
                                     "bInitRetains and bInCopyCode"))
            given[v.cname] = getattr(p, "value", p)
        args = ["FALSE", "FALSE"]
        for v in extra:
            value = given.get(v.cname)
            if value is None:
                args.append(self.default_c(v.type) if v.init is None else
                            ExprCompiler(self, None).coerce(self.literal_te(v.init, v.type), v.type, v.init))
            else:
                try:  # a literal or a constant (`E_Mode.Hold`, `Lib.GVL_Limits.LREAL_MAX`), as an initial value
                    args.append(ExprCompiler(self, None).coerce(self.literal_te(value, v.type), v.type, value))
                except StError:
                    if _cls(value) not in ("SimpleVariable", "MultiElementVariable"):
                        raise
                    args.append(self._fb_init_variable(var, value, v))
        return f"{method.cfunc}(&{target}, TRUE, NULL, {', '.join(args)});"

    def _fb_init_variable(self, var, value, pin):
        """User mode: an FB_init argument that names a variable (`Logger : FB_Logger(Results);`): one of the
        FUNCTION_BLOCK's or PROGRAM's own declared before the instance (initialised before it, as TwinCAT
        initialises in the order of declaration), or a global list's; an FB instance goes to an INTERFACE input."""
        owner = getattr(var, "fb_init_owner", None)
        te = None
        if _cls(value) == "SimpleVariable":
            src = owner.var(_name(value.name)) if owner is not None and owner.kind == "fb" else None
            if src is not None and owner.vars.index(src) < owner.vars.index(var):
                te = TE(src.type, f"&(data__->{src.cname})" if src.type.is_fb else f"data__->{src.cname}.value")
            elif src is None:
                g = user.lookup_global(self, value.name)
                if g is not None:
                    te = TE(g.type, f"&({g.csym})" if g.type.is_fb else f"{g.csym}.value")
        if te is None:
            raise self.err(value, f"FB_init argument '{pin.name}' of {var.type.name}: pacst passes literals, constants, "
                                  "a variable of the FUNCTION_BLOCK or PROGRAM declared before the instance and a "
                                  "global variable: declare the instance without it and set in code what FB_init "
                                  "sets from it")
        self.dialect(value, "a variable as an FB_init argument")
        return ExprCompiler(self, None).coerce(te, pin.type, value, "argument")

    def _init_code(self, var, target):
        """C statements that give `target` (an lvalue of var's type) var's initial value."""
        t = var.type
        if t.is_fb:
            lines = [f"{t.cname}_init__(&{target}, retain);"]
            if self.user and self._fb_init(t) is not None:
                lines.append(self._fb_init_call(var, target))
            if var.init is not None:  # user mode: Delay : TON := (PT := T#1S), the inputs' initial values
                lines += self._fb_inputs_init(t, var.init, target)
            return lines
        if t.is_array or t.is_struct:
            lines = [f"__pacst_init_{t.cname}(&{target});"]
            if var.init is not None:  # user mode: [1, 2, 3(0)] and (X := 1, Y := 2)
                lines += self._aggregate_init(t, var.init, target)
            return lines
        if var.init is not None and self.user and t.kind == "interface" and _cls(var.init) == "SimpleVariable":
            return [f"{target} = {self._interface_init(var)};"]
        if var.init is not None and self.user and t.is_pointer and not t.reference and _address_of(var.init):
            return [f"{target} = {self._address_init(var)};"]
        if var.init is not None:
            te = self.literal_te(var.init, t)
            return [f"{target} = {ExprCompiler(self, None).coerce(te, t, var.init)};"]
        return [f"{target} = {self.default_c(t)};"]

    def _address_init(self, var):
        """User mode: `pList : POINTER TO T := ADR(List);`, the address of a variable of the same FUNCTION_BLOCK
        or PROGRAM declared before it, or of a global list's."""
        operand = _address_of(var.init)
        owner = self.declaring or getattr(var, "fb_init_owner", None)
        code = None
        if _cls(operand) == "SimpleVariable":
            src = owner.var(_name(operand.name)) if owner is not None and owner.kind == "fb" else None
            if src is not None and (var not in owner.vars or owner.vars.index(src) < owner.vars.index(var)):
                code = f"&(data__->{src.cname})" if src.type.is_fb else f"&(data__->{src.cname}.value)"
            elif src is None:
                g = user.lookup_global(self, operand.name)
                if g is not None:
                    code = f"&({g.csym})" if g.type.is_fb else f"&({g.csym}.value)"
        if code is None:
            raise self.err(var.init, f"the initial value of the POINTER '{var.name}': pacst takes ADR of a variable "
                                     "of the same FUNCTION_BLOCK or PROGRAM declared before it, or of a global list; "
                                     f"{self._later_or_refused(operand)}assign it in code")
        self.dialect(var.init, "ADR(variable) as a POINTER's initial value")
        return f"(({var.type.cname})(void *){code})"

    def _later_or_refused(self, node):
        """What a refusal of an initial value naming the variable `node` adds when the POU being declared declares
        it after, or its declaration was refused: that, and to declare it before."""
        up = _name(node.name).upper() if _cls(node) == "SimpleVariable" else None
        for block in self.constant_blocks or ():
            for item in getattr(block, "items", ()):
                if any(_name(getattr(getattr(v, "variable", v), "name", v)).upper() == up
                       for v in getattr(item, "variables", ())):
                    return (f"'{_name(node.name)}' is declared after it or its declaration was refused (above): "
                            "declare it before, or ")
        return ""

    def _interface_init(self, var):
        """User mode: `Logger : I_Logger := AdsLogger;`, a variable of an INTERFACE given an FB instance of its
        FUNCTION_BLOCK or PROGRAM declared before it (TwinCAT initialises in the order of declaration) or of a
        global list."""
        owner = self.declaring or getattr(var, "fb_init_owner", None)
        name = _name(var.init.name)
        src = owner.var(name) if owner is not None and owner.kind == "fb" else None
        te = None
        before = src is not None and (var not in owner.vars or owner.vars.index(src) < owner.vars.index(var))
        if before and src.type.is_fb:
            te = TE(src.type, f"&(data__->{src.cname})")
        elif src is None:
            g = user.lookup_global(self, var.init.name)
            if g is not None and g.type.is_fb:
                te = TE(g.type, f"&({g.csym})")
        if te is None:
            raise self.err(var.init, f"the initial value '{name}' of the INTERFACE variable '{var.name}': pacst takes "
                                     "an FB instance of the same FUNCTION_BLOCK or PROGRAM declared before it, or of a "
                                     f"global list; {self._later_or_refused(var.init)}assign it in code")
        self.dialect(var.init, "an FB instance as an INTERFACE variable's initial value")
        return ExprCompiler(self, None).coerce(te, var.type, var.init)

    def _aggregate_init(self, t, node, target):
        """User mode: the C assignments of an array's or a struct's initial value, after its defaults."""
        cls = _cls(node)
        if t.is_array and cls == "ArrayInitialization":
            elements = []
            for el in _array_elements(node):
                count = literals.int_value(el.count) if el.count is not None else 1
                elements += [el.element] * count
            if self.user and t.elem.is_array and not any(_cls(e) == "ArrayInitialization" for e in elements):
                # ARRAY [1..2] OF ARRAY [1..3] OF INT := [1, 2, 3, 4, 5, 6]: TwinCAT fills the inner arrays in turn
                leaves = list(_array_leaves(t, target))
                if len(elements) > len(leaves):
                    raise self.err(node, f"{len(elements)} initial values for the {len(leaves)} elements of {t.name}")
                self.dialect(node, "the initial values of an array of arrays written flat")
                out = []
                for (elem, path), element in zip(leaves, elements):
                    out += self._element_init(elem, element, path)
                return out
            if len(elements) > t.high - t.low + 1:
                raise self.err(node, f"{len(elements)} initial values for the {t.high - t.low + 1} elements of "
                                     f"{t.name}")
            out = []
            for k, element in enumerate(elements):
                out += self._element_init(t.elem, element, f"{target}.table[{k}]")
            return out
        if t.is_struct and cls == "ParenthesizedExpression" and _cls(node.expr) == "BinaryOperation" \
                and str(node.expr.op) == ":=":  # blark's reading of a one-member (Y := 6)
            pairs = [(node.expr.left.name, node.expr.right)]
        elif t.is_struct and cls in ("StructureInitialization", "InitializedStructure"):
            pairs = _struct_elements(node.init if cls == "InitializedStructure" else node)
        else:
            pairs = None
        if pairs is None and self.user:  # `Error : T_Error := GVL_Errors.ERR_NO_ERROR;`
            named = user.constant_aggregate(self, node, t)
            if named is not None:
                self.dialect(node, "an initial value that is a global constant array or struct")
                return self._aggregate_init(t, named, target)
        if pairs is not None:
            out = []
            for name, value in pairs:
                m = T.find_var(t.members, _name(name))
                if m is None:
                    raise self.err(name, f"{t.name} has no member '{_name(name)}'")
                out += self._element_init(m.type, value, f"{target}.{m.cname}")
            return out
        raise self.err(node, f"the initial value of a {t.name} is written "
                             f"{'[a, b, n(c)]' if t.is_array else '(Member := value, ...)'}")

    def _fb_inputs_init(self, t, node, target):
        """User mode: the C assignments of an FB instance's `(Input := value, ...)`, after its own init."""
        cls = _cls(node)
        if cls not in ("StructureInitialization", "InitializedStructure"):
            raise self.err(node, f"the initial value of a {t.name} instance is written (Input := value, ...)")
        self.dialect(node, "initial values of an FB instance's inputs")
        out = []
        for name, value in _struct_elements(node.init if cls == "InitializedStructure" else node):
            v = t.var(_name(name))
            if v is None or v.section != "input":
                raise self.err(name, f"{t.name} has no input '{_name(name)}' to give an initial value")
            out += self._element_init(v.type, value, f"{target}.{v.cname}.value")
        return out

    def _element_init(self, t, node, target):
        if t.is_array or t.is_struct:
            return self._aggregate_init(t, node, target)
        te = self.literal_te(node, t)
        return [f"{target} = {ExprCompiler(self, None).coerce(te, t, node)};"]

    def init_code(self, var, target):
        return self._init_code(var, target)
