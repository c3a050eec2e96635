"""Arrays of variable length in user programs (docs/user_dialect.md): `ARRAY [*] OF T` and `ARRAY [*, *] OF T`,
declared, as in TwinCAT and CODESYS, only in a VAR_IN_OUT of a FUNCTION, FUNCTION_BLOCK or METHOD, with
LOWER_BOUND(a, n) and UPPER_BOUND(a, n).

Such a VAR_IN_OUT is a descriptor of the caller's array: the address of its first element and the bounds of each
dimension (`__VLA_<T>_<n>`: `table`, `bounds[2n]`, lower then upper of each dimension). A FUNCTION or METHOD is
given the descriptor's address, an FB keeps the descriptor in its member (set in every call, so its METHODs reach
the array of its last call). A call builds the descriptor of a fixed array (C99 compound literal) or passes one on.
An element is found with the last index running fastest, as the elements of a multi-dimensional array lie in
memory; every index is checked against the bounds of its dimension, so an FB never called has an empty array
(bounds 0..-1)."""
from . import types as T
from .common import TE, Ref, _cls, pos


class VarArrayType(T.Type):
    """ARRAY [*, ...] OF elem: `dims` dimensions of a length the caller's array gives."""

    kind = "vla"

    def __init__(self, elem, dims):
        super().__init__(f"ARRAY [{', '.join('*' * dims)}] OF {elem.name}")
        self.elem = elem
        self.dims = dims
        own = elem.name if elem.kind == "elementary" and elem.name != elem.cname else elem.cname
        self.cname = f"__VLA_{own.replace(' ', '_')}_{dims}"


# The refusal of an ARRAY [*] used whole (`what` it is used by): only its elements and bounds are.
NOT_WHOLE = ("{what} an ARRAY [*] as a whole is not translated: use its elements, from LOWER_BOUND to UPPER_BOUND "
             "(ADR(a[LOWER_BOUND(a, 1)]) is the address of the first)")


ONLY_IN_OUT = ("ARRAY [*] is declared only in a VAR_IN_OUT of a FUNCTION, FUNCTION_BLOCK or METHOD (as in TwinCAT "
               "and CODESYS): give the bounds here")


def is_var_length(spec):
    """Whether the ARRAY specification `spec` has a `*` for a bound."""
    return any(_cls(sub) == "FullSubrange" for sub in getattr(spec, "subranges", []))


def declare(comp, spec, file, in_out):
    """The type of `ARRAY [*, ...] OF T` (`in_out`: declared in a VAR_IN_OUT, where it may stand)."""
    if not in_out:
        raise comp.err(spec, ONLY_IN_OUT)
    if not all(_cls(sub) == "FullSubrange" for sub in spec.subranges):
        raise comp.err(spec, "an ARRAY with '*' and bounds mixed: write a '*' for every dimension ([*, *])")
    elem = comp._spec_type(spec.type, allow_fb=True)
    if elem.is_array:
        raise comp.err(spec.type, "an ARRAY [*] of arrays: declare ARRAY [*, *] OF the element type")
    comp.dialect(spec, "an array of variable length (ARRAY [*])")
    key = ("vla", len(spec.subranges), elem.cname, elem.name)
    t = comp.inline_arrays.get(key)
    if t is None:
        t = VarArrayType(elem, len(spec.subranges))
        comp.inline_arrays[key] = t
        comp.program.items.append(("type", t, file))
    return t


def check_section(comp, pou, item):
    """A VAR_IN_OUT of ARRAY [*] stands in a FUNCTION, FUNCTION_BLOCK or METHOD, not in a PROGRAM (`declare` refuses
    it in the other blocks)."""
    if pou.program:
        raise comp.err(item, ONLY_IN_OUT)


def c_declaration(t):
    """The C typedef of the descriptor type `t`."""
    return f"typedef struct {{ {t.elem.cname} *table; DINT bounds[{2 * t.dims}]; }} {t.cname};"


def default_c(t):
    """The descriptor of no array: every dimension empty (0..-1), so that any index stops the test."""
    return f"(({t.cname}){{NULL, {{{', '.join(['0, -1'] * t.dims)}}}}})"


def _shape(t, dims):
    """[(low, high)...] of the first `dims` dimensions of the fixed array type `t`, and the element type after
    them; None when `t` has fewer."""
    shape = []
    for _ in range(dims):
        if not t.is_array:
            return None
        shape.append((t.low, t.high))
        t = t.elem
    return shape, t


