"""Architecture.Dependencies: the folders' dependencies in the tree against the rules of
docs/architecture.md ("The dependency rules"), so that the page and the tree cannot part.

The page's table names, for each folder of code, the folders it may link (a CMake `target_link_libraries`
of a target another folder defines) and the folders it may include or import from (a C or C++ `#include`
of a header found in another folder, the headers pacst generates counting as the library's, `st/`; a
Python `import` of another folder's package). A folder's rules cover its subfolders unless the table has
a row of their own. The test fails naming the file and line of every dependency the page does not allow,
and every folder of code the page has no row for.

Usage: check_architecture.py <repository root> [--print]   (--print lists the dependencies found)"""
import os
import re
import subprocess
import sys

PAGE = "docs/architecture.md"
SECTION = "## The dependency rules"
SOURCES = (".c", ".cpp", ".h", ".hpp")
# Headers pacst writes from the library's ST (the build's, not the tree's): the library's interface.
GENERATED = {"POUS.h": "st", "GVL_PAC.h": "st", "pacst_enum_names.h": "st"}
# The Python packages of the tree and their folders.
PACKAGES = {"pacst": "translator", "pacexport": "tools/pacexport", "pacrelease": "tools/pacrelease",
            "pactest": "tools/pactest", "paccbmc": "tools/paccbmc"}
# Folders that hold no code of their own.
NO_CODE = ("docs/", "examples/", ".ci/", "cmake/")

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
IMPORT = re.compile(r"^\s*(?:from|import)\s+([A-Za-z_]\w*)")
LINK = re.compile(r"target_link_libraries\s*\(\s*(\S+)([^)]*)\)", re.S)
DEFINE = re.compile(r"\b(?:add_library|add_executable|pac_st_library)\s*\(\s*([A-Za-z_][\w-]*)")
FOLDER_CELL = re.compile(r"`([^`]+)/`")


def tracked(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-z"], check=True, capture_output=True).stdout
    return sorted(n for n in out.decode().split("\0") if n)


def rules(root):
    """{folder: (may link, may include)} from the page's table."""
    with open(os.path.join(root, PAGE), encoding="utf-8") as f:
        text = f.read()
    if SECTION not in text:
        raise SystemExit(f"{PAGE} has no section '{SECTION}'")
    table = {}
    for line in text.split(SECTION, 1)[1].split("\n## ", 1)[0].splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 3 and cells[0].startswith("`"):
            folder = FOLDER_CELL.findall(cells[0])
            if folder:
                table[folder[0]] = (set(FOLDER_CELL.findall(cells[1])), set(FOLDER_CELL.findall(cells[2])))
    return table


def unit(path, folders):
    """The folder of the table that `path` belongs to: the longest that holds it."""
    best = None
    for folder in folders:
        if path.startswith(folder + "/") and (best is None or len(folder) > len(best)):
            best = folder
    return best


def dependencies(root, files, folders):
    """[(kind, from folder, to folder, where)] of every dependency between two folders of the table."""
    found = []
    headers = {}
    for name in files:
        if name.endswith(SOURCES):
            headers.setdefault(os.path.basename(name), []).append(name)
    targets = {}
    cmake_files = [n for n in files if os.path.basename(n) == "CMakeLists.txt"]
    for name in cmake_files:
        with open(os.path.join(root, name), encoding="utf-8") as f:
            for target in DEFINE.findall(f.read()):
                if not target.startswith("$"):
                    targets[target] = os.path.dirname(name)
    for name in cmake_files:
        source = unit(name, folders)
        with open(os.path.join(root, name), encoding="utf-8") as f:
            text = f.read()
        for m in LINK.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            for target in m.group(2).split():
                target_unit = unit(targets[target] + "/CMakeLists.txt", folders) if target in targets else None
                if source and target_unit and target_unit != source:
                    found.append(("links", source, target_unit, f"{name}:{line} ({target})"))
    for name in files:
        source = unit(name, folders)
        if source is None or not name.endswith(SOURCES + (".py",)):
            continue
        with open(os.path.join(root, name), encoding="utf-8", errors="replace") as f:
            lines = f.read().splitlines()
        for number, line in enumerate(lines, 1):
            for to in _targets_of(name, line, headers, folders):
                if to and to != source:
                    found.append(("includes", source, to, f"{name}:{number}"))
    return found


def _targets_of(name, line, headers, folders):
    if name.endswith(".py"):
        m = IMPORT.match(line)
        return [PACKAGES.get(m.group(1))] if m else []
    m = INCLUDE.match(line)
    if not m:
        return []
    include = m.group(1)
    if include in GENERATED:
        return [GENERATED[include]]
    relative = os.path.normpath(os.path.join(os.path.dirname(name), include))
    candidates = [p for p in headers.get(os.path.basename(include), [])
                  if p == relative or p.endswith("/" + include)]
    if not candidates:
        return []  # a system or package header
    units = {unit(p, folders) for p in candidates}
    own = unit(name, folders)
    return [] if own in units else sorted(u for u in units if u)


def main(argv):
    if len(argv) not in (2, 3) or argv[2:] not in ([], ["--print"]):
        print(__doc__, file=sys.stderr)
        return 2
    root = argv[1]
    table = rules(root)
    files = tracked(root)
    problems = []
    unruled = sorted({"/".join(n.split("/")[:2 if n.startswith("tools/") else 1]) for n in files
                      if "/" in n and n.endswith(SOURCES + (".py", "CMakeLists.txt"))
                      and not n.startswith(NO_CODE) and unit(n, table) is None})
    problems += [f"{PAGE}: no rule for the folder '{folder}/', which holds code" for folder in unruled]
    deps = dependencies(root, files, table)
    for kind, source, to, where in deps:
        links, includes = table[source]
        allowed = links if kind == "links" else includes | links
        if to not in allowed:
            problems.append(f"{where}: `{source}/` {kind} `{to}/`, which {PAGE} does not allow")
    if len(argv) == 3:
        for edge in sorted({(s, k, t) for k, s, t, _ in deps}):
            print(f"{edge[0]}/ {edge[1]} {edge[2]}/")
    for problem in problems:
        print(problem, file=sys.stderr)
    if not problems:
        print(f"every dependency of {len(table)} folders as {PAGE} allows")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
