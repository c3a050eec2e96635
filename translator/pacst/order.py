"""The declaration order of a set of ST files, derived from the files themselves: MATIEC (and pacst) need
every type, enumeration value and POU declared before the file that uses it.

A file depends on every other file that declares a name it mentions (a type, an FB, a FUNCTION or an
enumeration value: the portable subset makes these one global namespace, so a local variable cannot take
such a name). The order is a topological sort; among the files that are ready at the same time the one
with the smaller file name (then path) comes first, so the order does not depend on how the files were
listed or in which folders they are.
"""
import dataclasses
import functools
import heapq
import os
import re
import types
import weakref

import lark

from .common import _cls, _name, pos
from .errors import StError, StErrors

_IDENTIFIER_TOKENS = {"IDENTIFIER", "DOTTED_IDENTIFIER"}
_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def declared_names(tree):
    """The global names `tree` declares, as spelled there: its types, their enumeration values and its
    POUs."""
    names = []
    for item in tree.items:
        if _cls(item) == "DataTypeDeclaration":
            decl = item.declaration
            if getattr(decl, "name", None) is not None:
                names.append(_name(decl.name))
            spec = getattr(getattr(decl, "init", None), "spec", None)
            names += [_name(value.name) for value in getattr(spec, "values", None) or []]
        elif getattr(item, "name", None) is not None and _cls(item) not in ("Method", "Action", "Property"):
            names.append(_name(item.name))  # a METHOD's name is its FB's, not global
    return names


@functools.lru_cache(maxsize=None)
def _fields(cls):
    """The names of the fields of the AST class `cls` but its meta (positions), or None for a class of no
    dataclass."""
    if not dataclasses.is_dataclass(cls):
        return None
    return tuple(f.name for f in dataclasses.fields(cls) if f.name != "meta")


def mentioned_names(tree):
    """The upper-case identifiers `tree` mentions anywhere (declarations, calls, expressions); a dotted
    or typed name (a.b, E_Type#Value) counts each of its parts."""
    words = set()
    stack = list(tree.items)
    while stack:
        node = stack.pop()
        if isinstance(node, lark.Token):
            if node.type in _IDENTIFIER_TOKENS:
                words.update(w.upper() for w in _WORD.findall(str(node)))
        elif isinstance(node, (list, tuple)):
            stack.extend(node)
        else:
            names = _fields(type(node))
            if names is not None:
                stack.extend(getattr(node, name) for name in names)
    return words


# A parsed file's mentioned names, for as long as the file is held: a tool that orders one library with each
# of several programs (the dialect page's check, pac-test's corpus) walks the library's trees once.
_MENTIONED = weakref.WeakKeyDictionary()


def mentioned(src):
    """mentioned_names of the parsed file `src`, kept for as long as the file is held."""
    found = _MENTIONED.get(src)
    if found is None:
        found = _MENTIONED[src] = frozenset(mentioned_names(src.tree))
    return found


def shadowed_library_files(sources, library_of):
    """User mode: the library files the program's own declarations shadow, {path: (namespace, [names], (program
    file, line))}, and `sources` without them. TwinCAT and CODESYS keep a library's names apart from the
    application's: a POU of the application named like one of the library (a test project's MAIN beside its
    library's) is the one its plain name means, and the library's stays `Namespace.Name`. pacst's C holds one
    declaration of each name, so a library file whose every declaration the program declares too is left out
    where no other file of the libraries names them; where one does, both stay and the compiler refuses the name
    as declared twice, with what to do. `library_of(path)`: the namespace of the library holding a file, or None."""
    own = {}
    for src in sources:
        if library_of(src.path) is None:
            for item in src.tree.items:
                for name in declared_names(types.SimpleNamespace(items=[item])):
                    own.setdefault(name.upper(), (src.path, pos(item)[0]))
    in_libraries = [src for src in sources if library_of(src.path) is not None]
    left = {}
    for src in in_libraries:
        names = declared_names(src.tree)
        ups = {name.upper() for name in names}
        if not ups or not ups <= own.keys():
            continue
        if any(other is not src and ups & mentioned(other) for other in in_libraries):
            continue
        left[src.path] = (library_of(src.path), names, own[names[0].upper()])
    return left, [src for src in sources if src.path not in left]


def _sort_key(path):
    return os.path.basename(path), path


def _cycle(deps, left):
    """One cycle among the files `left` (each has a dependency in `left`): [(file, name it uses)...]."""
    start = min(left, key=_sort_key)
    seen, path = {}, []
    node = start
    while node not in seen:
        seen[node] = len(path)
        dep, name = min(((d, n) for d, n in deps[node].items() if d in left), key=lambda dn: _sort_key(dn[0]))
        path.append((node, name))
        node = dep
    return path[seen[node]:]


def _list_files(sources, owner):
    """User mode: {path of a file of global lists only: {upper variable name: the paths of the files declaring the
    types its declaration names}}."""
    lists = {}
    for src in sources:
        items = src.tree.items
        if not items or any(_cls(item) != "GlobalVariableDeclarations" for item in items):
            continue
        found = lists[src.path] = {}
        for block in items:
            for item in block.items:
                words = mentioned_names(types.SimpleNamespace(items=[item.init]))
                paths = {owner[w][0] for w in words if w in owner and owner[w][0] != src.path}
                for token in item.spec.variables:
                    found[_name(token).upper()] = paths
    return lists


