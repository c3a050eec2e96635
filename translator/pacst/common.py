"""What the translator's modules share: positions and names of blark nodes, and the typed C values
(an expression's `TE`, a variable access's `Ref`) that declarations, expressions and statements pass
between each other."""
import lark

_INT_LITERALS = {"Integer", "HexInteger", "BinaryInteger", "OctalInteger"}
_BIT_LITERALS = {"BitString", "HexBitString", "BinaryBitString", "OctalBitString"}


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


class SourceLine(str):
    """A line of generated C and the ST line it comes from, for the #line directives of a coverage or
    debug build (emit.py); everywhere else it is the plain string."""

    def __new__(cls, text, st_line):
        self = super().__new__(cls, text)
        self.st_line = st_line
        return self

    def __reduce__(self):  # pickled with its ST line (cli.checked_library)
        return SourceLine, (str(self), self.st_line)


def located(lines, st_line):
    """`lines` with every line not yet located attributed to `st_line`."""
    return [line if isinstance(line, SourceLine) else SourceLine(line, st_line) for line in lines]


def _cls(node):
    return type(node).__name__


def _name(token):
    return str(token)


class TE:
    """A typed C expression. For untyped literals `value` holds the exact number and `code` is None."""

    def __init__(self, type_, code=None, value=None, narrow=False, wide=None):
        self.type = type_
        self.code = code
        self.value = value
        self.narrow = narrow  # a small-type arithmetic result that MATIEC compares as a promoted C int
        self.wide = wide  # user mode: that result's C code not wrapped to its type (int64_t), as TwinCAT compares it


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


def inouts_by_reference(pou):
    """The VAR_IN_OUTs that the FUNCTION_BLOCK `pou`'s body reaches through pointer parameters, in declaration
    order (docs/translator.md, "VAR_IN_OUT of a function block"): every one not CONSTANT, of an FB with no
    METHOD, ACTION, PROPERTY, INTERFACE or base (those read the FB's variables between its calls, where only
    the member holds a value); no ARRAY [*], whose member is the descriptor of the caller's array (varlen.py).
    None of a PROGRAM (only its host calls it), a FUNCTION or a standard FB."""
    if pou is None or pou.kind != "fb" or pou.program or pou.owner is not None or pou.methods \
            or pou.properties or pou.interfaces or pou.base is not None:
        return []
    return [v for v in pou.vars if v.section == "inout" and not v.constant and v.type.kind != "vla"]


def inout_parameter(var):
    """The C parameter of the body that holds the address of the VAR_IN_OUT `var` (lower case: no ST name
    becomes it)."""
    return f"inout__{var.cname}"


def chained_dispatcher(itf, proto):
    """The C function through which a METHOD `proto` of the INTERFACE `itf` is called on a call's result (user
    mode: `Buffer.Get(i).Dequeue()`): it takes the INTERFACE by value, so that the call giving it is made once."""
    return f"{itf.cname}__{proto.cname}__CHAIN"


def first_output(pou):
    """The first VAR_OUTPUT of a FUNCTION, or None: the value of a call of a FUNCTION without a result type (user
    mode, as TwinCAT 3 gives it)."""
    return next((v for v in pou.vars if v.section == "output"), None)


def first_output_returnable(var):
    """Whether the C function of first_output_cfunc can return `var`'s type by value."""
    t = var.type
    return (t.is_elementary or t.is_enum or t.is_pointer or t.is_struct) and not t.is_fb


def first_output_cfunc(pou):
    """The C function that calls the FUNCTION `pou`, which has no result type, and returns its first VAR_OUTPUT
    (user mode: emit.py declares it beside the FUNCTION)."""
    return f"{pou.cfunc}__FIRST_OUTPUT"
