"""The types of the portable subset and the C names MATIEC gives them."""


class Type:
    """Base of every ST type; `name` is the ST spelling, `cname` the C type name."""

    kind = "?"

    def __init__(self, name):
        self.name = name
        self.cname = name.upper()

    def __repr__(self):
        return self.name

    # Classification used by the type rules.
    is_bool = is_int = is_signed = is_bit = is_real = is_time = is_string = is_date = False
    is_enum = is_array = is_struct = is_fb = False
    is_pointer = False  # user mode: POINTER TO and REFERENCE TO
    bits = 0

    @property
    def is_elementary(self):
        return self.is_bool or self.is_int or self.is_bit or self.is_real or self.is_time or self.is_string \
            or self.is_date

    @property
    def is_numeric(self):
        return self.is_int or self.is_real


class Elementary(Type):
    kind = "elementary"

    def __init__(self, name, group, bits, signed=False):
        super().__init__(name)
        self.bits = bits
        self.is_bool = group == "bool"
        self.is_int = group == "int"
        self.is_bit = group == "bit"
        self.is_real = group == "real"
        self.is_time = group == "time"
        self.is_string = group == "string"
        self.is_date = group == "date"
        self.is_signed = signed

    def int_range(self):
        if self.is_signed:
            return -(1 << (self.bits - 1)), (1 << (self.bits - 1)) - 1
        return 0, (1 << self.bits) - 1


ELEMENTARY = {
    t.name: t
    for t in [
        Elementary("BOOL", "bool", 1),
        Elementary("SINT", "int", 8, True),
        Elementary("INT", "int", 16, True),
        Elementary("DINT", "int", 32, True),
        Elementary("USINT", "int", 8),
        Elementary("UINT", "int", 16),
        Elementary("UDINT", "int", 32),
        Elementary("BYTE", "bit", 8),
        Elementary("WORD", "bit", 16),
        Elementary("DWORD", "bit", 32),
        Elementary("REAL", "real", 32),
        Elementary("LREAL", "real", 64),
        Elementary("TIME", "time", 64),
        Elementary("STRING", "string", 0),
    ]
}
# The 64-bit types of user programs (pacst --user): TwinCAT and CODESYS have them, MATIEC's C does too.
USER_ELEMENTARY = {t.name: t for t in [Elementary("LINT", "int", 64, True), Elementary("ULINT", "int", 64),
                                       Elementary("LWORD", "bit", 64)]}
# TwinCAT's and CODESYS's register-wide pseudo types, as on a 64-bit target (TwinCAT 3 x64, the test host): PVOID
# is a __UXINT there, an address held as a number (written as pointer arithmetic's operand and ADR's result).
PSEUDO_TYPES = {"__XINT": "LINT", "__UXINT": "ULINT", "__XWORD": "LWORD",
                "XINT": "LINT", "UXINT": "ULINT", "XWORD": "LWORD", "PVOID": "ULINT"}
# LTIME of user programs: TwinCAT's and CODESYS's nanoseconds in 64 bits. pacst's TIME already counts
# nanoseconds (two longs), so an LTIME is that C type too; a type of its own for ST's rules and conversions.
LTIME = Elementary("LTIME", "time", 64)
LTIME.cname = "TIME"
# DATE, TIME_OF_DAY and DATE_AND_TIME of user programs, as TwinCAT and CODESYS keep them: 32 bits unsigned,
# DATE and DATE_AND_TIME seconds since 1970-01-01-00:00:00, TIME_OF_DAY milliseconds since midnight; a UDINT in C.
DATE = Elementary("DATE", "date", 32)
TOD = Elementary("TIME_OF_DAY", "date", 32)
DT = Elementary("DATE_AND_TIME", "date", 32)
for _t in (DATE, TOD, DT):
    _t.cname = "UDINT"
USER_DATES = {"DATE": DATE, "TIME_OF_DAY": TOD, "TOD": TOD, "DATE_AND_TIME": DT, "DT": DT}
BOOL = ELEMENTARY["BOOL"]
INT = ELEMENTARY["INT"]
DINT = ELEMENTARY["DINT"]
LREAL = ELEMENTARY["LREAL"]
TIME = ELEMENTARY["TIME"]
STRING = ELEMENTARY["STRING"]
# WSTRING of user programs: TwinCAT's and CODESYS's wide string, UCS-2 code units a WORD each as they store it
# (pacst_iec.h's WSTRING); a string for ST's rules, but no STRING where a WSTRING is expected: WSTRING_TO_STRING
# and back are written.
WSTRING = Elementary("WSTRING", "string", 0)


