"""The docs' text against drift (docs/testing.md, "Self-contained"):

  figures   a figure the tree can give is generated: written between `<!-- figure: NAME -->` and
            `<!-- /figure -->` by `check_doc_text.py figures --write ROOT` and checked here against the
            tree; any other figure of the kinds that drift with every commit (a count of files, lines or
            tests, a coverage total) is a dated measurement and lives in docs/measurements/ under a
            dated heading, never in a page beside it.
  words     no words of the project's own work in docs/ or README.md: other sessions, briefs, merged
            trees, branch names and anchors named after them.

Usage: check_doc_text.py figures [--write] ROOT | check_doc_text.py words ROOT"""
import os
import re
import sys

FIGURE = re.compile(r"<!-- figure: ([a-z-]+) -->(.*?)<!-- /figure -->")
# Figures that drift with the tree: counts of files, lines and tests, coverage totals.
DRIFTING = re.compile(r"(?<![\w.=/-])(?<!TwinCAT )\d[\d,]* (?:files|lines|tests)\b"
                      r"|\b\d+ of \d+ \(\d|\b\d+/\d+ (?:lines|branches)\b")
# A heading of a measurements log names its day: "2 December", "1 to 2 December", "2026-12-02".
MONTHS = "January|February|March|April|May|June|July|August|September|October|November|December"
DATED = re.compile(rf"\b\d{{1,2}} (?:{MONTHS})\b|(?:{MONTHS}) \d{{1,2}}\b|\b\d{{4}}-\d{{2}}-\d{{2}}\b")
MEASUREMENTS = "docs/measurements/"

WORK_WORDS = [
    # (an ONLINE session of the PA-CONTROL is the manual's word, and stays)
    ("another session of the work",
     re.compile(r"\b(?:other|helper|working|work) sessions?\b|\bthe session's last\b", re.I)),
    ("a brief", re.compile(r"\bbriefs?\b", re.I)),
    ("a merged tree", re.compile(r"\bmerged tree\b|\bmerges? of branch", re.I)),
    ("a branch by name", re.compile(r"\bbranch(?:es)? [`'\"]|\bbranch names?\b|\b(?:this|the) branch's\b", re.I)),
    ("a worktree", re.compile(r"\bworktrees?\b", re.I)),
    ("an anchor named after a branch", re.compile(r"\]\([^)]*#[^)]*\bbranch-[^)]*\)")),
]


def pages(root):
    """The Markdown pages users read: README.md and docs/**.md, relative paths, sorted."""
    found = ["README.md"]
    for folder, _, names in os.walk(os.path.join(root, "docs")):
        found += [os.path.relpath(os.path.join(folder, n), root).replace(os.sep, "/")
                  for n in names if n.endswith(".md")]
    return sorted(found)


def prose_lines(text):
    """(line number, line) outside fenced code blocks: a sample output is not a claim of the page."""
    fenced = False
    for number, line in enumerate(text.splitlines(), 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
        elif not fenced:
            yield number, line


def library_figures(root):
    """The library's size as the tree has it: its .st files, their lines, the largest file."""
    sizes = {}
    for folder, _, names in os.walk(os.path.join(root, "st")):
        for name in names:
            if name.endswith(".st"):
                with open(os.path.join(folder, name), encoding="utf-8") as f:
                    sizes[name] = len(f.read().splitlines())
    largest = max(sorted(sizes), key=lambda n: sizes[n])
    return {"library-files": f"{len(sizes)}", "library-lines": f"{sum(sizes.values()):,}",
            "library-largest-file": largest, "library-largest-lines": f"{sizes[largest]}"}


def check_figures(root, write):
    generated = library_figures(root)
    problems = []
    for rel in pages(root):
        path = os.path.join(root, rel)
        with open(path, encoding="utf-8") as f:
            text = f.read()

        def figure(m):
            name = m.group(1)
            if name not in generated:
                problems.append(f"{rel}: no command generates the figure '{name}'")
                return m.group(0)
            if m.group(2) != generated[name] and not write:
                problems.append(f"{rel}: the figure '{name}' says {m.group(2)}, the tree {generated[name]} "
                                f"(check_doc_text.py figures --write)")
            return f"<!-- figure: {name} -->{generated[name]}<!-- /figure -->"

        new = FIGURE.sub(figure, text)
        if write and new != text:
            with open(path, "w", encoding="utf-8") as f:
                f.write(new)
        heading = ""
        for number, line in prose_lines(new):
            if line.startswith("#"):
                heading = line
            for m in DRIFTING.finditer(FIGURE.sub("", line)):
                if not rel.startswith(MEASUREMENTS):
                    problems.append(f"{rel}:{number}: '{m.group(0)}' typed into the page: generate it "
                                    f"(<!-- figure: ... -->) or date it in {MEASUREMENTS}")
                elif not DATED.search(heading):
                    problems.append(f"{rel}:{number}: '{m.group(0)}' under a heading without a date: {heading!r}")
    return problems


def check_words(root):
    problems = []
    for rel in pages(root):
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            text = f.read()
        for number, line in enumerate(text.splitlines(), 1):
            for what, pattern in WORK_WORDS:
                m = pattern.search(line)
                if m:
                    problems.append(f"{rel}:{number}: {what}: '{m.group(0)}'")
    return problems


def main(argv):
    if len(argv) == 3 and argv[1] == "words":
        problems = check_words(argv[2])
    elif len(argv) in (3, 4) and argv[1] == "figures" and argv[2:-1] in ([], ["--write"]):
        problems = check_figures(argv[-1], write=len(argv) == 4)
    else:
        print(__doc__, file=sys.stderr)
        return 2
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
