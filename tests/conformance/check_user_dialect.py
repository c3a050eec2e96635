"""docs/user_dialect.md against the translator (CTest UserDialect.PageMatchesTranslator).

  check_user_dialect.py REPO [--cache DIR]

The page's construct table names a snippet of tests/conformance/dialect/ in each row, and says whether user
mode accepts it. Every snippet is in the table once; the verdict is the snippet's (its first line is
`(* accept *)` or `(* expect-error: LINE:COL: text *)`), and pacst --user, with the library under its
namespace as pac-test gives it (and, for a snippet whose second line is `(* library NAME: FOLDER *)`, the ST
files of the repository's FOLDER as a library of the program's own, as `--library NAME=FOLDER` gives it), gives
that verdict: an accepted snippet translates, and `pacst matiec` would
refuse it (a construct of the dialect, MATIEC compiles the portable subset only) unless the row says MATIEC
takes it; a refused one is refused at its line and column with that text. The page's table of standard
functions gives a call and its result type in each row: each accepted call is assigned to a variable of
that type in a PROGRAM and translates (the accepted calls in one PROGRAM, each alone when that one is
refused), each refused one is refused. Exit status 1 names every mismatch."""
import argparse
import gc
import glob
import os
import re
import sys
import tempfile

ROW = re.compile(r"^\|(.+)\|\s*$")
SNIPPET = re.compile(r"\]\(\.\./tests/conformance/dialect/(\w+\.st)\)")
EXPECT = re.compile(r"^\(\* expect-error: (\d+):(\d+): (.*?) \*\)")
CALL = re.compile(r"^`(.+)`$")
LIBRARY = re.compile(r"^\(\* library (\w+): (\S+) \*\)")


def table_rows(text, heading):
    """The cells of every body row of the first table after the line `heading`."""
    lines = text.splitlines()
    start = lines.index(heading)
    rows, seen_table = [], False
    for line in lines[start + 1:]:
        m = ROW.match(line)
        if not m:
            if seen_table:
                break
            continue
        seen_table = True
        cells = [c.strip() for c in m.group(1).split("|")]
        if set("".join(cells)) <= set("-: "):
            continue
        rows.append(cells)
    return rows[1:]  # the header


def main(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("repo")
    parser.add_argument("--cache")
    args = parser.parse_args(argv)
    sys.path.insert(0, os.path.join(args.repo, "translator"))
    from pacst import cli, libraries  # noqa: E402
    from pacst.errors import StError, StErrors  # noqa: E402
    from pacst.parsing import parse_files  # noqa: E402

    page = os.path.join(args.repo, "docs", "user_dialect.md")
    with open(page, encoding="utf-8") as f:
        text = f.read()
    folder = os.path.join(args.repo, "tests", "conformance", "dialect")
    library = sorted(p for p in glob.glob(os.path.join(args.repo, "st", "**", "*.st"), recursive=True))
    namespaces = {"PA_CONTROL": ("PA_CONTROL", os.path.join(args.repo, "st"))}
    lib_results = parse_files(library, args.cache, None, True)
    # The library's trees live to the end of this process and hold no garbage: left out of the cyclic garbage
    # collector's passes (as a pacst process does, parsing.FREEZE_LOADED_TREES), which were a quarter of the check.
    gc.collect()
    gc.freeze()
    problems = []

    def translate(path):
        """None when pacst --user translates `path` with the library (and the library of its own its second line
        names), else the first error; and the constructs `pacst matiec` refuses."""
        with open(path, encoding="utf-8") as f:
            own = LIBRARY.match((f.readlines()[1:2] or [""])[0])
        given, extra = namespaces, []
        if own is not None:
            folder = os.path.join(args.repo, own.group(2))
            given = dict(namespaces, **{own.group(1).upper(): (own.group(1), folder)})
            extra = parse_files(libraries.files(own.group(1), folder, None), args.cache, 1, True)
        results = parse_files([path], args.cache, 1, True)
        try:
            comp, _, _ = cli._translate_parsed(lib_results + extra + results, [], True, (), given)
        except StErrors as e:
            return e.errors[0], []
        except StError as e:
            return e, []
        return None, comp.dialect_uses

    rows = table_rows(text, "## Constructs")
    named = {}
    for cells in rows:
        m = SNIPPET.search(" ".join(cells))
        if m is None:
            problems.append(f"{page}: the row '{cells[0]}' names no snippet of tests/conformance/dialect/")
            continue
        if m.group(1) in named:
            problems.append(f"{page}: {m.group(1)} is named twice")
        named[m.group(1)] = cells
    on_disk = {os.path.basename(p) for p in glob.glob(os.path.join(folder, "*.st"))}
    for missing in sorted(on_disk - set(named)):
        problems.append(f"{page}: no row for tests/conformance/dialect/{missing}")
    for name in sorted(named):
        cells = named[name]
        path = os.path.join(folder, name)
        if name not in on_disk:
            problems.append(f"{page}: the row '{cells[0]}' names {name}, which does not exist")
            continue
        with open(path, encoding="utf-8") as f:
            first = f.readline()
        verdict = cells[1].lower()
        expect = EXPECT.match(first)
        if verdict.startswith("accepted") != (expect is None):
            problems.append(f"{page}: '{cells[0]}' is {verdict} on the page, the snippet {name} says {first.strip()}")
            continue
        error, dialect = translate(path)
        if expect is None:
            if error is not None:
                problems.append(f"{name}: accepted on the page, refused: {error}")
            elif not dialect and "MATIEC takes it" not in cells[-1]:
                problems.append(f"{name}: pacst matiec would not refuse it; say 'MATIEC takes it' on the page")
        else:
            want = f"{path}:{expect.group(1)}:{expect.group(2)}: error: {expect.group(3)}"
            if error is None or not str(error).startswith(want):
                problems.append(f"{name}: expected {want}..., got {error or 'no error'}")

    with tempfile.TemporaryDirectory() as tmp:
        def call_error(calls):
            """The first error of a PROGRAM assigning each (call, type) of `calls` to a variable of its own."""
            path = os.path.join(tmp, "Dialect_Call.st")
            with open(path, "w", encoding="utf-8") as f:
                f.write("PROGRAM Dialect_Call\nVAR\n" + "".join(f"  X{i} : {t};\n" for i, (_, t) in enumerate(calls))
                        + "  S : STRING;\n  W : WORD;\nEND_VAR\n"
                        + "".join(f"X{i} := {c};\n" for i, (c, _) in enumerate(calls)) + "END_PROGRAM\n")
            return translate(path)[0]

        accepted = []
        for cells in table_rows(text, "## Standard functions"):
            call = CALL.match(cells[0])
            if call is None or not re.fullmatch(r"\w+", cells[2]):
                problems.append(f"{page}: the row '{cells[0]}' is no `call` with a result type")
            elif cells[1].lower().startswith("accepted"):
                accepted.append((cells[0], call.group(1), cells[2]))
            elif call_error([(call.group(1), cells[2])]) is None:
                problems.append(f"{page}: {cells[0]} is refused on the page, but translates")
        # The accepted calls in one PROGRAM, each assignment checked on its own by the translator: when it
        # translates, each call alone does; when not, each is translated alone to name the refused ones.
        if accepted and call_error([(c, t) for _, c, t in accepted]) is not None:
            for row, c, t in accepted:
                error = call_error([(c, t)])
                if error is not None:
                    problems.append(f"{page}: {row} is accepted on the page, refused: {error}")
    for p in problems:
        print(p)
    print(f"check_user_dialect: {len(named)} constructs, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
