"""User mode: duration literals blark's grammar does not read, written before parsing as ones it reads that stand
for the same time. LTIME literals with microseconds and nanoseconds (`LTIME#1S2US44NS`, `LT#5MS100NS`), which it
reads only alone (`LTIME#5US`): their milliseconds, microseconds and nanoseconds become one fixed-point number of
milliseconds, which it reads after any unit: `LTIME#1S0.002044MS`. Literals that skip a unit (`T#1H500MS`,
`T#2D5S`), which IEC 61131-3 allows and the grammar does not: the units skipped are written as 0
(`T#1H0M0S500MS`). A literal keeps its first column; a longer spelling only moves the rest of its line
(rewrite.py)."""
import re

_LONG = {"LTIME", "LT"}
# the units of a duration, largest first, and their nanoseconds
_UNITS = {"D": 86400 * 10**9, "H": 3600 * 10**9, "M": 60 * 10**9, "S": 10**9, "MS": 10**6, "US": 10**3, "NS": 1}
_PART = re.compile(r"([0-9][0-9_]*(?:\.[0-9_]+)?)(MS|US|NS|D|H|M|S)_?", re.IGNORECASE)


def _parts(body):
    """[(number text, unit)] of a literal's body after `#` and its sign, or None when it is no duration."""
    parts, at = [], 0
    while at < len(body):
        m = _PART.match(body, at)
        if m is None:
            return None
        parts.append((m.group(1), m.group(2).upper()))
        at = m.end()
    return parts or None


def duration_edits(tokens):
    """([(start, end, replacement)], [(line, column, construct)]) for the duration literals among `tokens` (lexcheck's)
    that are LTIME literals whose microseconds or nanoseconds follow another unit, or that skip a unit."""
    edits, uses = [], []
    for tok in tokens:
        if tok.kind != "literal" or "#" not in tok.text:
            continue
        prefix, body = tok.text.split("#", 1)
        long = prefix.upper() in _LONG
        if not long and prefix.upper() not in ("T", "TIME"):
            continue
        sign = "-" if body.startswith("-") else ""
        parts = _parts(body[len(sign):])
        if parts is None or len(parts) < 2:
            continue
        order = [list(_UNITS).index(u) for _, u in parts]
        if order != sorted(set(order)) or any("." in n for n, _ in parts[:-1]):
            continue  # units out of order, a fraction before the last unit: left to the parser, which says so
        fine = [(n, u) for n, u in parts if u in ("MS", "US", "NS")]
        finer = any(u in ("US", "NS") for _, u in fine)
        if finer and not long:
            continue  # a TIME in microseconds: lexcheck refuses it
        coarse = [(n, u) for n, u in parts if u not in ("MS", "US", "NS")]
        merged = long and finer
        if merged and any("." in n for n, _ in fine):
            continue  # a fraction of a unit below the second: left to the parser
        if merged:
            ns = sum(int(n.replace("_", "")) * _UNITS[u] for n, u in fine)
            whole, rest = divmod(ns, 10**6)
            fraction = f"{rest:06d}".rstrip("0")
            fine = [(f"{whole}.{fraction}" if fraction else f"{whole}", "MS")]
        filled = _filled(coarse + fine)
        if not merged and len(filled) == len(parts):
            continue
        text = f"{prefix}#{sign}" + "".join(f"{n}{u}" for n, u in filled)
        edits.append((tok.start, tok.start + len(tok.text), text))
        if merged:
            uses.append((tok.line, tok.col, "an LTIME literal with microseconds or nanoseconds"))
        if len(filled) > len(coarse + fine):
            uses.append((tok.line, tok.col, "a duration literal that skips a unit"))
    return edits, uses


def _filled(parts):
    """`parts` (units in order, at most one below the second) with a 0 of every unit skipped between them."""
    units = list(_UNITS)
    have = dict((u, n) for n, u in parts)
    first, last = units.index(parts[0][1]), units.index(parts[-1][1])
    return [(have.get(u, "0"), u) for u in units[first:last + 1]]


def finer_than_milliseconds(prefix, literal):
    """The refusal of a duration literal whose units are not largest first, each once (`T#500MS1H`), or of a TIME
    literal (`T#1MS500US`) with microseconds or nanoseconds; or None."""
    parts = _parts(literal.lstrip("#").lstrip("-"))
    order = [list(_UNITS).index(u) for _, u in parts or ()]
    if order != sorted(set(order)):
        return (f"{prefix}{literal}: the units of a duration go from the largest to the smallest, each once "
                f"(D H M S MS US NS): write them in that order")
    if prefix.upper() not in ("T", "TIME"):
        return None
    if parts is None or not any(u in ("US", "NS") for _, u in parts):
        return None
    return (f"{prefix}{literal}: a TIME counts milliseconds in TwinCAT and CODESYS; write an LTIME for "
            f"microseconds and nanoseconds (LTIME{literal})")