def descriptor(ex, arg, pin):
    """C of the descriptor value the VAR_IN_OUT `pin` of type ARRAY [*...] is given for the argument `arg`."""
    t = pin.type
    r = ex.body.ref(arg) if ex.body is not None else None
    if r is None:
        raise ex.err(arg, f"VAR_IN_OUT '{pin.name}' of type {t.name} is given an array variable")
    if not r.writable and not pin.constant:
        raise ex.err(arg, f"'{r.var.name}' cannot be passed to a VAR_IN_OUT: {r.why_not}")
    if r.type.kind == "vla":
        if r.type.elem is not t.elem or r.type.dims != t.dims:
            raise ex.err(arg, f"type mismatch: {r.type.name} passed to VAR_IN_OUT '{pin.name}' of type {t.name}")
        return r.read()
    shape = _shape(r.type, t.dims)
    if shape is None or shape[1] is not t.elem:
        what = f"an array of {shape[1].name}" if shape is not None else r.type.name
        raise ex.err(arg, f"type mismatch: {what} passed to VAR_IN_OUT '{pin.name}' of type {t.name}: pass an "
                          f"array of {t.elem.name} with {t.dims} dimension{'s' if t.dims > 1 else ''}")
    bounds = ", ".join(f"{low}, {high}" for low, high in shape[0])
    return f"(({t.cname}){{({t.elem.cname} *)(void *)&({r.read()}), {{{bounds}}}}})"


def index(body, r, el):
    """The element `a[i, j...]` of the ARRAY [*...] `r`: every index checked against its dimension's bounds."""
    t = r.type
    if len(el.subscripts) != t.dims:
        raise body.err(el, f"{t.name} takes {t.dims} index{'es' if t.dims > 1 else ''} in one list: "
                           f"a[{', '.join('ijk'[k] if k < 3 else f'i{k}' for k in range(t.dims))}]")
    d = r.read()
    flat = None
    for k, sub in enumerate(el.subscripts):
        te = body.ex.expr(sub, T.DINT)
        if te.type is not T.ANY_INT and not (te.type.is_int or te.type.is_bit):
            raise body.err(sub, f"array index of type {te.type.name}: use an integer type")
        value = str(te.value) if te.type is T.ANY_INT else f"(long)({te.code})"
        line, col = pos(sub)
        where = f"{body.comp.file}:{line}:{col}".replace("\\", "/").replace('"', "'")
        low, high = f"(long)({d}).bounds[{2 * k}]", f"(long)({d}).bounds[{2 * k + 1}]"
        i = f"__pacst_index({value}, {low}, {high}, \"{where}\")"
        flat = i if flat is None else f"({flat}) * ({high} - {low} + 1L) + {i}"
    return Ref(f"({d}).table[{flat}]", False, t.elem, r.var, "", r.writable, r.why_not, True)


def bound(ex, node, fn):
    """LOWER_BOUND(a, n) / UPPER_BOUND(a, n): a DINT, of an ARRAY [*] from its caller's array, of a fixed array its
    declared bound (as CODESYS from compiler 3.5.14 and TwinCAT take it); n an integer literal."""
    ex.comp.dialect(node, fn)
    arr, dim = ex._positional(node, 2, ["ARR", "DIM"])
    r = ex.body.ref(arr) if ex.body is not None else None
    if r is None or not (r.type.is_array or r.type.kind == "vla"):
        raise ex.err(arr, f"{fn} takes an array, not {r.type.name if r is not None else 'a value'}")
    dims = r.type.dims if r.type.kind == "vla" else _dims(r.type)
    te = ex.expr(dim, T.DINT)
    if te.type is not T.ANY_INT or not 1 <= te.value <= dims:
        raise ex.err(dim, f"{fn}'s dimension is an integer literal, 1 to {dims} for {r.type.name}")
    upper = fn == "UPPER_BOUND"
    if r.type.kind == "vla":
        return TE(T.DINT, f"(({r.read()}).bounds[{2 * (te.value - 1) + upper}])")
    low, high = _shape(r.type, te.value)[0][-1]
    return TE(T.DINT, f"((DINT){high if upper else low})")


def size_c(r):
    """SIZEOF of the ARRAY [*] `r`: the bytes of the caller's array, its elements' count times an element's size."""
    d = r.read()
    count = " * ".join(f"(UDINT)(({d}).bounds[{2 * k + 1}] - ({d}).bounds[{2 * k}] + 1)" for k in range(r.type.dims))
    return f"((UDINT)({count} * (UDINT)sizeof({r.type.elem.cname})))"


def _dims(t):
    n = 0
    while t.is_array:
        n, t = n + 1, t.elem
    return n
