"""User mode: SIZEOF of a type in a constant expression (`ARRAY [0..N * SIZEOF(ST_Message) - 1] OF BYTE`, TcUnit's
FB_AdsLogStringMessageFifoQueue), in bytes as the C compiler lays out the type pacst writes for it on the test
host (LP64: a long and a pointer are 8 bytes). SIZEOF in code is C's `sizeof`; a bound is needed before any C
exists, so it is computed here from the same rules, and the C file of the POU states it again as a static
assertion (`sizes_c`), so a rule here that drifted from the compiler's fails the build, not a test."""
from . import types as T

# pacst_iec.h's C types: (bytes, alignment). TIME (and LTIME) is two longs; a STRING a length byte and 255 more; a
# WSTRING a length word and 255 more.
_C_TYPES = {"BOOL": (1, 1), "SINT": (1, 1), "USINT": (1, 1), "BYTE": (1, 1), "INT": (2, 2), "UINT": (2, 2),
            "WORD": (2, 2), "DINT": (4, 4), "UDINT": (4, 4), "DWORD": (4, 4), "REAL": (4, 4), "LINT": (8, 8),
            "ULINT": (8, 8), "LWORD": (8, 8), "LREAL": (8, 8), "TIME": (16, 8), "STRING": (256, 1),
            "WSTRING": (512, 2)}
_INT_RANGE = (-(1 << 31), (1 << 31) - 1)  # a C enum's values in an int: then the enum is an int


def size_align(t):
    """(bytes, alignment) of the C type pacst writes for `t`, or None for a type whose layout is not computed here
    (a function block instance, an ARRAY [*])."""
    if t.is_pointer:
        return 8, 8
    if t.kind == "interface":  # the instance's address and its table's
        return 16, 8
    if t.is_enum:
        return (4, 4) if all(_INT_RANGE[0] <= n <= _INT_RANGE[1] for n in t.numbers) else None
    if t.is_array:
        elem = size_align(t.elem)
        return None if elem is None else (elem[0] * (t.high - t.low + 1), elem[1])
    if t.is_struct:
        return _struct(t)
    if t.is_fb:
        return None
    if t.kind == "longstring":  # n units and the NUL
        return (t.length + 1) * (2 if t.wide else 1), 2 if t.wide else 1
    return _C_TYPES.get(t.cname)


def _struct(t):
    """A STRUCT's members in order, each at the next offset its alignment allows, the whole rounded up to the
    largest alignment; a UNION's at offset 0, as large as the largest rounded up the same way."""
    offset, largest, union = 0, 1, getattr(t, "union", False)
    for m in t.members:
        member = size_align(m.type)
        if member is None:
            return None
        size, align = member
        largest = max(largest, align)
        if union:
            offset = max(offset, size)
        else:
            offset = (offset + align - 1) // align * align + size
    return (offset + largest - 1) // largest * largest, largest


def sizes_c(checks):
    """The C lines that assert each (C type name, bytes) of `checks`, SIZEOF computed in a constant expression."""
    return [f'_Static_assert(sizeof({cname}) == {size}, "pacst: SIZEOF({name}) in a constant expression");'
            for name, cname, size in sorted(checks)]
