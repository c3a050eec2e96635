"""The pin tables of the docs say what the ST declares (docs/testing.md, "Self-contained").

  check_pins.py REPO [--cache DIR] [--comments]
      DocPins.MatchTheSt. Reads every FUNCTION_BLOCK and FUNCTION of st/**/*.st with pacst's parser
      (translator/pacst, DIR its parse cache) and every pin table of README.md and docs/**/*.md: a Markdown
      table whose header starts `| pin | dir | type |`. A table belongs to the POU its page is named after
      (docs/fb/FB_PAC_Cmd.md: FB_PAC_Cmd), or to the POUs named on the line before its header,
        <!-- pins: POU[, POU...] -->
      which a table on a page of several POUs needs (element_commands.md), and a table of pins that several
      POUs share (its "Common pins"). A row names its pins in backquotes in its first cell; with several
      (`Code`, `Param`) its dir and type cells hold one value for all or one each, comma-separated. dir is
      in (VAR_INPUT), out (VAR_OUTPUT) or in-out (VAR_IN_OUT); a row without a quoted name (`common pins`,
      a link to the shared table) is text. For every POU with a table, its tables together must hold each
      of its VAR_INPUT, VAR_OUTPUT and VAR_IN_OUT pins with the ST's direction and type, and no pin the ST
      lacks; a pin in two tables (the page's and a shared one) is checked in both. A page named after a
      POU needs a pin table, a marker a table right after it; every MC_ block needs one (MC_blocks.md). Any other POU
      without a pin table is not checked: the run lists them.
      --comments checks the style rule instead (DocPins.EveryPinHasAComment): every public pin has a comment
      (* ... *) with some text in it on its declaration's line; the run lists file:line of each that has none
      and fails. A // comment does not count (pacst refuses one: not in the portable subset)."""
import argparse
import glob
import os
import re
import sys

HEADER = re.compile(r"^\|\s*pin\s*\|", re.I)
MARKER = re.compile(r"^<!--\s*pins:\s*(.+?)\s*-->$")
QUOTED = re.compile(r"`([A-Za-z_]\w*)`")
COMMENT = re.compile(r"\(\*\s*[^\s*]")  # a (* *) comment with some text
TABLE_REQUIRED = ("MC_",)  # POUs that must have a pin table although no page is named after them
SECTIONS = {"InputDeclarations": "in", "OutputDeclarations": "out", "InputOutputDeclarations": "in-out"}


class Pin:
    def __init__(self, name, direction, type_, where, commented=True):
        self.name, self.direction, self.type, self.where = name, direction, type_, where
        self.commented = commented  # ST: its declaration's line holds a comment


