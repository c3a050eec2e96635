"""Translates one POU's body: variable access, statements, CASE and function block calls."""
import copy
import dataclasses
import re

from . import literals, system
from . import types as T
from . import user, varlen
from .common import _BIT_LITERALS, _INT_LITERALS, TE, Ref, SourceLine, _cls, _name, chained_dispatcher, \
    inout_parameter, inouts_by_reference, located, pos
from .errors import StError, StErrors
from .expressions import CHAINED_CALL, STATEMENT_FUNCTIONS, ExprCompiler, array_name_hint, long_inout_hint, \
    long_string_code, narrows, refused_call, widens


class BodyCompiler:
    """Translates one POU's variables and statements to C."""

    def __init__(self, comp, pou):
        self.comp = comp
        self.pou = pou
        self.ex = ExprCompiler(comp, self)
        self.loops = []
        self.errors = []  # user mode: the statements refused so far
        self.counter = 0
        self.result_assigned = False

    def err(self, node, message):
        return self.comp.err(node, message)

    def lookup(self, name):
        v = self.pou.var(name)
        if v is None:  # a METHOD or ACTION reads its FB's variables
            v = self._owner_var(name)
        if v is None:
            v = T.find_var((self.pou.owner or self.pou).statics, name)
        return v

    def _variable_or_result(self, name):
        """Whether `name` is a variable or the FUNCTION's or METHOD's own result (`Pack[1] := Seed;` in METHOD Pack):
        such a name heads no namespace."""
        own = self.pou.kind == "function" and self.pou.ret is not None and name.upper() == self.pou.cname
        return own or self.lookup(name) is not None

    def _owner_var(self, name):
        """A METHOD's or ACTION's variable of its FB: its own VAR_INST first, kept under another name where the
        FB has that name too."""
        if self.pou.owner is None:
            return None
        return self.pou.instance_vars.get(name.upper()) or self.pou.owner.var(name)

    def _fb_of_body(self):
        """The FUNCTION_BLOCK or PROGRAM whose variables `data__` points at here, or None (a FUNCTION)."""
        if self.pou.owner is not None:
            return self.pou.owner
        return self.pou if self.pou.kind == "fb" else None

    def this(self, node):
        """`THIS^.x` as `x` (user mode: inside a FUNCTION_BLOCK, PROGRAM, METHOD or ACTION); other nodes as
        they are."""
        if _cls(node) != "MultiElementVariable" or not self.comp.user or _cls(node.name) != "SimpleVariable" \
                or _name(node.name.name).upper() != "THIS":
            return node
        # blark puts THIS's '^' on THIS (THIS^.x) or, in THIS^.x.M, on the selector after it (as in p^.pNext^.Value)
        if not node.name.dereferenced and not getattr(node.elements[0], "dereferenced", False):
            return node
        if self._fb_of_body() is None:
            raise self.err(node, "THIS^ is used inside a FUNCTION_BLOCK, PROGRAM, METHOD or ACTION")
        self.comp.dialect(node, "THIS^")
        head = node.elements[0]
        if _cls(head) != "FieldSelector" or _cls(head.field) != "SimpleVariable":
            raise self.err(head, "THIS^ names a variable or a method: THIS^.Name")
        if _name(head.field.name).upper() in self.pou.instance_vars:
            raise self.err(head, f"THIS^.{_name(head.field.name)} in a METHOD whose VAR_INST has that name: pacst "
                                 "reads the METHOD's variable there; rename the METHOD's")
        if len(node.elements) == 1:
            return head.field
        return dataclasses.replace(node, name=head.field, elements=node.elements[1:])

    def _super(self, node):
        """`SUPER^()` and `SUPER^.M()` in a FUNCTION_BLOCK that EXTENDS another (or one of its METHODs):
        ("data__", the base's body or METHOD compiled for this FB), or None for any other name."""
        root = node.name if _cls(node) == "MultiElementVariable" else node
        if _cls(root) != "SimpleVariable" or not root.dereferenced or _name(root.name).upper() != "SUPER":
            return None
        fb = self._fb_of_body()
        if fb is None or fb.base is None:
            raise self.err(node, "SUPER^ is used in a FUNCTION_BLOCK that EXTENDS another")
        if self.pou.inherited_from is not None:
            raise self.err(node, "SUPER^ in a METHOD inherited through two EXTENDS is not translated yet")
        self.comp.dialect(node, "SUPER^")
        if root is node:
            return "data__", fb.methods["SUPER__BODY"]
        if len(node.elements) != 1 or _cls(node.elements[0]) != "FieldSelector":
            raise self.err(node, "SUPER^ names a METHOD of the base: SUPER^.Name()")
        name = _name(node.elements[0].field.name)
        m = fb.methods.get("SUPER__" + name.upper())
        if m is None:
            raise self.err(node.elements[0], f"{fb.base.name} has no METHOD or ACTION '{name}'")
        return "data__", m

    def property_target(self, node):
        """(the C pointer to the instance, the PROPERTY's {"name", "type", "get", "set"}) that the variable `node`
        names (`Velocity` inside the FB, `THIS^.Velocity`, `Axis.Velocity`), or None."""
        if not self.comp.user or _cls(node) not in ("SimpleVariable", "MultiElementVariable"):
            return None
        if _cls(node) == "SimpleVariable" and self.pou.accessor is not None and \
                _name(node.name).upper() == self.pou.cname:
            return None  # inside its own Get or Set the name is the value
        return self._member_target(node, "properties")

    def method_target(self, name_node):
        """(the C pointer to the instance, the METHOD or ACTION) a call's name `name_node` names, or None:
        `Move` inside the FB (or one of its methods), `THIS^.Move`, `Axis.Move`, `Axes[i].Move`."""
        if not self.comp.user:
            return None
        sup = self._super(name_node)
        if sup is not None:
            return sup
        return self._member_target(name_node, "methods")

    def _member_target(self, name_node, table):
        through_this = self.this(name_node)
        explicit, name_node = through_this is not name_node, through_this
        if _cls(name_node) == "SimpleVariable":
            fb = self._fb_of_body()
            m = getattr(fb, table).get(_name(name_node.name).upper()) if fb is not None else None
            # a METHOD's own variable hides the FB's METHOD of its name, but not from THIS^.Name
            if m is None or self.pou.var(_name(name_node.name)) is not None and not explicit:
                return None
            return "data__", m
        if _cls(name_node) != "MultiElementVariable" or not name_node.elements:
            return None
        last = name_node.elements[-1]
        if _cls(last) != "FieldSelector" or _cls(last.field) != "SimpleVariable":
            return None
        prefix = name_node.name if len(name_node.elements) == 1 else \
            dataclasses.replace(name_node, elements=name_node.elements[:-1])
        try:
            r = self.ref(prefix)
        except StError:
            return None
        if r.type.kind == "interface" and table == "methods":  # a call through the instance's table
            proto = r.type.protos.get(_name(last.field.name).upper())
            if proto is None:
                raise self.err(last, f"INTERFACE {r.type.name} has no METHOD '{_name(last.field.name)}'")
            line, col = pos(last)
            where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
            call = copy.copy(proto)
            call.cfunc = f"((const {r.type.cname}__VT *)__pacst_ptr((void *)({r.read()}).vt, \"{where}\"))->{proto.cname}"
            return f"({r.read()}).inst", call
        if r.type.kind == "interface":  # a PROPERTY through the instance's table
            return self._interface_property(r, last)
        pou = getattr(r.type, "pou", None) if r.type.is_fb else None
        m = getattr(pou, table).get(_name(last.field.name).upper()) if pou is not None else None
        if m is None:
            return None
        return f"&({r.read()})", m

    def _interface_property(self, r, last):
        """(the instance, the PROPERTY) of `itf.X`, X a PROPERTY of the INTERFACE r's type, its Get and Set called
        through the table of the instance's FB."""
        prop = r.type.properties.get(_name(last.field.name).upper())
        if prop is None:
            raise self.err(last, f"INTERFACE {r.type.name} has no METHOD or PROPERTY '{_name(last.field.name)}'")
        line, col = pos(last)
        where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
        through = dict(prop)
        for kind in ("get", "set"):
            if prop[kind] is not None:
                through[kind] = copy.copy(prop[kind])
                through[kind].cfunc = (f"((const {r.type.cname}__VT *)__pacst_ptr((void *)({r.read()}).vt, "
                                       f"\"{where}\"))->{prop[kind].cname}")
        return f"({r.read()}).inst", through

    # ------------------------------------------------------------------ variable access
    def _root(self, token):
        name = _name(token)
        up = name.upper()
        pou = self.pou
        if pou.kind == "function" and up == pou.cname and pou.ret is not None:
            return Ref(pou.cname, False, pou.ret, T.Var(name, "result", pou.ret, None, token))
        v = pou.var(name)
        static = T.find_var((pou.owner or pou).statics, name) if v is None else None
        if static is not None:  # VAR_STAT (user mode): one C variable for every instance
            return Ref(static.csym, not static.type.is_fb, static.type, static)
        ov = self._owner_var(name) if v is None and static is None else None
        if ov is not None:  # a METHOD's or ACTION's access to its FB's variables
            why = _constant_why(ov) if ov.constant else ""
            return Ref(f"data__->{ov.cname}", not ov.type.is_fb, ov.type, ov, writable=not why, why_not=why)
        if v is None and up in pou.externals:
            g, constant = pou.externals[up]
            return self._global_ref(g, constant)
        if v is None and self.comp.user:
            g = user.lookup_global(self.comp, token)
            if g is not None:
                pou.globals_used[g.csym] = g
                return self._global_ref(g, False)
        if v is None:
            if up in self.comp.enum_values:
                raise self.err(token, f"enumeration value '{name}' cannot be written")
            if up in self.comp.types:
                raise self.err(token, f"'{name}' is a type, not a variable")
            if self.comp.user and self.comp.namespace(name) is None and user.namespace_like(name):
                raise self.err(token, f"'{name}': {user.unknown_namespace(name, self.comp.namespace_names())}")
            self.comp.refused_global(token, name)
            raise self.err(token, f"undeclared name '{name}'{self._refused_lists()}")
        writable, why = True, ""
        if v.constant:
            writable, why = False, _constant_why(v)
        if pou.kind == "fb" and any(v is r for r in inouts_by_reference(pou)):  # the caller's variable itself
            return Ref(f"(*{inout_parameter(v)})", False, v.type, v, writable=writable, why_not=why)
        if pou.kind == "fb":
            return Ref(f"data__->{v.cname}", not v.type.is_fb, v.type, v, writable=writable, why_not=why)
        if v.section in ("output", "inout"):
            return Ref(f"(*{v.cname})", False, v.type, v, writable=writable, why_not=why)
        return Ref(v.cname, False, v.type, v, writable=writable, why_not=why)

    @staticmethod
    def _global_ref(g, constant):
        why = "it is a CONSTANT" if g.constant or constant else ""
        return Ref(g.csym, not g.type.is_fb, g.type, g, writable=not why, why_not=why)

    def _qualified_global(self, node):
        """`List.Name...` in user mode: (the Ref of the global, the elements after its name), or None."""
        root = _name(node.name.name).upper()
        if not self.comp.user or self.pou.var(root) is not None or root in self.pou.externals \
                or root not in self.comp.gvls:
            return None
        gvl = self.comp.gvls[root]
        first = node.elements[0]
        if _cls(first) != "FieldSelector" or _cls(first.field) != "SimpleVariable":
            raise self.err(first, f"{gvl.name} is a global variable list: name one of its variables")
        g = gvl.var(_name(first.field.name))
        if g is None and gvl.refused:
            raise self.err(first.field, f"{gvl.name}.{_name(first.field.name)} cannot be used: a declaration of the "
                                        f"global variable list {gvl.name} was refused (above)")
        if g is None:
            self._refused_pending(gvl, first.field)
            raise self.err(first.field, f"global variable list {gvl.name} has no variable '{_name(first.field.name)}'")
        if all(e is not g for e, _ in self.pou.externals.values()):
            self.pou.globals_used[g.csym] = g
        self.pou.qualifiers.append((node.name.name.start_pos, first.field.name.start_pos, g))
        return self._global_ref(g, False), node.elements[1:]

    def _refused_pending(self, gvl, field):
        """Refuses `List.Name`, a variable of the global list `gvl` that waits for a FUNCTION_BLOCK whose declaration
        was refused (Compiler.pending_globals), as a use of that FB's type is refused."""
        name = _name(field.name).upper()
        for fb, waiting in self.comp.pending_globals.items():
            if fb not in self.comp.refused:
                continue
            for list_, item, _, _ in waiting:
                if list_ is gvl and any(_name(t).upper() == name for t in item.spec.variables):
                    spelled = re.search(re.escape(fb), str(item.init), re.I)
                    raise self.err(field, f"{gvl.name}.{_name(field.name)} cannot be used: its type names "
                                          f"{spelled.group(0) if spelled else fb}, whose declaration was refused "
                                          "(above)")

    def _program_variable(self, node):
        """`MAIN.x` in user mode: (the Ref of a PROGRAM's variable, the elements after it), or None. TwinCAT and
        CODESYS let any POU read and write a PROGRAM's variables (a test reads the machine's state so)."""
        root = _name(node.name.name).upper()
        prog = self.comp.pous.get(root)
        if not self.comp.user or self.pou.var(root) is not None or root in self.pou.externals \
                or prog is None or not prog.program:
            return None
        first = node.elements[0]
        if _cls(first) != "FieldSelector" or _cls(first.field) != "SimpleVariable":
            raise self.err(first, f"{prog.name} is a PROGRAM: name one of its variables")
        v = prog.var(_name(first.field.name))
        if v is None:
            raise self.err(first.field, f"PROGRAM {prog.name} has no variable '{_name(first.field.name)}'")
        self.comp.dialect(node, f"a PROGRAM's variable read from another POU ({prog.name}.{v.name})")
        why = "it is a CONSTANT" if v.constant else ""
        return Ref(f"{program_instance(prog)}.{v.cname}", not v.type.is_fb, v.type, v, writable=not why,
                   why_not=why), node.elements[1:]

    def _bit(self, r, el, field):
        """User mode: bit n of an integer or bit string (`w.3`), read and written as a BOOL."""
        text = str(getattr(field, "value", field))
        if not text.isdigit():
            raise self.err(field, "a bit number is a decimal literal (w.3)")
        n = int(text)
        if n >= r.type.bits:
            raise self.err(field, f"bit {n} of a {r.type.name}, whose bits are 0..{r.type.bits - 1}")
        self.comp.dialect(el, f"bit access (.{n})")
        return BitRef(r, n)

    def _deref(self, r, node):
        """`p^` (user mode), and a REFERENCE read or written through: the variable the pointer points at; a
        null pointer stops the run with the ST file and line."""
        if not (self.comp.user and r.type.is_pointer):
            if self.comp.user:
                raise self.err(node, f"'^' on {r.type.name}: only a POINTER is dereferenced")
            raise self.err(node, "pointers are outside the portable subset")
        t = r.type.target
        line, col = pos(node)
        where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
        return Ref(f"(*({t.cname} *)__pacst_ptr((void *)({r.read()}), \"{where}\"))", False, t, r.var)

    def _caret(self, r, node):
        """`x^`: what the POINTER x points at; x a REFERENCE TO POINTER is read through first, as TwinCAT reads
        `pNode^.Key` with `pNode : REFERENCE TO POINTER TO ST_Node` (the collections' Delete_Node)."""
        if self.comp.user and r.type.is_pointer and r.type.reference and r.type.target.is_pointer:
            r = self._deref(r, node)
        return self._deref(r, node)

    def _through(self, r, node, raw):
        """`r`, read through when it is a REFERENCE (unless `raw`: REF= and __ISVALIDREF want the reference)."""
        if r.type.is_pointer and r.type.reference and not raw:
            return self._deref(r, node)
        return r

    def ref(self, node, raw=False):
        node = self.this(self.comp.unqualify(node, self._variable_or_result))
        cls = _cls(node)
        if cls == "SimpleVariable":
            if node.dereferenced and not self.comp.user:
                raise self.err(node, "pointers are outside the portable subset")
            r = self._root(node.name)
            return self._caret(r, node) if node.dereferenced else self._through(r, node, raw)
        if self.comp.user and (cls == "ChainedFunctionCall" or cls == "FunctionCall" and node.dereferenced):
            return self._through(self.call_result(node), node, raw)
        if cls != "MultiElementVariable":
            raise self.err(node, "a variable is expected here")
        if (node.dereferenced or node.name.dereferenced) and not self.comp.user:
            raise self.err(node, "pointers are outside the portable subset")
        root = _name(node.name.name).upper()
        if self.pou.var(root) is None and root in self.comp.types and self.comp.types[root].is_enum:
            raise self.err(node, "qualified enumeration value: write the value alone (E.A and E#A are not "
                                 "accepted by every tool)")
        qualified = self._qualified_global(node) or self._program_variable(node)
        r, elements = qualified if qualified is not None else (self._root(node.name.name), node.elements)
        if qualified is not None and getattr(node.elements[0].field, "dereferenced", False):
            r = self._deref(r, node.elements[0].field)  # GVL.p^: where the list's POINTER points
        if qualified is None and node.name.dereferenced:
            r = self._caret(r, node.name)
        elif elements:
            r = self._through(r, node.name, False)
        for k, el in enumerate(elements):
            last = k == len(elements) - 1
            if k > 0:
                r = self._through(r, el, False)
            ecls = _cls(el)
            if ecls == "FieldSelector":
                if el.dereferenced and not self.comp.user:
                    raise self.err(el, "pointers are outside the portable subset")
                if el.dereferenced:  # the `^` before the `.` (blark's reading of p^.pNext^.Value)
                    r = self._deref(r, el)
                field = el.field
                if _cls(field) != "SimpleVariable" and self.comp.user and (r.type.is_bit or r.type.is_int):
                    r = self._bit(r, el, field)
                    continue
                if _cls(field) != "SimpleVariable":
                    raise self.err(el, "bit access (w.15) is outside the portable subset: use "
                                       "(w AND WORD#16#8000) <> WORD#0")
                r = self._member(r, field)
            elif ecls == "SubscriptList" and self.comp.user and r.type.is_pointer and not r.type.reference:
                r = self._pointer_index(r, el)
            elif ecls == "SubscriptList" and self.comp.user and (r.type.is_string or r.type.kind == "longstring"):
                r = self._string_index(r, el)
            elif ecls == "SubscriptList" and r.type.kind == "vla":  # user mode: ARRAY [*]
                r = varlen.index(self, r, el)
            elif ecls == "SubscriptList":
                if not r.type.is_array:
                    raise self.err(el, f"{r.type.name} is not an array")
                if len(el.subscripts) != 1 and not self.comp.user:
                    raise self.err(el, "multi-dimensional index is outside the portable subset")
                for idx_node in el.subscripts:  # [i, j] is [i][j] (user mode)
                    if not r.type.is_array:
                        raise self.err(idx_node, f"{r.type.name} is not an array: one index too many")
                    r = self._index(r, idx_node)
            else:
                raise self.err(el, f"{ecls} is outside the portable subset")
            if ecls == "FieldSelector" and getattr(el.field, "dereferenced", False):  # a.pNext^
                r = self._deref(r, el.field)
            elif ecls != "FieldSelector" and getattr(el, "dereferenced", False):  # a[i]^
                r = self._deref(r, el)
        if node.dereferenced:
            r = self._deref(r, node)
        return self._through(r, node, raw)

    def _member(self, r, field):
        """The member `field` (a SimpleVariable) of the struct or FB instance `r`."""
        fname = _name(field.name)
        if r.type.is_struct:
            m = T.find_var(r.type.members, fname)
            if m is None:
                raise self.err(field, f"{r.type.name} has no member '{fname}'")
            return Ref(r.base, r.wrapped, m.type, r.var, r.suffix + "." + m.cname, r.writable, r.why_not,
                       r.subscripted)
        if r.type.is_fb:
            fv = r.type.var(fname)
            if fv is None:
                raise self.err(field, f"{r.type.name} has no variable '{fname}'")
            if fv.section == "var" and self.comp.user:  # read as TwinCAT reads it (SA0102); it refuses a write
                self.comp.dialect(field, f"a VAR of the function block {r.type.name} read from outside")
                return Ref(f"{r.read()}.{fv.cname}", not fv.type.is_fb, fv.type, r.var, "", False,
                           f"'{fname}' is a VAR of {r.type.name}: TwinCAT and CODESYS let other POUs read it, never "
                           "write it (make it a VAR_INPUT, or write it in a METHOD of the FB)")
            if fv.section not in ("input", "output"):
                raise self.err(field, f"'{fname}' is private to {r.type.name}: never read or write "
                                      "another FB's private variables")
            writable = fv.section == "input"
            return Ref(f"{r.read()}.{fv.cname}", True, fv.type, r.var, "", writable,
                       "an FB's outputs are written only by the FB itself")
        raise self.err(field, f"'{fname}': {r.type.name} has no members")

    def call_result(self, node):
        """User mode: what a call's result gives, as a Ref: `F(x)^` (a FunctionCall read through its POINTER
        result), `F(x).Member`, `Get(i)^.Data` (a ChainedFunctionCall whose members are rewritten before parsing,
        rewrite.CALL_MEMBER), `Buffer.Get(i).Dequeue()` (a METHOD called on the result before it). The result itself
        is read only; where a POINTER result points is read and written."""
        return self._chain(node.invocations if _cls(node) == "ChainedFunctionCall" else [node], False)

    def _chain(self, calls, statement):
        """The Ref of the last of `calls` (a call, then members and METHODs of the result before each), or as a
        `statement` the C call of the last METHOD. Each call is made once, left to right: an INTERFACE result is
        given by value to its METHOD's dispatcher (emit), an instance returned by value is a C object."""
        r = None
        for k, call in enumerate(calls):
            last = k == len(calls) - 1
            if k and (self.comp.file, *pos(call)) in self.comp.call_members:  # F(x).Member, rewritten F(x).Member()
                r = self._through(r, call, False)
                r = self._result_property(r, call) if r.type.kind == "interface" else self._member(r, call.name)
            else:
                plain = dataclasses.replace(call, dereferenced=False)
                if k:
                    this, method = self._chained_target(r, call)
                    if method.ret is None and not (statement and last):
                        raise self.err(call, f"METHOD {method.name} returns nothing: call it as a statement")
                    te = self.ex._user_call(plain, method, this=this)
                    if statement and last:
                        return te.code if method.ret is None else f"(void){te.code}"
                else:
                    te = self.ex.expr(plain)
                result = T.Var(str(plain), "result", te.type, None, call)
                code = f"(*{te.code})" if te.type.is_fb else te.code  # an instance's value is its address
                r = Ref(code, False, te.type, result, writable=False, why_not="it is a call's result")
            if call.dereferenced:
                r = self._deref(r, call)
        if statement:
            raise self.err(calls[-1], "a member of a call's result is no statement: call a METHOD")
        return r

    def _result_property(self, r, call):
        """User mode: `F(x).Index`, a PROPERTY of the INTERFACE `r` a call returns, read through its Get's dispatcher
        (emit), so that the call is made once."""
        name = _name(call.name.name)
        prop = r.type.properties.get(name.upper())
        if prop is None:
            raise self.err(call, f"INTERFACE {r.type.name} has no PROPERTY '{name}'")
        if prop["get"] is None:
            raise self.err(call, f"PROPERTY {prop['name']} has no Get: it is write only (declare its Get to read it)")
        line, col = pos(call)
        where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
        code = f"{chained_dispatcher(r.type, prop['get'])}({r.read()}, \"{where}\", TRUE, NULL)"
        result = T.Var(f"{r.var.name}.{name}", "result", prop["type"], None, call)
        return Ref(code, False, prop["type"], result, writable=False, why_not="it is a call's result")

    def _chained_target(self, r, call):
        """(the C arguments before EN, the METHOD) of `call`, a METHOD called on the result `r` of the call before
        it: on an instance, its address; on an INTERFACE, the value and the ST position, given to the dispatcher
        that reads the instance's table once (emit, chained_dispatcher)."""
        r = self._through(r, call, False)
        if _cls(call.name) != "SimpleVariable":
            raise self.err(call, CHAINED_CALL)
        name = _name(call.name.name)
        if r.type.kind == "interface":
            proto = r.type.protos.get(name.upper())
            if proto is None:
                raise self.err(call, f"INTERFACE {r.type.name} has no METHOD '{name}'")
            line, col = pos(call)
            where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
            through = copy.copy(proto)
            through.cfunc = chained_dispatcher(r.type, proto)
            return f"{r.read()}, \"{where}\"", through
        pou = getattr(r.type, "pou", None) if r.type.is_fb else None
        if pou is None:
            raise self.err(call, f"METHOD {name} called on a {r.type.name}: a METHOD is called on a function block "
                                 "instance or an INTERFACE")
        m = pou.methods.get(name.upper())
        if m is None:
            raise self.err(call, f"{r.type.name} has no METHOD '{name}'")
        return f"&({r.read()})", m

    def _pointer_index(self, r, el):
        """User mode: `p[i]`, the i-th element of p's target type from where p points, as TwinCAT reads it
        (`(p + i * SIZEOF(p^))^`); a null p stops the run with the ST line, as `p^` does."""
        if len(el.subscripts) != 1:
            raise self.err(el, f"{r.type.name} takes one index: p[i]")
        self.comp.dialect(el, "an index on a POINTER")
        te = self.ex.expr(el.subscripts[0], T.DINT)
        if te.type is not T.ANY_INT and not (te.type.is_int or te.type.is_bit):
            raise self.err(el.subscripts[0], f"an index of type {te.type.name}: use an integer type")
        t = r.type.target
        index = str(te.value) if te.type is T.ANY_INT else f"(long long)({te.code})"
        line, col = pos(el)
        where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
        return Ref(f"((({t.cname} *)__pacst_ptr((void *)({r.read()}), \"{where}\"))[{index}])", False, t, r.var)

    def _string_index(self, r, el):
        """User mode: `s[i]`, the character at offset i of a STRING as a BYTE (of a WSTRING as a WORD), as CODESYS
        and TwinCAT index a string; an offset outside the C STRING's room stops the run with the ST line."""
        if len(el.subscripts) != 1:
            raise self.err(el, f"a {r.type.name} takes one index: s[i]")
        self.comp.dialect(el, f"an index on a {r.type.name}")
        te = self.ex.expr(el.subscripts[0], T.DINT)
        if te.type is not T.ANY_INT and not (te.type.is_int or te.type.is_bit):
            raise self.err(el.subscripts[0], f"an index of type {te.type.name}: use an integer type")
        line, col = pos(el.subscripts[0])
        where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
        index = str(te.value) if te.type is T.ANY_INT else f"(long long)({te.code})"
        if r.type.kind == "longstring":  # its units themselves, up to the NUL as TwinCAT keeps them
            unit = T.ELEMENTARY["WORD" if r.type.wide else "BYTE"]
            idx = f"__pacst_index((long)({index}), 0L, {r.type.length - 1}L, \"{where}\")"
            return Ref(r.base, r.wrapped, unit, r.var, f"{r.suffix}.body[{idx}]", r.writable, r.why_not, True)
        return StringByteRef(r, f"__pacst_index((long)({index}), 0L, STR_MAX_LEN - 1L, \"{where}\")",
                             T.ELEMENTARY["WORD" if r.type is T.WSTRING else "BYTE"])

    def _index(self, r, idx_node):
        """The element `idx_node` of the array `r`: checked against the bounds at run time, or now."""
        te = self.ex.expr(idx_node, T.DINT)
        at = r.type
        if te.type is T.ANY_INT:
            if not at.low <= te.value <= at.high:
                raise self.err(idx_node, f"index {te.value} outside {at.name}'s bounds {at.low}..{at.high}")
            idx = f"{te.value - at.low}"
        else:
            # user mode: a bit string too, as TwinCAT takes it (_TaskInfo[GETCURTASKINDEXEX()], a BYTE)
            if not (te.type.is_int or self.comp.user and te.type.is_bit):
                raise self.err(idx_node, f"array index of type {te.type.name}: use an integer type")
            if te.type.is_bit:
                self.comp.dialect(idx_node, f"an array index of type {te.type.name}")
            line, col = pos(idx_node)
            where = f"{self.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
            idx = f"__pacst_index((long)({te.code}), {at.low}L, {at.high}L, \"{where}\")"
        return Ref(r.base, r.wrapped, at.elem, r.var, f"{r.suffix}.table[{idx}]", r.writable, r.why_not, True)

    def _refused_lists(self):
        """User mode: the words an undeclared name's refusal ends with when a global list's declaration was refused
        (the name may be that one's), else none."""
        refused = [g.name for g in self.comp.gvls.values() if g.refused] if self.comp.user else []
        return f" (or one whose declaration in {', '.join(refused)} was refused, above)" if refused else ""

    # ------------------------------------------------------------------ POU
    def compile(self):
        pou = self.pou
        statements = pou.node.body.statements if pou.node.body is not None else []
        if not statements and self.comp.user:  # a result keeps its initial value, as one never assigned
            self.comp.dialect(pou.node, f"{pou.name} with an empty body")
            return []
        if not statements:
            raise self.err(pou.node, f"{pou.name} has an empty body: MATIEC needs at least one statement")
        lines = self.block(statements, 1, pou.node)
        if self.errors:
            raise StErrors(self.errors)
        if pou.kind == "function" and pou.ret is not None and not self.result_assigned and self.comp.user:
            # TwinCAT and CODESYS return the result type's initial value (FsCommon's FB_init : BOOL, TcUnit's Copy)
            self.comp.dialect(pou.node, f"the result of {pou.name} never assigned")
        elif pou.kind == "function" and pou.ret is not None and not self.result_assigned:
            raise self.err(pou.node, f"the result of FUNCTION {pou.name} is never assigned")
        return lines

    def block(self, statements, depth, owner, allow_empty=False):
        if not statements and self.comp.user:
            self.comp.dialect(owner, "an empty branch or loop body")
            return []
        if not statements and not allow_empty:
            raise self.err(owner, "empty branch: MATIEC needs at least one statement")
        out = []
        for st in statements:
            if not self.comp.user:
                out.extend(self.stmt(st, depth))
                continue
            try:  # user mode: every refused statement is reported, not only the first
                out.extend(self.stmt(st, depth))
            except StError as e:
                self.errors.append(e)
            except StErrors as e:
                self.errors.extend(e.errors)
        return out

    @staticmethod
    def _stmts(stmt_list):
        return stmt_list.statements if stmt_list is not None else []

    def stmt(self, node, d):
        """C lines of one statement at depth d: `_s_<blark class>(node, indentation, d)` translates it."""
        cls = _cls(node)
        method = getattr(self, "_s_" + cls, None)
        if method is None:
            raise self.err(node, f"{cls} is outside the portable subset")
        # Lines a nested statement or an ELSIF / CASE branch already located keep their own ST line.
        return located(method(node, "  " * d, d), pos(node)[0])

    # ------------------------------------------------------------------ statements
    def _s_ChainedFunctionCallStatement(self, node, ind, d):
        if not self.comp.user:
            raise self.err(node, CHAINED_CALL)
        self.comp.dialect(node, "a METHOD called on a call's result")
        return [f"{ind}{self._chain(node.invocations, True)};"]

    def _s_AssignmentStatement(self, node, ind, d):
        if len(node.variables) != 1 and self.comp.user:
            # `a := b := 0;` (TwinCAT, CODESYS): the last variable first, then each from the one after it, as C reads
            # `a = b = 0` (the value each assignment left)
            self.comp.dialect(node, "a chained assignment (a := b := 0)")
            last = dataclasses.replace(node, variables=node.variables[-1:])
            return self._s_AssignmentStatement(last, ind, d) + self._s_AssignmentStatement(
                dataclasses.replace(node, variables=node.variables[:-1], expression=node.variables[-1]), ind, d)
        if len(node.variables) != 1:
            raise self.err(node, "chained assignment is outside the portable subset")
        target = node.variables[0]
        prop = self.property_target(target)
        if prop is not None:  # user mode: Axis.Velocity := v calls its Set
            this, p = prop
            if p["set"] is None:
                raise self.err(target, f"PROPERTY {p['name']} has no Set: it is read only (declare its Set to "
                                       "write it)")
            te = self.ex.expr(node.expression, p["type"])
            value = self.ex.coerce(te, p["type"], node.expression)
            return [f"{ind}{p['set'].cfunc}({this}, TRUE, NULL, {value});"]
        r = self.ref(target)
        if r.var.section == "result":
            self.result_assigned = True
        if not r.writable:
            raise self.err(target, f"'{r.var.name}' cannot be written: {r.why_not}")
        if r.type.is_fb and self.comp.user:  # `Stored := Suite.GetTestByPosition(1);`, `Other := Stored;`
            return self._instance_assignment(r, node.expression, ind)
        if r.type.is_fb:
            raise self.err(target, "function block instances cannot be assigned")
        if r.type.kind == "vla":
            raise self.err(target, varlen.NOT_WHOLE.format(what="an assignment to"))
        if self.comp.user and system.is_new(node.expression):  # p := __NEW(T)
            return system.new_assignment(self, r, node.expression, ind)
        te = self.ex.expr(node.expression, r.type)
        value = self.ex.coerce(te, r.type, node.expression)
        return [ind + r.write(value if isinstance(r, StringByteRef) else _limited(r.var, value, r.suffix))]

    def _instance_assignment(self, r, expression, ind):
        """User mode: an instance assigned to the instance `r` of its own function block, a copy of its memory as
        TwinCAT makes it (no FB_init); the value of an instance is its address here."""
        self.comp.dialect(expression, f"an instance of {r.type.name} assigned")
        te = self.ex.expr(expression, r.type)
        if te.type is not r.type:
            raise self.err(expression, f"type mismatch: {te.type.name} assigned to an instance of {r.type.name}; an "
                                       "instance is copied to one of its own type")
        return [f"{ind}{r.read()} = *({te.code});"]

    def _s_ReferenceAssignmentStatement(self, node, ind, d):
        """User mode: `R REF= X`: the REFERENCE R now stands for X (REF= 0: for nothing)."""
        target = self.ref(node.variable, raw=True)
        if not (target.type.is_pointer and target.type.reference):
            raise self.err(node.variable, f"REF= sets a REFERENCE, not {target.type.name}")
        self.comp.dialect(node, "REF=")
        expr = node.expression
        if _cls(expr) in ("Integer",) and literals.int_value(expr) == 0:
            return [ind + target.write("NULL")]
        if _cls(expr) == "FunctionCall" and not expr.dereferenced:  # R REF= Results.Get(): a REFERENCE result
            te = self.ex.expr(expr, target.type)
            if not (te.type.is_pointer and te.type.reference and te.type.target is target.type.target):
                raise self.err(expr, f"REF= of a call's {te.type.name} to a {target.type.name}: the call must "
                                     f"return a {target.type.name}")
            return [ind + target.write(f"({target.type.cname})({te.code})")]
        src = self.ref(expr, raw=True)
        if src.type.is_pointer and src.type.reference:
            value = src.read()
        else:
            if src.type is not target.type.target or isinstance(src, BitRef):
                raise self.err(expr, f"REF= of a {src.type.name} to a {target.type.name}")
            value = f"&({src.read()})"
        return [ind + target.write(f"({target.type.cname})({value})")]

    def _s_IfStatement(self, node, ind, d):
        out = [f"{ind}if ({self.cond(node.if_expression)}) {{"]
        out += self.block(self._stmts(node.statements), d + 1, node)
        for eif in node.else_ifs:
            out.append(SourceLine(f"{ind}}} else if ({self.cond(eif.if_expression)}) {{", pos(eif)[0]))
            out += self.block(self._stmts(eif.statements), d + 1, eif)
        if node.else_clause is not None:
            out.append(f"{ind}}} else {{")
            out += self.block(self._stmts(node.else_clause.statements), d + 1, node.else_clause)
        out.append(f"{ind}}}")
        return out

    def _s_WhileStatement(self, node, ind, d):
        out = [f"{ind}while ({self.cond(node.expression)}) {{"]
        out += self._loop_body(node, "while", d)
        return out + [f"{ind}}}"]

    def _s_RepeatStatement(self, node, ind, d):
        out = [f"{ind}do {{"] + self._loop_body(node, "repeat", d)
        return out + [SourceLine(f"{ind}}} while (!{self.cond(node.expression)});", pos(node.expression)[0])]

    def _loop_body(self, node, kind, d):
        """The loop's statements, inside which EXIT and CONTINUE are allowed."""
        self.loops.append(kind)
        lines = self.block(self._stmts(node.statements), d + 1, node)
        self.loops.pop()
        return lines

    def _s_ForStatement(self, node, ind, d):
        if self.comp.user:
            return self._user_for(node, ind, d)
        raise self.err(node, "MATIEC miscompiles FOR (FOR I := 5 TO 5 runs zero times there, and the variable "
                             "ends at the last value instead of last + step): write a WHILE loop")

    def _user_for(self, node, ind, d):
        """User mode: FOR as TwinCAT and CODESYS run it: the start assigned once, the end and the step read
        before each pass, the body run while the variable has not passed the end (a step of 0 or one that
        does not reach the end runs forever, as there); after the loop the variable holds last + step."""
        self.comp.dialect(node, "FOR (MATIEC runs FOR I := 5 TO 5 zero times)")
        r = self.ref(node.control)
        if not r.type.is_int:
            raise self.err(node.control, f"a FOR variable is an integer, not {r.type.name}")
        if not r.writable:
            raise self.err(node.control, f"'{r.var.name}' cannot be written: {r.why_not}")
        start = self.ex.coerce(self.ex.expr(node.from_, r.type), r.type, node.from_)
        end = self.ex.coerce(self.ex.expr(node.to, r.type), r.type, node.to)
        step = "1"
        if node.step is not None:
            st = self.ex.expr(node.step, r.type)
            if st.type is T.ANY_INT and st.value == 0:
                raise self.err(node.step, "FOR ... BY 0 never ends: write a step other than 0")
            if st.type is T.ANY_INT and st.value < 0 and not r.type.is_signed and r.type.bits < 64:
                step = str(st.value)  # F_Murmur3_Hash's UDINT counted down BY -1: added below in the counter's bits
            else:
                step = self.ex.coerce(st, r.type, node.step)
        self.counter += 1
        k = self.counter
        wide = "long long" if r.type.is_signed or r.type.bits < 64 else "unsigned long long"
        var = r.read()
        out = [f"{ind}{r.write(start)}",
               f"{ind}for (;;) {{",
               f"{ind}  {wide} __for_end{k} = ({wide})({end}), __for_step{k} = ({wide})({step});",
               f"{ind}  if (__for_step{k} >= 0 ? ({wide})({var}) > __for_end{k} : ({wide})({var}) < __for_end{k}) break;"]
        self.loops.append(f"for{k}")  # CONTINUE goes to the step (_s_ContinueStatement)
        body = self.block(self._stmts(node.statements), d + 1, node, allow_empty=True)
        self.loops.pop()
        step_c = f"({r.type.cname})({var} + ({r.type.cname})__for_step{k})"
        return out + body + [f"{ind}  __for_next{k}: ;", f"{ind}  {r.write(step_c)}", f"{ind}}}"]

    def _s_ExitStatement(self, node, ind, d):
        if not self.loops:
            raise self.err(node, "EXIT outside a loop")
        return [f"{ind}break;"]

    def _s_ContinueStatement(self, node, ind, d):
        if not self.loops:
            raise self.err(node, "CONTINUE outside a loop")
        if self.loops[-1].startswith("for"):
            return [f"{ind}goto __for_next{self.loops[-1][3:]};"]
        return [f"{ind}continue;"]

    def _s_ReturnStatement(self, node, ind, d):
        return [f"{ind}goto __end;"]

    def _s_NoOpStatement(self, node, ind, d):
        raise self.err(node, "a statement that only names a variable does nothing")

    def _s_SetStatement(self, node, ind, d):
        raise self.err(node, "S= and R= are outside the portable subset: write an IF")

    _s_ResetStatement = _s_SetStatement

    def _s_JumpStatement(self, node, ind, d):
        raise self.err(node, "JMP and labels are outside the portable subset: write IF, CASE or a loop with EXIT "
                             "and CONTINUE")

    _s_LabeledStatement = _s_JumpStatement

    def cond(self, node):
        te = self.ex.expr(node, T.BOOL)
        return self.ex.coerce(te, T.BOOL, node, "condition")

    def _user_case_label(self, node, sel_type):
        """User mode: a CASE label's number: a literal of any base, typed or not, a named constant (local,
        global, List.Name, PA_CONTROL.GVL_PAC.Name) or an enumeration value (E.A too), as TwinCAT and CODESYS
        take them."""
        cls = _cls(node)
        if cls == "UnaryOperation" and str(node.op) == "-":
            return -self._user_case_label(node.expr, sel_type)
        if cls in _INT_LITERALS or cls in _BIT_LITERALS:
            if cls != "Integer" or node.type_name is not None:
                self.comp.dialect(node, "a CASE label that is no decimal literal")
            if sel_type.is_enum:
                raise self.err(node, f"CASE label must be a value of {sel_type.name}")
            value = literals.int_value(node)
        elif cls in ("EnumeratedValue", "SimpleVariable", "MultiElementVariable"):
            value = None if sel_type.is_enum else self._enum_label_number(node)
            if value is not None:  # never matches where the selector's type cannot hold it (16#F000 on an INT)
                return value
            value = self._named_label(node, sel_type)
        else:
            raise self.err(node, "a CASE label is a literal, a named constant or an enumeration value")
        if not sel_type.is_enum:
            lo, hi = sel_type.int_range()
            if not lo <= value <= hi:
                raise self.err(node, f"CASE label {value} outside {sel_type.name}'s range")
        return value

    def _enum_label_number(self, node):
        """User mode: the number of a qualified enumeration value as a label on an integer selector
        (`IBaseLibrary.TypeClass.TYPE_BOOL` in TcUnit's F_AnyTypeClassToString, `E_Level.HIGH`), as TwinCAT compares
        an enumeration without {attribute 'strict'}; None for any other label."""
        if _cls(node) == "EnumeratedValue" and node.type_name is None:
            parts = _name(node.name).split(".")
        elif _cls(node) == "MultiElementVariable" and all(
                _cls(e) == "FieldSelector" and _cls(e.field) == "SimpleVariable" for e in node.elements):
            parts = [_name(node.name.name)] + [_name(e.field.name) for e in node.elements]
        else:
            return None
        if len(parts) < 2 or self.lookup(parts[0]) is not None:
            return None
        known = system.case_label(self.comp, parts, node)
        t = known[0] if known is not None else self.comp.types.get(parts[0].upper()) if len(parts) == 2 else None
        if t is None or not t.is_enum:
            return None
        self.comp.dialect(node, "an enumeration value as a CASE label on an integer")
        return t.number(known[1] if known is not None else self.comp.enum_value_of(t, parts[1], node))

    def _named_label(self, node, sel_type):
        if _cls(node) == "EnumeratedValue":
            if node.type_name is not None:
                raise self.err(node, "E#A is not read by TwinCAT: write E.A")
            parts = _name(node.name).split(".")
        elif _cls(node) == "SimpleVariable":
            parts = [_name(node.name)]
        else:
            node = self.comp.unqualify(node, self.lookup)
            parts = [_name(node.name.name if _cls(node) != "SimpleVariable" else node.name)]
            if _cls(node) != "SimpleVariable":
                parts += [_name(e.field.name) if _cls(e) == "FieldSelector" and _cls(e.field) == "SimpleVariable"
                          else "?" for e in node.elements]
        if len(parts) > 1 and self.comp.namespace(parts[0]) is not None and self.lookup(parts[0]) is None:
            if not self.comp.in_namespace(parts[0], parts[1]):
                self.comp.taken_by_program(parts[0], parts[1], node)
                raise self.err(node, f"the library {parts[0]} has no declaration '{parts[1]}'")
            self.comp.dialect(node, f"the namespace in '{parts[0]}.{parts[1]}'")
            parts = parts[1:]
        text = ".".join(parts)
        known = system.case_label(self.comp, parts, node) if self.lookup(parts[0]) is None else None
        if known is not None:  # __SYSTEM.TYPE_CLASS.TYPE_INT
            if known[0] is not sel_type:
                raise self.err(node, f"CASE label '{text}' must be a value of {sel_type.name}")
            return sel_type.number(known[1])
        if sel_type.is_enum:
            if len(parts) == 2 and (parts[0].upper() == sel_type.name.upper()
                                    or self.comp.types.get(parts[0].upper()) is sel_type):  # an alias's name too
                return sel_type.number(self.comp.enum_value_of(sel_type, parts[1], node))
            if len(parts) == 1 and self.lookup(parts[0]) is None:
                self.comp.shared_enum_value(parts[0], node)
                et = self.comp.enum_values.get(parts[0].upper())
                if et is sel_type:
                    self.comp.bare_enum_value(et, parts[0], node)
                    return sel_type.number(parts[0])
                if et is not None:
                    raise self.err(node, f"'{parts[0]}' is a value of {et.name}, not of {sel_type.name}")
            raise self.err(node, f"CASE label '{text}' must be a value of {sel_type.name}")
        var = None
        if len(parts) == 1:
            var = self.lookup(parts[0])
            if var is None and parts[0].upper() in self.pou.externals:
                var = self.pou.externals[parts[0].upper()][0]
            if var is None:
                var = user.lookup_global(self.comp, parts[0], at=node)
        elif len(parts) == 2 and parts[0].upper() in self.comp.gvls:
            var = self.comp.gvls[parts[0].upper()].var(parts[1])
        if var is None or not var.constant or var.init is None:
            raise self.err(node, f"CASE label '{text}' is no literal and no constant with a literal value")
        self.comp.dialect(node, f"the named constant {text} as a CASE label")
        init = var.init
        negative = _cls(init) == "UnaryOperation" and str(init.op) == "-"
        inner = init.expr if negative else init
        if _cls(inner) not in _INT_LITERALS | _BIT_LITERALS:
            raise self.err(node, f"CASE label '{text}': the constant's value is no integer literal")
        return -literals.int_value(inner) if negative else literals.int_value(inner)

    def _case_label(self, node, sel_type):
        if self.comp.user:
            return self._user_case_label(node, sel_type)
        cls = _cls(node)
        # blark parses a name as a CASE label into an EnumeratedValue (E#A and E.A included).
        label = _name(node.name) if cls in ("SimpleVariable", "EnumeratedValue") else None
        if cls == "EnumeratedValue" and self.comp.user and node.type_name is None and label.count(".") == 1 \
                and sel_type.is_enum and label.split(".")[0].upper() == sel_type.name.upper():
            value = self.comp.enum_value_of(sel_type, label.split(".")[1], node)  # TwinCAT's qualified_only
            return sel_type.values.index(value)
        elif cls == "EnumeratedValue" and (node.type_name is not None or "." in label):
            raise self.err(node, "qualified enumeration value: write the value alone (E#A and E.A are not "
                                 "accepted by every tool)")
        if sel_type.is_enum:
            if label is not None:
                self.comp.shared_enum_value(label, node)
            if label is None or label.upper() not in self.comp.enum_values:
                raise self.err(node, f"CASE label must be a value of {sel_type.name}")
            et = self.comp.enum_values[label.upper()]
            self.comp.bare_enum_value(et, label, node)
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

    def _s_CaseStatement(self, node, ind, d):
        te = self.ex.expr(node.expression)
        if te.narrow:
            raise self.err(node.expression, "CASE on a small-type arithmetic result: MATIEC switches on the "
                                            "promoted C int; store it in a variable first")
        t = te.type
        if t is T.ANY_INT:
            raise self.err(node.expression, "CASE on a literal")
        if t.is_bit and not self.comp.user:
            raise self.err(node.expression, f"CASE on {t.name}: MATIEC selects only on integers and "
                                            "enumerations; convert to INT or DINT")
        if t.is_bit:
            self.comp.dialect(node.expression, f"CASE on {t.name}")
            t = T.Elementary(t.name, "int", t.bits)  # user mode: its labels are numbers in its range
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
                    if t.is_enum and not self.comp.user:
                        raise self.err(m, "ranges of enumeration values are outside the portable subset")
                    lo, hi = self._case_label(m.start, t), self._case_label(m.stop, t)
                    if lo > hi:
                        raise self.err(m, f"empty CASE range {lo}..{hi}")
                    conds.append(f"({sel} >= {lo} && {sel} <= {hi})")
                else:
                    lo = hi = self._case_label(m, t)
                    conds.append(f"{sel} == {t.cvalue(t.values[lo]) if t.is_enum and not self.comp.user else lo}")
                for slo, shi in seen:
                    if lo <= shi and slo <= hi:
                        raise self.err(m, "CASE label used twice")
                seen.append((lo, hi))
            out.append(SourceLine(f"{ind}  {keyword} ({' || '.join(conds)}) {{", pos(el)[0]))
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

    def _s_FunctionCallStatement(self, node, ind, d):
        node = dataclasses.replace(node, name=self.comp.unqualify(node.name, self.lookup))
        node = self.ex.generic_assert(node)
        target = self.method_target(node.name)
        if target is not None:  # user mode: Axis.Move(...), THIS^.Move(...), Move(...) inside the FB
            if target[1] is self.pou:
                raise self.err(node, "recursion is outside pacst's user programs")
            if getattr(target[1], "action", False) and node.parameters:
                # Ring.A_AddTail(pWrite := p, cbWrite := n): the FB's inputs set, the ACTION run, its outputs read
                self.comp.dialect(node, "an ACTION called with its FB's pins")
                fbt = target[1].owner.fbtype
                call = f"{target[1].cfunc}({target[0]}, TRUE, NULL);"
                return self._fb_call(node, f"(*{target[0]})", fbt, ind, call=call)
            return [ind + "(void)" + self.ex._user_call(node, target[1], this=target[0]).code + ";"]
        node = dataclasses.replace(node, name=self.this(node.name))
        if self.comp.user and (_cls(node.name) != "SimpleVariable" or node.name.dereferenced or (
                self.pou.var(_name(node.name.name)) is None and _name(node.name.name).upper() not in self.comp.pous)):
            if _cls(node.name) == "SimpleVariable" and _name(node.name.name).upper() == "__DELETE":
                return system.delete_statement(self, node, ind)
            # User mode: MEMCPY(...) and the other functions the translator provides, as statements
            if _cls(node.name) == "SimpleVariable" and self.lookup(_name(node.name.name)) is None \
                    and _name(node.name.name).upper() in STATEMENT_FUNCTIONS:
                return [ind + "(void)(" + self.ex._e_FunctionCall(node, None).code + ");"]
            # User mode: an instance in an array, a struct, a global list (Axes[i](...), GVL_Io.Timer(...))
            if _cls(node.name) == "SimpleVariable" and self.lookup(_name(node.name.name)) is None \
                    and _name(node.name.name).upper() not in self.pou.externals \
                    and user.lookup_global(self.comp, node.name.name) is None:
                if _name(node.name.name).upper() in self.comp.refused:  # as in an expression: point at the refusal
                    raise self.err(node, refused_call(_name(node.name.name)))
                self.comp.refused_global(node, _name(node.name.name))
                raise self.err(node, f"undeclared function, METHOD, ACTION or function block instance "
                                     f"'{_name(node.name.name)}'{self._refused_lists()}")
            r = self.ref(node.name)
            if _cls(node.name) == "SimpleVariable" and node.name.dereferenced and r.type.is_fb:
                # Timer^(IN := TRUE): the instance a POINTER TO TON points at (TcUnit's FB_SkipAssertionsWhenFinished)
                self.comp.dialect(node, "a call of the FB instance a POINTER points at")
            if not r.type.is_fb:
                raise self.err(node, f"'{r.var.name}' is a {r.type.name}, not a function block instance")
            if _cls(node.name) != "SimpleVariable":
                self.comp.dialect(node.name, "a call of an FB instance in an array, a struct or a global list")
            return self._fb_call(node, r.read(), r.type, ind)
        if _cls(node.name) != "SimpleVariable":
            raise self.err(node, "only a function block instance declared in VAR can be called")
        name = _name(node.name.name)
        up = name.upper()
        v = self.pou.var(name)
        if v is None and up in self.comp.pous and self.comp.pous[up].native:
            # A native FUNCTION (an assert) may be called as a statement: the host implements it.
            return [ind + self.ex._user_call(node, self.comp.pous[up]).code + ";"]
        if v is None and self.comp.user and up in self.comp.pous and self.comp.pous[up].kind == "function":
            self.comp.dialect(node, f"FUNCTION {name} called as a statement")
            if self.comp.pous[up] is self.pou:
                raise self.err(node, "recursion is outside pacst's user programs")
            return [ind + "(void)" + self.ex._user_call(node, self.comp.pous[up]).code + ";"]
        if v is None:
            if up in self.comp.pous and self.comp.pous[up].kind == "function" or up in ("SHL", "SHR", "ABS") \
                    or re.fullmatch(r"[A-Z]+_TO_[A-Z]+", up):
                raise self.err(node, f"FUNCTION {name} called as a statement: assign its result (MATIEC)")
            raise self.err(node, f"undeclared function block instance '{name}'")
        if not v.type.is_fb and self.comp.user and up in self.comp.function_names:
            raise self.err(node, f"'{name}' is a variable in this POU, which hides the FUNCTION of that name: rename "
                                 "the variable to call the FUNCTION")
        if not v.type.is_fb:
            raise self.err(node, f"'{name}' is a {v.type.name}, not a function block instance")
        if self.pou.kind == "function" and any(x is v for x in self.pou.vars):  # in a METHOD's VAR (user mode)
            # a VAR_IN_OUT (user mode) is the caller's instance, through its address
            return self._fb_call(node, f"(*{v.cname})" if v.section == "inout" else v.cname, v.type, ind)
        return self._fb_call(node, f"data__->{v.cname}", v.type, ind)

    def _lean(self, fbt):
        """"_lean" where a call of a standard FB may skip the EN test and the ENO write: in the library's subset no
        ST names an instance's EN or ENO (a call's `EN :=` or `ENO =>`, `inst.EN` are refused) nor takes its address,
        so EN keeps the TRUE its _init__ gives it and ENO the TRUE; C code keeps both members and `<FB>_body__`."""
        return "_lean" if fbt.standard and not self.comp.user else ""

    def _fb_call(self, node, inst, fbt, ind, call=None):
        """The C of a call of the FB instance `inst` (its C lvalue) of type `fbt`; `call`: the C statement run
        between the pins set and read instead of the FB's body (user mode: an ACTION called with its FB's pins)."""
        pre, post = [], []
        given = set()
        by_reference = inouts_by_reference(fbt.pou)
        addresses = {}  # the C address each VAR_IN_OUT in by_reference is given, by its C name
        for p in node.parameters:
            if p.name is None:
                raise self.err(p, "function block calls must be formal: name every argument (Pin := value)")
            fv = self.ex.formal_pin(p, fbt, given)
            pname = _name(p.name.name)
            given.add(fv.cname)
            member = f"{inst}.{fv.cname}"
            if _cls(p) == "OutputParameterAssignment":
                target = self.ref(p.value)
                if not target.writable:
                    raise self.err(p.value, f"'{target.var.name}' cannot be written: {target.why_not}")
                value = f"{member}.value"
                if target.type is not fv.type and self.comp.user and widens(fv.type, target.type):
                    # user mode: an output to a wider variable, as TwinCAT converts it (Index => DintVariable)
                    self.comp.dialect(p.value, f"the implicit conversion of {fv.type.name} to {target.type.name}")
                    value = f"(({target.type.cname})({value}))"
                elif target.type is not fv.type and self.comp.user and narrows(fv.type, target.type):
                    value = self.ex.narrowed(TE(fv.type, value), target.type, p.value)  # Count => UsintVariable
                elif target.type is not fv.type and self.comp.user and \
                        (code := long_string_code(TE(fv.type, value), target.type)) is not None:
                    value = code  # user mode: a STRING output to a STRING(300), or the other way, cut to the target
                elif target.type is not fv.type:
                    raise self.err(p.value, f"type mismatch: output {pname} is {fv.type.name}, "
                                            f"'{target.var.name}' is {target.type.name}")
                post.append(ind + target.write(_limited(target.var, value, target.suffix)))
            elif fv.section == "input" and getattr(fv.type, "any", False):  # an ANY input (user mode)
                pre.append(f"{ind}__PACST_SETP({member}, , {system.any_argument(self.ex, p.value, fv)});")
            elif fv.section == "input" and (bound := self.ex.reference_input(p.value, fv)) is not None:
                pre.append(f"{ind}__PACST_SETP({member}, , {bound});")
            elif fv.section == "input":
                te = self.ex.expr(p.value, fv.type)
                value = _limited(fv, self.ex.coerce(te, fv.type, p.value, "argument"))
                pre.append(f"{ind}__PACST_SETP({member}, , {value});")
            elif fv.type.kind == "vla":  # ARRAY [*] (user mode): the member describes the caller's array
                pre.append(f"{ind}{member}.value = {varlen.descriptor(self.ex, p.value, fv)};")
            elif fv.constant:  # VAR_IN_OUT CONSTANT (user mode): read only, a value may be passed
                te = self.ex.expr(p.value, fv.type)
                pre.append(f"{ind}{member}.value = {self.ex.coerce(te, fv.type, p.value, 'argument')};")
            else:
                arg = self.ref(p.value)
                if arg.type is not fv.type:
                    raise self.err(p.value, f"type mismatch: VAR_IN_OUT {pname} is {fv.type.name}, "
                                            f"'{arg.var.name}' is {arg.type.name}"
                                            f"{array_name_hint(arg.type, fv.type)}{long_inout_hint(arg.type, fv.type)}")
                if not arg.writable:
                    raise self.err(p.value, f"'{arg.var.name}' cannot be passed to a VAR_IN_OUT: {arg.why_not}")
                if type(arg) is Ref and any(fv is r for r in by_reference):  # an lvalue: the FB works on it
                    addresses[fv.cname] = f"&({arg.read()})"
                    continue
                # Copied in and out: an FB whose body works on the member, or a bit of a variable (user mode)
                pre.append(f"{ind}{member}.value = {arg.read()};")
                post.insert(0, ind + arg.write(f"{member}.value"))
        missing = [fv.name for fv in fbt.vars if fv.section == "inout" and fv.cname not in given]
        if missing:
            raise self.err(node, f"VAR_IN_OUT {', '.join(missing)} of {fbt.name} must be passed in every call")
        if call is not None:  # an ACTION: its FB's VAR_IN_OUTs are the members the ACTION reads
            if addresses:
                raise self.err(node, f"a VAR_IN_OUT given in a call of an ACTION of {fbt.name} is not translated: call "
                                     "the FB with it first")
            return pre + [ind + call] + post
        # A call through a pointer or reference (user mode) may reach an instance of the caller's own type:
        # it keeps the body out of line (PACST_INLINE_ONCE must never meet a recursion).
        direct = "*" not in inst and inst.count("->") <= 1
        self.comp.fb_call_sites[fbt.cname] = self.comp.fb_call_sites.get(fbt.cname, 0) + (1 if direct else 2)
        if not by_reference:
            return pre + [f"{ind}{fbt.cname}_body{self._lean(fbt)}__(&{inst});"] + post
        args = "".join(", " + addresses.get(fv.cname, f"&{inst}.{fv.cname}.value") for fv in by_reference)
        return pre + [f"{ind}{fbt.cname}_body_ref__(&{inst}{args});"] + post


