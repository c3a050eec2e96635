"""Parses code the way blark reads TwinCAT's files, and memoises the parse on disk.

blark's Earley parser needs several milliseconds per line, and the export and its checks read the same
declarations and bodies several times (the source, the TwinCAT files, the PLCopen round trip). A parse
is a pure function of the grammar rule, the code and the versions of blark and lark, so it is stored
under the SHA-256 of those and read back instead of being repeated; a failed parse is never stored.
"""
import hashlib
import os
import pickle
import tempfile

import blark
import lark
from blark import transform as tf
from blark.input import BlarkCompositeSourceItem, BlarkSourceItem, BlarkSourceLine
from blark.parse import parse_source_code
from blark.util import SourceType

_FORMAT = 1

SOURCE_TYPES = {
    "dataType": SourceType.dut,
    "function": SourceType.function,
    "functionBlock": SourceType.function_block,
    "program": SourceType.program,
    "globalVars": SourceType.var_global,
}


class ParseFailure(Exception):
    pass


class Parsed:
    """One parse: the code blark saw, its tree and its comments."""

    def __init__(self, code, tree, comments):
        self.code = code
        self.tree = tree
        self.comments = comments

    def items(self, comments=True):
        """blark's typed items; without comments their text is the canonical form of the code."""
        source = tf.transform(source_code=self.code, tree=self.tree,
                              comments=list(self.comments) if comments else [])
        return source.items


class ParseCache:
    def __init__(self, directory=None):
        self.directory = directory

    def parse(self, code, rule, where):
        key = hashlib.sha256(
            f"{_FORMAT}|{blark.__version__}|{lark.__version__}|{rule}|{code}".encode("utf-8")).hexdigest()
        stored = os.path.join(self.directory, key + ".pickle") if self.directory else None
        if stored and os.path.exists(stored):
            try:
                with open(stored, "rb") as f:
                    return Parsed(code, *pickle.load(f))
            except Exception:  # a damaged entry is parsed again, never trusted
                pass
        result = parse_source_code(code, starting_rule=rule, fn=where)
        if result.exception is not None:
            raise ParseFailure(f"{where}: blark cannot parse this as {rule}: {result.exception}")
        if stored:
            os.makedirs(self.directory, exist_ok=True)
            fd, tmp = tempfile.mkstemp(dir=self.directory, suffix=".tmp")
            with os.fdopen(fd, "wb") as f:
                pickle.dump((result.tree, result.comments), f, protocol=pickle.HIGHEST_PROTOCOL)
            os.replace(tmp, stored)
        return Parsed(code, result.tree, result.comments)

    def parse_item(self, item, where):
        """Parses one blark source item (a declaration or an implementation) as blark.parse would."""
        code, _ = item.get_code_and_line_map()
        return self.parse(code, item.grammar_rule, f"{where} ({item.identifier})")


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
