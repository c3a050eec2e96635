"""A program's own libraries (user mode, `--library NAME=PATH`): a project split into a library and the
application that references it under a namespace (TwinCAT's and CODESYS's library reference), so that
`NAME.FB_X`, `NAME.GVL.x`, `IMPLEMENTS NAME.I_Y` and `EXTENDS NAME.FB_Z` resolve. A library is a TwinCAT
`.plcproj` (or the folder holding one), a PLCopen XML project, or a folder of `.st` and TwinCAT object files;
its declarations are those of the files under its folder (the compiler's namespaces, `--namespace`)."""
import os

from . import plcopen_read, twincat
from .errors import StError

# what pacst reads of a folder given as a library without a .plcproj
SOURCE_EXTENSIONS = (".st",) + twincat.OBJECT_EXTENSIONS


class LibraryError(Exception):
    """A library given wrong: the message names where it is given (`--library NAME`, or the wiring file's key)."""


def parse(items):
    """[(NAME, PATH)] of `NAME=PATH` texts; a LibraryError for a malformed one, a namespace given twice or a
    library given twice (under two namespaces)."""
    found = []
    for item in items:
        name, sep, path = item.partition("=")
        name = name.strip()
        if not sep or not name or not path:
            raise LibraryError(f"--library {item}: write NAMESPACE=PATH (a .plcproj, a PLCopen XML file or a folder)")
        found.append((name, path))
    check(found)
    return found


def check(libraries, labels=None):
    """A LibraryError for a namespace given twice, a library given twice, a PATH that is no library; `labels`
    (one per library, default `--library NAME`) say where each is given."""
    labels = labels or [f"--library {name}" for name, _ in libraries]
    names, paths = {}, {}
    for (name, path), label in zip(libraries, labels):
        if not name.replace("_", "").isalnum() or name[0].isdigit():
            raise LibraryError(f"{label}: the namespace {name} is no ST identifier")
        if name.upper() in names:
            raise LibraryError(f"{label}: the namespace {name} is given twice, also by {names[name.upper()]} "
                               "(namespaces are case-insensitive)")
        key = os.path.realpath(path)
        if key in paths:
            raise LibraryError(f"{label}: {path} is given twice, also by {paths[key]}")
        if not (os.path.isdir(path) or os.path.isfile(path) and path.lower().endswith((".plcproj", ".xml"))):
            raise LibraryError(f"{label}: {path} is no library (a .plcproj, a PLCopen XML file or a folder)")
        names[name.upper()], paths[key] = label, label


def project_file(path):
    """The .plcproj a library folder holds (one), or None."""
    if not os.path.isdir(path):
        return path if path.lower().endswith(".plcproj") else None
    found = [n for n in sorted(os.listdir(path)) if n.lower().endswith(".plcproj")]
    return os.path.join(path, found[0]) if len(found) == 1 else None


def folder(name, path, sources_dir):
    """The folder whose declarations the library `name` at `path` holds: a PLCopen XML project's objects are
    written to `sources_dir`/NAME."""
    if path.lower().endswith(".xml") and not os.path.isdir(path):
        return os.path.abspath(os.path.join(sources_dir, name))
    return os.path.abspath(path if os.path.isdir(path) else os.path.dirname(path))


def files(name, path, sources_dir):
    """The ST and TwinCAT files of the library `name` at `path`; raises StError on a project it cannot read."""
    plcproj = project_file(path)
    if plcproj is not None:
        return twincat.project_files(plcproj, generated=False)
    if os.path.isdir(path):
        found = sorted(os.path.join(d, n) for d, _, names in os.walk(path) for n in names
                       if n.lower().endswith(SOURCE_EXTENSIONS))
        if not found:
            raise StError(path, 1, 1, f"the library {name}: no .plcproj and no ST or TwinCAT file in this folder")
        return [os.path.abspath(f) for f in found]
    return plcopen_read.extract(path, folder(name, path, sources_dir))