def st_pous(repo, cache):
    """{upper POU name: (name, {upper pin name: Pin})} of every FUNCTION_BLOCK and FUNCTION in st/, as pacst
    parses them."""
    sys.path.insert(0, os.path.join(repo, "translator"))
    from pacst.errors import StError
    from pacst.parsing import parse_files
    paths = sorted(glob.glob(os.path.join(repo, "st", "**", "*.st"), recursive=True))
    pous = {}
    for src in parse_files(paths, cache):
        if isinstance(src, StError):
            raise SystemExit(f"check_pins: {src}")
        rel = os.path.relpath(src.path, repo)
        lines = src.text.splitlines()
        for item in src.tree.items:
            if type(item).__name__ not in ("FunctionBlock", "Function"):
                continue
            pins = {}
            for block in item.declarations:
                direction = SECTIONS.get(type(block).__name__)
                for decl in block.items if direction else ():
                    spec = getattr(decl.init, "spec", decl.init)
                    text = lines[decl.meta.line - 1]
                    for var in decl.variables:
                        name = str(var.name)
                        pins[name.upper()] = Pin(name, direction, str(spec), f"{rel}:{decl.meta.line}",
                                                 bool(COMMENT.search(text)))
            pous[str(item.name).upper()] = (str(item.name), pins)
    return pous


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def doc_tables(path, rel, errors):
    """(line of the header, its cells, [POU names] or None, [(line, cells)]) of every pin table of `path`
    (`rel` in messages)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        if MARKER.match(line.strip()) and not (i + 1 < len(lines) and HEADER.match(lines[i + 1])):
            errors.append(f"{rel}:{i + 1}: <!-- pins: --> must stand on the line right before "
                          "a pin table's header, or it names nothing")
        if not HEADER.match(line):
            continue
        marker = MARKER.match(lines[i - 1].strip()) if i > 0 else None
        owners = [n.strip() for n in marker.group(1).split(",")] if marker else None
        rows = []
        for j in range(i + 2, len(lines)):
            if not lines[j].lstrip().startswith("|"):
                break
            rows.append((j + 1, cells(lines[j])))
        yield i + 1, cells(line), owners, rows


def documented(repo, pous, errors):
    """{upper POU name: [Pin, each with its page:line]} from every pin table of the docs."""
    pages = [os.path.join(repo, "README.md")] + sorted(glob.glob(os.path.join(repo, "docs", "**", "*.md"),
                                                                  recursive=True))
    docs = {}
    for page in pages:
        rel = os.path.relpath(page, repo)
        stem = os.path.splitext(os.path.basename(page))[0]
        tables = list(doc_tables(page, rel, errors))
        if stem.upper() in pous and not tables:
            errors.append(f"{rel}: the page of {stem} has no pin table (| pin | dir | type | meaning |)")
        for line, header, owners, rows in tables:
            where = f"{rel}:{line}"
            if [h.lower() for h in header[:3]] != ["pin", "dir", "type"]:
                errors.append(f"{where}: a pin table's header starts | pin | dir | type |, not {' | '.join(header)}")
                continue
            if owners is None:
                if stem.upper() not in pous:
                    errors.append(f"{where}: a pin table on a page not named after a POU: say whose pins they are "
                                  "on the line before, <!-- pins: POU -->")
                    continue
                owners = [stem]
            unknown = [o for o in owners if o.upper() not in pous]
            if unknown:
                errors.append(f"{where}: <!-- pins: --> names {', '.join(unknown)}, which st/ does not declare")
                continue
            for row_line, row in rows:
                for pin in row_pins(f"{rel}:{row_line}", row, errors):
                    for owner in owners:
                        docs.setdefault(owner.upper(), []).append(pin)
    return docs


def row_pins(where, row, errors):
    """The Pins a row names: one direction and type for all of them, or one each, comma-separated."""
    names = QUOTED.findall(row[0])
    if not names:
        return []
    columns = []
    for what, cell in (("dir", row[1] if len(row) > 1 else ""), ("type", row[2] if len(row) > 2 else "")):
        values = [v.strip().strip("`") for v in cell.split(",")] if cell else []
        if len(values) == 1:
            values *= len(names)
        if len(values) != len(names):
            errors.append(f"{where}: {', '.join(names)}: {len(names)} pin(s) need one {what} or one each, "
                          f"not '{cell}'")
            return []
        columns.append(values)
    bad = [d for d in columns[0] if d.lower() not in ("in", "out", "in-out")]
    if bad:
        errors.append(f"{where}: {', '.join(names)}: dir is in, out or in-out, not '{bad[0]}'")
        return []
    return [Pin(n, d.lower(), t, where) for n, d, t in zip(names, *columns)]


def compare(pous, docs, errors):
    for up, pins in sorted(docs.items()):
        name, st = pous[up]
        seen = set()
        for pin in pins:
            declared = st.get(pin.name.upper())
            if declared is None:
                errors.append(f"{pin.where}: {name}: pin {pin.name} is not declared in the ST")
                continue
            if pin.name != declared.name:
                errors.append(f"{pin.where}: {name}: pin {pin.name} is spelled {declared.name} in {declared.where}")
            if pin.direction != declared.direction:
                errors.append(f"{pin.where}: {name}: pin {pin.name} is {pin.direction} here, "
                              f"{declared.direction} in {declared.where}")
            if pin.type.upper() != declared.type.upper():
                errors.append(f"{pin.where}: {name}: pin {pin.name} is {pin.type} here, "
                              f"{declared.type} in {declared.where}")
            seen.add(pin.name.upper())
        for up_pin, declared in st.items():
            if up_pin not in seen:
                tables = ", ".join(sorted({p.where.rsplit(":", 1)[0] for p in pins}))
                errors.append(f"{declared.where}: {name}: {declared.direction} pin {declared.name} : {declared.type} "
                              f"is in no pin table of {name} ({tables})")


def uncommented(pous):
    """The style rule "every public pin a one-line comment": file:line of each pin whose line has none."""
    return [f"{pin.where}: {name}: {pin.direction} pin {pin.name} has no comment on its line"
            for name, pins in sorted(pous.values()) for pin in pins.values() if not pin.commented]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("repo")
    parser.add_argument("--cache", help="pacst's parse cache")
    parser.add_argument("--comments", action="store_true",
                        help="instead: every public pin of st/ has a comment on its declaration's line")
    args = parser.parse_args(argv)
    repo = os.path.abspath(args.repo)
    pous = st_pous(repo, args.cache)
    if args.comments:
        missing = uncommented(pous)
        print("\n".join(missing + [f"check_pins: {len(missing)} public pin(s) without a comment"]))
        return 1 if missing else 0
    errors = []
    docs = documented(repo, pous, errors)
    compare(pous, docs, errors)
    unchecked = sorted(name for up, (name, pins) in pous.items() if up not in docs and pins)
    errors += [f"{name}: an MC_ block without a pin table (docs/fb/MC_blocks.md tables every one)"
               for name in unchecked if name.upper().startswith(TABLE_REQUIRED)]
    for e in errors:
        print(e)
    print(f"check_pins: not checked, no pin table: {', '.join(unchecked)}")
    print(f"check_pins: {len(docs)} POU(s) with pin tables, {len(errors)} difference(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