class LongStringType(Type):
    """User mode: STRING(n) or WSTRING(n) with n over 255, longer than pacst's STRING: a C type of its own, the n
    characters (code units) and the terminating NUL as TwinCAT lays it out (SIZEOF n + 1, two bytes a unit for a
    WSTRING). The string functions take and give STRING(255), as Tc2_Standard's do: an argument is cut to 255."""

    kind = "longstring"

    def __init__(self, length, wide):
        word = "WSTRING" if wide else "STRING"
        super().__init__(f"{word}({length})")
        self.length = length
        self.wide = wide
        self.short = WSTRING if wide else STRING  # the type its text is read as by the string functions
        self.unit = "uint16_t" if wide else "uint8_t"
        self.cname = f"__PACST_{word}_{length}"


# A STRING literal may not be longer than CODESYS's and TwinCAT's default STRING (80 characters).
STRING_LITERAL_MAX = 80

# Types IEC and the tools know but the portable subset leaves out, with the reason a refusal gives.
OUTSIDE_SUBSET = {
    "LINT": "64-bit integers are outside the portable subset",
    "ULINT": "64-bit integers are outside the portable subset",
    "LWORD": "64-bit bit strings are outside the portable subset",
    "LTIME": "LTIME is outside the portable subset (MATIEC has no LTIME)",
    "STRING": "sized STRING is outside the portable subset (MATIEC has no STRING[n]): use STRING",
    "WSTRING": "WSTRING is outside the portable subset",
    "DATE": "DATE is outside the portable subset",
    "TOD": "TIME_OF_DAY is outside the portable subset",
    "TIME_OF_DAY": "TIME_OF_DAY is outside the portable subset",
    "DT": "DATE_AND_TIME is outside the portable subset",
    "DATE_AND_TIME": "DATE_AND_TIME is outside the portable subset",
    "WCHAR": "WCHAR is outside the portable subset",
    "CHAR": "CHAR is outside the portable subset",
    "BIT": "BIT is outside the portable subset",
    "__XWORD": "XWORD is outside the portable subset",
}


class AnyInt(Type):
    """An untyped integer literal (or a folded expression of them): takes the type its context needs."""

    kind = "anyint"

    def __init__(self):
        super().__init__("integer literal")


class AnyReal(Type):
    """An untyped REAL literal: becomes REAL or LREAL from its context."""

    kind = "anyreal"

    def __init__(self):
        super().__init__("real literal")


ANY_INT = AnyInt()
ANY_REAL = AnyReal()


class EnumType(Type):
    kind = "enum"
    is_enum = True

    def __init__(self, name, values, numbers=None, base=None):
        super().__init__(name)
        self.values = values  # ST spellings, in order
        self.numbers = numbers if numbers is not None else list(range(len(values)))  # user mode: A := 10
        self.base = base  # user mode: the base type of `(A, B) INT`, or None
        self.default = values[0] if values else None

    @property
    def numbered(self):
        """Whether a value has a number of its own (user mode): then the C enum spells them out."""
        return self.numbers != list(range(len(self.values)))

    def number(self, value):
        return self.numbers[[v.upper() for v in self.values].index(value.upper())]

    def cvalue(self, value):
        return f"{self.cname}__{value.upper()}"


class ArrayType(Type):
    kind = "array"
    is_array = True

    def __init__(self, name, low, high, elem):
        super().__init__(name)
        self.low = low
        self.high = high
        self.elem = elem


class StructType(Type):
    kind = "struct"
    is_struct = True

    def __init__(self, name):
        super().__init__(name)
        self.members = []  # list of Var


class Var:
    """A declared variable: a POU's interface or private variable, or a struct member."""

    location = None  # user mode: the parsed `AT %...` address (user.Location)
    strlen = None  # user mode: n of a STRING(n)

    def __init__(self, name, section, type_, init, node, constant=False):
        self.name = name
        self.cname = name.upper()
        self.section = section  # input, output, inout, var, temp, member
        self.type = type_
        self.init = init  # blark literal node or None
        self.node = node
        self.constant = constant


def find_var(variables, name):
    """The variable called `name` (case-insensitive), or None. A plain loop with both spellings made once: the
    checks call it millions of times in a program's translation."""
    up = name.upper()
    safe = c_safe_name(up)
    for v in variables:
        if v.cname == up or v.cname == safe:
            return v
    return None


# user mode: the C name of a variable or member named like a C keyword or macro (Register, EOF), which no ST name
# can be (no user name starts with '__'); messages, symbols.json and the VCD keep the ST name
def c_safe_name(up):
    return f"__V_{up}"


