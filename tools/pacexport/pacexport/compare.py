"""The canonical form in which the checks compare two parses of the same object.

blark's text of a node without comments is its canonical form (T#1S and TIME#1S, spacing and
line breaks come out alike). Variables are compared one by one, so 'A, B : INT' equals 'A : INT;
B : INT;', which is how PLCopen lists them. Both sides are cut into blark's source items as blark
reads TwinCAT's files (a declaration and an implementation) and parsed by the translator's parser.
"""
from blark.input import BlarkCompositeSourceItem, BlarkSourceItem, BlarkSourceLine
from blark.util import SourceType
from pacst.parsing import parse_text

SOURCE_TYPES = {
    "dataType": SourceType.dut,
    "function": SourceType.function,
    "functionBlock": SourceType.function_block,
    "program": SourceType.program,
    "globalVars": SourceType.var_global,
}


def source_items(kind, name, declaration, body):
    """The items blark makes of a TwinCAT object with this declaration and body: the same rules and
    implicit ends, so that source and export are parsed alike."""
    source_type = SOURCE_TYPES[kind]
    parts = [BlarkSourceItem(identifier=f"{name}/declaration", type=source_type,
                             lines=BlarkSourceLine.from_code(declaration),
                             grammar_rule=source_type.get_grammar_rule(),
                             implicit_end=source_type.get_implicit_block_end())]
    if body is not None:
        parts.append(BlarkSourceItem(identifier=f"{name}/implementation", type=source_type,
                                     lines=BlarkSourceLine.from_code(body),
                                     grammar_rule=SourceType.statement_list.name,
                                     implicit_end=SourceType.statement_list.get_implicit_block_end()))
    return parts


def flatten(items):
    for item in items:
        if isinstance(item, BlarkCompositeSourceItem):
            yield from flatten(item.parts)
        else:
            yield item


def parse_item(cache_dir, item, where):
    """Parses one blark source item (a declaration or an implementation) as blark.parse would."""
    code, _ = item.get_code_and_line_map()
    return parse_text(code, f"{where} ({item.identifier})", cache_dir, item.grammar_rule)


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


def canonical_items(cache_dir, items, where):
    """The canonical form of every part (declaration, implementation) of blark source items."""
    forms = []
    for item in flatten(items):
        nodes = parse_item(cache_dir, item, where).items(comments=False)
        forms += [canonical(n) for n in nodes]
    return forms
