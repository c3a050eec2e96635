"""Checks ST POUs against the portable subset and generates C with MATIEC's interface.

One pass does both: every expression is typed as it is translated, so the check mode and the build
mode refuse exactly the same programs. IEC semantics that C does not give by itself (wrap-around of
small types, truncating division, rounding conversions, TIME arithmetic) are spelled out in the
generated C; see docs/translator.md.
"""
import re
from fractions import Fraction

import lark

from . import literals
from . import types as T
from .errors import StError, StErrors
from .names import reserved_reason

_INT_LITERALS = {"Integer", "HexInteger", "BinaryInteger", "OctalInteger"}
_BIT_LITERALS = {"BitString", "HexBitString", "BinaryBitString", "OctalBitString"}
_CONVERTIBLE = {"BOOL", "SINT", "INT", "DINT", "USINT", "UINT", "UDINT", "BYTE", "WORD", "DWORD", "REAL", "LREAL"}
_CMP_C = {"=": "==", "<>": "!=", "<": "<", ">": ">", "<=": "<=", ">=": ">="}


def pos(node):
    """(line, column) of a blark node or token."""
    if isinstance(node, lark.Token):
        return node.line or 1, node.column or 1
    meta = getattr(node, "meta", None)
    if meta is not None and getattr(meta, "line", None):
        return meta.line, meta.column
    for field in getattr(node, "__dataclass_fields__", {}):
        if field == "meta":
            continue
        child = getattr(node, field, None)
        if isinstance(child, list):
            child = child[0] if child else None
        if child is not None and (isinstance(child, lark.Token) or hasattr(child, "__dataclass_fields__")):
            return pos(child)
    return 1, 1


def _cls(node):
    return type(node).__name__


def _name(token):
    return str(token)


class TE:
    """A typed C expression. For untyped literals `value` holds the exact number and `code` is None."""

    def __init__(self, type_, code=None, value=None, narrow=False):
        self.type = type_
        self.code = code
        self.value = value
        self.narrow = narrow  # a small-type arithmetic result that MATIEC compares as a promoted C int


class Ref:
    """An ST variable access path and its C spelling (`base` is a {value; flags} wrapper when `wrapped`)."""

    def __init__(self, base, wrapped, type_, var, suffix="", writable=True, why_not="", subscripted=False):
        self.base = base
        self.wrapped = wrapped
        self.type = type_
        self.var = var
        self.suffix = suffix
        self.writable = writable
        self.why_not = why_not
        self.subscripted = subscripted

    def read(self):
        return f"{self.base}.value{self.suffix}" if self.wrapped else f"{self.base}{self.suffix}"

    def write(self, value):
        if self.wrapped:
            return f"__PACST_SETP({self.base}, {self.suffix}, {value});"
        return f"{self.base}{self.suffix} = {value};"


class Pou:
    def __init__(self, kind, name, file, node):
        self.kind = kind  # "fb" or "function"
        self.name = name
        self.cname = name.upper()
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