class BitRef(Ref):
    """Bit n of an integer or bit-string variable (user mode): a BOOL; a write keeps the other bits."""

    def __init__(self, whole, n):
        super().__init__(whole.base, whole.wrapped, T.BOOL, whole.var, whole.suffix, whole.writable, whole.why_not,
                         whole.subscripted)
        self.whole, self.n = whole, n

    def read(self):
        return f"((BOOL)(((unsigned long long)({self.whole.read()}) >> {self.n}) & 1u))"

    def write(self, value):
        t = self.whole.type.cname
        mask = f"(({t})1 << {self.n})"
        return self.whole.write(f"(({t})(({value}) ? ({self.whole.read()} | {mask}) : ({self.whole.read()} & ({t})~{mask})))")


class StringByteRef(Ref):
    """A character of a STRING variable by its offset (user mode): a BYTE (WORD of a WSTRING) read and written."""

    def __init__(self, whole, index, type_):
        super().__init__(whole.base, whole.wrapped, type_, whole.var, whole.suffix, whole.writable, whole.why_not,
                         whole.subscripted)
        self.whole, self.index = whole, index

    def read(self):
        fn = "wstr_word" if self.whole.type is T.WSTRING else "str_byte"
        return f"(({self.type.cname})__pacst_{fn}({self.whole.read()}, {self.index}))"

    def write(self, value):
        fn, unit = ("wstr_setword", "WORD") if self.whole.type is T.WSTRING else ("str_setbyte", "BYTE")
        return self.whole.write(_limited(self.var, f"__pacst_{fn}({self.whole.read()}, {self.index}, "
                                                   f"({unit})({value}))", self.whole.suffix))


def program_instance(pou):
    """The C variable of a PROGRAM's one instance (user mode), which the host runs and other POUs read."""
    return f"{pou.cname}__INSTANCE"


def _limited(var, value, suffix=""):
    """`value` as written to `var` (a member or element of it when `suffix`): a STRING(n) keeps its first
    n characters (user mode)."""
    if var.strlen is None or suffix:
        return value
    return f"__pacst_{'wstr' if var.type is T.WSTRING else 'str'}_limit({value}, {var.strlen})"


def _constant_why(var):
    """Why the CONSTANT `var` cannot be written: a VAR_INPUT or VAR_IN_OUT CONSTANT (user mode) with what to write
    instead, or a VAR CONSTANT."""
    if var.section in ("input", "inout"):
        return "it is a CONSTANT input: copy it to a VAR and write that"
    return "it is a CONSTANT"
