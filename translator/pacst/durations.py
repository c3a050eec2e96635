"""User mode: LTIME literals with microseconds and nanoseconds (`LTIME#1S2US44NS`, `LT#5MS100NS`), which
blark's grammar reads only alone (`LTIME#5US`), not after another unit. Before parsing, the milliseconds,
microseconds and nanoseconds of such a literal are written as one fixed-point number of milliseconds, which
the grammar reads after any unit and which stands for the same nanoseconds: `LTIME#1S0.002044MS`. A literal
keeps its first column; a longer spelling only moves the rest of its line (rewrite.py)."""
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


def long_time_edits(tokens):
    """([(start, end, replacement)], [(line, column, construct)]) for the LTIME literals among `tokens` (lexcheck's)
    whose microseconds or nanoseconds follow another unit."""
    edits, uses = [], []
    for tok in tokens:
        if tok.kind != "literal" or "#" not in tok.text:
            continue
        prefix, body = tok.text.split("#", 1)
        if prefix.upper() not in _LONG:
            continue
        sign = "-" if body.startswith("-") else ""
        parts = _parts(body[len(sign):])
        if parts is None or len(parts) < 2 or not any(u in ("US", "NS") for _, u in parts):
            continue
        coarse = [(n, u) for n, u in parts if u not in ("MS", "US", "NS")]
        fine = [(n, u) for n, u in parts if u in ("MS", "US", "NS")]
        if any("." in n for n, _ in fine):
            continue  # a fraction of a unit below the second: left to the parser
        ns = sum(int(n.replace("_", "")) * _UNITS[u] for n, u in fine)
        whole, rest = divmod(ns, 10**6)
        fraction = f"{rest:06d}".rstrip("0")
        ms = f"{whole}.{fraction}MS" if fraction else f"{whole}MS"
        text = f"{prefix}#{sign}" + "".join(f"{n}{u}" for n, u in coarse) + ms
        edits.append((tok.start, tok.start + len(tok.text), text))
        uses.append((tok.line, tok.col, "an LTIME literal with microseconds or nanoseconds"))
    return edits, uses


def finer_than_milliseconds(prefix, literal):
    """The refusal of a TIME literal (`T#1MS500US`) with microseconds or nanoseconds, or None."""
    if prefix.upper() not in ("T", "TIME"):
        return None
    parts = _parts(literal.lstrip("#").lstrip("-"))
    if parts is None or not any(u in ("US", "NS") for _, u in parts):
        return None
    return (f"{prefix}{literal}: a TIME counts milliseconds in TwinCAT and CODESYS; write an LTIME for "
            f"microseconds and nanoseconds (LTIME{literal})")