class Compiler:
    def __init__(self):
        self.types = {}  # upper name -> Type
        self.pous = {}  # upper name -> Pou
        self.enum_values = {}  # upper value -> EnumType
        self.declared_at = {}  # upper name -> (file, line) for every global name, including later ones
        self.program = Program()
        self.errors = []
        self.refused = set()  # upper names whose declaration was refused: later uses say so, not more
        self.file = None

    # ------------------------------------------------------------------ errors
    def err(self, node, message):
        line, col = pos(node) if node is not None else (1, 1)
        return StError(self.file, line, col, message)

    # ------------------------------------------------------------------ driver
    def compile(self, sources):
        """Check and translate parsed files (in declaration order); raise StErrors on any refusal."""
        for src in sources:
            self.file = src.path
            for item in src.tree.items:
                name = self._item_name(item)
                if name is not None and name.upper() not in self.declared_at:
                    self.declared_at[name.upper()] = (src.path, pos(item)[0])
        for src in sources:
            self.file = src.path
            for item in src.tree.items:
                try:
                    self._item(item, src)
                except StError as e:
                    self.errors.append(e)
                    name = self._item_name(item)
                    if name is not None:
                        self.refused.add(name.upper())
        if self.errors:
            raise StErrors(self.errors)
        return self.program

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
            raise self.err(item, "PROGRAM is outside the library's subset: write a FUNCTION_BLOCK")
        elif cls == "GlobalVariableDeclarations":
            raise self.err(item, "VAR_GLOBAL is outside the subset: MATIEC allows globals only inside a "
                                 "CONFIGURATION (see docs/translator.md for library constants)")
        else:
            raise self.err(item, f"{cls} is outside the portable subset (no METHOD, PROPERTY, ACTION, INTERFACE)")

    # ------------------------------------------------------------------ names
    def _check_ident(self, token, what):
        name = _name(token)
        why = reserved_reason(name)
        if why:
            raise self.err(token, f"{what} {why}")

    def _declare_global(self, token, what):
        name = _name(token)
        self._check_ident(token, what)
        up = name.upper()
        if up in self.types or up in self.pous:
            raise self.err(token, f"{what} '{name}' is declared twice (names are case-insensitive)")
        if up in self.enum_values:
            raise self.err(token, f"{what} '{name}' has the name of an enumeration value")

    def _resolve_type(self, token, allow_fb=True):
        name = _name(token)
        up = name.upper()
        if up in T.ELEMENTARY:
            return T.ELEMENTARY[up]
        if up in T.OUTSIDE_SUBSET:
            raise self.err(token, T.OUTSIDE_SUBSET[up])
        if up in T.NONPORTABLE_FBS:
            raise self.err(token, f"standard FB {up} has different pin names in MATIEC and CODESYS/TwinCAT: "
                                  "write that logic by hand")
        if up in T.STANDARD_FBS:
            if not allow_fb:
                raise self.err(token, f"a function block ({up}) cannot be used here")
            return T.STANDARD_FBS[up]
        if up in self.types:
            return self.types[up]
        if up in self.pous:
            pou = self.pous[up]
            if pou.kind == "fb":
                if not allow_fb:
                    raise self.err(token, f"a function block ({name}) cannot be used here")
                return pou.fbtype
            raise self.err(token, f"'{name}' is a FUNCTION, not a type")
        if up in self.refused:
            raise self.err(token, f"type '{name}' cannot be used: its declaration was refused (above)")
        if up in self.declared_at:
            file, line = self.declared_at[up]
            raise self.err(token, f"type '{name}' is used before its declaration ({file}:{line}): "
                                  "declare before use (MATIEC)")
        raise self.err(token, f"undeclared type '{name}'")

    # ------------------------------------------------------------------ types
    def _literal_int(self, node):
        """An array bound: a decimal literal, possibly negative."""
        if _cls(node) == "UnaryOperation" and str(node.op) == "-":
            return -self._literal_int(node.expr)
        if _cls(node) in _INT_LITERALS and node.type_name is None:
            return literals.int_value(node)
        raise self.err(node, "array bounds must be integer literals (no constants, MATIEC)")

    def _spec_type(self, spec, allow_fb=True):
        cls = _cls(spec)
        if cls in ("SimpleSpecification", "DataType"):
            tok = spec.type if cls == "SimpleSpecification" else spec.type_name
            if _cls(tok) == "StringTypeSpecification":  # STRING[10], WSTRING
                if str(tok.type_name).upper() == "STRING" and tok.length is None:
                    return T.STRING
                raise self.err(tok, T.OUTSIDE_SUBSET.get(str(tok.type_name).upper(), T.OUTSIDE_SUBSET["STRING"]))
            if cls == "DataType" and spec.indirection is not None:
                raise self.err(spec, "pointers and references are outside the portable subset")
            return self._resolve_type(tok, allow_fb)
        if cls == "ArraySpecification":
            raise self.err(spec, "inline ARRAY declaration: declare a named array type (TYPE ... END_TYPE)")
        if cls in ("StringTypeSpecification", "StringSpecLength"):
            raise self.err(spec, T.OUTSIDE_SUBSET["STRING"])
        if cls == "IndirectSimpleSpecification":
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
            if decl.extends is not None or decl.indirection is not None:
                raise self.err(decl, "EXTENDS and pointers are outside the portable subset")
            t = T.StructType(_name(decl.name))
            seen = set()
            for el in decl.declarations:
                if _cls(el) != "StructureElementDeclaration":
                    raise self.err(el, f"{_cls(el)} in a STRUCT is outside the portable subset")
                init = el.init
                if _cls(init) != "TypeInitialization":
                    raise self.err(el, "a STRUCT member needs a plain type (named arrays, structs, enums)")
                mtype = self._spec_type(init.spec, allow_fb=False)
                for dv in el.variables:
                    name = self._decl_var_name(dv, "member")
                    if name.upper() in seen:
                        raise self.err(dv, f"member '{name}' is declared twice")
                    seen.add(name.upper())
                    v = T.Var(name, "member", mtype, init.value, dv)
                    if init.value is not None:
                        self._init_code(v, "x")  # checks the initial value now
                    t.members.append(v)
        elif cls == "EnumeratedTypeDeclaration":
            self._declare_global(decl.name, "type")
            init = decl.init
            if init.value is not None:
                raise self.err(init.value, "a default value for an enumeration type is outside the portable "
                                           "subset: the first value is the default")
            spec = init.spec
            if _cls(spec) != "EnumeratedSpecification" or spec.type_name is not None:
                raise self.err(decl, "enumerations are plain value lists without base type (portable subset)")
            values = []
            for ev in spec.values:
                if ev.value is not None or ev.type_name is not None:
                    raise self.err(ev, "enumeration values without explicit numbers (portable subset)")
                vname = _name(ev.name)
                if "." in vname:
                    raise self.err(ev, "qualified enumeration value")
                self._check_ident(ev.name, "enumeration value")
                up = vname.upper()
                if up in self.enum_values or up in self.types or up in self.pous:
                    raise self.err(ev, f"enumeration value '{vname}' is not globally unique: give it a prefix")
                values.append(vname)
            t = T.EnumType(_name(decl.name), values)
            for v in values:
                self.enum_values[v.upper()] = t
        elif cls == "SimpleTypeDeclaration":
            raise self.err(decl, "type aliases are outside the portable subset")
        elif cls == "StringTypeDeclaration":
            raise self.err(decl, T.OUTSIDE_SUBSET["STRING"])
        elif cls == "UnionTypeDeclaration":
            raise self.err(decl, "UNION is outside the portable subset")
        elif cls == "SubrangeTypeDeclaration":
            raise self.err(decl, "subrange types are outside the portable subset")
        else:
            raise self.err(decl, f"{cls} is outside the portable subset")
        self.types[t.cname] = t
        self.program.items.append(("type", t, self.file))

    def _decl_var_name(self, dv, what):
        if _cls(dv) != "DeclaredVariable":
            raise self.err(dv, f"{_cls(dv)} is outside the portable subset")
        if dv.location is not None:
            raise self.err(dv, "located variables (AT %...) are outside the library's subset")
        token = dv.variable.name
        self._check_ident(token, what)
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
        what = "function block" if kind == "fb" else "function"
        if getattr(node, "access", None) is not None:
            raise self.err(node, "access specifiers are outside the portable subset")
        if kind == "fb" and (node.extends is not None or node.implements is not None):
            raise self.err(node, "EXTENDS and IMPLEMENTS are outside the portable subset")
        self._declare_global(node.name, what)
        pou = Pou(kind, _name(node.name), self.file, node)
        if kind == "fb":
            pou.fbtype = T.FbType(pou.name)
            pou.fbtype.pou = pou
        else:
            if node.return_type is None:
                raise self.err(node, "a FUNCTION needs a return type (MATIEC)")
            pou.ret = self._spec_type(node.return_type, allow_fb=False) if _cls(node.return_type) != "Token" \
                else self._resolve_type(node.return_type, allow_fb=False)
        constant_block = None
        for block in node.declarations:
            attrs = getattr(block, "attrs", None)
            is_constant = attrs is not None and str(attrs.name).lower() == "constant"
            if kind == "function" and constant_block is not None and not is_constant \
                    and self._SECTIONS.get(_cls(block)) == "var":
                raise self.err(block, "VAR after VAR CONSTANT in a FUNCTION: MATIEC then takes the VAR variables "
                                      "for constants too; put VAR CONSTANT last")
            if is_constant:
                constant_block = block
            self._var_block(pou, block)
        if kind == "fb":
            pou.fbtype.vars = pou.vars
        # Register before the body so that an error message can name it, but refuse recursion below.
        self.pous[pou.cname] = pou
        try:
            pou.body_c = BodyCompiler(self, pou).compile()
        except StError:
            del self.pous[pou.cname]
            raise
        self.program.items.append(("pou", pou, self.file))

    def _var_block(self, pou, block):
        cls = _cls(block)
        section = self._SECTIONS.get(cls)
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
            else:
                raise self.err(block, f"{str(attrs.name).upper()} variables are outside the portable subset")
        if section == "temp" and pou.kind == "function":
            raise self.err(block, "a FUNCTION has no VAR_TEMP in the portable subset: use VAR")
        for item in block.items:
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
            if vtype.is_fb and section != "var":
                raise self.err(item, "function block instances are only allowed in VAR")
            if vtype.is_fb and constant:
                raise self.err(item, "a function block instance cannot be CONSTANT")
            if pou.kind == "function" and vtype.is_array and section in ("input", "output"):
                raise self.err(item, "arrays are passed to a FUNCTION only whole and as VAR_IN_OUT (MATIEC)")
            for dv in item.variables:
                name = self._decl_var_name(dv, "variable")
                up = name.upper()
                if pou.var(name) is not None:
                    raise self.err(dv, f"variable '{name}' is declared twice (names are case-insensitive)")
                if up in self.types or up in self.pous or up in self.declared_at:
                    raise self.err(dv, f"variable '{name}' has the name of a type or POU (MATIEC refuses it)")
                if up in self.enum_values:
                    raise self.err(dv, f"variable '{name}' has the name of an enumeration value")
                if up == pou.cname:
                    raise self.err(dv, f"variable '{name}' has the name of its POU")
                v = T.Var(name, section, vtype, init.value, dv, constant)
                if constant and init.value is None:
                    raise self.err(dv, f"constant '{name}' needs a value")
                if init.value is not None:
                    if vtype.is_fb or vtype.is_array or vtype.is_struct:
                        raise self.err(init.value, "initial values are only for elementary and enumeration "
                                                   "variables: give defaults in the TYPE or in code")
                    if section == "inout":
                        raise self.err(init.value, "a VAR_IN_OUT has no initial value")
                    if section == "temp":
                        raise self.err(init.value, "a VAR_TEMP variable has no initial value in MATIEC: it starts "
                                                   "from zero in every call; assign it in the body")
                    self._init_code(v, "x")
                pou.vars.append(v)

    # ------------------------------------------------------------------ initial values
    def literal_te(self, node, want):
        """Type an initial value, which must be a literal or an enumeration value."""
        cls = _cls(node)
        if cls == "UnaryOperation" and str(node.op) == "-":
            inner = _cls(node.expr)
            if inner not in _INT_LITERALS | {"Real"}:
                raise self.err(node, "initial value must be a literal")
        elif cls not in _INT_LITERALS | _BIT_LITERALS | {"Real", "Boolean", "Duration", "String"}:
            if cls == "SimpleVariable" and _name(node.name).upper() in self.enum_values:
                pass
            else:
                raise self.err(node, "initial value must be a literal (MATIEC, CODESYS and TwinCAT differ on "
                                     "constant expressions)")
        return ExprCompiler(self, None).expr(node, want)

    def default_c(self, t):
        if t.is_string:
            return '__pacst_string("", 0)'
        if t.is_time:
            return "__time_make(0L, 0L)"
        if t.is_enum:
            return t.cvalue(t.values[0])
        if t.is_real:
            return f"(({t.cname})0.0)"
        if t.is_bool:
            return "FALSE"
        return f"(({t.cname})0)"

    def _init_code(self, var, target):
        """C statements that give `target` (an lvalue of var's type) var's initial value."""
        t = var.type
        if t.is_fb:
            return [f"{t.cname}_init__(&{target}, retain);"]
        if t.is_array or t.is_struct:
            return [f"__pacst_init_{t.cname}(&{target});"]
        if var.init is not None:
            te = self.literal_te(var.init, t)
            return [f"{target} = {ExprCompiler(self, None).coerce(te, t, var.init)};"]
        return [f"{target} = {self.default_c(t)};"]

    def init_code(self, var, target):
        return self._init_code(var, target)


