"""User mode: a library's checked state kept in a file (`pacst library`), so that `pacst build --user
--checked-library FILE` neither parses nor checks the library's files again (docs/translator.md, "A library
checked once"). The file holds the parsed files and the Compiler that declared them, and is taken only where it
stands for what this run would make itself: the same translator and packages, the same text of every file it holds (a
SHA-256 each), every one of them given to this run, and nothing of the run's that the check could have seen (a
namespace or a native FUNCTION it did not have). Anything else and the run parses and checks them as it would
without the file: a stale file costs time, never a wrong result."""
import glob
import hashlib
import os
import pickle
import sys
import tempfile
import types

import blark
import lark

from . import order, parsing, system
from .compiler import Compiler
from . import types as T

FORMAT = 1
_CODE = (types.FunctionType, types.BuiltinFunctionType, types.MethodType, types.ModuleType, type)
_PLAIN = (int, float, bool, str, bytes, type(None))


def _translator_version():
    """What the pickled state depends on besides the files: the translator's source and the packages' versions."""
    here = os.path.dirname(__file__)
    sources = parsing._sources_version(sorted(glob.glob(os.path.join(here, "**", "*.py"), recursive=True)))
    versions = f"{FORMAT}|{blark.__version__}|{lark.__version__}|{sys.version}|{sources}"
    return hashlib.sha256(versions.encode()).hexdigest()


def _digest(path):
    """The SHA-256 of the file's bytes, or None for a file that cannot be read."""
    try:
        with open(path, "rb") as f:
            return hashlib.sha256(f.read()).hexdigest()
    except OSError:
        return None


def _module_objects():
    """{path: object} of every object reachable from the translator's modules that the compiler compares by identity
    (the elementary and standard types, __SYSTEM's): the file names each by a path, so that a run takes its own."""
    found, seen = {}, set()
    stack = [(f"{mod.__name__}.{name}", value) for mod in (T, system) for name, value in sorted(vars(mod).items())
             if not isinstance(value, _CODE) and not name.startswith("__")]
    while stack:
        path, obj = stack.pop()
        if isinstance(obj, _PLAIN) or isinstance(obj, _CODE):
            continue
        found[path] = obj
        if id(obj) in seen:
            continue
        seen.add(id(obj))
        if isinstance(obj, dict):
            stack += [(f"{path}[{k!r}]", v) for k, v in obj.items() if isinstance(k, _PLAIN)]
        elif isinstance(obj, (list, tuple)):
            stack += [(f"{path}[{i}]", v) for i, v in enumerate(obj)]
        elif not isinstance(obj, (set, frozenset)):
            stack += [(f"{path}.{k}", v) for k, v in sorted(getattr(obj, "__dict__", {}).items())]
    return found


class _Pickler(pickle.Pickler):
    def __init__(self, file, paths):
        super().__init__(file, protocol=pickle.HIGHEST_PROTOCOL)
        self.paths = paths  # id -> path

    def persistent_id(self, obj):
        return self.paths.get(id(obj))


def save(path, sources, comp):
    """Writes the checked state of the library files `sources` (SourceFiles, declared by `comp` without a
    refusal) to `path`, atomically."""
    objects = _module_objects()
    paths = {}
    for key, obj in sorted(objects.items(), reverse=True):
        paths[id(obj)] = key
    header = {"format": FORMAT, "translator": _translator_version(), "namespaces": dict(comp.namespaces),
              "natives": sorted(comp.native_files & {src.path for src in sources}),
              "files": {src.path: _digest(src.path) for src in sources}}
    mentioned = {src.path: order.mentioned(src) for src in sources}
    header["names"] = sorted(set().union(*mentioned.values()))
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=folder, suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            pickle.dump(header, f, protocol=pickle.HIGHEST_PROTOCOL)
            _Pickler(f, paths).dump((list(sources), comp, mentioned))
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


class Kept:
    """A library's checked state read from its file: `sources` (by path) and `compiler(native, namespaces)`."""

    def __init__(self, sources, comp):
        self.sources = sources
        self.by_path = {src.path: src for src in sources}
        self._comp = comp
        self.used = False  # the run declared its program on the kept Compiler (cli._translate_parsed)

    def covers(self, library):
        """Whether the run's library files (user_order's first list) hold every file kept, as kept: a program
        that declares a name the library uses keeps its file out of the library, which this state cannot show."""
        ids = {id(src) for src in library}
        return all(id(src) in ids for src in self.sources)

    def compiler(self, native, namespaces):
        """The kept Compiler with the run's natives and namespaces (load() made sure the check saw no difference)."""
        comp, self._comp = self._comp, None
        comp.native_files = set(native)
        comp.namespaces = {k.upper(): v for k, v in (namespaces or {}).items()}
        return comp


def load(path, files, native, namespaces):
    """(Kept or None, why not): the state in `path` where it stands for this run's `files`, `native` and
    `namespaces` (--namespace as the Compiler takes them)."""
    try:
        with open(path, "rb") as f:
            header = pickle.load(f)
            if not isinstance(header, dict) or header.get("format") != FORMAT:
                return None, "another format"
            why = _stale(header, files, native, {k.upper(): v for k, v in (namespaces or {}).items()})
            if why:
                return None, why
            objects = _module_objects()
            unpickler = pickle.Unpickler(f)
            unpickler.persistent_load = objects.__getitem__
            with parsing.LoadingTrees(always=True):
                sources, comp, mentioned = unpickler.load()
    except FileNotFoundError:
        return None, "no such file"
    except Exception as e:  # a damaged file, or one of a translator whose objects this one lacks
        return None, f"unreadable ({type(e).__name__})"
    for src in sources:
        order._MENTIONED[src] = mentioned[src.path]
    return Kept(sources, comp), None


def _stale(header, files, native, namespaces):
    """Why the file's state does not stand for this run, or None."""
    if header.get("translator") != _translator_version():
        return "made by another translator or packages"
    given = set(files)
    for path, digest in header["files"].items():
        if path not in given:
            return f"{path} is not given"
        if _digest(path) != digest:
            return f"{path} changed"
    kept = set(header["files"])
    if sorted(set(native) & kept) != header["natives"]:
        return "other native files"
    before = header["namespaces"]
    for path in kept:  # each file in the same library, under the same folder
        owner = [next((up for up, (_, folder) in spaces.items() if Compiler._under(path, folder)), None)
                 for spaces in (before, namespaces)]
        if owner[0] != owner[1] or (owner[1] is not None and tuple(before[owner[0]]) != tuple(namespaces[owner[1]])):
            return f"{path} is given under another namespace"
    # a namespace the check did not have changes nothing of it unless the files name it (Name.x, or a declaration
    # of that name, which the compiler refuses)
    named = (set(namespaces) - set(before)) & set(header["names"])
    if named:
        return f"the files name the namespace {min(named)}, which their check did not have"
    return None

