"""Reads the library's ST files into the model the exports write."""
from dataclasses import dataclass
from typing import List

from pacst.errors import StError
from pacst.parsing import parse_text

from .declarations import data_type_shape, type_of, var_blocks
from .errors import ExportError
from .metadata import LibraryInfo
from .model import DataType, GlobalList, Pou
from .splitting import END_OF, read_source

# A global list is used as GVL_PAC.PAC_CMD_STOP: the FBs' local constants of the same names
# (docs/constants.md) then never meet the list's (docs/import.md).
GLOBAL_LIST_ATTRIBUTES = ("qualified_only",)


@dataclass
class Library:
    info: LibraryInfo
    data_types: List[DataType]
    pous: List[Pou]
    global_lists: List[GlobalList]

    def objects(self):
        return [*self.data_types, *self.pous, *self.global_lists]


def load_library(info, sources, global_lists, cache_dir=None):
    """sources: the library's files in declaration order; global_lists: its VAR_GLOBAL files; cache_dir:
    the translator's parse cache (pacst.parsing), shared with its builds."""
    library = Library(info, [], [], [])
    names = {}
    for path in [*sources, *global_lists]:
        source = read_source(path)
        if source.name.upper() in names:
            raise ExportError(path, f"{source.name} is declared in {names[source.name.upper()]} too")
        names[source.name.upper()] = path
        code = _object_text(source)
        try:
            node = _single(path, parse_text(code, path, cache_dir).items())
        except StError as exc:
            raise ExportError(path, f"{exc.line}:{exc.col}: {exc.message}") from None
        if source.kind == "dataType":
            shape, initial = data_type_shape(path, code, node.declaration)
            library.data_types.append(DataType(source, shape, initial))
        elif source.kind == "globalVars":
            (block,) = var_blocks(path, code, [node])
            library.global_lists.append(GlobalList(source, block, GLOBAL_LIST_ATTRIBUTES))
        else:
            library.pous.append(Pou(source, _return_type(path, node), var_blocks(path, code, node.declarations)))
    return library


def _object_text(source):
    """The object as the translator's parser reads it: the declaration first, so that the parse's
    offsets are the declaration's (declarations.initial_text cuts initial values out at them)."""
    if source.body is None:
        return source.declaration
    return f"{source.declaration}{source.body}\n{END_OF[source.kind]}\n"


def _single(path, items):
    if len(items) != 1:
        raise ExportError(path, f"holds {len(items)} declarations; the export takes one per file")
    return items[0]


def _return_type(path, node):
    ret = getattr(node, "return_type", None)
    return None if ret is None else type_of(path, ret, "return type")