class ExprCompiler:
    """Types and translates expressions inside one POU (or an initial value, with pou None)."""

    def __init__(self, comp, body):
        self.comp = comp
        self.body = body

    def err(self, node, message):
        return self.comp.err(node, message)

    # ------------------------------------------------------------------ coercion
    def coerce(self, te, target, node, what="value"):
        """C code of `te` as type `target`; ST has no implicit conversion, so types must match."""
        if te.type is target:
            return te.code
        if te.type is T.ANY_INT:
            if target.is_int or target.is_bit:
                lo, hi = target.int_range()
                if not lo <= te.value <= hi:
                    raise self.err(node, f"{te.value} does not fit {target.name} ({lo}..{hi})")
                return f"(({target.cname}){te.value}LL)"
            if target.is_real:
                raise self.err(node, f"integer literal {te.value} where {target.name} is expected: write "
                                     f"{te.value}.0 (an integer literal never becomes REAL)")
            raise self.err(node, f"integer literal where {target.name} is expected")
        if te.type is T.ANY_REAL:
            if target.is_real:
                code = literals.real_c(te.value, target.cname)
                if code is None:
                    raise self.err(node, f"{float(te.value)} does not fit {target.name}")
                return code
            raise self.err(node, f"REAL literal where {target.name} is expected")
        if te.type.is_fb:
            raise self.err(node, f"function block instance used as a {what}")
        hint = ""
        if te.type.is_elementary and target.is_elementary and \
                te.type.name in _CONVERTIBLE and target.name in _CONVERTIBLE:
            hint = f" (write {te.type.name}_TO_{target.name})"
        raise self.err(node, f"type mismatch: {te.type.name} where {target.name} is expected; ST has no "
                             f"implicit conversion{hint}")

    def default_type(self, te, want):
        if te.type is T.ANY_INT:
            if want is not None and (want.is_int or want.is_bit):
                return want
            return T.DINT
        if te.type is T.ANY_REAL:
            if want is not None and want.is_real:
                return want
            return T.LREAL
        return te.type

    def unify(self, a, b, want, node):
        """The common type of two operands and both their C codes."""
        if a.type.kind in ("anyint", "anyreal") and b.type.kind in ("anyint", "anyreal"):
            if a.type is not b.type:
                raise self.err(node, "integer and REAL literals mixed: write the integer as REAL (3.0)")
            t = self.default_type(a, want)
        elif a.type.kind in ("anyint", "anyreal"):
            t = b.type
        else:
            t = a.type
        # A mismatch is reported at the operand that does not fit (a binary operation has left/right).
        left, right = getattr(node, "left", node), getattr(node, "right", node)
        return t, self.coerce(a, t, left, "operand"), self.coerce(b, t, right, "operand")

    # ------------------------------------------------------------------ expressions
    def expr(self, node, want=None):
        cls = _cls(node)
        method = getattr(self, "_e_" + cls, None)
        if method is None:
            if cls in ("Lduration", "Date", "DateTime", "TimeOfDay", "Ldate", "LdateTime", "LtimeOfDay"):
                raise self.err(node, f"{cls} literals are outside the portable subset")
            raise self.err(node, f"{cls} is outside the portable subset")
        return method(node, want)

    def _typed_int(self, node, value, tname):
        t = self.comp._resolve_type(tname, allow_fb=False)
        if not (t.is_int or t.is_bit or t.is_bool):
            raise self.err(node, f"{t.name}# needs a {t.name} literal")
        if t.is_bool:
            if value not in (0, 1):
                raise self.err(node, "BOOL# takes 0 or 1")
            return TE(t, "TRUE" if value else "FALSE")
        return TE(t, self.coerce(TE(T.ANY_INT, value=value), t, node))

    def _e_Integer(self, node, want):
        value = literals.int_value(node)
        if node.type_name is not None:
            return self._typed_int(node, value, node.type_name)
        return TE(T.ANY_INT, value=value)

    _e_HexInteger = _e_BinaryInteger = _e_OctalInteger = _e_Integer
    _e_BitString = _e_HexBitString = _e_BinaryBitString = _e_OctalBitString = _e_Integer

    def _e_Real(self, node, want):
        value = literals.real_value(node)
        if node.type_name is not None:
            t = self.comp._resolve_type(node.type_name, allow_fb=False)
            return TE(t, self.coerce(TE(T.ANY_REAL, value=value), t, node))
        return TE(T.ANY_REAL, value=value)

    def _e_Boolean(self, node, want):
        return TE(T.BOOL, "TRUE" if str(node.value).upper() == "TRUE" else "FALSE")

    def _e_String(self, node, want):
        text = str(node.value)
        if not text.startswith("'"):
            raise self.err(node, "double-quoted WSTRING literals are outside the portable subset")
        body, out, i = text[1:-1], [], 0
        escapes = {"$": "$", "'": "'", "N": "\n", "L": "\n", "R": "\r", "T": "\t", "P": "\f"}
        while i < len(body):
            c = body[i]
            if c == "$":
                nxt = body[i + 1:i + 2].upper()
                if nxt in escapes:
                    out.append(escapes[nxt])
                    i += 2
                    continue
                if re.fullmatch(r"[0-9A-Fa-f]{2}", body[i + 1:i + 3]):
                    out.append(chr(int(body[i + 1:i + 3], 16)))
                    i += 3
                    continue
                raise self.err(node, f"unknown escape '${body[i + 1:i + 2]}' in a STRING literal")
            out.append(c)
            i += 1
        value = "".join(out)
        if len(value) > T.STRING_LITERAL_MAX:
            raise self.err(node, f"STRING literal of {len(value)} characters: at most {T.STRING_LITERAL_MAX}, "
                                 "the default STRING length of CODESYS and TwinCAT")
        c_text = "".join(ch if 32 <= ord(ch) < 127 and ch not in '"\\?' else f"\\{ord(ch):03o}" for ch in value)
        return TE(T.STRING, f'__pacst_string("{c_text}", {len(value)})')

    def _e_Duration(self, node, want):
        line, col = pos(node)
        return TE(T.TIME, literals.time_c(literals.duration_ns(node, self.comp.file, line, col)))

    def _e_ParenthesizedExpression(self, node, want):
        inner = self.expr(node.expr, want)
        if inner.code is None:
            return inner
        return TE(inner.type, f"({inner.code})", narrow=inner.narrow)

    def _e_BracketedExpression(self, node, want):
        raise self.err(node, "bracketed expression is outside the portable subset")

    def _e_SimpleVariable(self, node, want):
        return self._value_of(node)

    def _e_MultiElementVariable(self, node, want):
        return self._value_of(node)

    def _value_of(self, node):
        name = _name(node.name) if _cls(node) == "SimpleVariable" else None
        if name is not None and (self.body is None or self.body.lookup(name) is None) \
                and name.upper() in self.comp.enum_values:
            et = self.comp.enum_values[name.upper()]
            value = next(v for v in et.values if v.upper() == name.upper())
            return TE(et, et.cvalue(value))
        if self.body is None:
            raise self.err(node, "initial value must be a literal")
        ref = self.body.ref(node)
        if ref.type.is_fb:
            raise self.err(node, f"function block instance '{ref.var.name}' used as a value")
        return TE(ref.type, ref.read())

    def _e_UnaryOperation(self, node, want):
        op = str(node.op).upper()
        inner = self.expr(node.expr, want)
        if op == "-":
            if inner.type is T.ANY_INT or inner.type is T.ANY_REAL:
                return TE(inner.type, value=-inner.value)
            t = inner.type
            if t.is_real:
                return TE(t, f"(-{inner.code})")
            if t.is_int and t.is_signed:
                return TE(t, f"(({t.cname})-{inner.code})", narrow=t.bits < 32)
            raise self.err(node, f"unary minus on {t.name}: only signed integers and REAL have a sign")
        if op == "NOT":
            if inner.type is T.ANY_INT:
                t = self.default_type(inner, want)
                if not t.is_bit:
                    raise self.err(node, "NOT of an integer literal needs a typed literal (WORD#16#FF)")
                inner = TE(t, self.coerce(inner, t, node))
            t = inner.type
            if t.is_bool:
                return TE(t, f"(!{inner.code})")
            if t.is_bit:
                return TE(t, f"(({t.cname})~{inner.code})", narrow=t.bits < 32)
            raise self.err(node, f"NOT on {t.name}: only BOOL, BYTE, WORD and DWORD")
        if op == "+":
            return inner
        raise self.err(node, f"unary operator {op} is outside the portable subset")

    def _e_BinaryOperation(self, node, want):
        op = str(node.op).upper()
        if op in ("AND_THEN", "OR_ELSE"):
            raise self.err(node.op, f"{op} is a CODESYS/TwinCAT extension outside the portable subset")
        if op == "&":
            op = "AND"
        if op in ("+", "-", "*", "/", "MOD"):
            return self._arith(node, op, want)
        if op in _CMP_C:
            return self._compare(node, op)
        if op in ("AND", "OR", "XOR"):
            return self._logic(node, op, want)
        raise self.err(node, f"operator {op} is outside the portable subset")

    def _arith(self, node, op, want):
        a = self.expr(node.left, want)
        b = self.expr(node.right, want)
        if a.type is T.ANY_INT and b.type is T.ANY_INT:
            return TE(T.ANY_INT, value=self._fold(node, op, a.value, b.value))
        # The operator's own rules come before the operands' types must agree (W + I is refused for the
        # WORD, T * N for the TIME), and are reported at the operator.
        for te in (a, b):
            if te.type.is_time and op not in ("+", "-"):
                raise self.err(node.op, f"TIME {op}: TIME only adds and subtracts (MATIEC overflows otherwise)")
            if te.type.is_bit:
                raise self.err(node.op, f"arithmetic on {te.type.name}: bit strings have no arithmetic; convert "
                                        "to an integer type first")
        t, ca, cb = self.unify(a, b, want, node)
        if t.is_time:
            if op == "+":
                return TE(t, f"__time_add({ca}, {cb})")
            if op == "-":
                return TE(t, f"__time_sub({ca}, {cb})")
        if not t.is_numeric:
            raise self.err(node.op, f"arithmetic on {t.name}")
        if op == "MOD" and not t.is_int:
            raise self.err(node.op, "MOD needs integer operands")
        if t.is_real:
            return TE(t, f"(({t.cname})({ca} {op} {cb}))")
        if op == "/":
            return TE(t, f"__div_{t.cname}({ca}, {cb})")
        if op == "MOD":
            return TE(t, f"__mod_{t.cname}({ca}, {cb})")
        return TE(t, f"(({t.cname})({ca} {op} {cb}))", narrow=t.bits < 32)

    def _fold(self, node, op, a, b):
        if op == "+":
            return a + b
        if op == "-":
            return a - b
        if op == "*":
            return a * b
        if b == 0:
            raise self.err(node, "division by zero in a constant expression")
        q = abs(a) // abs(b) * (1 if (a >= 0) == (b >= 0) else -1)
        return q if op == "/" else a - q * b

    def _compare(self, node, op):
        a = self.expr(node.left)
        b = self.expr(node.right)
        for side, te in ((node.left, a), (node.right, b)):
            if te.narrow:
                raise self.err(side, f"comparison of the {te.type.name} result of arithmetic, NOT or a shift: "
                                     "MATIEC compares it as a promoted C int; store it in a variable first")
        t, ca, cb = self.unify(a, b, None, node)
        if t.is_array or t.is_struct or t.is_fb:
            raise self.err(node.op, f"{t.name} values cannot be compared")
        if op not in ("=", "<>") and (t.is_bool or t.is_enum):
            raise self.err(node.op, f"{op} on {t.name}: only = and <> compare BOOL and enumeration values")
        if t.is_string:
            if op not in ("=", "<>"):
                raise self.err(node.op, f"{op} on STRING: only = and <> compare strings")
            return TE(T.BOOL, f"({'' if op == '=' else '!'}__pacst_string_eq({ca}, {cb}))")
        if t.is_time:
            return TE(T.BOOL, f"(__time_cmp({ca}, {cb}) {_CMP_C[op]} 0)")
        return TE(T.BOOL, f"({ca} {_CMP_C[op]} {cb})")

    def _logic(self, node, op, want):
        a = self.expr(node.left, want)
        b = self.expr(node.right, want)
        if a.type is T.ANY_INT and b.type is T.ANY_INT and (want is None or not want.is_bit):
            raise self.err(node.op, f"{op} of two integer literals: give one a type (WORD#16#FF)")
        for te in (a, b):  # INT AND BOOL is refused for the INT, at the operator
            if te.type is not T.ANY_INT and not (te.type.is_bool or te.type.is_bit):
                raise self.err(node.op, f"{op} on {te.type.name}: only BOOL, BYTE, WORD and DWORD (portable subset)")
        t, ca, cb = self.unify(a, b, want, node)
        if t.is_bool:
            c_op = {"AND": "&&", "OR": "||", "XOR": "!="}[op]
            return TE(t, f"({ca} {c_op} {cb})")
        if t.is_bit:
            c_op = {"AND": "&", "OR": "|", "XOR": "^"}[op]
            return TE(t, f"(({t.cname})({ca} {c_op} {cb}))")
        raise self.err(node.op, f"{op} on {t.name}: only BOOL, BYTE, WORD and DWORD (portable subset)")

    # ------------------------------------------------------------------ calls
    def _e_FunctionCall(self, node, want):
        if _cls(node.name) != "SimpleVariable":
            raise self.err(node, "only plain function names can be called")
        name = _name(node.name.name)
        up = name.upper()
        m = re.fullmatch(r"([A-Z]+)_TO_([A-Z]+)", up)
        if m:
            return self._conversion(node, m.group(1), m.group(2))
        if up in ("SHL", "SHR", "ROL", "ROR"):
            return self._shift(node, up, want)
        if up in ("ABS", "MIN", "MAX", "LIMIT", "SEL"):
            return self._std_numeric(node, up, want)
        if up in self.comp.pous:
            pou = self.comp.pous[up]
            if pou.kind == "fb":
                raise self.err(node, f"function block type '{name}' called like a function: declare an instance")
            if self.body is not None and pou is self.body.pou:
                raise self.err(node, "recursion is outside the portable subset")
            return self._user_call(node, pou)
        if self.body is not None and self.body.lookup(name) is not None:
            raise self.err(node, f"function block instance '{name}' called inside an expression: call it as a "
                                 "statement and read its outputs")
        if up in self.comp.declared_at:
            file, line = self.comp.declared_at[up]
            raise self.err(node, f"'{name}' is called before its declaration ({file}:{line}): declare before use")
        if up in T.STANDARD_FBS or up in T.NONPORTABLE_FBS:
            raise self.err(node, f"{up} is a function block: declare an instance")
        from .names import STANDARD_FUNCTIONS
        if up in STANDARD_FUNCTIONS:
            raise self.err(node, f"standard function {up} is not supported by pacst")
        raise self.err(node, f"undeclared function '{name}'")

    def _positional(self, node, count, names):
        """Arguments of a standard function: all positional, or all formal with the IEC pin names."""
        params = node.parameters
        if len(params) != count:
            raise self.err(node, f"{_name(node.name.name).upper()} takes {count} argument(s), not {len(params)}")
        if all(_cls(p) == "InputParameterAssignment" and p.name is None for p in params):
            return [p.value for p in params]
        by_name = {}
        for p in params:
            if _cls(p) != "InputParameterAssignment" or p.name is None:
                raise self.err(p, "mix of formal and positional arguments")
            by_name[_name(p.name.name).upper()] = p.value
        if set(by_name) != set(names):
            raise self.err(node, f"the inputs are {', '.join(names)}")
        return [by_name[n] for n in names]

    def _conversion(self, node, src, dst):
        for tname in (src, dst):
            if tname in T.OUTSIDE_SUBSET:
                raise self.err(node, T.OUTSIDE_SUBSET[tname])
            if tname == "TIME":
                raise self.err(node, "TIME is never converted to or from numbers (MATIEC counts seconds, "
                                     "CODESYS milliseconds)")
            if tname not in _CONVERTIBLE:
                raise self.err(node, f"unknown conversion {src}_TO_{dst}")
        if src == dst:
            raise self.err(node, f"{src}_TO_{dst} converts nothing and is not a standard function (MATIEC)")
        (arg,) = self._positional(node, 1, ["IN"])
        st, dt = T.ELEMENTARY[src], T.ELEMENTARY[dst]
        te = self.expr(arg, st)
        code = self.coerce(te, st, arg, "argument")
        if dt.is_bool:
            return TE(dt, f"(({code}) != 0)")
        if st.is_real and not dt.is_real:
            helper = "__real_to_i64" if dt.is_int and dt.is_signed else "__real_to_u64"
            return TE(dt, f"(({dt.cname}){helper}({code}))")
        return TE(dt, f"(({dt.cname})({code}))")

    def _shift(self, node, fn, want):
        value, count = self._positional(node, 2, ["IN", "N"])
        te = self.expr(value, want)
        if te.type is T.ANY_INT:
            if want is None or not want.is_bit:
                raise self.err(value, f"{fn} of an integer literal needs a typed literal (WORD#16#FF)")
            te = TE(want, self.coerce(te, want, value))
        t = te.type
        if not t.is_bit:
            raise self.err(value, f"{fn} on {t.name}: only BYTE, WORD and DWORD (portable subset)")
        ne = self.expr(count, T.INT)
        if ne.type is T.ANY_INT:
            if not 0 <= ne.value < t.bits:
                raise self.err(count, f"shift count {ne.value} outside 0..{t.bits - 1} for {t.name}")
        ncode = self.coerce(ne, T.INT, count, "shift count")
        return TE(t, f"__{fn.lower()}_{t.cname}({te.code}, (long){ncode})", narrow=(fn != "SHR" and t.bits < 32))

    def _std_numeric(self, node, fn, want):
        if fn == "SEL":
            g, a, b = self._positional(node, 3, ["G", "IN0", "IN1"])
            gte = self.expr(g, T.BOOL)
            gcode = self.coerce(gte, T.BOOL, g, "selector")
            t, ca, cb = self.unify(self.expr(a, want), self.expr(b, want), want, node)
            return TE(t, f"({gcode} ? {cb} : {ca})")
        if fn == "ABS":
            (a,) = self._positional(node, 1, ["IN"])
            te = self.expr(a, want)
            if te.type is T.ANY_INT or te.type is T.ANY_REAL:
                return TE(te.type, value=abs(te.value))
            if not te.type.is_numeric:
                raise self.err(a, f"ABS on {te.type.name}")
            if te.type.is_int and not te.type.is_signed:
                return te
            return TE(te.type, f"__abs_{te.type.cname}({te.code})")
        if fn == "LIMIT":
            args = self._positional(node, 3, ["MN", "IN", "MX"])
        else:
            args = self._positional(node, 2, ["IN1", "IN2"])
        tes = [self.expr(a, want) for a in args]
        concrete = [te.type for te in tes if te.type.kind not in ("anyint", "anyreal")]
        t = concrete[0] if concrete else self.default_type(tes[0], want)
        codes = [self.coerce(te, t, a, "argument") for te, a in zip(tes, args)]
        if not (t.is_numeric or t.is_bit):
            raise self.err(node, f"{fn} on {t.name}")
        return TE(t, f"__{fn.lower()}_{t.cname}({', '.join(codes)})")

    def _user_call(self, node, pou):
        params = pou.vars
        interface = [v for v in params if v.section in ("input", "output", "inout")]
        inputs = [v for v in interface if v.section == "input"]
        given = {}
        positional = [p for p in node.parameters if _cls(p) == "InputParameterAssignment" and p.name is None]
        if positional and len(positional) != len(node.parameters):
            raise self.err(node, "mix of formal and positional arguments")
        if positional:
            if len(positional) != len(inputs) or any(v.section == "inout" for v in interface):
                raise self.err(node, f"positional call of {pou.name}: give every input, or call formally")
            for v, p in zip(inputs, positional):
                given[v.cname] = p.value
        else:
            for p in node.parameters:
                pname = _name(p.name.name)
                v = pou.var(pname)
                if v is None or v.section not in ("input", "output", "inout"):
                    raise self.err(p, f"{pou.name} has no input, output or in-out '{pname}'")
                if v.cname in given:
                    raise self.err(p, f"'{pname}' is given twice")
                if _cls(p) == "OutputParameterAssignment":
                    if v.section != "output":
                        raise self.err(p, f"'{pname}' is not an output: use :=")
                    if p.inverted:
                        raise self.err(p, "inverted output assignment is outside the portable subset")
                elif v.section == "output":
                    raise self.err(p, f"'{pname}' is an output: use =>")
                given[v.cname] = p.value if _cls(p) != "OutputParameterAssignment" else p.value
        args = []
        for v in interface:
            arg = given.get(v.cname)
            if v.section == "input":
                if arg is None:
                    args.append(self.comp.default_c(v.type) if v.type.is_elementary or v.type.is_enum
                                else f"__pacst_default_{v.type.cname}()")  # the TYPE's member defaults
                    if v.init is not None:
                        args[-1] = self.coerce(self.comp.literal_te(v.init, v.type), v.type, v.init)
                else:
                    args.append(self.coerce(self.expr(arg, v.type), v.type, arg, "argument"))
                continue
            if arg is None:
                if v.section == "inout":
                    raise self.err(node, f"VAR_IN_OUT '{v.name}' of {pou.name} must be passed")
                args.append(f"&({v.type.cname}){{0}}")
                continue
            ref = self.body.ref(arg) if self.body is not None else None
            if ref is None:
                raise self.err(arg, "initial value must be a literal")
            if ref.type is not v.type:
                raise self.err(arg, f"type mismatch: {ref.type.name} passed to {v.section} '{v.name}' of type "
                                    f"{v.type.name}")
            if not ref.writable:
                raise self.err(arg, f"'{ref.var.name}' cannot be written: {ref.why_not}")
            if v.section == "inout" and ref.subscripted:
                raise self.err(arg, "never pass an array element to a FUNCTION's VAR_IN_OUT (MATIEC)")
            args.append(f"&({ref.read()})")
        return TE(pou.ret, f"{pou.cname}(TRUE, NULL{''.join(', ' + a for a in args)})")


