"""The code in the user docs cannot drift from the code that builds (docs/testing.md, "Self-contained").

  check_doc_examples.py sync REPO
      DocExamples.InSync. Every fenced block of README.md and docs/**/*.md names its language. A `cpp`,
      `iecst` or `json` block carries, on the line before its fence, one of
        <!-- example: PATH -->         the block is the text of PATH (a file of the repository), or of
                                       the parts of PATH between lines that contain `doc-example begin`
                                       and `doc-example end`, each without its common indentation,
                                       joined by a blank line; CTest builds and
                                       runs PATH (tests/docs/CMakeLists.txt);
        <!-- synopsis: PATH[, PATH] --> (cpp) a summary of headers, not compilable: every name in it
                                       (outside comments) must occur in one of the PATHs;
        <!-- vendor-specific: WHY -->  (iecst) code for one vendor's library that no tool here has.
  check_doc_examples.py st REPO OUTDIR PACST... -- LIBRARY.st...
      DocExamples.St. Every `iecst` example file (PATH above, .st) is translated by pacst with the
      library: a PROGRAM (which the portable subset leaves to the vendor's tool) is read as a
      FUNCTION_BLOCK named after its file and its located variables (`AT %IB0`, `AT %I*`) as plain ones.
      Examples of a machine program (examples/, tools/pactest/) are left to PacTest.*, which runs them.
      A `yaml` block (a CI job) needs no marker: PacTest.DocsCiJobs runs its pac-test command lines."""
import glob
import os
import re
import subprocess
import sys
import textwrap

FENCE = re.compile(r"^\s*```(\S*)\s*$")
MARKER = re.compile(r"^<!-- (example|synopsis|vendor-specific): (.+?) -->$")
NEEDS_MARKER = {"cpp", "iecst", "json"}
KNOWN = NEEDS_MARKER | {"sh", "text", "yaml"}
CPP_WORDS = set("""alignas auto bool break case catch char class const constexpr continue default delete do double
else enum explicit extern false float for friend if inline int long mutable namespace new noexcept nullptr
operator override private protected public return short signed sizeof static struct switch template this
throw true try typedef typename union unsigned using virtual void volatile while std size_t""".split())


def doc_files(repo):
    return [os.path.join(repo, "README.md")] + sorted(glob.glob(os.path.join(repo, "docs", "**", "*.md"),
                                                                recursive=True))


def blocks(path):
    """(line number of the fence, language, marker kind, marker argument, text) of every fenced block."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        opening = FENCE.match(lines[i])
        if not opening:
            i += 1
            continue
        end = i + 1
        while end < len(lines) and not lines[end].strip().startswith("```"):
            end += 1
        marker = MARKER.match(lines[i - 1].strip()) if i > 0 else None
        yield (i + 1, opening.group(1), marker.group(1) if marker else None,
               marker.group(2) if marker else None, "\n".join(lines[i + 1:end]))
        i = end + 1


def example_text(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if "doc-example begin" not in text:
        return text.rstrip("\n")
    parts, part = [], None
    for line in text.splitlines():
        if "doc-example begin" in line:
            part = []
        elif "doc-example end" in line:
            parts.append(textwrap.dedent("\n".join(part)))
            part = None
        elif part is not None:
            part.append(line)
    return "\n\n".join(parts)


def names(code):
    code = re.sub(r"//[^\n]*|/\*.*?\*/", " ", code, flags=re.S)
    code = re.sub(r'"[^"\n]*"', " ", code)
    return {w for w in re.findall(r"\b[A-Za-z_]\w{2,}\b", code) if w not in CPP_WORDS}


def sync(repo):
    problems = []
    for doc in doc_files(repo):
        where = os.path.relpath(doc, repo)
        for line, lang, kind, arg, text in blocks(doc):
            at = f"{where}:{line}"
            if lang not in KNOWN:
                problems.append(f"{at}: a fenced block needs its language, one of {sorted(KNOWN)} (got '{lang}')")
                continue
            if lang not in NEEDS_MARKER:
                continue
            if kind is None:
                problems.append(f"{at}: a {lang} block needs an <!-- example: PATH --> line before it "
                                "(or synopsis / vendor-specific, tests/docs/check_doc_examples.py)")
            elif kind == "example":
                path = os.path.join(repo, arg)
                if not os.path.isfile(path):
                    problems.append(f"{at}: example file {arg} does not exist")
                elif example_text(path) != text:
                    problems.append(f"{at}: the block differs from {arg}: copy the file's text into the doc")
            elif kind == "synopsis":
                if lang != "cpp":
                    problems.append(f"{at}: a synopsis is for cpp blocks")
                    continue
                sources = ""
                for header in (p.strip() for p in arg.split(",")):
                    if not os.path.isfile(os.path.join(repo, header)):
                        problems.append(f"{at}: synopsis source {header} does not exist")
                        continue
                    with open(os.path.join(repo, header), encoding="utf-8") as f:
                        sources += f.read()
                missing = sorted(n for n in names(text) if not re.search(r"\b" + n + r"\b", sources))
                if missing:
                    problems.append(f"{at}: names not in {arg}: {', '.join(missing)}")
            elif kind == "vendor-specific" and lang != "iecst":
                problems.append(f"{at}: vendor-specific is for iecst blocks")
    return problems


def st(repo, outdir, pacst, library):
    os.makedirs(outdir, exist_ok=True)
    files = []
    for doc in doc_files(repo):
        for _, lang, kind, arg, _ in blocks(doc):
            # A machine program's files (examples/, pac-test's vocabulary) need pacst's user mode and the test
            # vocabulary: the PacTest.* tests translate, build and run them with pac-test.
            if lang == "iecst" and kind == "example" and arg not in files and \
                    not arg.startswith(("examples/", "tools/pactest/")):
                files.append(arg)
    copies = []
    for name in files:
        with open(os.path.join(repo, name), encoding="utf-8") as f:
            text = f.read()
        stem = "".join(w.capitalize() for w in re.split(r"[_.]", os.path.basename(name)[:-3]))
        text = re.sub(r"^PROGRAM\s+\w+", "FUNCTION_BLOCK DocExample" + stem, text, flags=re.M)
        text = re.sub(r"^END_PROGRAM\b", "END_FUNCTION_BLOCK", text, flags=re.M)
        text = re.sub(r"\s+AT\s+%[IQM][XBWD]?(?:\*|[\d.]+)", "", text)
        copy = os.path.join(outdir, os.path.basename(name))
        with open(copy, "w", encoding="utf-8") as f:
            f.write(text)
        copies.append(copy)
    print(f"{len(copies)} ST examples: {', '.join(files)}")
    if len(copies) < 1:
        return 1
    return subprocess.run(pacst + ["check"] + library + copies).returncode


def main(argv):
    if len(argv) >= 2 and argv[0] == "sync":
        problems = sync(os.path.abspath(argv[1]))
        for p in problems:
            print(p)
        print(f"{len(problems)} problem(s)" if problems else "every code block of the docs is in sync")
        return 1 if problems else 0
    if len(argv) >= 4 and argv[0] == "st" and "--" in argv:
        cut = argv.index("--")
        return st(os.path.abspath(argv[1]), argv[2], argv[3:cut], argv[cut + 1:])
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
