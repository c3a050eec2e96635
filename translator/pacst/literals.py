"""Values of ST literals, exact, and their C spelling."""
from decimal import Decimal
from fractions import Fraction

from .errors import StError

_NS = {"days": 86400 * 10**9, "hours": 3600 * 10**9, "minutes": 60 * 10**9, "seconds": 10**9,
       "milliseconds": 10**6, "microseconds": 10**3, "nanoseconds": 1}  # the last two: LTIME literals


def int_value(node):
    """The integer a blark integer or bit-string literal stands for."""
    cls = type(node).__name__
    text = str(node.value).replace("_", "")
    if "#" in text:  # blark keeps the base prefix in some typed forms
        text = text.split("#")[-1]
    base = 10
    if cls in ("HexInteger", "HexBitString"):
        base = 16
    elif cls in ("BinaryInteger", "BinaryBitString"):
        base = 2
    elif cls in ("OctalInteger", "OctalBitString"):
        base = 8
    return int(text, base)


def real_value(node):
    return Fraction(Decimal(str(node.value).replace("_", "")))


def duration_ns(node, file, line, col):
    total = Fraction(0)
    for field, scale in _NS.items():
        part = getattr(node, field, None)
        if part is not None:
            total += Fraction(Decimal(str(part).replace("_", ""))) * scale
    if total.denominator != 1:
        raise StError(file, line, col, "TIME literal finer than a nanosecond")
    ns = int(total)
    return -ns if getattr(node, "negative", False) else ns


def time_c(ns):
    sign = -1 if ns < 0 else 1
    sec, nsec = divmod(abs(ns), 10**9)
    return f"__time_make({sign * sec}L, {sign * nsec}L)"


def _float32(value):
    """`value` (a Fraction) rounded to the nearest IEEE-754 single, ties to even, as a Fraction; None on overflow."""
    if value == 0:
        return Fraction(0)
    sign = -1 if value < 0 else 1
    mag = abs(value)
    exp = mag.numerator.bit_length() - mag.denominator.bit_length()
    if Fraction(2) ** exp > mag:
        exp -= 1
    while Fraction(2) ** (exp + 1) <= mag:
        exp += 1
    exp = max(exp, -126)  # subnormals share the smallest exponent
    quantum = Fraction(2) ** (exp - 23)
    q, r = divmod(mag, quantum)
    q = int(q)
    if r * 2 > quantum or (r * 2 == quantum and q % 2 == 1):
        q += 1
    result = q * quantum
    if result >= Fraction(2) ** 128:
        return None
    return sign * result


def real_c(value, ctype):
    """C spelling of `value` as REAL or LREAL, bit-exact (hexadecimal floating constant)."""
    if ctype == "REAL":
        rounded = _float32(value)
        if rounded is None:
            return None
        return f"((REAL){float(rounded).hex()})"
    as_double = float(value)
    if as_double in (float("inf"), float("-inf")):
        return None
    return f"((LREAL){as_double.hex()})"