class PointerType(Type):
    """User mode: POINTER TO T (`reference` False) or REFERENCE TO T, a C pointer `T *`; a REFERENCE is read
    and written through without `^`."""

    kind = "pointer"
    is_pointer = True

    def __init__(self, target, reference=False):
        super().__init__(f"{'REFERENCE' if reference else 'POINTER'} TO {target.name}")
        self.target = target
        self.reference = reference
        # a type sharing its C type with another (LTIME, the dates) gets a pointer type of its own
        own = target.name if target.kind == "elementary" and target.name != target.cname else target.cname
        self.cname = f"__{'REF' if reference else 'PTR'}_{own}"


class InterfaceType(Type):
    """A user INTERFACE: the names of its METHODs (user mode; no variable has this type)."""

    kind = "interface"

    def __init__(self, name):
        super().__init__(name)
        self.methods = []  # the METHODs' names, in order
        self.protos = {}  # upper name -> the METHOD's prototype (a Pou without body)
        self.properties = {}  # upper name -> {"name", "type", "get", "set"}: a PROPERTY's accessors' prototypes
        self.bases = []  # the INTERFACEs it EXTENDS, theirs too, the farthest first

    def vtable(self, fb_cname):
        """The C name of the table of `fb_cname`'s METHODs for this interface."""
        return f"{fb_cname}__{self.cname}__VT"


class FbType(Type):
    """A function block type: a user FUNCTION_BLOCK or one of the standard FBs."""

    kind = "fb"
    is_fb = True

    def __init__(self, name, standard=False):
        super().__init__(name)
        self.vars = []
        self.standard = standard
        self.pou = None

    def var(self, name):
        return find_var(self.vars, name)


def _standard_fbs():
    fbs = {}
    for name in ("R_TRIG", "F_TRIG"):
        fb = FbType(name, standard=True)
        fb.vars = [Var("CLK", "input", BOOL, None, None), Var("Q", "output", BOOL, None, None),
                   Var("M", "var", BOOL, None, None)]
        fbs[name] = fb
    for name in ("TON", "TOF", "TP"):
        fb = FbType(name, standard=True)
        fb.vars = [Var("IN", "input", BOOL, None, None), Var("PT", "input", TIME, None, None),
                   Var("Q", "output", BOOL, None, None), Var("ET", "output", TIME, None, None),
                   Var("STATE", "var", ELEMENTARY["SINT"], None, None), Var("PREV_IN", "var", BOOL, None, None),
                   Var("CURRENT_TIME", "var", TIME, None, None), Var("START_TIME", "var", TIME, None, None)]
        fbs[name] = fb
    return fbs


STANDARD_FBS = _standard_fbs()


def _user_fbs():
    """The counters and bistables of user programs, with the pin names of CODESYS's Standard and TwinCAT's
    Tc2_Standard (PV and CV are WORDs there); `M...` members keep the last CU / CD for the edges."""
    word = ELEMENTARY["WORD"]

    def fb(name, pins):
        t = FbType(name, standard=True)
        t.vars = [Var(n, section, typ, None, None) for n, section, typ in pins]
        return t
    return {
        "CTU": fb("CTU", [("CU", "input", BOOL), ("RESET", "input", BOOL), ("PV", "input", word),
                          ("Q", "output", BOOL), ("CV", "output", word), ("MU", "var", BOOL)]),
        "CTD": fb("CTD", [("CD", "input", BOOL), ("LOAD", "input", BOOL), ("PV", "input", word),
                          ("Q", "output", BOOL), ("CV", "output", word), ("MD", "var", BOOL)]),
        "CTUD": fb("CTUD", [("CU", "input", BOOL), ("CD", "input", BOOL), ("RESET", "input", BOOL),
                            ("LOAD", "input", BOOL), ("PV", "input", word), ("QU", "output", BOOL),
                            ("QD", "output", BOOL), ("CV", "output", word), ("MU", "var", BOOL), ("MD", "var", BOOL)]),
        "SR": fb("SR", [("SET1", "input", BOOL), ("RESET", "input", BOOL), ("Q1", "output", BOOL)]),
        "RS": fb("RS", [("SET", "input", BOOL), ("RESET1", "input", BOOL), ("Q1", "output", BOOL)]),
    }


USER_FBS = _user_fbs()

# Standard FBs whose pin names differ between MATIEC and CODESYS/TwinCAT: refused with that reason.
NONPORTABLE_FBS = {"SR", "RS", "CTU", "CTD", "CTUD"}