class BodyCompiler:
    """Translates one POU's variables and statements to C."""

    def __init__(self, comp, pou):
        self.comp = comp
        self.pou = pou
        self.ex = ExprCompiler(comp, self)
        self.loops = []
        self.counter = 0
        self.result_assigned = False

    def err(self, node, message):
        return self.comp.err(node, message)

    def lookup(self, name):
        return self.pou.var(name)

    # ------------------------------------------------------------------ variable access
    def _root(self, token):
        name = _name(token)
        up = name.upper()
        pou = self.pou
        if pou.kind == "function" and up == pou.cname:
            return Ref(pou.cname, False, pou.ret, T.Var(name, "result", pou.ret, None, token))
        v = pou.var(name)
        if v is None:
            if up in self.comp.enum_values:
                raise self.err(token, f"enumeration value '{name}' cannot be written")
            if up in self.comp.types:
                raise self.err(token, f"'{name}' is a type, not a variable")
            raise self.err(token, f"undeclared name '{name}'")
        writable, why = True, ""
        if v.constant:
            writable, why = False, "it is a CONSTANT"
        if pou.kind == "fb":
            return Ref(f"data__->{v.cname}", not v.type.is_fb, v.type, v, writable=writable, why_not=why)
        if v.section in ("output", "inout"):
            return Ref(f"(*{v.cname})", False, v.type, v, writable=writable, why_not=why)
        return Ref(v.cname, False, v.type, v, writable=writable, why_not=why)

    def ref(self, node):
        cls = _cls(node)
        if cls == "SimpleVariable":
            if node.dereferenced:
                raise self.err(node, "pointers are outside the portable subset")
            return self._root(node.name)
        if cls != "MultiElementVariable":
            raise self.err(node, "a variable is expected here")
        if node.dereferenced or node.name.dereferenced:
            raise self.err(node, "pointers are outside the portable subset")
        root = _name(node.name.name).upper()
        if self.pou.var(root) is None and root in self.comp.types and self.comp.types[root].is_enum:
            raise self.err(node, "qualified enumeration value: write the value alone (E.A and E#A are not "
                                 "accepted by every tool)")
        r = self._root(node.name.name)
        for el in node.elements:
            ecls = _cls(el)
            if ecls == "FieldSelector":
                if el.dereferenced:
                    raise self.err(el, "pointers are outside the portable subset")
                field = el.field
                if _cls(field) != "SimpleVariable":
                    raise self.err(el, "bit access (w.15) is outside the portable subset: use "
                                       "(w AND WORD#16#8000) <> WORD#0")
                fname = _name(field.name)
                if r.type.is_struct:
                    m = next((m for m in r.type.members if m.cname == fname.upper()), None)
                    if m is None:
                        raise self.err(field, f"{r.type.name} has no member '{fname}'")
                    r = Ref(r.base, r.wrapped, m.type, r.var, r.suffix + "." + m.cname, r.writable, r.why_not,
                            r.subscripted)
                elif r.type.is_fb:
                    fv = r.type.var(fname)
                    if fv is None:
                        raise self.err(field, f"{r.type.name} has no variable '{fname}'")
                    if fv.section not in ("input", "output"):
                        raise self.err(field, f"'{fname}' is private to {r.type.name}: never read or write "
                                              "another FB's private variables")
                    writable = fv.section == "input"
                    r = Ref(f"{r.base}{r.suffix}.{fv.cname}", True, fv.type, r.var, "", writable,
                            "an FB's outputs are written only by the FB itself")
                else:
                    raise self.err(field, f"'{fname}': {r.type.name} has no members")
            elif ecls == "SubscriptList":
                if not r.type.is_array:
                    raise self.err(el, f"{r.type.name} is not an array")
                if len(el.subscripts) != 1:
                    raise self.err(el, "multi-dimensional index is outside the portable subset")
                idx_node = el.subscripts[0]
                te = self.ex.expr(idx_node, T.DINT)
                at = r.type
                if te.type is T.ANY_INT:
                    if not at.low <= te.value <= at.high:
                        raise self.err(idx_node, f"index {te.value} outside {at.name}'s bounds {at.low}..{at.high}")
                    idx = f"{te.value - at.low}"
                else:
                    if not te.type.is_int:
                        raise self.err(idx_node, f"array index of type {te.type.name}: use an integer type")
                    line, col = pos(idx_node)
                    where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
                    idx = f"__pacst_index((long)({te.code}), {at.low}L, {at.high}L, \"{where}\")"
                r = Ref(r.base, r.wrapped, at.elem, r.var, f"{r.suffix}.table[{idx}]", r.writable, r.why_not, True)
            else:
                raise self.err(el, f"{ecls} is outside the portable subset")
        return r

    # ------------------------------------------------------------------ POU
    def compile(self):
        pou = self.pou
        statements = pou.node.body.statements if pou.node.body is not None else []
        if not statements:
            raise self.err(pou.node, f"{pou.name} has an empty body: MATIEC needs at least one statement")
        lines = self.block(statements, 1, pou.node)
        if pou.kind == "function" and not self.result_assigned:
            raise self.err(pou.node, f"the result of FUNCTION {pou.name} is never assigned")
        return lines

    def block(self, statements, depth, owner, allow_empty=False):
        if not statements and not allow_empty:
            raise self.err(owner, "empty branch: MATIEC needs at least one statement")
        out = []
        for st in statements:
            out.extend(self.stmt(st, depth))
        return out

    @staticmethod
    def _stmts(stmt_list):
        return stmt_list.statements if stmt_list is not None else []

    def stmt(self, node, d):
        cls = _cls(node)
        ind = "  " * d
        if cls == "AssignmentStatement":
            if len(node.variables) != 1:
                raise self.err(node, "chained assignment is outside the portable subset")
            target = node.variables[0]
            r = self.ref(target)
            if r.var.section == "result":
                self.result_assigned = True
            if not r.writable:
                raise self.err(target, f"'{r.var.name}' cannot be written: {r.why_not}")
            if r.type.is_fb:
                raise self.err(target, "function block instances cannot be assigned")
            te = self.ex.expr(node.expression, r.type)
            return [ind + r.write(self.ex.coerce(te, r.type, node.expression))]
        if cls == "IfStatement":
            out = [f"{ind}if ({self.cond(node.if_expression)}) {{"]
            out += self.block(self._stmts(node.statements), d + 1, node)
            for eif in node.else_ifs:
                out.append(f"{ind}}} else if ({self.cond(eif.if_expression)}) {{")
                out += self.block(self._stmts(eif.statements), d + 1, eif)
            if node.else_clause is not None:
                out.append(f"{ind}}} else {{")
                out += self.block(self._stmts(node.else_clause.statements), d + 1, node.else_clause)
            out.append(f"{ind}}}")
            return out
        if cls == "CaseStatement":
            return self.case(node, d)
        if cls == "WhileStatement":
            out = [f"{ind}while ({self.cond(node.expression)}) {{"]
            self.loops.append("while")
            out += self.block(self._stmts(node.statements), d + 1, node)
            self.loops.pop()
            return out + [f"{ind}}}"]
        if cls == "RepeatStatement":
            out = [f"{ind}do {{"]
            self.loops.append("repeat")
            out += self.block(self._stmts(node.statements), d + 1, node)
            self.loops.pop()
            return out + [f"{ind}}} while (!{self.cond(node.expression)});"]
        if cls == "ForStatement":
            raise self.err(node, "MATIEC miscompiles FOR (FOR I := 5 TO 5 runs zero times there, and the variable "
                                 "ends at the last value instead of last + step): write a WHILE loop")
        if cls == "ExitStatement":
            if not self.loops:
                raise self.err(node, "EXIT outside a loop")
            return [f"{ind}break;"]
        if cls == "ContinueStatement":
            if not self.loops:
                raise self.err(node, "CONTINUE outside a loop")
            return [f"{ind}continue;"]
        if cls == "ReturnStatement":
            return [f"{ind}goto __end;"]
        if cls == "FunctionCallStatement":
            return self.fb_call(node, d)
        if cls == "NoOpStatement":
            raise self.err(node, "a statement that only names a variable does nothing")
        if cls in ("SetStatement", "ResetStatement"):
            raise self.err(node, "S= and R= are outside the portable subset")
        if cls in ("JumpStatement", "LabeledStatement"):
            raise self.err(node, "JMP and labels are outside the portable subset")
        raise self.err(node, f"{cls} is outside the portable subset")

    def cond(self, node):
        te = self.ex.expr(node, T.BOOL)
        return self.ex.coerce(te, T.BOOL, node, "condition")

    def _case_label(self, node, sel_type):
        cls = _cls(node)
        # blark parses a name as a CASE label into an EnumeratedValue (E#A and E.A included).
        label = _name(node.name) if cls in ("SimpleVariable", "EnumeratedValue") else None
        if cls == "EnumeratedValue" and (node.type_name is not None or "." in label):
            raise self.err(node, "qualified enumeration value: write the value alone (E#A and E.A are not "
                                 "accepted by every tool)")
        if sel_type.is_enum:
            if label is None or label.upper() not in self.comp.enum_values:
                raise self.err(node, f"CASE label must be a value of {sel_type.name}")
            et = self.comp.enum_values[label.upper()]
            if et is not sel_type:
                raise self.err(node, f"'{label}' is a value of {et.name}, not of {sel_type.name}")
            return et.values.index(next(v for v in et.values if v.upper() == label.upper()))
        negative = False
        if cls == "UnaryOperation" and str(node.op) == "-":
            negative, node, cls = True, node.expr, _cls(node.expr)
        if cls in ("HexInteger", "BinaryInteger", "OctalInteger") or cls in _BIT_LITERALS:
            raise self.err(node, "CASE labels must be decimal literals (MATIEC)")
        if label is not None:
            raise self.err(node, "CASE labels must be decimal literals, not named constants (MATIEC)")
        if cls != "Integer" or node.type_name is not None:
            raise self.err(node, "CASE labels must be decimal literals")
        value = literals.int_value(node)
        value = -value if negative else value
        lo, hi = sel_type.int_range()
        if not lo <= value <= hi:
            raise self.err(node, f"CASE label {value} outside {sel_type.name}'s range")
        return value

    def case(self, node, d):
        ind = "  " * d
        te = self.ex.expr(node.expression)
        if te.narrow:
            raise self.err(node.expression, "CASE on a small-type arithmetic result: MATIEC switches on the "
                                            "promoted C int; store it in a variable first")
        t = te.type
        if t is T.ANY_INT:
            raise self.err(node.expression, "CASE on a literal")
        if t.is_bit:
            raise self.err(node.expression, f"CASE on {t.name}: MATIEC selects only on integers and "
                                            "enumerations; convert to INT or DINT")
        if not (t.is_int or t.is_enum):
            raise self.err(node.expression, f"CASE on {t.name}")
        self.counter += 1
        sel = f"__case{self.counter}"
        out = [f"{ind}{{", f"{ind}  {t.cname} {sel} = {te.code};"]
        seen = []
        keyword = "if"
        for el in node.cases:
            conds = []
            for m in el.matches:
                if _cls(m) == "PartialSubrange":
                    if t.is_enum:
                        raise self.err(m, "ranges of enumeration values are outside the portable subset")
                    lo, hi = self._case_label(m.start, t), self._case_label(m.stop, t)
                    if lo > hi:
                        raise self.err(m, f"empty CASE range {lo}..{hi}")
                    conds.append(f"({sel} >= {lo} && {sel} <= {hi})")
                else:
                    lo = hi = self._case_label(m, t)
                    conds.append(f"{sel} == {t.cvalue(t.values[lo]) if t.is_enum else lo}")
                for slo, shi in seen:
                    if lo <= shi and slo <= hi:
                        raise self.err(m, "CASE label used twice")
                seen.append((lo, hi))
            out.append(f"{ind}  {keyword} ({' || '.join(conds)}) {{")
            out += self.block(self._stmts(el.statements), d + 2, el)
            out.append(f"{ind}  }}")
            keyword = "else if"
        if node.else_clause is not None:
            if keyword == "if":
                out.append(f"{ind}  {{")
            else:
                out[-1] = f"{ind}  }} else {{"
            out += self.block(self._stmts(node.else_clause.statements), d + 2, node.else_clause)
            out.append(f"{ind}  }}")
        out.append(f"{ind}}}")
        return out

    def fb_call(self, node, d):
        ind = "  " * d
        if _cls(node.name) != "SimpleVariable":
            raise self.err(node, "only a function block instance declared in VAR can be called")
        name = _name(node.name.name)
        up = name.upper()
        v = self.pou.var(name)
        if v is None:
            if up in self.comp.pous and self.comp.pous[up].kind == "function" or up in ("SHL", "SHR", "ABS") \
                    or re.fullmatch(r"[A-Z]+_TO_[A-Z]+", up):
                raise self.err(node, f"FUNCTION {name} called as a statement: assign its result (MATIEC)")
            raise self.err(node, f"undeclared function block instance '{name}'")
        if not v.type.is_fb:
            raise self.err(node, f"'{name}' is a {v.type.name}, not a function block instance")
        fbt = v.type
        inst = f"data__->{v.cname}"
        pre, post = [], []
        given = set()
        for p in node.parameters:
            if p.name is None:
                raise self.err(p, "function block calls must be formal: name every argument (Pin := value)")
            pname = _name(p.name.name)
            fv = fbt.var(pname)
            if fv is None or fv.section not in ("input", "output", "inout"):
                raise self.err(p, f"{fbt.name} has no input, output or in-out '{pname}'")
            if fv.cname in given:
                raise self.err(p, f"'{pname}' is given twice")
            given.add(fv.cname)
            member = f"{inst}.{fv.cname}"
            if _cls(p) == "OutputParameterAssignment":
                if fv.section != "output":
                    raise self.err(p, f"'{pname}' is not an output: use :=")
                if p.inverted:
                    raise self.err(p, "inverted output assignment is outside the portable subset")
                target = self.ref(p.value)
                if not target.writable:
                    raise self.err(p.value, f"'{target.var.name}' cannot be written: {target.why_not}")
                if target.type is not fv.type:
                    raise self.err(p.value, f"type mismatch: output {pname} is {fv.type.name}, "
                                            f"'{target.var.name}' is {target.type.name}")
                post.append(ind + target.write(f"{member}.value"))
            elif fv.section == "output":
                raise self.err(p, f"'{pname}' is an output: use =>")
            elif fv.section == "input":
                te = self.ex.expr(p.value, fv.type)
                pre.append(f"{ind}__PACST_SETP({member}, , {self.ex.coerce(te, fv.type, p.value, 'argument')});")
            else:
                arg = self.ref(p.value)
                if arg.type is not fv.type:
                    raise self.err(p.value, f"type mismatch: VAR_IN_OUT {pname} is {fv.type.name}, "
                                            f"'{arg.var.name}' is {arg.type.name}")
                if not arg.writable:
                    raise self.err(p.value, f"'{arg.var.name}' cannot be passed to a VAR_IN_OUT: {arg.why_not}")
                pre.append(f"{ind}{member}.value = {arg.read()};")
                post.insert(0, ind + arg.write(f"{member}.value"))
        missing = [fv.name for fv in fbt.vars if fv.section == "inout" and fv.cname not in given]
        if missing:
            raise self.err(node, f"VAR_IN_OUT {', '.join(missing)} of {fbt.name} must be passed in every call")
        return pre + [f"{ind}{fbt.cname}_body__(&{inst});"] + post
