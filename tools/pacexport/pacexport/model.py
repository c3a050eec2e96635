"""The library as the exports see it: each object's source text and its structured interface."""
from dataclasses import dataclass
from typing import Optional, Tuple, Union

from .splitting import SourceObject, scan
from .types import TypeRef

# PLCopen's variable lists and the ST keyword that opens each.
SECTION_KEYWORDS = {
    "inputVars": "VAR_INPUT",
    "outputVars": "VAR_OUTPUT",
    "inOutVars": "VAR_IN_OUT",
    "localVars": "VAR",
    "tempVars": "VAR_TEMP",
    "externalVars": "VAR_EXTERNAL",
    "globalVars": "VAR_GLOBAL",
}


# The IDEs' marker of an object a library's user does not see: CODESYS and TwinCAT leave a POU or type
# with {attribute 'hide'} out of the Library Manager's tree, the input assistant and the list components.
INTERNAL_ATTRIBUTES = ("hide",)


def with_pragmas(source, attributes):
    """The declaration as CODESYS and TwinCAT hold it: the source with the attributes on the lines just
    before its keyword (FUNCTION_BLOCK, TYPE, VAR_GLOBAL...), after the header comments."""
    text = source.declaration
    if not attributes:
        return text
    tokens, _ = scan(source.path, text)
    line_start = text.rfind("\n", 0, tokens[0].start) + 1
    # The translator's lexer refuses pragmas in the source, so each is written here once.
    pragmas = "".join(f"{{attribute '{a}'}}\n" for a in attributes)
    return text[:line_start] + pragmas + text[line_start:]


def object_attributes(source):
    """The pragmas an object of the library gets in the exports."""
    return INTERNAL_ATTRIBUTES if source.internal else ()


@dataclass(frozen=True)
class Variable:
    name: str
    type: TypeRef
    initial: Optional[str]  # the initial value as the source spells it
    doc: Optional[str]
    address: Optional[str] = None  # a machine program's located variable: "%IB0"


@dataclass(frozen=True)
class VarBlock:
    section: str  # a key of SECTION_KEYWORDS
    constant: bool
    variables: Tuple[Variable, ...]
    doc: Optional[str]


@dataclass(frozen=True)
class EnumShape:
    values: Tuple[Tuple[str, Optional[str]], ...]  # name, explicit value
    base: Optional[TypeRef]


@dataclass(frozen=True)
class AliasShape:
    """TYPE T : ARRAY[0..7] OF BYTE; or TYPE T : INT := 5;"""
    type: TypeRef


@dataclass(frozen=True)
class StructShape:
    members: Tuple[Variable, ...]


@dataclass(frozen=True)
class DataType:
    source: SourceObject
    shape: Union[EnumShape, AliasShape, StructShape]
    initial: Optional[str]

    @property
    def attributes(self):
        return object_attributes(self.source)

    @property
    def declaration(self):
        return with_pragmas(self.source, self.attributes)


@dataclass(frozen=True)
class Pou:
    source: SourceObject
    return_type: Optional[TypeRef]
    blocks: Tuple[VarBlock, ...]

    @property
    def attributes(self):
        return object_attributes(self.source)

    @property
    def declaration(self):
        return with_pragmas(self.source, self.attributes)


@dataclass(frozen=True)
class GlobalList:
    source: SourceObject
    block: VarBlock
    attributes: Tuple[str, ...]  # pragmas the IDEs get, e.g. qualified_only

    @property
    def declaration(self):
        return with_pragmas(self.source, self.attributes)
