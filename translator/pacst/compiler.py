"""Checks ST POUs against the portable subset and generates C with MATIEC's interface.

One pass does both: every expression is typed as it is translated, so the check mode and the build
mode refuse exactly the same programs. IEC semantics that C does not give by itself (wrap-around of
small types, truncating division, rounding conversions, TIME arithmetic) are spelled out in the
generated C; see docs/translator.md.

This module holds the driver and the declarations (types, POUs and their variables, initial values);
expressions.py types and translates expressions, body.py a POU's statements.
"""
from . import literals
from . import types as T
from .body import BodyCompiler
from .common import _BIT_LITERALS, _INT_LITERALS, _cls, _name, pos
from .errors import StError, StErrors
from .expressions import ExprCompiler
from .names import reserved_reason
from . import user


class Pou:
    def __init__(self, kind, name, file, node):
        self.kind = kind  # "fb" or "function" (a user PROGRAM is an "fb" with `program` set)
        self.program = False
        self.native = False  # a FUNCTION the host implements (user mode, --native)
        self.externals = {}  # upper name -> (GlobalVar, constant), from VAR_EXTERNAL (user mode)
        self.globals_used = {}  # C name -> GlobalVar the body names without VAR_EXTERNAL (user mode)
        self.qualifiers = []  # (start, end, GlobalVar): the offsets of each `List.` before a global in the body
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
    """`user`: the user-program mode (docs/translator.md, "User programs"): PROGRAMs, global variable
    lists, located variables, VAR_EXTERNAL, sized STRINGs, inline arrays and the string functions are
    accepted on top of the library's subset. `native`: files whose FUNCTIONs the host implements."""

    def __init__(self, user=False, native=()):
        self.user = user
        self.native_files = set(native)
        self.globals = {}  # upper name -> [GlobalVar] (one per list that declares the name)
        self.gvls = {}  # upper list name -> GlobalList
        self.inline_arrays = {}  # (low, high, element cname) -> ArrayType of an inline ARRAY declaration
        self.types = {}  # upper name -> Type
        self.pous = {}  # upper name -> Pou
        self.enum_values = {}  # upper value -> EnumType
        self.enum_shared = {}  # user mode: upper value -> the EnumTypes that share it (written E.A only)
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
        self.sources = sources
        for src in sources:
            self.file = src.path
            for item in src.tree.items:
                name = self._item_name(item)
                if name is not None and name.upper() not in self.declared_at:
                    self.declared_at[name.upper()] = (src.path, pos(item)[0])
        for src, item in self._in_order(sources):
            self.file = src.path
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

    def _in_order(self, sources):
        """(file, item) in the order they are declared: the files' order; in user mode every type first,
        then the global lists, then the POUs, so that a POU may use a global of any list and a list a type
        of any file (TwinCAT and CODESYS have no declaration order)."""
        items = [(src, item) for src in sources for item in src.tree.items]
        if not self.user:
            return items
        rank = {"DataTypeDeclaration": 0, "GlobalVariableDeclarations": 1}
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
        else:
            raise self.err(item, f"{cls} is outside the portable subset (no METHOD, PROPERTY, ACTION, INTERFACE)")

    # ------------------------------------------------------------------ names
    def _check_ident(self, token, what):
        name = _name(token)
        why = reserved_reason(name, self.user)
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
            if pou.program:
                raise self.err(token, f"'{name}' is a PROGRAM: a task runs it, no POU declares an instance")
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
                if str(tok.type_name).upper() == "STRING" and self.user:
                    # A struct member, array element or result: a STRING, its length checked, not kept.
                    user.string_length(self, tok)
                    return T.STRING
                raise self.err(tok, T.OUTSIDE_SUBSET.get(str(tok.type_name).upper(), T.OUTSIDE_SUBSET["STRING"]))
            if cls == "DataType" and spec.indirection is not None:
                raise self.err(spec, "pointers and references are outside the portable subset")
            return self._resolve_type(tok, allow_fb)
        if cls == "ArraySpecification":
            raise self.err(spec, "inline ARRAY declaration: declare a named array type (TYPE ... END_TYPE)")
        if cls == "StringTypeSpecification" and self.user and str(spec.type_name).upper() == "STRING":
            if spec.length is not None:  # an array's element: a STRING, its length checked, not kept
                user.string_length(self, spec)
            return T.STRING
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
                if self.user and _cls(init) == "ArrayTypeInitialization":
                    mtype = user.var_type(self, init, allow_fb=False)[0]  # an inline array (user mode)
                elif _cls(init) != "TypeInitialization":
                    raise self.err(el, "a STRUCT member needs a plain type (named arrays, structs, enums)")
                else:
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
                    given = f"{_name(ev.name)} := {ev.value}" if ev.value is not None else _name(ev.name)
                    raise self.err(ev, f"'{given}': an enumeration value with an explicit "
                                       "number is outside the portable subset (user programs too): leave the "
                                       "numbers out, the values count from 0 in their order")
                vname = _name(ev.name)
                if "." in vname:
                    raise self.err(ev, "qualified enumeration value")
                self._check_ident(ev.name, "enumeration value")
                up = vname.upper()
                shared = self.user and (up in self.enum_values or up in self.enum_shared)
                if not shared and (up in self.enum_values or up in self.types or up in self.pous):
                    raise self.err(ev, f"enumeration value '{vname}' is not globally unique: give it a prefix")
                values.append(vname)
            t = T.EnumType(_name(decl.name), values)
            for v in values:
                up = v.upper()
                if up in self.enum_values and self.user or up in self.enum_shared:
                    # TwinCAT's qualified_only types share names (E_Mode.IDLE, E_Step.IDLE): written E.A only
                    self.enum_shared.setdefault(up, [self.enum_values.pop(up, None)]).append(t)
                    self.enum_shared[up] = [e for e in self.enum_shared[up] if e is not None]
                else:
                    self.enum_values[up] = t
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
        what = {"fb": "function block", "program": "program"}.get(kind, "function")
        program = kind == "program"
        kind = "fb" if program else kind
        if getattr(node, "access", None) is not None:
            raise self.err(node, "access specifiers are outside the portable subset")
        if kind == "fb" and not program and (node.extends is not None or node.implements is not None):
            raise self.err(node, "EXTENDS and IMPLEMENTS are outside the portable subset")
        self._declare_global(node.name, what)
        if self.user and _name(node.name).upper() in self.globals:
            raise self.err(node.name, f"{what} '{_name(node.name)}' has the name of a global variable")
        pou = Pou(kind, _name(node.name), self.file, node)
        pou.program = program
        pou.native = kind == "function" and self.file in self.native_files
        if kind == "fb":
            pou.fbtype = T.FbType(pou.name)
            pou.fbtype.pou = pou
        elif node.return_type is None:
            if not pou.native:
                raise self.err(node, "a FUNCTION needs a return type (MATIEC)")
        else:
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
            if kind == "function" and pou.ret is not None and pou.ret.is_struct and \
                    self._SECTIONS.get(_cls(block)) in ("output", "inout"):
                raise self.err(block, f"a FUNCTION returning the STRUCT {pou.ret.name} has no VAR_OUTPUT or "
                                      "VAR_IN_OUT: iec2c accepts it but writes C that does not compile; "
                                      "return the struct alone or use a FUNCTION_BLOCK")
        if kind == "fb":
            pou.fbtype.vars = pou.vars
        # Register before the body so that an error message can name it, but refuse recursion below.
        self.pous[pou.cname] = pou
        if pou.native:  # the host implements it: its ST body (if any) is for the other tools
            self.program.items.append(("pou", pou, self.file))
            return
        try:
            pou.body_c = BodyCompiler(self, pou).compile()
        except StError:
            del self.pous[pou.cname]
            raise
        self.program.items.append(("pou", pou, self.file))

    def _var_block(self, pou, block):
        cls = _cls(block)
        section = self._SECTIONS.get(cls)
        if self.user and cls == "ExternalVariableDeclarations" and pou.kind == "fb":
            return user.external(self, pou, block)
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
            if self.user and _cls(item) in ("VariableOneInitDeclaration", "ArrayVariableInitDeclaration"):
                self._user_vars(pou, section, constant, item)
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

    def _check_section(self, pou, section, constant, vtype, item):
        """Whether a variable of type `vtype` may stand in this block of `pou`."""
        if vtype.is_fb and section != "var":
            raise self.err(item, "function block instances are only allowed in VAR")
        if vtype.is_fb and constant:
            raise self.err(item, "a function block instance cannot be CONSTANT")
        if pou.kind == "function" and vtype.is_array and section in ("input", "output"):
            raise self.err(item, "arrays are passed to a FUNCTION only whole and as VAR_IN_OUT (MATIEC)")

    def _user_vars(self, pou, section, constant, item):
        """One declaration line of a POU in user mode: inline arrays, sized STRINGs and located variables too."""
        vtype, strlen = user.var_type(self, item.init, allow_fb=(pou.kind == "fb"))
        value = getattr(item.init, "value", None)
        self._check_section(pou, section, constant, vtype, item)
        for dv in item.variables:
            location = None
            if dv.location is not None:
                # TwinCAT links an FB instance's `AT %I*` / `%Q*` variables one by one: the host binds them.
                linked = _cls(dv.location) == "IncompleteLocation" and pou.kind == "fb"
                if not (pou.program or linked) or section != "var" or constant:
                    # At the name: blark reads `AT %I*` as an enumeration value, which has no position.
                    raise self.err(dv, "located variables (AT %...) are declared in a global list or "
                                       "in a PROGRAM's VAR (MATIEC), AT %I* and %Q* in an FB's VAR too")
                location = user.parse_location(self, dv.location, vtype)
            v = self._declare_var(pou, section, constant, vtype, value, dv, may_be_located=True)
            v.location = location
            v.strlen = strlen
            user.check_string_init(self, v)

    def _declare_var(self, pou, section, constant, vtype, value, dv, may_be_located=False):
        """Check and add one variable of a POU."""
        if may_be_located and _cls(dv) == "DeclaredVariable":
            token = dv.variable.name
            self._check_ident(token, "variable")
            name = _name(token)
        else:
            name = self._decl_var_name(dv, "variable")
        up = name.upper()
        if pou.var(name) is not None or up in pou.externals:
            raise self.err(dv, f"variable '{name}' is declared twice (names are case-insensitive)")
        if up in self.types or up in self.pous or up in self.declared_at:
            raise self.err(dv, f"variable '{name}' has the name of a type or POU (MATIEC refuses it)")
        if up in self.enum_values and not self.user:  # user mode: the variable shadows it; E.A names the value
            raise self.err(dv, f"variable '{name}' has the name of an enumeration value")
        if up == pou.cname:
            raise self.err(dv, f"variable '{name}' has the name of its POU")
        v = T.Var(name, section, vtype, value, dv, constant)
        if constant and value is None:
            raise self.err(dv, f"constant '{name}' needs a value")
        if value is not None:
            if vtype.is_fb or vtype.is_array or vtype.is_struct:
                raise self.err(value, "initial values are only for elementary and enumeration "
                                      "variables: give defaults in the TYPE or in code")
            if section == "inout":
                raise self.err(value, "a VAR_IN_OUT has no initial value")
            if section == "temp":
                raise self.err(value, "a VAR_TEMP variable has no initial value in MATIEC: it starts "
                                           "from zero in every call; assign it in the body")
            self._init_code(v, "x")
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
        types = self.enum_shared.get(name.upper()) if self.user else None
        if types:
            names = sorted(t.name for t in types)
            raise self.err(node, f"'{name}' is a value of {' and '.join(names)}: qualify it ({names[0]}.{name})")

    def enum_value_of(self, t, name, node):
        """The spelling of the value `name` of the enumeration `t`; an error at `node` when it has none."""
        value = next((v for v in t.values if v.upper() == name.upper()), None)
        if value is None:
            raise self.err(node, f"{t.name} has no value '{name}'")
        return value

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
            elif self.qualified_enum_value(node) is not None:
                pass
            elif cls == "SimpleVariable" and self.shared_enum_value(_name(node.name), node):
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