def _through_lists(src, uses, lists):
    """User mode: the uses of the POU file `src` with each global list it names replaced by the files of the types
    of the list's variables it names: a compiler in user mode declares every list before the POUs, but an
    instance of an FB of the program only after that FB (TcUnit's GVL_TcUnit holds an FB_TcUnitRunner, whose
    FB_AdsTestResultLogger reads GVL_TcUnit.AdsMessageQueue)."""
    if any(_cls(item) in ("DataTypeDeclaration", "GlobalVariableDeclarations") for item in src.tree.items):
        return uses
    words = mentioned(src)
    kept = {}
    for dep, name in uses.items():
        if dep not in lists:
            kept.setdefault(dep, name)
            continue
        for var, paths in lists[dep].items():
            if var in words:
                for path in paths - {src.path}:
                    kept.setdefault(path, name)
    return kept


def _owners(sources):
    """{upper name: (path of the file that declares it, the name as spelled there)}. A name declared twice is the
    compiler's to refuse; here the first file (by sort key) owns it."""
    owner = {}
    for src in sorted(sources, key=lambda s: _sort_key(s.path)):
        for name in declared_names(src.tree):
            owner.setdefault(name.upper(), (src.path, name))
    return owner


def _uses(src, owner):
    """{path of another file: a name `src` mentions that the file declares}."""
    uses = {}
    words = mentioned(src)
    if words & {"TIME", "LTIME"}:  # CODESYS's TIME() and LTIME() read Tc2_System's F_GetSystemTime (expressions.py)
        words = words | {"F_GETSYSTEMTIME"}
    for word in sorted(words):
        dep, name = owner.get(word, (src.path, None))
        if dep != src.path:
            uses.setdefault(dep, name)
    return uses


def closed_under_uses(sources, candidates):
    """The paths of `candidates` (paths of `sources`, a library's files) that mention no name of a file outside
    them, nor through the files they use: these can be declared and checked before the rest. A name the rest
    declares too (or a word of theirs it declares, even a local variable's) keeps a candidate out."""
    owner = _owners(sources)
    deps = {src.path: set(_uses(src, owner)) for src in sources}
    closed = set(candidates)
    changed = True
    while changed:
        changed = False
        for path in sorted(closed):
            if not deps[path] <= closed:
                closed.discard(path)
                changed = True
    return closed


def _sorted(deps):
    """(the paths of `deps` {path: {path it depends on: name}} in declaration order, the paths left in a cycle)."""
    users = {path: [] for path in deps}
    for path, uses in deps.items():
        for dep in uses:
            users[dep].append(path)
    waiting = {path: len(uses) for path, uses in deps.items()}
    ready = [_sort_key(path) for path, n in waiting.items() if n == 0]
    heapq.heapify(ready)
    order = []
    while ready:
        _, path = heapq.heappop(ready)
        order.append(path)
        for user in users[path]:
            waiting[user] -= 1
            if waiting[user] == 0:
                heapq.heappush(ready, _sort_key(user))
    return order, {path for path, n in waiting.items() if n > 0}


def _interface_file(src):
    """The upper names the INTERFACE of the file `src` EXTENDS, or None for a file that declares more than an
    INTERFACE and its METHODs and PROPERTYs."""
    kinds = [_cls(item) for item in src.tree.items]
    if kinds.count("Interface") != 1 or not set(kinds) <= {"Interface", "Method", "Property"}:
        return None
    itf = next(item for item in src.tree.items if _cls(item) == "Interface")
    bases = itf.extends.interfaces if itf.extends is not None else []
    return {_name(token).upper().rsplit(".", 1)[-1] for token in bases}


def _signature_uses(by_path, left, deps):
    """User mode: the dependencies (path, path it uses) among the files `left` of a cycle that are an INTERFACE
    naming another INTERFACE in its METHODs' or PROPERTYs' pins and results only (not as its base): pacst's user
    mode declares such a name ahead of its INTERFACE (compiler._interface), so they need no order."""
    found = set()
    for path in left:
        bases = _interface_file(by_path[path])
        if bases is None:
            continue
        for dep, name in deps[path].items():
            if dep in left and _interface_file(by_path[dep]) is not None and name.upper() not in bases:
                found.add((path, dep))
    return found


def declaration_order(sources, user=False):
    """The parsed files `sources` (SourceFiles) in declaration order; raises StErrors naming the files of a
    cycle, whose files no order can declare before each other. `user`: pacst's user mode, which declares the
    global lists before the POUs (_through_lists)."""
    owner = _owners(sources)
    lists = _list_files(sources, owner) if user else {}
    deps = {}  # path -> {path it depends on: a name it uses from there}
    for src in sources:
        uses = _uses(src, owner)
        deps[src.path] = _through_lists(src, uses, lists) if user else uses
    order, left = _sorted(deps)
    if left and user:  # INTERFACEs whose METHODs name each other: declared in turn, each naming the later one ahead
        signatures = _signature_uses({src.path: src for src in sources}, left, deps)
        if signatures:
            deps = {path: {dep: name for dep, name in uses.items() if (path, dep) not in signatures}
                    for path, uses in deps.items()}
            order, left = _sorted(deps)
    if left:
        cycle = _cycle(deps, left)
        text = " -> ".join(f"{os.path.basename(path)} (uses {name})" for path, name in cycle)
        raise StErrors([StError(cycle[0][0], 1, 1, f"declaration cycle, no order declares each of these files "
                                                   f"before its users: {text} -> {os.path.basename(cycle[0][0])}")])
    return order
