"""Type references of variables and types, between ST text and the PLCopen type elements.

PLCopen spells a type as an element (<BOOL/>, <string length="20"/>, <derived name="TON"/>,
<array>); ST as text. Both directions go through these few classes, so the round trip test compares
the same notion of a type on both sides.
"""
import re
from dataclasses import dataclass
from typing import Optional, Tuple, Union

# The elementary types of TC6 XML v2.01 (group elementaryTypes), by the names ST uses for them.
ELEMENTARY = {"BOOL", "BYTE", "WORD", "DWORD", "LWORD", "SINT", "INT", "DINT", "LINT", "USINT", "UINT",
              "UDINT", "ULINT", "REAL", "LREAL", "TIME", "DATE", "DT", "TOD"}
LONG_NAMES = {"DATE_AND_TIME": "DT", "TIME_OF_DAY": "TOD"}


@dataclass(frozen=True)
class Elementary:
    name: str


@dataclass(frozen=True)
class StringType:
    wide: bool
    length: Optional[str]


@dataclass(frozen=True)
class Derived:
    """A user type, a function block (TON, FB_PAC_Cmd) or any name the schema does not list."""
    name: str


@dataclass(frozen=True)
class ArrayType:
    dimensions: Tuple[Tuple[str, str], ...]
    base: "TypeRef"


TypeRef = Union[Elementary, StringType, Derived, ArrayType]

_STRING = re.compile(r"(W?STRING)\s*(?:[\[(]\s*([^\])]+?)\s*[\])])?", re.IGNORECASE)
_ARRAY = re.compile(r"ARRAY\s*\[(.+?)\]\s*OF\s+(.+)", re.IGNORECASE | re.DOTALL)
_NAME = re.compile(r"[A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*")


def parse_type(text):
    """The type named by ST text such as 'UINT', 'STRING(20)', 'ARRAY [0..7] OF BYTE'; ValueError if
    the export has no PLCopen form for it."""
    text = text.strip()
    m = _ARRAY.fullmatch(text)
    if m:
        dims = []
        for dim in m.group(1).split(","):
            bounds = dim.split("..")
            if len(bounds) != 2 or not all(b.strip() for b in bounds):
                raise ValueError(f"array dimension '{dim.strip()}' is not lower..upper")
            dims.append((bounds[0].strip(), bounds[1].strip()))
        return ArrayType(tuple(dims), parse_type(m.group(2)))
    m = _STRING.fullmatch(text)
    if m:
        return StringType(m.group(1).upper() == "WSTRING", m.group(2))
    if _NAME.fullmatch(text):
        upper = LONG_NAMES.get(text.upper(), text.upper())
        return Elementary(upper) if upper in ELEMENTARY else Derived(text)
    raise ValueError(f"type '{text}' has no PLCopen form in this export")


def type_text(ref):
    """The ST spelling of a type."""
    if isinstance(ref, Elementary):
        return ref.name
    if isinstance(ref, StringType):
        name = "WSTRING" if ref.wide else "STRING"
        return f"{name}({ref.length})" if ref.length else name
    if isinstance(ref, Derived):
        return ref.name
    dims = ", ".join(f"{lo}..{hi}" for lo, hi in ref.dimensions)
    return f"ARRAY[{dims}] OF {type_text(ref.base)}"
