"""A counterexample as a scan-by-scan table: the harness assigns its timeline to globals named tl_<column>
at the end of every scan, tl_scan last; each assignment of tl_scan closes a row (the scenario program's
timeline: one line per scan, the FB's pins and the module bytes both ways)."""
from typing import Dict, List

PREFIX = "tl_"
ROW_KEY = "scan"
BYTE_COLUMNS = ("to_pac", "from_pac")  # 8 bytes each, PAC byte 0 first


def _value(step: dict):
    value = step.get("value", {})
    data = value.get("data")
    if data is None:
        return None
    if data in ("TRUE", "FALSE"):  # a _Bool
        return 1 if data == "TRUE" else 0
    try:
        return int(str(data).rstrip("ulUL"), 0)
    except ValueError:
        return data


def rows(trace: list) -> List[Dict[str, object]]:
    """The rows of a trace, in scan order; a column keeps its last value until assigned again."""
    current: Dict[str, object] = {}
    out = []
    for step in trace or []:
        if step.get("stepType") != "assignment" or step.get("hidden", False):
            continue
        lhs = step.get("lhs", "")
        if not lhs.startswith(PREFIX):
            continue
        name = lhs[len(PREFIX):]
        current[name] = _value(step)
        if name == ROW_KEY:
            out.append(dict(current))
    return out


def _cell(name: str, value) -> str:
    if value is None:
        return "?"
    if name in BYTE_COLUMNS and isinstance(value, int):
        return " ".join(f"{(value >> (8 * (7 - i))) & 0xFF:02X}" for i in range(8))
    if isinstance(value, int) and (name.endswith("code") or name.endswith("errorid") or name.endswith("param")):
        return f"{value & 0xFFFF:04X}"
    if isinstance(value, int) and name.endswith("data"):
        return f"{value & 0xFFFFFFFF:08X}"
    return str(value)


def table(trace: list) -> str:
    """The trace's rows as a fixed-width text table, columns in the order the harness first assigns them."""
    table_rows = rows(trace)
    if not table_rows:
        return "(no timeline in the trace)"
    columns: List[str] = [ROW_KEY]
    for row in table_rows:
        for name in row:
            if name not in columns:
                columns.append(name)
    cells = [[_cell(c, row.get(c)) for c in columns] for row in table_rows]
    widths = [max(len(c), *(len(r[i]) for r in cells)) for i, c in enumerate(columns)]
    lines = ["  ".join(c.rjust(w) for c, w in zip(columns, widths))]
    lines += ["  ".join(v.rjust(w) for v, w in zip(r, widths)) for r in cells]
    return "\n".join(lines)


def nondet_values(trace: list) -> List[int]:
    """The values the free inputs took, in the order the harness asked for them (a replay's input)."""
    out = []
    for step in trace or []:
        if step.get("stepType") == "assignment" and step.get("lhs", "").startswith("return_value_nondet_") \
                and not step.get("hidden", False):
            value = _value(step)
            out.append(value if isinstance(value, int) else 0)
    return out
