"""Types and translates expressions: literals, operators, conversions and calls of functions."""
import dataclasses
import datetime
import decimal
import re

from . import literals, system
from . import types as T
from . import user, varlen
from .common import TE, Ref, _cls, _name, first_output, first_output_cfunc, first_output_returnable, pos
from .names import STANDARD_FUNCTIONS

_CONVERTIBLE = {"BOOL", "SINT", "INT", "DINT", "USINT", "UINT", "UDINT", "BYTE", "WORD", "DWORD", "REAL", "LREAL"}
_CONVERTIBLE_64 = {"LINT", "ULINT", "LWORD"}  # and their conversions in user programs
# The standard string functions of user programs and their IEC input names.
_STRING_FUNCTIONS = {"LEN": ["IN"], "CONCAT": ["IN1", "IN2"], "LEFT": ["IN", "L"], "RIGHT": ["IN", "L"],
                     "MID": ["IN", "L", "P"], "FIND": ["IN1", "IN2"], "INSERT": ["IN1", "IN2", "P"],
                     "DELETE": ["IN", "L", "P"], "REPLACE": ["IN1", "IN2", "L", "P"]}
# Their input names in TwinCAT's Tc2_Standard and CODESYS's Standard, accepted too.
_STRING_PINS = {"LEN": ["STR"], "CONCAT": ["STR1", "STR2"], "LEFT": ["STR", "SIZE"], "RIGHT": ["STR", "SIZE"],
                "MID": ["STR", "LEN", "POS"], "FIND": ["STR1", "STR2"], "INSERT": ["STR1", "STR2", "POS"],
                "DELETE": ["STR", "LEN", "POS"], "REPLACE": ["STR1", "STR2", "L", "P"]}
# The numeric standard functions of user programs and their C functions (the float ones take an f).
_MATH = {"SQRT": "sqrt", "LN": "log", "LOG": "log10", "EXP": "exp", "SIN": "sin", "COS": "cos", "TAN": "tan",
         "ASIN": "asin", "ACOS": "acos", "ATAN": "atan", "EXPT": "pow", "TRUNC": "", "TRUNC_INT": "", "MOVE": ""}
# Pointers and memory (user mode): TwinCAT's operators and Tc2_System's functions, CODESYS's the same.
_MEMORY = {"ADR", "SIZEOF", "MEMCPY", "MEMMOVE", "MEMSET", "MEMCMP", "__ISVALIDREF", "PACST_MEMORY_AREA"}
# Functions a user program may call as a statement, its result unused.
STATEMENT_FUNCTIONS = {"MEMCPY", "MEMMOVE", "MEMSET"}
# What to write instead of a standard function pacst does not translate (docs/user_dialect.md).
_INSTEAD = {"MUX": ": write a CASE", **{fn: f": write the operator (A {op} B)" for fn, op in (
    ("ADD", "+"), ("SUB", "-"), ("MUL", "*"), ("DIV", "/"), ("GT", ">"), ("GE", ">="),
    ("EQ", "="), ("LE", "<="), ("LT", "<"), ("NE", "<>"))}}
_CMP_C = {"=": "==", "<>": "!=", "<": "<", ">": ">", "<=": "<=", ">=": ">="}


def array_name_hint(actual, target):
    """What to write when an array is given where an array type of the same bounds is expected."""
    if actual.is_array and target.is_array and (actual.low, actual.high, actual.elem) == \
            (target.low, target.high, target.elem):
        return f" (declare it as {target.name}: an array type is matched by its name, not by its bounds)"
    return ""


def _converted(st, dt, code):
    """`code` of the elementary type `st` converted to `dt`: REAL to integers rounded half to even."""
    if dt.is_bool:
        return TE(dt, f"(({code}) != 0)")
    if st.is_real and not dt.is_real:
        helper = "__real_to_i64" if dt.is_int and dt.is_signed else "__real_to_u64"
        return TE(dt, f"(({dt.cname}){helper}({code}))")
    return TE(dt, f"(({dt.cname})({code}))")


def widens(source, target):
    """Whether a user program converts `source` to `target` implicitly (TwinCAT and CODESYS do, without a
    warning): to a wider integer that holds every value (INT to DINT, USINT to INT), to a wider bit string,
    an unsigned integer to a bit string as wide or wider (UINT to WORD), a bit string to an integer that holds its
    values (BYTE to DINT, WORD to UDINT), any integer to REAL or LREAL, REAL
    to LREAL, an enumeration to an integer or a bit string (its number; TwinCAT's types without {attribute
    'strict'})."""
    if source.is_enum and (target.is_int or target.is_bit):  # its base type's (INT without one); a bit string as
        base = getattr(source, "base", None)  # wide as that base (FB_ValueChangeDetector's TypeClass to a DWORD)
        if base is not None and base.is_int:
            return base is target or widens(base, target) or target.is_bit and target.bits >= base.bits
        return target.bits >= 16
    if not (source.is_elementary and target.is_elementary) or source is target:
        return False
    if source.is_int and target.is_int:
        if source.is_signed and not target.is_signed:
            return False
        return target.bits > source.bits or (target.bits == source.bits and source.is_signed == target.is_signed)
    if source.is_bit and target.is_bit:
        return target.bits >= source.bits
    if source.is_int and target.is_bit:
        return not source.is_signed and target.bits >= source.bits
    if source.is_bit and target.is_int:  # TwinCAT takes an assignment whose source range lies within the target's
        return target.bits > source.bits if target.is_signed else target.bits >= source.bits
    if source.is_int and target.is_real:
        return True
    if source.is_time and target.is_time:  # TIME to LTIME
        return target is T.LTIME
    return source.is_real and target.is_real and target.bits > source.bits


def changes_sign(source, target):
    """Whether a user program converts `source` to `target` implicitly with a warning only (TwinCAT's and CODESYS's
    C0195, C0196: a possible change of sign): integers and bit strings of the same width or a wider target that
    differ in sign (DINT to UDINT, UDINT to DINT, BYTE to USINT, DWORD to DINT), two's complement as C casts."""
    if not (source.is_elementary and target.is_elementary) or source is target:
        return False
    if not ((source.is_int or source.is_bit) and (target.is_int or target.is_bit)):
        return False
    return target.bits >= source.bits and not widens(source, target)


def narrows(source, target):
    """Whether a user program converts `source` to `target` implicitly with a warning only (CODESYS's and TwinCAT's
    C0197, a possible loss of information): an integer or bit string to a narrower one (DINT to INT, UDINT to USINT,
    DWORD to BYTE), the bits that fit kept, as <INT type>_TO_<INT type> keeps them (two's complement, as C casts)."""
    if not (source.is_elementary and target.is_elementary):
        return False
    if not ((source.is_int or source.is_bit) and (target.is_int or target.is_bit)):
        return False
    return target.bits < source.bits


def long_string_code(te, target):
    """User mode: the C of `te` as `target` where one of them is a STRING(n) or WSTRING(n) over 255 (LongStringType),
    as TwinCAT assigns strings of other lengths: cut to the target's n (a STRING's 255), the rest kept; None where
    they are no such pair (a STRING and a WSTRING). A long value is read through an array of one, so that its
    units have an address whatever the expression (C99 gives a function's result none)."""
    src, dst = te.type, target
    if "longstring" not in (src.kind, dst.kind):
        return None
    if src.kind == "longstring":
        p = "__pacst_lwstr" if src.wide else "__pacst_lstr"
        units = f"(({src.cname}[1]){{{te.code}}})[0].body"
        if dst is src.short:
            return f"{p}_short({units}, {src.length})"
        if dst.kind == "longstring" and dst.wide == src.wide:
            return f"(*({dst.cname} *){p}_copy(({dst.cname}){{{{0}}}}.body, {dst.length}, {units}, {src.length}))"
        return None
    if src is dst.short:
        p = "__pacst_lwstr" if dst.wide else "__pacst_lstr"
        return f"(*({dst.cname} *){p}_of_short(({dst.cname}){{{{0}}}}.body, {dst.length}, {te.code}))"
    return None


def long_inout_hint(actual, expected):
    """What to write where a string of one length is given to a VAR_IN_OUT of another and one of them is over 255
    (user mode), else ""."""
    if "longstring" not in (actual.kind, expected.kind) or not (actual.is_string or expected.is_string
                                                                 or actual.kind == expected.kind):
        return ""
    return (f": a VAR_IN_OUT takes a variable of its own type; declare it {actual.name}, or VAR_IN_OUT CONSTANT "
            f"where it is only read (a string over {user.STRING_CAPACITY} is read there as its first "
            f"{user.STRING_CAPACITY} characters)")


def _long_string_pointer(ex, source, target, node):
    """Refuses a pointer to a STRING(n) over 255 given to a POINTER TO STRING (or the other way): pacst's STRING is
    a length and 255 bytes, the long one TwinCAT's n characters and a NUL, so the one read through the other's
    pointer would read other bytes."""
    kinds = (source.kind, target.kind)
    if "longstring" in kinds and source is not target and (source.is_string or target.is_string
                                                           or kinds == ("longstring", "longstring")):
        raise ex.err(node, f"a POINTER TO {source.name} given where a POINTER TO {target.name} is expected: pacst "
                           f"lays out a STRING(n) over {user.STRING_CAPACITY} as TwinCAT does, its n characters and a "
                           f"NUL, but a STRING of up to {user.STRING_CAPACITY} as a length and the characters; declare "
                           "the pointer as the variable's type")


def _ltime_converted(st, dt, code):
    """User mode: LTIME to and from a number of nanoseconds (LTIME_TO_ULINT, LREAL_TO_LTIME), as TwinCAT and
    CODESYS count it, unsigned; TIME_TO_LTIME exact, LTIME_TO_TIME to whole milliseconds, TIME's resolution."""
    if st.is_time and dt.is_time:
        return TE(dt, code if dt is T.LTIME else f"__time_from_ms(__time_to_ms({code}))")
    if st.is_time:
        return TE(dt, f"(__time_to_ns({code}) != 0u)" if dt.is_bool else f"(({dt.cname})__time_to_ns({code}))")
    ns = f"(uint64_t)__real_to_i64({code})" if st.is_real else f"(uint64_t)({code})"
    return TE(dt, f"__time_from_ns({ns})")


# user mode: `Buffer.Get(i).Dequeue()`, a METHOD called on a call's result (blark's ChainedFunctionCall)
CHAINED_CALL = ("a METHOD called on the result of a call (Buffer.Get(i).Dequeue()) is not translated: assign the "
                "result to a variable of its type first (Item := Buffer.Get(i); Item.Dequeue();)")


def refused_call(name):
    """The refusal of a call of the FUNCTION `name` whose declaration was refused: statement or expression alike."""
    return f"FUNCTION {name} cannot be called: its declaration was refused (above)"


