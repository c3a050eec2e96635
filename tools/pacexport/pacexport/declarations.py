"""The structured interface of a declaration, from blark's parse: variable lists, types, initial
values and the comments that document them."""
from typing import Optional

from .errors import ExportError
from .model import AliasShape, EnumShape, StructShape, Variable, VarBlock
from .splitting import comment_body
from .types import parse_type

# blark's classes for the variable blocks the export writes, by PLCopen list.
_SECTIONS = {
    "InputDeclarations": "inputVars",
    "OutputDeclarations": "outputVars",
    "InputOutputDeclarations": "inOutVars",
    "VariableDeclarations": "localVars",
    "LocatedVariableDeclarations": "localVars",  # a PROGRAM's VAR holding AT %IX0.3 (a machine program's)
    "FunctionVariableDeclarations": "localVars",
    "TemporaryVariableDeclarations": "tempVars",
    "ExternalVariableDeclarations": "externalVars",
    "GlobalVariableDeclarations": "globalVars",
}
_INITIALISERS_WITHOUT_PLCOPEN_FORM = {"ArrayInitialization", "StructureInitialization"}


def doc_of(node) -> Optional[str]:
    meta = getattr(node, "meta", None)
    comments = getattr(meta, "comments", None) or []
    words = [comment_body(str(c)) for c in comments if str(c).startswith(("(*", "//"))]
    return "\n".join(w for w in words if w) or None


def var_blocks(where, code, blocks):
    return tuple(var_block(where, code, b) for b in blocks)


def var_block(where, code, block):
    kind = type(block).__name__
    section = _SECTIONS.get(kind)
    if section is None:
        raise ExportError(where, f"{kind} has no PLCopen variable list in this export")
    attrs = str(getattr(block, "attrs", None) or "").strip().upper()
    if attrs not in ("", "CONSTANT"):
        raise ExportError(where, f"variable block attribute {attrs} is not exported")
    variables = tuple(v for item in block.items for v in variables_of(where, code, item))
    return VarBlock(section, attrs == "CONSTANT", variables, doc_of(block))


def variables_of(where, code, item):
    """One Variable per name of a declaration such as 'A, B : INT := 5'."""
    names = [_name(v) for v in getattr(item, "variables", None) or []]
    if not names and getattr(item, "name", None) is not None:  # a located declaration names one variable
        names = [_name(item)]
    # A located variable (AT %IB0) belongs to a machine program, never to the library: PLCopen's address.
    locations = [getattr(item, "location", None)] + [getattr(v, "location", None)
                                                     for v in getattr(item, "variables", None) or []]
    address = next((str(loc).split()[-1] for loc in locations if loc is not None), None)  # "AT %IB0"
    if address is not None and not address.startswith("%"):
        raise ExportError(where, f"'{item}' has the location {address}, which PLCopen cannot hold")
    init = item.init
    spec = getattr(item, "spec", None) if init is None else getattr(init, "spec", None)
    if spec is None or getattr(init, "indirection", None) is not None:
        raise ExportError(where, f"declaration '{_plain(item)}' has no plain type the export can write")
    ref = type_of(where, spec, ", ".join(names))
    initial = initial_text(where, code, getattr(init, "value", None) if init is not None else None)
    doc = doc_of(item)
    return [Variable(n, ref, initial, doc, address) for n in names]


def type_of(where, spec, what):
    """The type of a blark type specification, or the reason the export cannot write it."""
    try:
        return parse_type(str(spec))
    except ValueError as exc:
        raise ExportError(where, f"{what}: {exc}") from None


def initial_text(where, code, value):
    """The initial value as the source spells it (T#1S, not blark's TIME#1S)."""
    if value is None:
        return None
    if type(value).__name__ in _INITIALISERS_WITHOUT_PLCOPEN_FORM:
        raise ExportError(where, f"initial value '{value}' is not a single value; the export writes "
                                 "simple values only")
    meta = getattr(value, "meta", None)
    start, end = getattr(meta, "start_pos", None), getattr(meta, "end_pos", None)
    if start is not None and end is not None:
        return code[start:end].strip()
    return str(value)


def data_type_shape(where, code, declaration):
    """The shape and initial value of TYPE ... END_TYPE's one declaration."""
    kind = type(declaration).__name__
    if kind == "EnumeratedTypeDeclaration":
        spec = declaration.init.spec
        values = tuple((str(v.name), None if v.value is None else str(v.value)) for v in spec.values)
        base = None if spec.type_name is None else type_of(where, spec.type_name, declaration.name)
        return EnumShape(values, base), initial_text(where, code, declaration.init.value)
    if kind == "StructureTypeDeclaration":
        if declaration.extends is not None or declaration.indirection is not None:
            raise ExportError(where, "a STRUCT with EXTENDS or a pointer is not exported")
        members = tuple(v for item in declaration.declarations for v in variables_of(where, code, item))
        return StructShape(members), None
    if kind == "StringTypeDeclaration":
        ref = type_of(where, declaration.string_type, declaration.name)
        return AliasShape(ref), initial_text(where, code, declaration.value)
    if kind in ("ArrayTypeDeclaration", "SimpleTypeDeclaration"):
        init = declaration.init
        if getattr(declaration, "extends", None) is not None or getattr(init, "indirection", None):
            raise ExportError(where, f"{declaration.name}: EXTENDS or a pointer is not exported")
        return AliasShape(type_of(where, init.spec, declaration.name)), initial_text(where, code, init.value)
    raise ExportError(where, f"{kind} is not a type this export writes (enumeration, array, structure "
                             "or alias)")


def _name(variable):
    inner = getattr(variable, "variable", variable)
    return str(getattr(inner, "name", inner))


def _plain(item):
    return str(item).splitlines()[-1]
