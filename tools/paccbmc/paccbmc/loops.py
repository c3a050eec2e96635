"""The loops an --unwindset names, checked against the source before CBMC runs: CBMC numbers a function's loops
in order (`FB_PAC_CMDINTERFACE_body_ref__.22`), so a statement added before a loop moves its number, and a
stale number in --unwindset bounds another loop without a word (the bound meant for the queue's WHILE then
cuts a FOR, or the WHILE falls back to --unwind). Each loop named carries a pattern (--loop NAME=TEXT): the
text its source line must contain, read from `cbmc --show-loops` on the C files that hold the loop's function."""
import json
import re
import subprocess
from pathlib import Path
from typing import Dict, List, Optional, Tuple

# CBMC renames a static function defined in several translation units (a header's static inline) foo$link1,
# foo$link2, ... when it links them; each copy has the same loops as foo.
_LINK = re.compile(r"\$link\d+$")


class LoopError(ValueError):
    """A loop of --unwindset that is not the one its pattern names, or has no pattern."""


def unwindset_loops(cbmc_args: List[str]) -> List[str]:
    """The loop ids of every --unwindset in CBMC's arguments (`id:bound,id:bound`), in order."""
    ids = []
    for i, arg in enumerate(cbmc_args[:-1]):
        if arg == "--unwindset":
            for entry in cbmc_args[i + 1].split(","):
                loop = entry.rsplit(":", 1)[0].strip()
                if loop and loop not in ids:
                    ids.append(loop)
    return ids


def parse_patterns(specs: List[str]) -> Dict[str, str]:
    """--loop NAME=TEXT options as a dict."""
    patterns = {}
    for spec in specs:
        name, sep, text = spec.partition("=")
        if not sep or not name or not text:
            raise LoopError(f"--loop {spec!r}: expected LOOP=TEXT (a loop id and the text of its source line)")
        patterns[name] = text
    return patterns


def base_function(loop: str) -> Tuple[str, str]:
    """`fn$link2.3` -> (`fn`, `3`)."""
    function, _, number = loop.rpartition(".")
    return _LINK.sub("", function), number


# A line of a unit of translated files (tests/cbmc/CMakeLists.txt, pac_cbmc_one_unit): one C file included.
_INCLUDED_C = re.compile(r'^#include "([^"]+\.c)"\s*$', re.MULTILINE)


def _files_of(c_file: Path) -> List[Path]:
    """A C file of CBMC's arguments, or the C files it includes when it is a unit of them."""
    included = _INCLUDED_C.findall(c_file.read_text(errors="replace"))
    return [c_file.parent / name for name in included] if included else [c_file]


def sources_for(loops: List[str], cbmc_args: List[str]) -> List[str]:
    """The C files among CBMC's arguments (or in a unit of them) that mention a function of the loops: enough for
    --show-loops to number them (a function's numbering depends on its own body only) at a fraction of the whole
    program's cost."""
    names = {base_function(loop)[0] for loop in loops}
    words = re.compile(r"\b(" + "|".join(re.escape(n) for n in sorted(names)) + r")\b")
    files = [f for a in cbmc_args if a.endswith(".c") and Path(a).is_file() for f in _files_of(Path(a))]
    return [str(f) for f in files if words.search(f.read_text(errors="replace"))]


def show_loops_args(cbmc_args: List[str], files: List[str]) -> List[str]:
    """--show-loops on the files given, with the run's preprocessor options (-I, -D)."""
    pre, i = [], 0
    while i < len(cbmc_args):
        arg = cbmc_args[i]
        if arg in ("-I", "-D") and i + 1 < len(cbmc_args):
            pre += [arg, cbmc_args[i + 1]]
            i += 1
        elif arg.startswith(("-I", "-D")) and len(arg) > 2:
            pre.append(arg)
        i += 1
    return [*pre, *files, "--show-loops", "--json-ui"]


def locations(show_loops_json: str) -> Dict[str, dict]:
    """Loop id -> sourceLocation from `cbmc --show-loops --json-ui`."""
    found = {}
    for message in json.loads(show_loops_json):
        for loop in (message.get("loops", []) if isinstance(message, dict) else []):
            found[loop["name"]] = loop.get("sourceLocation", {})
    return found


def _source_line(location: dict) -> Optional[str]:
    path = Path(location.get("file", ""))
    if not path.is_absolute():
        path = Path(location.get("workingDirectory", ".")) / path
    try:
        lines = path.read_text(errors="replace").splitlines()
        return lines[int(location["line"]) - 1]
    except (OSError, KeyError, ValueError, IndexError):
        return None


def check(loops: List[str], patterns: Dict[str, str], found: Dict[str, dict]) -> List[str]:
    """The problems: a loop without a pattern, a loop CBMC does not know, a loop whose line lacks the pattern."""
    problems = []
    for loop in loops:
        function, number = base_function(loop)
        pattern = patterns.get(loop, patterns.get(f"{function}.{number}"))  # one pattern for every $link copy
        if pattern is None:
            problems.append(f"{loop} in --unwindset has no --loop {loop}=TEXT naming the loop meant")
            continue
        location = found.get(loop) or found.get(f"{function}.{number}")
        if location is None:
            problems.append(f"{loop}: no such loop in `cbmc --show-loops` (has {function} fewer loops now?)")
            continue
        line = _source_line(location)
        if line is None or pattern not in line:
            problems.append(f"{loop} is now {location.get('file')}:{location.get('line')} `{(line or '?').strip()}`, "
                            f"not the loop meant (`{pattern}`): its number moved; find the loop's new number "
                            "with `cbmc --show-loops` and update the unwindset and its --loop")
    return problems


def verify(cbmc: str, cbmc_args: List[str], specs: List[str]) -> List[str]:
    """Every loop of the run's --unwindset checked against its pattern; the problems found (empty: all meant)."""
    loops = unwindset_loops(cbmc_args)
    if not loops:
        return []
    try:
        patterns = parse_patterns(specs)
    except LoopError as err:
        return [str(err)]
    files = sources_for(loops, cbmc_args)
    proc = subprocess.run([cbmc, *show_loops_args(cbmc_args, files)], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    try:
        found = locations(proc.stdout)
    except ValueError:
        return [f"`cbmc --show-loops` on {' '.join(files)} failed (exit {proc.returncode}): {proc.stderr[-2000:]}"]
    return check(loops, patterns, found)