class ExprCompiler:
    """Types and translates expressions inside one POU (or an initial value, with pou None)."""

    def __init__(self, comp, body):
        self.comp = comp
        self.body = body

    def err(self, node, message):
        return self.comp.err(node, message)

    # ------------------------------------------------------------------ coercion
    def coerce(self, te, target, node, what="value"):
        """C code of `te` as type `target`; ST has no implicit conversion, so types must match (user mode: the
        widening ones TwinCAT and CODESYS make, widens())."""
        if te.type is target:
            return te.code
        if self.comp.user and "longstring" in (te.type.kind, target.kind):
            code = long_string_code(te, target)
            if code is not None:
                return code
        if te.type is T.ANY_INT and target.is_pointer and te.value == 0:
            return "NULL"  # user mode: p := 0, p <> 0
        if te.type is T.ANY_INT and target.kind == "interface" and te.value == 0:
            return self.comp.default_c(target)  # user mode: itf := 0, itf <> 0
        if te.type.is_fb and target.kind == "interface" and self.comp.user:
            pou = te.type.pou
            if pou is None or target not in pou.interfaces:
                raise self.err(node, f"{te.type.name} does not IMPLEMENT {target.name}: add IMPLEMENTS {target.name} "
                                     "to its heading")
            return f"(({target.cname}){{(void *)({te.code}), &{target.vtable(pou.cname)}}})"
        if te.type.kind == "interface" and target.kind == "interface" and target in te.type.bases:
            # an INTERFACE's variable given to one of a base's type: the instance's table for the base
            return (f"(({target.cname}){{({te.code}).inst, ({te.code}).vt != NULL ? ({te.code}).vt->{target.cname}__BASE "
                    ": NULL})")
        if self.comp.user and system.same_struct(te.type, target):  # an ANY input to a __SYSTEM.AnyType
            return te.code
        if te.type.is_pointer and target.is_pointer and self.comp.user:
            _long_string_pointer(self, te.type.target, target.target, node)
            return f"(({target.cname})({te.code}))"  # ADR's result is any pointer, as TwinCAT's PVOID
        if te.type is T.ANY_INT:
            if target.is_int or target.is_bit:
                lo, hi = target.int_range()
                if not lo <= te.value <= hi:
                    raise self.err(node, f"{te.value} does not fit {target.name} ({lo}..{hi})")
                return f"(({target.cname}){te.value}{'ULL' if te.value > 0x7FFFFFFFFFFFFFFF else 'LL'})"
            if target.is_real and self.comp.user:
                self.comp.dialect(node, f"the integer literal {te.value} where {target.name} is expected")
                code = literals.real_c(te.value, target.cname)
                if code is None:
                    raise self.err(node, f"{te.value} does not fit {target.name}")
                return code
            if self.integer_to_enum(target, node, str(te.value)):
                return f"(({target.cname}){te.value})"
            if target.is_bool and self.comp.user and te.value in (0, 1):
                self.comp.dialect(node, f"the integer literal {te.value} where BOOL is expected")
                return "TRUE" if te.value else "FALSE"
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
        if (te.type.is_int or te.type.is_bit) and self.integer_to_enum(target, node, te.type.name):
            return f"(({target.cname})({te.code}))"
        if self.comp.user and widens(te.type, target):
            self.comp.dialect(node, f"the implicit conversion of {te.type.name} to {target.name}")
            return te.code if target.is_time else f"(({target.cname})({te.code}))"  # TIME to LTIME: one C type
        if self.comp.user and what != "operand" and changes_sign(te.type, target):  # not `D = UD`: TwinCAT
            # compares those at the register width
            self.comp.dialect(node, f"the implicit conversion of {te.type.name} to {target.name}")
            return f"(({target.cname})({te.code}))"
        if self.comp.user and what != "operand" and narrows(te.type, target):
            return self.narrowed(te, target, node)
        hint = ""
        named = _CONVERTIBLE | _CONVERTIBLE_64 if self.comp.user else _CONVERTIBLE
        convertible = te.type.name in named and target.name in named
        if te.type.is_string and target.is_string and self.comp.user:
            convertible = True
        if te.type.is_elementary and target.is_elementary and (convertible or te.type.is_time and target.is_time):
            hint = f" (write {te.type.name}_TO_{target.name})"
        elif target.is_enum and self.comp.user:
            hint = f" (assign a value of {target.name})"
        elif self.comp.user and "longstring" in (te.type.kind, target.kind) and \
                (te.type.is_string or target.is_string or te.type.kind == target.kind):
            hint = " (write STRING_TO_WSTRING or WSTRING_TO_STRING, which take and give 255 characters)"
        else:
            hint = array_name_hint(te.type, target)
        raise self.err(node, f"type mismatch: {te.type.name} where {target.name} is expected; ST has no "
                             f"implicit conversion{hint}")

    def narrowed(self, te, target, node):
        """User mode: the C of `te` cut to the narrower `target` (narrows()), with the vendors' warning; refused
        under --strict-narrowing, for a programmer who holds the program to explicit conversions."""
        source = te.type
        if self.comp.strict_narrowing:
            raise self.err(node, f"implicit narrowing of {source.name} to {target.name}, refused by "
                                 f"--strict-narrowing: write {source.name}_TO_{target.name}")
        self.comp.dialect(node, f"the implicit conversion of {source.name} to {target.name}")
        self.comp.warn(node, f"implicit conversion of {source.name} to {target.name}: a value outside "
                             f"{target.name} is cut to its {target.bits} bits, as TwinCAT and CODESYS cut it "
                             f"(their C0197); write {source.name}_TO_{target.name} to say so")
        return f"(({target.cname})({te.code}))"

    def _output_converted(self, ref, v, pou):
        """User mode: whether a FUNCTION's output `v` given to the variable of `ref`, of another integer or bit string
        type (`usiLength => udiLength`), is converted as TwinCAT and CODESYS convert an assignment (widened, or cut
        with their warning): through a temporary of the output's type, in a GCC statement expression."""
        if not self.comp.user or v.section != "output" or (pou.ret is not None and pou.ret.is_fb):
            return False
        numeric = [t.is_elementary and (t.is_int or t.is_bit) for t in (ref.type, v.type)]
        return all(numeric) and not ref.type.is_bool and not v.type.is_bool

    def integer_to_enum(self, target, node, what):
        """User mode: whether an integer may be assigned to the enumeration `target` (TwinCAT's and CODESYS's
        types without {attribute 'strict'}: the number kept as it is, a value of the type or not)."""
        if not self.comp.user or not target.is_enum or getattr(target, "strict", False):
            return False
        self.comp.dialect(node, f"{what} assigned to the enumeration {target.name}")
        return True

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
        """The common type of two operands and both their C codes (user mode: the wider of two types one of
        which widens to the other, as TwinCAT and CODESYS compute INT + DINT)."""
        if a.type.kind in ("anyint", "anyreal") and b.type.kind in ("anyint", "anyreal"):
            if a.type is not b.type and not self.comp.user:
                raise self.err(node, "integer and REAL literals mixed: write the integer as REAL (3.0)")
            if a.type is not b.type:  # user mode: 2 * 1.5
                a, b = [TE(T.ANY_REAL, value=x.value) for x in (a, b)]
            t = self.default_type(a, want)
        elif self.comp.user and T.ANY_REAL in (a.type, b.type) and (a.type.is_int or b.type.is_int):
            t = want if want is not None and want.is_real else T.LREAL  # user mode: Raw * 0.5 is a REAL
        elif a.type.kind in ("anyint", "anyreal"):
            t = b.type
        elif self.comp.user and b.type is not a.type and widens(a.type, b.type):
            t = b.type
        elif self.comp.user and a.type.is_int and b.type.is_int and a.type.is_signed != b.type.is_signed \
                and not widens(b.type, a.type):
            # DINT * UDINT (F_Malloc_Generic's SIZEOF(T_Generic) * Count): in the smallest signed type that holds
            # both, as TwinCAT computes at the register width; LINT with ULINT stays a mismatch
            t = next((w for w in (T.ELEMENTARY["INT"], T.DINT, T.USER_ELEMENTARY.get("LINT"))
                      if w is not None and widens(a.type, w) and widens(b.type, w)), a.type)
            if t is not a.type:
                self.comp.dialect(node, f"{a.type.name} and {b.type.name} in one operation")
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
            if cls in ("Date", "DateTime", "TimeOfDay", "Ldate", "LdateTime", "LtimeOfDay"):
                raise self.err(node, f"{cls} literals are outside the portable subset")
            raise self.err(node, f"{cls} is outside the portable subset")
        return method(node, want)

    def _e_ChainedFunctionCall(self, node, want):
        if not self.comp.user or self.body is None:
            raise self.err(node, CHAINED_CALL)
        return self._read(self.body.call_result(node), node)

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
        wide = text.startswith('"')
        if wide and not self.comp.user:
            raise self.err(node, "double-quoted WSTRING literals are outside the portable subset")
        if wide:
            self.comp.dialect(node, "a WSTRING literal")
        kind = "WSTRING" if wide else "STRING"
        body, out, i = text[1:-1], [], 0
        escapes = {"$": "$", text[0]: text[0], "N": "\n", "L": "\n", "R": "\r", "T": "\t", "P": "\f"}
        digits = 4 if wide else 2  # $0041 in a WSTRING, $41 in a STRING
        while i < len(body):
            c = body[i]
            if c == "$":
                nxt = body[i + 1:i + 2].upper()
                if nxt in escapes:
                    out.append(escapes[nxt])
                    i += 2
                    continue
                if re.fullmatch(f"[0-9A-Fa-f]{{{digits}}}", body[i + 1:i + 1 + digits]):
                    out.append(chr(int(body[i + 1:i + 1 + digits], 16)))
                    i += 1 + digits
                    continue
                raise self.err(node, f"unknown escape '${body[i + 1:i + 2]}' in a {kind} literal")
            out.append(c)
            i += 1
        value = "".join(out)
        if wide and any(ord(ch) > 0xFFFF or 0xD800 <= ord(ch) <= 0xDFFF for ch in value):
            bad = next(ch for ch in value if ord(ch) > 0xFFFF or 0xD800 <= ord(ch) <= 0xDFFF)
            raise self.err(node, f"the character U+{ord(bad):04X} in a WSTRING literal: a WSTRING holds UCS-2, the "
                                 "characters U+0000 to U+FFFF but the surrogates, as in TwinCAT and CODESYS; write "
                                 "the text without it")
        if self.comp.user and len(value) > user.STRING_CAPACITY:
            raise self.err(node, f"STRING literal of {len(value)} characters: a STRING holds at most "
                                 f"{user.STRING_CAPACITY}")
        if self.comp.user and len(value) > user.MATIEC_STRING_CAPACITY:
            self.comp.dialect(node, f"a STRING literal of {len(value)} characters (MATIEC's STRING holds "
                                    f"{user.MATIEC_STRING_CAPACITY})")
        if not self.comp.user and len(value) > T.STRING_LITERAL_MAX:
            raise self.err(node, f"STRING literal of {len(value)} characters: at most {T.STRING_LITERAL_MAX}, "
                                 "the default STRING length of CODESYS and TwinCAT")
        if wide:  # its UCS-2 code units, one a character
            units = ", ".join(f"0x{ord(ch):04X}" for ch in value) or "0"
            return TE(T.WSTRING, f"__pacst_wstring((const uint16_t[]){{{units}}}, {len(value)})")
        c_text = "".join(ch if 32 <= ord(ch) < 127 and ch not in '"\\?' else f"\\{ord(ch):03o}" for ch in value)
        return TE(T.STRING, f'__pacst_string("{c_text}", {len(value)})')

    def _e_Date(self, node, want):
        """User mode: D#2000-01-01, seconds since 1970-01-01 at its midnight, as TwinCAT keeps a DATE."""
        return self._date_literal(node, T.DATE, node, None)

    def _e_DateTime(self, node, want):
        """User mode: DT#2000-01-01-12:30:15, seconds since 1970-01-01-00:00:00."""
        return self._date_literal(node, T.DT, node.date, node.time)

    def _e_TimeOfDay(self, node, want):
        """User mode: TOD#12:30:15.250, milliseconds since midnight."""
        return self._date_literal(node, T.TOD, None, node)

    def _date_literal(self, node, t, day, clock):
        if not self.comp.user:
            raise self.err(node, f"{_cls(node)} literals are outside the portable subset")
        self.comp.dialect(node, f"a {t.name} literal")
        value = 0
        if day is not None:
            try:
                value = (datetime.date(int(day.year), int(day.month), int(day.day or 1)) -
                         datetime.date(1970, 1, 1)).days * 86400
            except ValueError:
                raise self.err(node, f"{node} is no date") from None
        if clock is not None:
            second = decimal.Decimal(str(clock.second or 0))
            hour, minute = int(clock.hour), int(clock.minute)
            if not (0 <= hour < 24 and 0 <= minute < 60 and 0 <= second < 60):
                raise self.err(node, f"{node} is no time of day")
            ms = (hour * 3600 + minute * 60) * 1000 + int(second * 1000)
            value = value + ms // 1000 if day is not None else ms
        if not 0 <= value <= 0xFFFFFFFF:
            raise self.err(node, f"{node}: a {t.name} holds D#1970-01-01 to DT#2106-02-07-06:28:15, 32 bits as in "
                                 "TwinCAT")
        return TE(t, f"((UDINT){value}U)")

    def _e_Duration(self, node, want):
        line, col = pos(node)
        return TE(T.TIME, literals.time_c(literals.duration_ns(node, self.comp.file, line, col)))

    def _e_Lduration(self, node, want):
        """User mode: LTIME#1S2US44NS, exact to the nanosecond."""
        if not self.comp.user:
            raise self.err(node, "Lduration literals are outside the portable subset")
        line, col = pos(node)
        ns = literals.duration_ns(node, self.comp.file, line, col)
        if not 0 <= ns < 2**64:
            raise self.err(node, "an LTIME holds 0 to LTIME#213503D23H34M33S709MS551US615NS")
        return TE(T.LTIME, literals.time_c(ns))

    def _e_ParenthesizedExpression(self, node, want):
        inner = self.expr(node.expr, want)
        if inner.code is None:
            return inner
        return TE(inner.type, f"({inner.code})", narrow=inner.narrow, wide=inner.wide)

    def _e_BracketedExpression(self, node, want):
        raise self.err(node, "bracketed expression is outside the portable subset")

    def _e_SimpleVariable(self, node, want):
        return self._value_of(node)

    def _e_MultiElementVariable(self, node, want):
        return self._value_of(node)

    def _value_of(self, node):
        if self.comp.user and _cls(node) == "SimpleVariable" and node.dereferenced \
                and _name(node.name).upper() == "THIS" and (self.body is None or self.body.lookup("THIS") is None):
            return self._this_instance(node)
        if self.comp.user and _cls(node) == "SimpleVariable" and not node.dereferenced \
                and _name(node.name).upper() == "THIS" and (self.body is None or self.body.lookup("THIS") is None):
            this = self._this_instance(node)  # THIS alone: the instance's address, a POINTER TO its FB
            return TE(self.comp.pointer_to(this.type), f"(({self.comp.pointer_to(this.type).cname})data__)")
        node = self.comp.unqualify(node, self.body.lookup if self.body is not None else None)
        known = system.enum_value(self.comp, node) if self.comp.user and (
            self.body is None or self.body.lookup(_name(getattr(node.name, "name", node.name))) is None) else None
        if known is not None:  # __SYSTEM.TYPE_CLASS.TYPE_INT
            return TE(known[0], known[0].cvalue(known[1]))
        name = _name(node.name) if _cls(node) == "SimpleVariable" else None
        if name is not None and (self.body is None or self.body.lookup(name) is None) \
                and name.upper() in self.comp.enum_values and not (
                    getattr(self.comp.enum_values[name.upper()], "qualified_only", False)
                    and self.comp.globals.get(name.upper())):  # a global's name, a qualified_only value's too
            et = self.comp.enum_values[name.upper()]
            self.comp.bare_enum_value(et, name, node)
            value = next(v for v in et.values if v.upper() == name.upper())
            return TE(et, et.cvalue(value))
        qualified = None
        if _cls(node) == "MultiElementVariable" and (self.body is None or self.body.lookup(_name(node.name.name)) is None):
            qualified = self.comp.qualified_enum_value(node)  # a variable of the type's name shadows it
        if qualified is not None:
            et, value = qualified
            return TE(et, et.cvalue(value))
        if name is not None and (self.body is None or self.body.lookup(name) is None):
            self.comp.shared_enum_value(name, node)
        if self.body is None:
            raise self.err(node, "initial value must be a literal")
        prop = self.body.property_target(node)
        if prop is not None:  # user mode: Axis.Velocity calls its Get
            this, p = prop
            if p["get"] is None:
                raise self.err(node, f"PROPERTY {p['name']} has no Get: it is write only (declare its Get to read it)")
            return TE(p["type"], f"{p['get'].cfunc}({this}, TRUE, NULL)")
        return self._read(self.body.ref(node), node)

    def _read(self, ref, node):
        """The value of the variable `ref` (an FB instance's address in user mode)."""
        if ref.type.is_fb and self.comp.user:  # its address: an INTERFACE variable may take it (coerce)
            return TE(ref.type, f"&({ref.read()})")
        if ref.type.is_fb:
            raise self.err(node, f"function block instance '{ref.var.name}' used as a value")
        return TE(ref.type, ref.read())

    def _this_instance(self, node):
        """User mode: `THIS^` alone, the instance of the FUNCTION_BLOCK whose body or METHOD this is (its address, as
        an instance's value is here): given to an INTERFACE it implements (`Get := THIS^;` in a METHOD returning
        one, as TwinCAT_DynCollections' FB_Immutable_List returns itself)."""
        fb = self.body._fb_of_body() if self.body is not None else None
        if fb is None or getattr(fb, "fbtype", None) is None:
            raise self.err(node, "THIS^ is used inside a FUNCTION_BLOCK, its METHODs and ACTIONs")
        self.comp.dialect(node, "THIS^")
        return TE(fb.fbtype, "data__")

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
            if t.is_int and self.comp.user:  # bit by bit, as TwinCAT and CODESYS take it
                self.comp.dialect(node, f"NOT on {t.name}")
            if t.is_bit or t.is_int and self.comp.user:
                return TE(t, f"(({t.cname})~{inner.code})", narrow=t.bits < 32)
            raise self.err(node, f"NOT on {t.name}: only BOOL, BYTE, WORD and DWORD")
        if op == "+":
            return inner
        raise self.err(node, f"unary operator {op} is outside the portable subset")

    def _e_BinaryOperation(self, node, want):
        op = str(node.op).upper()
        if op in ("AND_THEN", "OR_ELSE") and self.comp.user:  # the right operand only when it decides
            self.comp.dialect(node.op, op)
            sides = []
            for side in (node.left, node.right):
                te = self.expr(side, T.BOOL)
                if not te.type.is_bool:
                    raise self.err(side, f"{op} takes BOOL operands, not {te.type.name}: write "
                                         f"{'AND' if op == 'AND_THEN' else 'OR'} on bit strings")
                sides.append(te.code)
            return TE(T.BOOL, f"({sides[0]} {'&&' if op == 'AND_THEN' else '||'} {sides[1]})")
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
        if self.comp.user and op in ("+", "-") and a.type.is_pointer and b.type.is_bit:
            # CODESYS adds a bit string's number of bytes as an integer's (`p + LINT_TO___XWORD(k)`, `p + DWORD#1`)
            self.comp.dialect(node.op, f"a POINTER {op} a {b.type.name}, its number of bytes")
        if self.comp.user and op in ("+", "-") and a.type.is_pointer and (
                b.type is T.ANY_INT or b.type.is_int or b.type.is_bit):
            n = b.code if b.code is not None else f"{b.value}LL"
            return TE(a.type, f"(({a.type.cname})((char *)({a.code}) {op} ({n})))")  # bytes, as TwinCAT counts
        if self.comp.user and op in ("*", "/") and (a.type.is_time or b.type.is_time) \
                and not (a.type.is_time and b.type.is_time) and (op == "*" or a.type.is_time):
            return self._time_scale(node, op, a, b)
        if self.comp.user and (a.type.is_date or b.type.is_date):
            return self._date_arithmetic(node, op, a, b)
        # The operator's own rules come before the operands' types must agree (W + I is refused for the
        # WORD, T * N for the TIME), and are reported at the operator.
        for te in (a, b):
            if te.type.is_time and op not in ("+", "-"):
                raise self.err(node.op, f"TIME {op}: TIME only adds and subtracts (MATIEC overflows otherwise)")
            if te.type.is_bit and self.comp.user:  # TwinCAT and CODESYS compute them as unsigned integers
                self.comp.dialect(node.op, f"arithmetic on {te.type.name}")
            elif te.type.is_bit:
                raise self.err(node.op, f"arithmetic on {te.type.name}: bit strings have no arithmetic; convert "
                                        "to an integer type first")
        t, ca, cb = self.unify(a, b, want, node)
        if t.is_bit and self.comp.user:  # unsigned, wrapping at the width (no C promotion to a signed int)
            if op in ("/", "MOD"):
                return TE(t, f"__{'div' if op == '/' else 'mod'}_{t.cname}({ca}, {cb})")
            return TE(t, f"(({t.cname})((uint64_t)({ca}) {op} (uint64_t)({cb})))", narrow=t.bits < 32,
                      wide=self._wide(a, ca, op, b, cb) if t.bits < 32 else None)
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
        return TE(t, f"(({t.cname})({ca} {op} {cb}))", narrow=t.bits < 32,
                  wide=self._wide(a, ca, op, b, cb) if t.bits < 32 and self.comp.user else None)

    @staticmethod
    def _wide(a, ca, op, b, cb):
        """User mode: `a op b` (+ - *) of types narrower than 32 bits computed in 64 bits and not wrapped, as
        TwinCAT and CODESYS compute intermediate results at the register width (x64)."""
        return f"((int64_t)({a.wide or ca}) {op} (int64_t)({b.wide or cb}))"

    def _date_arithmetic(self, node, op, a, b):
        """User mode: DT, TOD + or - a TIME (DT whole seconds of it), DT - DT, TOD - TOD and DATE - DATE a TIME,
        as IEC 61131-3 and TwinCAT define them; 32 bits wrapping as TwinCAT's."""
        t = a.type
        if op == "-" and b.type is t:
            scale = "" if t is T.TOD else " * 1000"
            self.comp.dialect(node.op, f"{t.name} - {t.name}")
            return TE(T.TIME, f"__time_from_ms(((int64_t)({a.code}) - (int64_t)({b.code})){scale})")
        if op in ("+", "-") and t in (T.DT, T.TOD) and b.type is T.TIME:
            self.comp.dialect(node.op, f"{t.name} {op} TIME")
            amount = f"__time_to_ms({b.code})" if t is T.TOD else f"(__time_to_ms({b.code}) / 1000)"
            return TE(t, f"((UDINT)((int64_t)({a.code}) {op} {amount}))")
        raise self.err(node.op, f"{a.type.name} {op} {b.type.name}: of DATE, TIME_OF_DAY and DATE_AND_TIME, a DT or "
                                "TOD adds and subtracts a TIME, and two of one type subtract to a TIME; convert to "
                                "a number for anything else")

    def _time_scale(self, node, op, a, b):
        """User mode: TIME * number, number * TIME, TIME / number, rounded toward zero to the nanosecond."""
        t, n = (a, b) if a.type.is_time else (b, a)
        if n.type.kind in ("anyint", "anyreal"):
            if op == "/" and n.value == 0:
                raise self.err(node, "TIME divided by zero")
            factor = f"{float(n.value)!r}"
        elif n.type.is_int or n.type.is_real:
            factor = f"(double)({n.code})"
        else:
            raise self.err(node.op, f"TIME {op} {n.type.name}: a TIME is scaled by a number")
        self.comp.dialect(node.op, f"TIME {op} a number")
        if op == "/":
            return TE(t.type, f"(({factor}) == 0.0 ? __time_make(0L, 0L) : __time_scale({t.code}, 1.0 / ({factor})))")
        return TE(t.type, f"__time_scale({t.code}, {factor})")

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
        wide = self._wide_compare(node, op, a, b)
        if wide is not None:
            return wide
        for side, te in ((node.left, a), (node.right, b)):
            if te.narrow and self.comp.user:
                raise self.err(side, f"comparison of the {te.type.name} result of arithmetic, a negation, NOT or "
                                     "a shift: TwinCAT and CODESYS compare it unwrapped at the register width, "
                                     "pacst does so for + - * compared with a REAL or an integer of up to 32 bits; "
                                     "store it in a variable first")
            if te.narrow:
                raise self.err(side, f"comparison of the {te.type.name} result of arithmetic, NOT or a shift: "
                                     "MATIEC compares it as a promoted C int; store it in a variable first")
        a, b = self._enum_as_number(node, a, b), self._enum_as_number(node, b, a)
        if self.comp.user and "longstring" in (a.type.kind, b.type.kind):
            return self._long_compare(node, op, a, b)
        t, ca, cb = self.unify(a, b, None, node)
        if t.is_array or t.is_struct or t.is_fb:
            raise self.err(node.op, f"{t.name} values cannot be compared")
        if t.is_pointer and op not in ("=", "<>"):
            raise self.err(node.op, f"{op} on pointers: only = and <>")
        if t.kind == "interface":  # user mode: the same instance, or none (itf = 0)
            if op not in ("=", "<>"):
                raise self.err(node.op, f"{op} on INTERFACE variables: only = and <>")
            return TE(T.BOOL, f"(({ca}).inst {_CMP_C[op]} ({cb}).inst)")
        if op not in ("=", "<>") and t.is_enum and self.comp.user:
            self.comp.dialect(node.op, f"{op} on enumeration values")  # TwinCAT and CODESYS compare the numbers
        elif op not in ("=", "<>") and (t.is_bool or t.is_enum):
            raise self.err(node.op, f"{op} on {t.name}: only = and <> compare BOOL and enumeration values")
        if t.is_string and op not in ("=", "<>") and self.comp.user:  # as TwinCAT's GT, GE, LT and LE take them
            self.comp.dialect(node.op, f"{op} on {t.name}")
            cmp = "__pacst_wstring_cmp" if t is T.WSTRING else "__pacst_string_cmp"
            return TE(T.BOOL, f"({cmp}({ca}, {cb}) {_CMP_C[op]} 0)")
        if t.is_string:
            if op not in ("=", "<>"):
                raise self.err(node.op, f"{op} on {t.name}: only = and <> compare strings here: compare their "
                                        f"characters (s[i], a {'WORD' if t is T.WSTRING else 'BYTE'}) in a FOR loop")
            eq = "__pacst_wstring_eq" if t is T.WSTRING else "__pacst_string_eq"
            return TE(T.BOOL, f"({'' if op == '=' else '!'}{eq}({ca}, {cb}))")
        if t.is_time:
            return TE(T.BOOL, f"(__time_cmp({ca}, {cb}) {_CMP_C[op]} 0)")
        return TE(T.BOOL, f"({ca} {_CMP_C[op]} {cb})")

    def _long_compare(self, node, op, a, b):
        """User mode: a comparison with a STRING(n) or WSTRING(n) over 255: the whole texts compared, to its NUL;
        < > <= >= ordered as shorter strings are (__PACST_UNITS_CMP)."""
        other_side, swapped = node.right, a.type.kind != "longstring"
        if swapped:
            a, b, other_side = b, a, node.left
        t = a.type
        p = "__pacst_lwstr" if t.wide else "__pacst_lstr"
        units = f"(({t.cname}[1]){{{a.code}}})[0].body"
        how = "eq" if op in ("=", "<>") else "cmp"
        if b.type.kind == "longstring" and b.type.wide == t.wide:
            other = f"(({b.type.cname}[1]){{{b.code}}})[0].body"
            code = f"{p}_{how}({units}, {t.length}, {other}, {b.type.length})"
        else:
            code = f"{p}_{how}_short({units}, {t.length}, {self.coerce(b, t.short, other_side, 'operand')})"
        if how == "eq":
            return TE(T.BOOL, f"({'' if op == '=' else '!'}{code})")
        self.comp.dialect(node.op, f"{op} on {t.name}")
        order = f"({code})" if not swapped else f"(-({code}))"  # the text over 255 was the right operand
        return TE(T.BOOL, f"({order} {_CMP_C[op]} 0)")

    def _enum_as_number(self, node, te, other):
        """User mode: `te`, an enumeration value compared with an integer or bit string that cannot hold all its values
        (`UDINT_TO_INT(Class) = IBaseLibrary.TypeClass.TYPE_STRING`, TcUnit's FB_TestSuite), as its number in its base
        type, so that both are compared as numbers in a type that holds both, as TwinCAT compares them for a type
        without {attribute 'strict'}; `te` unchanged otherwise."""
        o = other.type
        if not (self.comp.user and te.type.is_enum and not getattr(te.type, "strict", False)
                and (o.is_int or o.is_bit) and not widens(te.type, o)):
            return te
        base = te.type.base if getattr(te.type, "base", None) is not None and te.type.base.is_int else T.INT
        self.comp.dialect(node, f"an enumeration value of {te.type.name} compared with {o.name}")
        return TE(base, f"(({base.cname})({te.code}))")

    def _wide_compare(self, node, op, a, b):
        """User mode: a comparison of the result of + - * on types narrower than 32 bits, unwrapped in 64 bits
        (`(w + 1) = 0` is FALSE for w = 65535, as on TwinCAT x64), or None for any other comparison."""
        if not self.comp.user or not (a.wide or b.wide):
            return None
        if any(te.narrow and not te.wide for te in (a, b)):
            return None  # a negation, NOT or shift on one side: refused by the caller
        t, ca, cb = self.unify(a, b, None, node)
        if t.is_real:  # (i + 1) > 2.5
            c = "LREAL"
        elif (t.is_int or t.is_bit) and t.bits <= 32:
            c = "int64_t"
        else:
            return None
        self.comp.dialect(node.op, "a comparison of small-type arithmetic at the register width")
        return TE(T.BOOL, f"(({c})({a.wide or ca}) {_CMP_C[op]} ({c})({b.wide or cb}))")

    def _logic(self, node, op, want):
        a = self.expr(node.left, want)
        b = self.expr(node.right, want)
        if a.type is T.ANY_INT and b.type is T.ANY_INT and (want is None or not want.is_bit):
            raise self.err(node.op, f"{op} of two integer literals: give one a type (WORD#16#FF)")
        for te in (a, b):  # INT AND BOOL is refused for the INT, at the operator
            if te.type is not T.ANY_INT and not (te.type.is_bool or te.type.is_bit
                                                 or self.comp.user and te.type.is_int):
                raise self.err(node.op, f"{op} on {te.type.name}: only BOOL, BYTE, WORD and DWORD (portable subset)")
        t, ca, cb = self.unify(a, b, want, node)
        if t.is_bool:
            c_op = {"AND": "&&", "OR": "||", "XOR": "!="}[op]
            return TE(t, f"({ca} {c_op} {cb})")
        if t.is_int and self.comp.user:  # TwinCAT and CODESYS: bit by bit on an integer too (FsCommon's F_Hash)
            self.comp.dialect(node.op, f"{op} on {t.name}")
        if t.is_bit or t.is_int and self.comp.user:
            c_op = {"AND": "&", "OR": "|", "XOR": "^"}[op]
            return TE(t, f"(({t.cname})({ca} {c_op} {cb}))")
        raise self.err(node.op, f"{op} on {t.name}: only BOOL, BYTE, WORD and DWORD (portable subset)")

    # ------------------------------------------------------------------ calls
    def generic_assert(self, node):
        """User mode: TcUnit's AssertEquals (Expected, Actual : ANY) as pac-test's AssertEquals_<type> of the
        arguments (Expected's type, or Actual's where Expected is a literal); other calls unchanged."""
        if not self.comp.user or _cls(node.name) != "SimpleVariable" or _name(node.name.name).upper() != "ASSERTEQUALS" \
                or "ASSERTEQUALS" in self.comp.pous:
            return node
        pins = {str(p.name.name if hasattr(p.name, "name") else p.name).upper(): p.value
                for p in node.parameters if getattr(p, "name", None) is not None}
        types = [self.expr(pins[k]).type for k in ("EXPECTED", "ACTUAL") if k in pins]
        named = [t for t in types if not t.name.startswith("ANY")]
        if not named:
            raise self.err(node, "AssertEquals needs Expected := and Actual := with a typed variable")
        # an enumeration by its number (TcUnit compares it as its base type)
        first = named[0].short if named[0].kind == "longstring" else named[0]  # STRING(300): as T_MaxString
        name = first.name if first is T.WSTRING else "STRING" if first.is_string else \
            "DINT" if first.is_enum else first.name
        if f"ASSERTEQUALS_{name}" not in self.comp.pous:
            have = sorted(n[len("ASSERTEQUALS_"):] for n in self.comp.pous if n.startswith("ASSERTEQUALS_"))
            raise self.err(node, f"AssertEquals on {named[0].name}: pac-test asserts {', '.join(have)}; "
                                 f"compare and call AssertTrue")
        return dataclasses.replace(node, name=dataclasses.replace(node.name, name=f"AssertEquals_{name}"))

    def _e_FunctionCall(self, node, want):
        if node.dereferenced and self.comp.user and self.body is not None:  # F(x)^
            return self._read(self.body.call_result(node), node)
        node = dataclasses.replace(node, name=self.comp.unqualify(node.name, self.body.lookup if self.body else None))
        node = self.generic_assert(node)
        target = self.body.method_target(node.name) if self.body is not None else None
        if target is not None:  # user mode: a METHOD's result (Ok := Axis.Move(...))
            if target[1].ret is None:
                raise self.err(node, f"{target[1].owner.name}.{target[1].name} returns nothing: call it as a statement")
            if target[1] is self.body.pou:
                raise self.err(node, "recursion is outside pacst's user programs")
            return self._user_call(node, target[1], this=target[0])
        if _cls(node.name) != "SimpleVariable":
            if self.comp.user and self.body is not None:
                self.body.ref(node.name)  # what is wrong with the instance it names (a list's variable refused)
            raise self.err(node, "only plain function names can be called")
        name = _name(node.name.name)
        up = name.upper()
        if self.comp.user and up not in self.comp.pous:  # TIME_OF_DAY_TO_DWORD, TO_DATE_AND_TIME
            up = up.replace("TIME_OF_DAY", "TOD").replace("DATE_AND_TIME", "DT")
        pseudo = re.fullmatch(r"(?:(\w+?)_)?TO_(\w+)", up) if self.comp.user and up not in self.comp.pous else None
        if pseudo and {pseudo.group(1), pseudo.group(2)} & set(T.PSEUDO_TYPES):  # LINT_TO___XWORD, TO_PVOID
            self.comp.dialect(node, f"a conversion to or from a pseudo type ({up})")
            src, dst = (T.PSEUDO_TYPES.get(g, g) for g in pseudo.groups())
            up = f"{src}_TO_{dst}" if src else f"TO_{dst}"  # as on a 64-bit target: __XWORD is an LWORD
        m = re.fullmatch(r"([A-Z]+)_TO_([A-Z]+)", up)
        if m and not (self.comp.user and up in self.comp.pous):  # a user FUNCTION BIN_TO_BYTE is the user's
            return self._conversion(node, m.group(1), m.group(2))
        if self.comp.user and up in _MATH and up not in self.comp.pous:
            return self._math(node, up, want)
        if self.comp.user and up in ("__NEW", "__DELETE"):
            raise self.err(node, f"{up} inside an expression: TwinCAT takes __NEW in an assignment only "
                                 "(p := __NEW(T)), __DELETE as a statement (__DELETE(p);)")
        if self.comp.user and up in ("LOWER_BOUND", "UPPER_BOUND") and up not in self.comp.pous:
            return varlen.bound(self, node, up)
        if self.comp.user and up in _MEMORY and up not in self.comp.pous and self.body is not None:
            return self._memory(node, up)
        m = re.fullmatch(r"TO_([A-Z]+)", up)
        if m and self.comp.user and up not in self.comp.pous:  # TO_DINT(x): from the argument's type
            (arg,) = self._positional(node, 1, ["IN"])
            te = self.expr(arg, None)
            if te.type.kind == "longstring":  # TO_STRING(Path): its first 255 characters, then as a STRING's
                te = TE(te.type.short, long_string_code(te, te.type.short))
            src = self.default_type(te, None).name if te.type.kind in ("anyint", "anyreal") else te.type.name
            if te.type.is_enum:
                src = "DINT"
            src = {"DATE_AND_TIME": "DT", "TIME_OF_DAY": "TOD"}.get(src, src)  # TO_DT of a DT converts nothing
            self.comp.dialect(node, f"the generic conversion {up}")
            if te.type.is_pointer:  # F_Generic_To_String, _To_LREAL: the address, a ULINT on TwinCAT's 64-bit targets
                address = f"((ULINT)(uintptr_t)({te.code}))"
                if up == "TO_STRING":
                    return TE(T.STRING, f"__pacst_digits_to_string({address}, 0)")
                dt = T.ELEMENTARY.get(m.group(1)) or T.USER_ELEMENTARY.get(m.group(1))
                if dt is not None and (dt.is_int or dt.is_bit or dt.is_real or dt.is_bool):
                    return _converted(T.USER_ELEMENTARY["ULINT"], dt, address)
                ulint = T.USER_ELEMENTARY["ULINT"]  # TO_LTIME, TO_DT: as ULINT_TO_LTIME and ULINT_TO_DT of it
                if m.group(1) == "LTIME":
                    return _ltime_converted(ulint, T.LTIME, address)
                if m.group(1) == "TIME":
                    return TE(T.TIME, f"__time_from_ms((int64_t)({address}))")
                if m.group(1) in T.USER_DATES:
                    return TE(T.USER_DATES[m.group(1)], _converted(ulint, T.ELEMENTARY["UDINT"], address).code)
            return self._conversion(node, src, m.group(1)) if src != m.group(1) else \
                TE(te.type, self.coerce(te, te.type, arg)) if te.type.kind not in ("anyint", "anyreal") else te
        if self.comp.user and up in ("TIME", "LTIME") and not node.parameters:
            return self._uptime(node, up)
        if up in ("SHL", "SHR", "ROL", "ROR"):
            return self._shift(node, up, want)
        if up in ("ABS", "MIN", "MAX", "LIMIT", "SEL"):
            return self._std_numeric(node, up, want)
        if self.comp.user and up in _STRING_FUNCTIONS and up not in self.comp.pous:
            return self._string_function(node, up)
        if self.comp.user and up[1:] in _STRING_FUNCTIONS and up[0] == "W" and up not in self.comp.pous:
            self.comp.dialect(node, up)  # Tc2_Standard's and Standard's WLEN, WCONCAT, WLEFT, ...: on code units
            return self._string_function(node, up[1:], wide=True)
        if up in self.comp.pous and self.comp.user and self.body is not None and self.body.lookup(name) is not None \
                and self.comp.pous[up].kind == "function":
            raise self.err(node, f"'{name}' is a variable in this POU, which hides the FUNCTION of that name: rename "
                                 "the variable to call the FUNCTION")
        if up in self.comp.pous:
            pou = self.comp.pous[up]
            if pou.ret is None and self.comp.user and not pou.native and pou.kind == "function":
                return self._first_output_value(node, pou)
            if pou.ret is None and (pou.native or self.comp.user):
                raise self.err(node, f"FUNCTION {pou.name} returns nothing: call it as a statement")
            if pou.kind == "fb":
                raise self.err(node, f"function block type '{name}' called like a function: declare an instance")
            if self.body is not None and pou is self.body.pou:
                raise self.err(node, "recursion is outside the portable subset")
            return self._user_call(node, pou)
        if self.body is not None and self.body.lookup(name) is not None:
            raise self.err(node, f"function block instance '{name}' called inside an expression: call it as a "
                                 "statement and read its outputs")
        if up in self.comp.refused:
            raise self.err(node, refused_call(name))
        if up in self.comp.declared_at:
            file, line = self.comp.declared_at[up]
            raise self.err(node, f"'{name}' is called before its declaration ({file}:{line}): declare before use")
        if up in T.STANDARD_FBS or up in T.NONPORTABLE_FBS:
            raise self.err(node, f"{up} is a function block: declare an instance")
        if up in STANDARD_FUNCTIONS:
            raise self.err(node, f"standard function {up} is not supported by pacst{_INSTEAD.get(up, '')}")
        raise self.err(node, f"undeclared function '{name}'")

    def _uptime(self, node, up):
        """User mode: CODESYS's TIME() and LTIME(), the time since the PLC started (the CODESYS help, Operands,
        Functions: TIME() in milliseconds, a 32-bit TIME that starts again at 0 after its overflow): the test
        runtime's clock, __CURRENT_TIME, which starts at 0 at power-on and which the standard timers read too."""
        self.comp.dialect(node, f"{up}()")
        if up == "LTIME":
            return TE(T.LTIME, "__time_from_ns(__time_to_ns(__CURRENT_TIME))")
        return TE(T.TIME, "__time_from_ms((int64_t)(uint32_t)__time_to_ms(__CURRENT_TIME))")

    def _first_output_value(self, node, pou):
        """User mode: the value of a FUNCTION without a result type is its first VAR_OUTPUT after the call, as
        TwinCAT 3 gives it (`bSuccess := F_Swap_Generics(A, B, bSuccess => bSuccess)`), read through the C
        function emit.py declares beside it (docs/user_dialect.md)."""
        first = first_output(pou)
        if first is None:
            raise self.err(node, f"FUNCTION {pou.name} has no result type and no VAR_OUTPUT, so its call has no "
                                 "value: call it as a statement")
        if not first_output_returnable(first):
            raise self.err(node, f"FUNCTION {pou.name} has no result type and its first VAR_OUTPUT '{first.name}' "
                                 f"is of type {first.type.name}, which pacst does not give as a call's value: "
                                 "call it as a statement and read the output")
        self.comp.dialect(node, "the value of a FUNCTION without a result type (its first VAR_OUTPUT)")
        te = self._user_call(node, pou)
        assert te.code.startswith(pou.cfunc + "(")
        return TE(first.type, first_output_cfunc(pou) + te.code[len(pou.cfunc):])

    def _math(self, node, fn, want):
        """User mode: the numeric standard functions on REAL and LREAL (an integer argument is an LREAL), TRUNC
        (toward zero, to DINT), MOVE."""
        self.comp.dialect(node, f"the standard function {fn}")
        if fn == "EXPT":
            base, power = self._positional(node, 2, ["IN1", "IN2"])
            bt = self._real_arg(base, want)
            pt = self._real_arg(power, T.LREAL)
            c = "powf" if bt[0] is T.ELEMENTARY["REAL"] else "pow"
            return TE(bt[0], f"(({bt[0].cname}){c}({bt[1]}, {pt[1]}))")
        (arg,) = self._positional(node, 1, ["IN"])
        if fn == "MOVE":
            te = self.expr(arg, want)
            return te
        if fn in ("TRUNC", "TRUNC_INT"):
            t, code = self._real_arg(arg, T.LREAL)
            dst = T.DINT if fn == "TRUNC" else T.INT
            return TE(dst, f"(({dst.cname})__trunc_i64({code}))")
        t, code = self._real_arg(arg, want)
        c = _MATH[fn] + ("f" if t is T.ELEMENTARY["REAL"] else "")
        return TE(t, f"(({t.cname}){c}({code}))")

    def _memory(self, node, fn):
        """User mode: ADR(x) (a POINTER TO x's type), SIZEOF(x or a type) in bytes as the C layout has them (a
        STRING is 256 bytes here), MEMCPY / MEMMOVE / MEMSET (destAddr, srcAddr or fillByte, n: UDINT, the bytes
        done), MEMCMP (pBuf1, pBuf2, n: DINT, -1, 0 or 1), __ISVALIDREF(r)."""
        self.comp.dialect(node, fn)
        if fn in ("ADR", "__ISVALIDREF"):
            (arg,) = self._positional(node, 1, ["IN"] if fn == "ADR" else ["REF"])
            r = self.body.ref(arg, raw=fn == "__ISVALIDREF")
            if fn == "__ISVALIDREF":
                if getattr(r.var, "section", None) == "inout" and r.var.type is r.type:
                    return TE(T.BOOL, "TRUE")  # a VAR_IN_OUT: every call gives one (FsCommon's F_DeallocateMemory)
                if not (r.type.is_pointer and r.type.reference):
                    raise self.err(arg, "__ISVALIDREF takes a REFERENCE or a VAR_IN_OUT")
                return TE(T.BOOL, f"(({r.read()}) != NULL)")
            if getattr(r, "whole", None) is not None:
                raise self.err(arg, "ADR of a bit: a bit has no address")
            if r.type.kind == "vla":
                raise self.err(arg, varlen.NOT_WHOLE.format(what="ADR of"))
            t = self.comp.pointer_to(r.type)
            return TE(t, f"(({t.cname})&({r.read()}))")
        if fn == "SIZEOF":
            (arg,) = self._positional(node, 1, ["IN"])
            name = _name(arg.name) if _cls(arg) == "SimpleVariable" else None
            own_result = name is not None and self.body.pou.ret is not None and name.upper() == self.body.pou.cname
            if name is not None and self.body.lookup(name) is None and user.lookup_global(self.comp, arg.name) is None \
                    and not own_result:  # SIZEOF(F_Name) in F_Name: its result's bytes, as TwinCAT reads it
                t = self.comp._resolve_type(arg.name, allow_fb=True)
                return TE(T.ELEMENTARY["UDINT"], f"((UDINT)sizeof({t.cname}))")
            r = self.body.ref(arg)
            if r.type.kind == "vla":  # the caller's array's bytes
                return TE(T.ELEMENTARY["UDINT"], varlen.size_c(r))
            return TE(T.ELEMENTARY["UDINT"], f"((UDINT)sizeof({r.read()}))")
        if fn == "PACST_MEMORY_AREA":  # pac-test's Tc2_System.F_CheckMemoryArea: 0 unknown, 1 static, 2 __NEW's
            pdata, nsize = self._positional(node, 2, ["PDATA", "NSIZE"])
            te, ne = self.expr(pdata, None), self.expr(nsize, T.ELEMENTARY["UDINT"])
            if not te.type.is_pointer:
                raise self.err(pdata, f"{fn}'s pData is an address (ADR(x) or a POINTER), not {te.type.name}")
            ncode = self.coerce(ne, T.ELEMENTARY["UDINT"], nsize, "argument")
            pcode = f"(const void *)({te.code})"
            return TE(T.ELEMENTARY["UDINT"], f"__pacst_memory_area({pcode}, (size_t)({ncode}))")
        names = {"MEMSET": ["DESTADDR", "FILLBYTE", "N"], "MEMCMP": ["PBUF1", "PBUF2", "N"]}.get(
            fn, ["DESTADDR", "SRCADDR", "N"])
        args = self._positional(node, 3, names)
        codes = []
        for name, arg in zip(names, args):
            te = self.expr(arg, T.ELEMENTARY["UDINT"] if name in ("N", "FILLBYTE") else None)
            if name in ("N", "FILLBYTE"):
                if te.type is not T.ANY_INT and not (te.type.is_int or te.type.is_bit):
                    raise self.err(arg, f"{fn}'s {name.lower()} is a number, not {te.type.name}")
                codes.append(f"(size_t)({te.code if te.code is not None else te.value})")
            else:
                if not te.type.is_pointer:
                    raise self.err(arg, f"{fn}'s {name} is an address (ADR(x) or a POINTER), not {te.type.name}")
                codes.append(f"(void *)({te.code})")
        if fn == "MEMCMP":
            return TE(T.DINT, f"__pacst_memcmp({', '.join(codes)})")
        c = {"MEMCPY": "memcpy", "MEMMOVE": "memmove", "MEMSET": "memset"}[fn]
        second = f"(int){codes[1]}" if fn == "MEMSET" else codes[1]
        return TE(T.ELEMENTARY["UDINT"], f"((UDINT)(({c}({codes[0]}, {second}, {codes[2]}), {codes[2]})))")

    def _real_arg(self, arg, want):
        """(REAL or LREAL, C code) of a numeric standard function's argument: a REAL stays REAL, an integer or an
        untyped literal is an LREAL (a REAL where the context wants one)."""
        te = self.expr(arg, want if want is not None and want.is_real else None)
        if te.type.is_real:
            return te.type, te.code
        t = want if want is not None and want.is_real and te.type.kind in ("anyint", "anyreal") else T.LREAL
        if te.type.kind in ("anyint", "anyreal"):
            return t, literals.real_c(te.value, t.cname) or "0.0"
        if not te.type.is_int:
            raise self.err(arg, f"a number is expected here, not {te.type.name}")
        return T.LREAL, f"((LREAL)({te.code}))"

    def _string_conversion(self, node, src, dst):
        """User mode: an integer, bit string or BOOL to STRING, in decimal ('TRUE', 'FALSE'), as CODESYS,
        TwinCAT and MATIEC write them, and a REAL as TwinCAT does; the other conversions with STRING are refused
        with the reason."""
        name = f"{src}_TO_{dst}"
        if dst != "STRING":
            return self._string_to_number(node, src, dst)
        if src in ("REAL", "LREAL"):  # as TwinCAT writes them in TcUnit's messages: 1234.4, -23.0
            (arg,) = self._positional(node, 1, ["IN"])
            st = T.ELEMENTARY[src]
            code = self.coerce(self.expr(arg, st), st, arg, "argument")
            self.comp.dialect(node, name)
            return TE(T.STRING, f"__pacst_real_to_string((double)({code}), {7 if src == 'REAL' else 16})")
        if src not in _CONVERTIBLE and src not in T.USER_ELEMENTARY:
            raise self.err(node, f"{name} is outside pacst's user programs: only integers, bit strings and BOOL "
                                 "are converted to STRING")
        (arg,) = self._positional(node, 1, ["IN"])
        st = T.ELEMENTARY.get(src) or T.USER_ELEMENTARY[src]
        code = self.coerce(self.expr(arg, st), st, arg, "argument")
        if src in ("ULINT", "LWORD"):  # above LINT's range too
            self.comp.dialect(node, name)
            return TE(T.STRING, f"__pacst_digits_to_string((unsigned long long)({code}), 0)")
        if st.is_bool:
            return TE(T.STRING, f'(({code}) ? __pacst_string("TRUE", 4) : __pacst_string("FALSE", 5))')
        return TE(T.STRING, f"__pacst_int_to_string((long long)({code}))")

    def _string_to_number(self, node, src, dst):
        """User mode: a STRING or WSTRING to a number or BOOL as TwinCAT's and CODESYS's help describe it: a literal
        of the type after spaces, text after it ignored, text before it 0, an integer cut to its type's bits."""
        name = f"{src}_TO_{dst}"
        t = T.ELEMENTARY.get(dst) or T.USER_ELEMENTARY.get(dst)
        if t is None or not (t.is_int or t.is_bit or t.is_real or t.is_bool):
            raise self.err(node, f"{name} is outside pacst's user programs: a STRING is converted to the integers, "
                                 "bit strings, REAL, LREAL and BOOL only")
        (arg,) = self._positional(node, 1, ["IN"])
        code = self._text_code(arg, src)
        self.comp.dialect(node, name)
        if t.is_bool:
            return TE(t, f"__pacst_string_to_bool({code})")
        if t.is_real:
            return TE(t, f"(({t.cname})__pacst_string_to_real({code}))")
        return TE(t, f"(({t.cname})__pacst_string_to_bits({code}))")

    def _text_code(self, arg, src):
        """The C of a STRING or WSTRING argument read as a STRING's text (a WSTRING's units above 16#FF skipped:
        no literal of a number, a duration or a date holds one)."""
        st = T.WSTRING if src == "WSTRING" else T.STRING
        code = self.coerce(self.expr(arg, st), st, arg, "argument")
        return f"__pacst_wstring_to_string({code})" if st is T.WSTRING else code

    def _string_function(self, node, fn, wide=False):
        """The standard string functions (user mode): positions count from 1, results keep at most the
        STRING capacity, as MATIEC's library does; `wide`: their W versions (WLEFT) on a WSTRING's code units."""
        st, prefix = (T.WSTRING, "__pacst_wstr") if wide else (T.STRING, "__pacst_str")
        names = _STRING_FUNCTIONS[fn]
        if fn == "CONCAT" and len(node.parameters) > 2 and all(p.name is None for p in node.parameters):
            names = [f"IN{i + 1}" for i in range(len(node.parameters))]
        vendor = _STRING_PINS[fn] if len(_STRING_PINS[fn]) == len(names) else None  # not CONCAT of 3 or more
        if wide and fn == "DELETE" and any(getattr(p, "name", None) is not None and
                                           _name(p.name.name).upper() == "STR1" for p in node.parameters):
            vendor = ["STR1", "LEN", "POS"]  # TwinCAT's WDELETE names its string STR1, CODESYS's STR
        args = self._positional(node, len(names), names, vendor)
        codes = []
        for name, arg in zip(names, args):
            if name in ("L", "P"):
                te = self.expr(arg, T.INT)
                if te.type is not T.ANY_INT and not te.type.is_int:
                    raise self.err(arg, f"{fn}'s {name} is an integer, not {te.type.name}")
                codes.append(self.coerce(te, T.INT, arg, "argument") if te.type is T.ANY_INT
                             else f"(long)({te.code})")
            else:
                codes.append(self.coerce(self.expr(arg, st), st, arg, "argument"))
        if fn == "CONCAT":
            code = codes[0]
            for c in codes[1:]:
                code = f"{prefix}_concat({code}, {c})"
            return TE(st, code)
        return TE(T.INT if fn in ("LEN", "FIND") else st, f"{prefix}_{fn.lower()}({', '.join(codes)})")

    def _positional(self, node, count, names, vendor_names=None):
        """Arguments of a standard function: all positional, or all formal with the IEC pin names (or, in
        user mode, with `vendor_names`, TwinCAT's and CODESYS's)."""
        params = node.parameters
        if len(params) != count:
            raise self.err(node, f"{_name(node.name.name).upper()} takes {count} argument(s), not {len(params)}")
        if all(_cls(p) == "InputParameterAssignment" and p.name is None for p in params):
            return [p.value for p in params]
        by_name = {}
        for k, p in enumerate(params):
            if _cls(p) != "InputParameterAssignment" or p.name is None and not self.comp.user:
                raise self.err(p, "mix of formal and positional arguments")
            if p.name is None:  # user mode: FIND(STR1 := s, '.'), as for a FUNCTION of the program's
                return self._formal_then_positional(node, params, k, by_name, names, vendor_names)
            by_name[_name(p.name.name).upper()] = p.value
        if vendor_names and self.comp.user and set(by_name) == set(vendor_names):
            self.comp.dialect(node, f"the input names {', '.join(vendor_names)} of Tc2_Standard and Standard")
            return [by_name[n] for n in vendor_names]
        if set(by_name) != set(names):
            also = f" (or {', '.join(vendor_names)})" if vendor_names and self.comp.user else ""
            raise self.err(node, f"the inputs are {', '.join(names)}{also}")
        return [by_name[n] for n in names]

    def _formal_then_positional(self, node, params, first, by_name, names, vendor_names):
        """User mode: a standard function's arguments, formal ones then positional ones (`FIND(STR1 := s, '.')`):
        the positional ones go to the inputs not given yet, in order, as TwinCAT passes them."""
        order = vendor_names if vendor_names and set(by_name) & set(vendor_names) else names
        if not set(by_name) <= set(order):
            raise self.err(node, f"the inputs are {', '.join(order)}")
        rest = [n for n in order if n not in by_name]
        for name, p in zip(rest, params[first:]):
            if _cls(p) != "InputParameterAssignment" or p.name is not None:
                raise self.err(p, "a formal argument after a positional one: write the formal ones first")
            by_name[name] = p.value
        self.comp.dialect(node, "formal arguments followed by positional ones")
        return [by_name[n] for n in order]

    def _conversion(self, node, src, dst):
        if self.comp.user and "BIT" in (src, dst):  # BIT is a BOOL here (BIT_TO_BOOL, BOOL_TO_BIT, BIT_TO_INT)
            self.comp.dialect(node, f"{src}_TO_{dst}")
            src, dst = ("BOOL" if src == "BIT" else src), ("BOOL" if dst == "BIT" else dst)
            if src == dst:
                (arg,) = self._positional(node, 1, ["IN"])
                return TE(T.BOOL, self.coerce(self.expr(arg, T.BOOL), T.BOOL, arg, "argument"))
        if self.comp.user and src in ("STRING", "WSTRING") and dst in ("TIME", "LTIME", *T.USER_DATES):
            return self._text_to_time(node, src, dst)
        if self.comp.user and dst == "STRING" and src in ("TIME", "LTIME", *T.USER_DATES):
            return self._time_to_string(node, src)
        if self.comp.user and {src, dst} & set(T.USER_DATES):
            return self._date_conversion(node, src, dst)
        if self.comp.user and {src, dst} == {"STRING", "WSTRING"}:  # a unit above 16#FF skipped to a STRING
            self.comp.dialect(node, f"{src}_TO_{dst}")
            (arg,) = self._positional(node, 1, ["IN"])
            st, dt = (T.STRING, T.WSTRING) if src == "STRING" else (T.WSTRING, T.STRING)
            code = self.coerce(self.expr(arg, st), st, arg, "argument")
            return TE(dt, f"__pacst_{src.lower()}_to_{dst.lower()}({code})")
        if self.comp.user and src == "WSTRING" and dst not in ("TIME", "LTIME"):  # WSTRING_TO_LREAL: as a STRING
            return self._string_to_number(node, src, dst)
        if self.comp.user and "WSTRING" in (src, dst):
            raise self.err(node, f"{src}_TO_{dst} is outside pacst's user programs: of the WSTRING conversions, "
                                 "WSTRING_TO_STRING and STRING_TO_WSTRING are translated; convert through a STRING")
        if self.comp.user and "STRING" in (src, dst):
            return self._string_conversion(node, src, dst)
        if self.comp.user and ({"TIME", "LTIME"} & {src, dst} or {src, dst} & set(T.USER_ELEMENTARY)):
            return self._user_conversion(node, src, dst)
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
        return _converted(st, dt, self.coerce(te, st, arg, "argument"))

    def _time_to_string(self, node, src):
        """User mode: TIME_TO_STRING, LTIME_TO_STRING and the date types' _TO_STRING, the literal TwinCAT writes
        ('T#1h30m', 'LTIME#1s2us', 'D#2002-08-18', 'TOD#14:01:05.123', 'DT#1998-02-13-14:20:00')."""
        st = T.LTIME if src == "LTIME" else T.TIME if src == "TIME" else T.USER_DATES[src]
        (arg,) = self._positional(node, 1, ["IN"])
        code = self.coerce(self.expr(arg, st), st, arg, "argument")
        self.comp.dialect(node, f"{src}_TO_STRING")
        if st.is_time:
            return TE(T.STRING, f"__pacst_time_to_string({code}, {1 if st is T.LTIME else 0})")
        return TE(T.STRING, f"__pacst_date_to_string({code}, {[T.DATE, T.TOD, T.DT].index(st)})")

    def _text_to_time(self, node, src, dst):
        """User mode: a STRING or WSTRING to TIME, LTIME, DATE, TOD or DT: the literal of the type in the text, as
        TwinCAT's help writes them (T#1h30m, LTIME#1s2us44ns, D#2002-08-18, TOD#14:01:05.123,
        DT#1998-02-13-14:20:00), spaces before it skipped; text that is no such literal gives 0."""
        (arg,) = self._positional(node, 1, ["IN"])
        code = self._text_code(arg, src)
        self.comp.dialect(node, f"{src}_TO_{dst}")
        if dst == "LTIME":
            return TE(T.LTIME, f"__time_from_ns(__pacst_string_to_ns({code}))")
        if dst == "TIME":  # TIME's resolution: whole milliseconds
            return TE(T.TIME, f"__time_from_ms((int64_t)(__pacst_string_to_ns({code}) / 1000000u))")
        dt = T.USER_DATES[dst]
        return TE(dt, f"__pacst_string_to_date({code}, {[T.DATE, T.TOD, T.DT].index(dt)})")

    def _date_conversion(self, node, src, dst):
        """User mode: DATE, TIME_OF_DAY and DATE_AND_TIME as TwinCAT and CODESYS convert them: to and from
        numbers their count (seconds, TOD milliseconds) cut to 32 bits; DT to DATE its midnight, DT to TOD its
        time of day, DATE to DT the same second; TOD to and from TIME the milliseconds."""
        numbers = dict(T.ELEMENTARY, **T.USER_ELEMENTARY)
        types = dict(numbers, TIME=T.TIME, LTIME=T.LTIME, **T.USER_DATES)
        name = f"{src}_TO_{dst}"
        for tname in (src, dst):
            if tname not in types or tname == "STRING":
                raise self.err(node, f"{name} is outside pacst's user programs: DATE, TIME_OF_DAY and DATE_AND_TIME "
                                     "are converted to and from numbers, TOD to and from TIME, DT to DATE and TOD, "
                                     "DATE to DT, and to STRING")
        st, dt = types[src], types[dst]
        if st is dt:
            raise self.err(node, f"{name} converts nothing")
        (arg,) = self._positional(node, 1, ["IN"])
        code = self.coerce(self.expr(arg, st), st, arg, "argument")
        self.comp.dialect(node, name)
        if st.is_date and dt.is_date:
            if (st, dt) == (T.DT, T.DATE):
                return TE(dt, f"__pacst_dt_to_date({code})")
            if (st, dt) == (T.DT, T.TOD):
                return TE(dt, f"((UDINT)({code} % 86400U * 1000U))")
            if (st, dt) == (T.DATE, T.DT):
                return TE(dt, code)
            if (st, dt) == (T.TOD, T.DT):  # the same second of 1970-01-01 (the collections' F_Generic_To_DT)
                return TE(dt, f"((UDINT)({code} / 1000U))")
            raise self.err(node, f"{name} is outside pacst's user programs: TwinCAT has no such conversion")
        if st.is_time or dt.is_time:
            # TOD its milliseconds since midnight; DATE and DT the time since 1970-01-01-00:00:00 in whole seconds
            # (TIME_TO_DATE its midnight), which the manuals leave open (the collections' F_Generic_To_LTIME)
            date = dt if st.is_time else st
            ns = 1000000 if date is T.TOD else 1000000000
            if st.is_time:
                count = f"((UDINT)(__time_to_ns({code}) / {ns}u))" if st is T.LTIME else \
                    f"((UDINT)__time_to_ms({code}))" if date is T.TOD else f"((UDINT)(__time_to_ms({code}) / 1000))"
                return TE(dt, f"__pacst_dt_to_date({count})" if dt is T.DATE else count)
            return TE(dt, f"__time_from_ns((uint64_t)({code}) * {ns}u)" if dt is T.LTIME else
                      f"__time_from_ms((int64_t)({code}){'' if date is T.TOD else ' * 1000'})")
        # a number: the count, cut to 32 bits (REAL rounded half to even)
        if st.is_date:
            return _converted(T.ELEMENTARY["UDINT"], dt, code)
        return TE(dt, _converted(st, T.ELEMENTARY["UDINT"], code).code)

    def _user_conversion(self, node, src, dst):
        """User mode: TIME to and from a number of milliseconds (TIME_TO_DINT, UDINT_TO_TIME: CODESYS and TwinCAT
        count TIME in ms), LTIME's (_ltime_converted), and the 64-bit types' conversions."""
        types = dict(T.ELEMENTARY, LTIME=T.LTIME, **T.USER_ELEMENTARY)
        for tname in (src, dst):
            if tname not in types or tname == "STRING" or tname not in ("TIME", "LTIME") and tname not in _CONVERTIBLE \
                    and tname not in T.USER_ELEMENTARY:
                raise self.err(node, f"unknown conversion {src}_TO_{dst}")
        if src == dst:
            raise self.err(node, f"{src}_TO_{dst} converts nothing")
        self.comp.dialect(node, f"{src}_TO_{dst}")
        (arg,) = self._positional(node, 1, ["IN"])
        st, dt = types[src], types[dst]
        code = self.coerce(self.expr(arg, st), st, arg, "argument")
        if T.LTIME in (st, dt):
            return _ltime_converted(st, dt, code)
        if st.is_time:
            return TE(dt, f"(__time_to_ms({code}) != 0)" if dt.is_bool else f"(({dt.cname})__time_to_ms({code}))")
        if dt.is_time:
            ms = f"__real_to_i64({code})" if st.is_real else f"(int64_t)({code})"
            return TE(dt, f"__time_from_ms({ms})")
        return _converted(st, dt, code)

    def _shift(self, node, fn, want):
        value, count = self._positional(node, 2, ["IN", "N"])
        te = self.expr(value, want)
        if te.type is T.ANY_INT and self.comp.user and fn in ("SHL", "SHR") and (want is None or not want.is_bit):
            # SHL(16#D800, 10), SHL(1, n): TwinCAT and CODESYS shift a literal at the register width, 32 bits (64
            # where a 64-bit value is expected or the literal needs them); where an integer is expected, its bits
            wide = want is not None and want.bits == 64 or not 0 <= te.value <= 0xFFFFFFFF
            bits = T.USER_ELEMENTARY["LWORD"] if wide else T.ELEMENTARY["DWORD"]
            self.comp.dialect(node, f"{fn} of an integer literal")
            shifted = self._shift_code(node, fn, TE(bits, self.coerce(te, bits, value)), bits, count)
            if want is not None and want.is_int:
                return TE(want, f"(({want.cname}){shifted.code})")
            return shifted
        if te.type is T.ANY_INT:
            if want is None or not want.is_bit:
                raise self.err(value, f"{fn} of an integer literal needs a typed literal (WORD#16#FF)")
            te = TE(want, self.coerce(te, want, value))
        t = te.type
        if self.comp.user and t.is_int:
            # SHR on a UDINT (TwinCAT_DynCollections' F_Murmur3_Hash): the bits of the bit string of its width; SHR
            # on a signed one (FB_Array_List's SHR(THIS^._Count, 1)) fills with the sign bit, as CODESYS's help says
            self.comp.dialect(node, f"{fn} on {t.name}")
            if t.is_signed and fn == "SHR":
                ncode = self.coerce(self.expr(count, T.INT), T.INT, count, "shift count")
                return TE(t, f"__sar_{t.cname}({te.code}, (long){ncode})")
            bits = T.USER_ELEMENTARY.get("LWORD") if t.bits == 64 else \
                T.ELEMENTARY[{8: "BYTE", 16: "WORD", 32: "DWORD"}[t.bits]]
            wider = want if fn == "SHL" and want is not None and want.is_int and want.bits > t.bits else None
            shifted = self._shift_code(node, fn, TE(bits, f"(({bits.cname})({te.code}))"), bits, count, wider)
            if wider is not None:  # Low + SHL(High, 8) of USINTs where a UINT is expected: at the UINT's width
                return shifted
            return TE(t, f"(({t.cname}){shifted.code})", narrow=shifted.narrow)
        if not t.is_bit:
            raise self.err(value, f"{fn} on {t.name}: only BYTE, WORD and DWORD (portable subset)")
        return self._shift_code(node, fn, te, t, count, want, value)

    def _shift_code(self, node, fn, te, t, count, want=None, value=None):
        """The C of SHL, SHR, ROL or ROR of `te`, of the bit string type `t`, by `count`."""
        ne = self.expr(count, T.INT)
        if self.comp.user and fn == "SHL" and want is not None and want.is_bit and widens(t, want):
            # nK := nK XOR SHL(pTail[2], 16): TwinCAT shifts at the register width, the DWORD keeps the bits
            self.comp.dialect(node, f"SHL of a {t.name} where a {want.name} is expected")
            te, t = TE(want, self.coerce(te, want, value)), want
        elif self.comp.user and fn == "SHL" and want is not None and want.is_int and want.bits > t.bits:
            # Word := Low + SHL(High, 8) of BYTEs where a UINT is expected: shifted at the register width, as above,
            # the bits of the integer's width kept
            wider = T.USER_ELEMENTARY["LWORD"] if want.bits == 64 else \
                T.ELEMENTARY[{16: "WORD", 32: "DWORD"}[want.bits]]
            self.comp.dialect(node, f"SHL of a {t.name} where a {want.name} is expected")
            shifted = self._shift_code(node, fn, TE(wider, f"(({wider.cname})({te.code}))"), wider, count)
            return TE(want, f"(({want.cname}){shifted.code})")
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
        elif self.comp.user and len(node.parameters) > 2:  # MIN(a, b, c): IEC's MIN and MAX take any number
            n = len(node.parameters)
            args = self._positional(node, n, [f"IN{i}" for i in range(1, n + 1)])
            self.comp.dialect(node, f"{fn} of more than two inputs")
        else:
            args = self._positional(node, 2, ["IN1", "IN2"])
        tes = [self.expr(a, want) for a in args]
        concrete = [te.type for te in tes if te.type.kind not in ("anyint", "anyreal")]
        t = concrete[0] if concrete else self.default_type(tes[0], want)
        if self.comp.user:  # LIMIT(UDINT, LINT, UDINT): the type every argument widens to, as TwinCAT takes it
            wide = [c for c in concrete if all(o is c or widens(o, c) for o in concrete)]
            if wide and wide[0] is not t:
                self.comp.dialect(node, f"{fn} of arguments of different types")
                t = wide[0]
        codes = [self.coerce(te, t, a, "argument") for te, a in zip(tes, args)]
        if not (t.is_numeric or t.is_bit):
            raise self.err(node, f"{fn} on {t.name}")
        if fn != "LIMIT":  # one input after another: MIN(MIN(a, b), c)
            code = codes[0]
            for c in codes[1:]:
                code = f"__{fn.lower()}_{t.cname}({code}, {c})"
            return TE(t, code)
        return TE(t, f"__{fn.lower()}_{t.cname}({', '.join(codes)})")

    def formal_pin(self, p, callee, given):
        """The variable of `callee` (a POU or FB type) that the formal argument `p` names; `given` holds
        the C names of the pins named before it."""
        pname = _name(p.name.name)
        v = callee.var(pname)
        if v is None or v.section not in ("input", "output", "inout"):
            raise self.err(p, f"{callee.name} has no input, output or in-out '{pname}'")
        if v.cname in given:
            raise self.err(p, f"'{pname}' is given twice")
        if _cls(p) == "OutputParameterAssignment":
            if v.section != "output":
                raise self.err(p, f"'{pname}' is not an output: use :=")
            if p.inverted:
                raise self.err(p, "inverted output assignment is outside the portable subset")
        elif v.section == "output":
            raise self.err(p, f"'{pname}' is an output: use =>")
        return v

    def _constant_inout(self, arg, v):
        """The C pointer a VAR_IN_OUT CONSTANT is given: a variable's address, or (as TwinCAT takes a literal or an
        expression there) the address of a one-element array holding the value, alive during the call."""
        ref = system.variable(self, arg)
        if ref is not None and ref.type.kind == "longstring" and v.type is ref.type.short:
            ref = None  # a STRING(1023) read as a VAR_IN_OUT CONSTANT STRING, as Beckhoff's help passes a long one
        if ref is not None:
            if ref.type is not v.type:
                raise self.err(arg, f"type mismatch: {ref.type.name} passed to VAR_IN_OUT CONSTANT '{v.name}' of type "
                                    f"{v.type.name}")
            return f"&({ref.read()})"
        value = self.coerce(self.expr(arg, v.type), v.type, arg, "argument")
        return f"(({v.type.cname}[]){{{value}}})"

    def reference_input(self, arg, v):
        """User mode: the C of the argument for the REFERENCE TO T input `v` when `arg` is a variable of type T (the
        reference is bound to it, as REF= binds it) or a REFERENCE TO T itself (its reference is passed on), as TwinCAT
        and CODESYS pass `Get_As_String(Index, sItem)`; None for any other argument."""
        call = _cls(arg) == "ChainedFunctionCall" or _cls(arg) == "FunctionCall" and arg.dereferenced
        if not (self.comp.user and v.type.is_pointer and v.type.reference) or self.body is None \
                or _cls(arg) not in ("SimpleVariable", "MultiElementVariable") and not call:
            return None
        src = self.body.ref(arg, raw=True)
        if call and not src.writable:  # F(x).Member: a member of a value, which has no address
            return None
        if src.type is v.type or src.type.is_pointer and src.type.reference and src.type.target is v.type.target:
            return f"(({v.type.cname})({src.read()}))"
        if (src.type is v.type.target or system.same_struct(src.type, v.type.target)) and type(src) is Ref:
            # not a bit or a byte of a STRING (no address); an ANY input to a REFERENCE TO __SYSTEM.AnyType as it is
            self.comp.dialect(arg, "a variable passed to a REFERENCE TO input")
            return f"(({v.type.cname})&({src.read()}))"
        return None

    def _user_call(self, node, pou, this=None):
        params = pou.vars
        interface = [v for v in params if v.section in ("input", "output", "inout")]
        inputs = [v for v in interface if v.section == "input"]
        given = {}
        positional = [p for p in node.parameters if _cls(p) == "InputParameterAssignment" and p.name is None]
        leading = positional and node.parameters[:len(positional)] == positional
        if positional and len(positional) != len(node.parameters) and leading and self.comp.user:
            # user mode: TwinCAT's and CODESYS's positional arguments followed by formal ones: the positional ones
            # take the inputs and VAR_IN_OUTs in the order of declaration, as in an all-positional call, the formal
            # ones any pin (TwinCAT_DynCollections' Get(Index, Item, bSuccess => bSuccess))
            order = [v for v in interface if v.section != "output"]
            if len(positional) > len(order):
                raise self.err(positional[len(order)], f"{pou.name} has no input left for this argument")
            self.comp.dialect(node.parameters[len(positional)], "a formal argument after positional ones")
            given.update((v.cname, p.value) for v, p in zip(order, positional))
            for p in node.parameters[len(positional):]:
                given[self.formal_pin(p, pou, given).cname] = p.value
        elif positional and len(positional) != len(node.parameters):
            # user mode: TwinCAT's and CODESYS's formal arguments followed by positional ones, which take the
            # inputs not given yet in the order of declaration (AssertEquals(Expected := a, Actual := b, 'text'))
            formal = node.parameters[:len(node.parameters) - len(positional)]
            if not self.comp.user or any(_cls(p) == "InputParameterAssignment" and p.name is None for p in formal):
                raise self.err(node, "mix of formal and positional arguments")
            for p in formal:
                given[self.formal_pin(p, pou, given).cname] = p.value
            rest = [v for v in inputs if v.cname not in given]
            if len(positional) > len(rest):
                raise self.err(positional[len(rest)], f"{pou.name} has no input left for this argument")
            self.comp.dialect(positional[0], "a positional argument after formal ones")
            given.update((v.cname, p.value) for v, p in zip(rest, positional))
        elif positional:
            # user mode: the VAR_IN_OUTs too, in the order of declaration, as TwinCAT takes F(Counter)
            order = [v for v in interface if v.section != "output"] if self.comp.user else inputs
            # user mode: the last inputs left out take their initial values, as TwinCAT takes M_Open(Name) for
            # M_Open(sFileName, eMode := SysFile.AM_APPEND_PLUS) (Tc3_Event's FB_FileLogger)
            short = self.comp.user and len(positional) < len(order) \
                and all(v.section == "input" for v in order[len(positional):])
            if len(positional) != len(order) and not short \
                    or not self.comp.user and any(v.section == "inout" for v in interface):
                raise self.err(node, f"positional call of {pou.name}: give every input, or call formally")
            if short:
                self.comp.dialect(node, f"a positional call of {pou.name} without its last inputs")
            if any(v.section == "inout" for v in order):
                self.comp.dialect(positional[0], "a positional argument for a VAR_IN_OUT")
            for v, p in zip(order, positional):
                given[v.cname] = p.value
        else:
            for p in node.parameters:
                given[self.formal_pin(p, pou, given).cname] = p.value
        args = []
        converted = []  # user mode: (a temporary's declaration, the write of its variable) of each output converted
        for v in interface:
            arg = given.get(v.cname)
            if v.section == "input":
                if arg is None and v.type.is_fb:
                    raise self.err(node, f"input '{v.name}' of {pou.name}, an instance of {v.type.name}, must be "
                                         "passed")
                if arg is None:
                    args.append(self.comp.default_c(v.type) if v.type.is_elementary or v.type.is_enum
                                or v.type.kind == "longstring"
                                else f"__pacst_default_{v.type.cname}()")  # the TYPE's member defaults
                    if v.init is not None:
                        args[-1] = self.coerce(self.comp.literal_te(v.init, v.type), v.type, v.init)
                elif getattr(v.type, "any", False):  # an ANY input (user mode)
                    args.append(system.any_argument(self, arg, v))
                elif (bound := self.reference_input(arg, v)) is not None:
                    args.append(bound)
                elif v.type.is_fb:  # user mode: a copy of the caller's instance (its value here is its address)
                    te = self.expr(arg, v.type)
                    if te.type is not v.type:
                        raise self.err(arg, f"type mismatch: {te.type.name} passed to input '{v.name}' of type "
                                            f"{v.type.name}")
                    args.append(f"(*{te.code})")
                else:
                    args.append(self.coerce(self.expr(arg, v.type), v.type, arg, "argument"))
                continue
            if arg is None:
                if v.section == "inout":
                    raise self.err(node, f"VAR_IN_OUT '{v.name}' of {pou.name} must be passed")
                args.append(f"&({v.type.cname}){{0}}")
                continue
            if v.type.kind == "vla":  # ARRAY [*] (user mode): the address of a descriptor of the caller's array
                args.append(f"&({varlen.descriptor(self, arg, v)})")
                continue
            if v.section == "inout" and v.constant and self.body is not None:  # VAR_IN_OUT CONSTANT (user mode)
                args.append(self._constant_inout(arg, v))
                continue
            ref = self.body.ref(arg) if self.body is not None else None
            if ref is None:
                raise self.err(arg, "initial value must be a literal")
            if ref.type is not v.type and self._output_converted(ref, v, pou):
                if not ref.writable:
                    raise self.err(arg, f"'{ref.var.name}' cannot be written: {ref.why_not}")
                temporary = f"__pacst_out{len(converted)}"
                converted.append((f"{v.type.cname} {temporary} = {self.comp.default_c(v.type)};",
                                  ref.write(self.coerce(TE(v.type, temporary), ref.type, arg, "argument"))))
                args.append(f"&{temporary}")
                continue
            if ref.type is not v.type:
                raise self.err(arg, f"type mismatch: {ref.type.name} passed to {v.section} '{v.name}' of type "
                                    f"{v.type.name}{long_inout_hint(ref.type, v.type)}")
            if not ref.writable:
                raise self.err(arg, f"'{ref.var.name}' cannot be written: {ref.why_not}")
            if v.section == "inout" and ref.subscripted and not self.comp.user:
                raise self.err(arg, "never pass an array element to a FUNCTION's VAR_IN_OUT (MATIEC)")
            if v.section == "inout" and ref.subscripted:  # user mode: the element's address, as TwinCAT passes it
                self.comp.dialect(arg, "an array element passed to a FUNCTION's VAR_IN_OUT")
            args.append(f"&({ref.read()})")
        # A native FUNCTION (user mode) is given the call's position: with #line directives,
        # __FILE__ and __LINE__ are the ST file and line of the call (docs/translator.md).
        where = "__FILE__, __LINE__, " if pou.native else ""
        first = f"{this}, " if this is not None else ""
        call = f"{pou.cfunc}({first}{where}TRUE, NULL{''.join(', ' + a for a in args)})"
        if converted:  # the outputs land in temporaries of their own types, converted to the variables after the call
            declarations, writes = " ".join(d for d, _ in converted), " ".join(w for _, w in converted)
            if pou.ret is None:
                call = f"({{ {declarations} {call}; {writes} }})"
            else:
                call = f"({{ {declarations} {pou.ret.cname} __pacst_result = {call}; {writes} __pacst_result; }})"
        if pou.ret is not None and pou.ret.is_fb:  # user mode: an instance returned by value, read by its address
            # as every instance's value here (_read), the address of a C object holding the result (a compound
            # literal lives to the end of the C block: the statement)
            return TE(pou.ret, f"(&((struct {{ {pou.ret.cname} v; }}){{ {call} }}).v)")
        return TE(pou.ret, call)
