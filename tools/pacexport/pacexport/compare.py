"""The canonical form in which the checks compare two parses of the same object.

blark's text of a node without comments is its canonical form (T#1S and TIME#1S, spacing and
line breaks come out alike). Variables are compared one by one, so 'A, B : INT' equals 'A : INT;
B : INT;', which is how PLCopen lists them.
"""
from .blarkparse import flatten


def canonical_variables(items):
    result = []
    for item in items:
        names, _, rest = str(item).rstrip(";").partition(" : ")
        result += [(name.strip(), rest) for name in names.split(",")]
    return tuple(result)


def canonical(node):
    kind = type(node).__name__
    if kind in ("FunctionBlock", "Function", "Program"):
        header = tuple(str(getattr(node, a, None)) for a in ("name", "return_type", "access", "extends",
                                                             "implements"))
        blocks = tuple((type(b).__name__, str(getattr(b, "attrs", None) or ""), canonical_variables(b.items))
                       for b in node.declarations)
        return (kind, header, blocks, None if node.body is None else str(node.body))
    if kind == "DataTypeDeclaration":
        declaration = node.declaration
        if type(declaration).__name__ == "StructureTypeDeclaration":
            return ("STRUCT", str(declaration.name), canonical_variables(declaration.declarations))
        return (type(declaration).__name__, str(declaration))
    if kind == "GlobalVariableDeclarations":
        return ("VAR_GLOBAL", str(node.attrs or ""), canonical_variables(node.items))
    if kind == "StatementList":
        return ("BODY", str(node))
    raise ValueError(f"no canonical form for {kind}")


def canonical_items(cache, items, where):
    """The canonical form of every part (declaration, implementation) of blark source items."""
    forms = []
    for item in flatten(items):
        nodes = cache.parse_item(item, where).items(comments=False)
        forms += [canonical(n) for n in nodes]
    return forms
