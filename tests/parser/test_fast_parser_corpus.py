"""The fast parser against blark's Earley parser on every ST file the project has: the library (st/,
which must all take the fast path), the conformance suite's accepted and refused files (the user
programs' too), the MATIEC
verdict snippets and the damaged-input tests' own inputs. Each file's tree must equal Earley's
exactly, or the file is declined (blark's parser then parses it). Run by ctest as FastParser.Corpus;
the files are spread over the cores, since Earley needs several milliseconds per line. Earley's tree of a
text is the one recorded in earley_digests.txt (a digest of every node and position, written by
record_earley.py) when the fast tree has that digest; every text the record lacks, and one in 16 of those
it holds (audited()), is parsed by Earley, and a recorded digest that is not Earley's fails. Earley's trees
are kept in the build tree ($PAC_ORACLE_CACHE) so that a second run parses only changed files."""
import concurrent.futures
import glob
import os
import re
import sys
import unittest

from tree_oracle import RECORD, REPO, read_record, Oracle
from pacst.fastparse import Decline  # noqa: E402 (tree_oracle puts the translator on the path)

VERDICTS = os.path.join(REPO, "tests", "conformance", "matiec_verdicts", "snippets")
CORPORA = {
    "library": sorted(glob.glob(os.path.join(REPO, "st", "**", "*.st"), recursive=True)),
    "conformance accept": sorted(glob.glob(os.path.join(REPO, "tests", "conformance", "accept", "*.st"))),
    "conformance refuse": sorted(glob.glob(os.path.join(REPO, "tests", "conformance", "refuse", "*.st"))),
    "matiec verdicts": sorted(glob.glob(os.path.join(VERDICTS, "*.st"))),
    # User programs (pacst --user): PROGRAMs, VAR_EXTERNAL and inline arrays take the fast path; located
    # variables, array initial values and sized STRINGs are Earley's.
    "user programs": sorted(glob.glob(os.path.join(REPO, "tests", "conformance", "user", "**", "*.st"),
                                      recursive=True)),
    "user refusals": sorted(glob.glob(os.path.join(REPO, "tests", "conformance", "refuse_user", "*.st"))),
    # The TwinCAT / CODESYS dialect of user programs (docs/user_dialect.md): empty branches, FOR, methods...
    "user dialect": sorted(glob.glob(os.path.join(REPO, "tests", "conformance", "dialect", "*.st"))
                           + glob.glob(os.path.join(REPO, "tools", "pactest", "tests", "dialect", "*.st"))),
}

_ORACLE = None


def audited(key):
    """The recorded texts Earley parses all the same: those whose key starts with 0 (one in 16, a different
    sample as the texts change), so that a record not written by Earley is found out."""
    return key.startswith("0")


def _oracle():
    global _ORACLE
    if _ORACLE is None:
        _ORACLE = Oracle(os.environ.get("PAC_ORACLE_CACHE"), read_record(), audited)
    return _ORACLE


# A POU's body alone (statement_list), as TwinCAT files and PLCopen XML keep it: what follows the last
# END_VAR up to the POU's end, in the conformance suite's accepted files.
_BODY = re.compile(r"^END_VAR[ \t]*\n(?!.*^END_VAR)(.*)^END_(?:FUNCTION_BLOCK|FUNCTION|PROGRAM)\b", re.S | re.M)
# A POU's declaration alone, as the same files keep it: up to its last END_VAR, which blark ends with the
# POU's end (the start rule of each kind of POU); a TYPE's declaration is the whole file.
_DECLARATION = re.compile(r"^(.*^END_VAR)[ \t]*\n(?!.*^END_VAR)", re.S | re.M)
_ELEMENT_RULES = {"FUNCTION_BLOCK": ("function_block_type_declaration", "END_FUNCTION_BLOCK"),
                  "FUNCTION": ("function_declaration", "END_FUNCTION"),
                  "PROGRAM": ("program_declaration", "END_PROGRAM"), "TYPE": ("data_type_declaration", "")}
_FIRST_WORD = re.compile(r"^(FUNCTION_BLOCK|FUNCTION|PROGRAM|TYPE)\b", re.M)


def _body(path):
    """(start rule, text) of the body alone of the file's POU, or None."""
    with open(path, encoding="utf-8") as f:
        found = _BODY.search(f.read())
    return ("statement_list", found.group(1)) if found and found.group(1).strip() else None


def _compare_file(path):
    """(path, verdict, whether Earley parsed it)."""
    oracle = _oracle()
    before = oracle.earley_parses
    with open(path, encoding="utf-8") as f:
        return path, oracle.compare(f.read()), oracle.earley_parses > before


def _compare_body(path):
    found = _body(path)
    return path, _oracle().compare(found[1], found[0]) if found else None


def _declaration(path):
    """(start rule, text) of the declaration alone of the file's first POU or type, or None."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    kind = _FIRST_WORD.search(text)
    if kind is None:
        return None
    rule, end = _ELEMENT_RULES[kind.group(1)]
    if not end:
        return rule, text
    found = _DECLARATION.search(text)
    return (rule, f"{found.group(1)}\n{end}\n") if found else None


def _compare_declaration(path):
    found = _declaration(path)
    return path, _oracle().compare(found[1], found[0]) + (found[0],) if found else None


def _body_paths():
    return CORPORA["conformance accept"]


def _declaration_paths():
    return CORPORA["conformance accept"] + CORPORA["user programs"] + CORPORA["user dialect"]


def corpus_texts():
    """(start rule, source) of every text the tests below compare from the corpora's files: what
    record_earley.py records."""
    texts = []
    for path in sorted({p for paths in CORPORA.values() for p in paths}):
        with open(path, encoding="utf-8") as f:
            texts.append(("iec_source", f.read()))
    texts += [found for found in map(_body, _body_paths()) if found]
    texts += [found for found in map(_declaration, _declaration_paths()) if found]
    return texts


def _compare_all(paths):
    jobs = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    if jobs <= 1:
        compared = list(map(_compare_file, paths))
    else:
        with concurrent.futures.ProcessPoolExecutor(max_workers=jobs) as pool:
            # Longest first, so that no worker is left with a long file at the end.
            ordered = sorted(paths, key=os.path.getsize, reverse=True)
            compared = list(pool.map(_compare_file, ordered))
    # A record that lacks many files costs Earley's time: record_earley.py writes it again.
    print(f"{sum(parsed for _, _, parsed in compared)} of {len(compared)} files given to Earley (not in "
          f"{os.path.basename(RECORD)}, audited, or another tree than recorded)", file=sys.stderr)
    return {path: result for path, result, _ in compared}


def _compare_bodies(paths, compare=_compare_body):
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
        return {path: result for path, result in pool.map(compare, paths) if result is not None}


class Corpus(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.results = _compare_all([p for paths in CORPORA.values() for p in paths])

    def test_every_tree_equals_earleys(self):
        for name, paths in CORPORA.items():
            self.assertTrue(paths, f"no ST files found for the corpus '{name}'")  # a moved folder reads as empty
            declined = [p for p in paths if self.results[p][0] == "declined"]
            print(f"{name}: {len(paths)} files, {len(paths) - len(declined)} parsed fast, "
                  f"{len(declined)} declined", file=sys.stderr)
            for path in paths:
                verdict, what = self.results[path]
                with self.subTest(path=os.path.relpath(path, REPO)):
                    self.assertNotEqual(verdict, "different", what)

    def test_the_library_takes_the_fast_path(self):
        self.assertTrue(CORPORA["library"])
        declined = [os.path.relpath(p, REPO) for p in CORPORA["library"] if self.results[p][0] != "same"]
        self.assertEqual(declined, [])

    def test_user_programs_without_located_variables_take_the_fast_path(self):
        paths = [p for p in CORPORA["user programs"] if os.path.basename(p) in
                 ("PRG_UserAsserts.st", "F_UserScale.st", "GVL_Hmi.st")]
        self.assertEqual(len(paths), 3)
        declined = [os.path.relpath(p, REPO) for p in paths if self.results[p][0] != "same"]
        self.assertEqual(declined, [])

    def test_bodies_alone_equal_earleys(self):
        """The bodies the PLCopen and TwinCAT readers parse alone (pacst.parsing.parse_text)."""
        results = _compare_bodies(_body_paths())
        self.assertGreater(len(results), 30)
        for path, (verdict, what) in results.items():
            with self.subTest(path=os.path.relpath(path, REPO)):
                self.assertEqual(verdict, "same", what)

    def test_declarations_alone_equal_earleys(self):
        """The declarations the PLCopen and TwinCAT readers parse alone (pacst.parsing.parse_text), each
        from its POU's or type's rule, in the files of one element (a file of several is declined)."""
        results = _compare_bodies(_declaration_paths(), _compare_declaration)
        for path, (verdict, what, _) in results.items():
            with self.subTest(path=os.path.relpath(path, REPO)):
                self.assertNotEqual(verdict, "different", what)
        fast = {rule for verdict, _, rule in results.values() if verdict == "same"}
        self.assertEqual(fast, {rule for rule, _ in _ELEMENT_RULES.values()})  # every rule read alone

    def test_the_librarys_declarations_take_the_fast_path(self):
        """Their trees are those of the whole files (the same readers, test_every_tree_equals_earleys) but
        for the empty body, which the test above compares with Earley's."""
        oracle = _oracle()  # its fast parser alone
        declined, read = [], 0
        for path in CORPORA["library"]:
            found = _declaration(path)
            if found is None:
                continue
            read += 1
            try:
                oracle.fast.parse(oracle.processed(found[1]), found[0])
            except Decline as exc:
                declined.append(f"{os.path.relpath(path, REPO)}: {exc}")
        self.assertGreater(read, 100)
        self.assertEqual(declined, [])

    def test_pragmas_take_the_fast_path(self):
        """The export's TwinCAT files carry `{attribute 'hide'}` before a type or a POU, and a program's own
        files pragmas anywhere: the fast parser skips them as blark's grammar ignores them, with Earley's tree;
        a pragma followed by `;` is declined (the `;` could end a statement too)."""
        oracle = _oracle()
        cases = {"data_type_declaration": "{attribute 'hide'}\nTYPE E_Hidden :\n(\n  A,  (* one *)\n  B\n);\nEND_TYPE\n",
                 "iec_source": "{attribute 'hide'}\nFUNCTION_BLOCK FB_Hidden\nVAR_INPUT\n  {attribute 'x'} A : BOOL;\n"
                               "END_VAR\nVAR\n  N : INT;\nEND_VAR\n{region}N := N + 1; {endregion}\nIF A THEN\n  N := 0;\n"
                               "END_IF;\nEND_FUNCTION_BLOCK\n",
                 "statement_list": "X := 1;\n{attribute 'x'}\nY := 2;\n"}
        for rule, text in cases.items():
            with self.subTest(rule=rule):
                self.assertEqual(oracle.compare(text, rule), ("same", None))
        self.assertEqual(oracle.compare("X := 1; {pragma};\nY := 2;\n", "statement_list")[0], "declined")

    def test_loops_and_arrays_take_the_fast_path(self):
        """FOR (with and without BY, nested, EXIT and CONTINUE in it) and inline ARRAY types (`[*]`, several
        dimensions, bounds that are expressions, arrays of arrays and of STRING, in every kind of variable block,
        VAR_EXTERNAL and VAR_GLOBAL, and in a STRUCT) as user programs and pac-test's TcUnit asserts write them,
        with Earley's tree. An empty FOR body and an array's initial value are declined."""
        oracle = _oracle()
        # pac-test's TcUnit array asserts: one of each dimension (the others differ only in the element type).
        with open(os.path.join(REPO, "tools", "pactest", "tcunit", "AssertArrayEquals.st"), encoding="utf-8") as f:
            asserts = f.read()
        for name in ("AssertArrayEquals_LREAL", "AssertArray2dEquals_REAL", "AssertArray3dEquals_LREAL"):
            found = re.search(rf"^FUNCTION {name} :.*?^END_FUNCTION\n", asserts, re.S | re.M)
            with self.subTest(name=name):
                self.assertIsNotNone(found)
                self.assertEqual(oracle.compare(found.group(0)), ("same", None))
        cases = {"iec_source": "FUNCTION_BLOCK FB_Loops\nVAR\n  i : DINT;\n  n : INT;\nEND_VAR\n"
                               "FOR i := 0 TO 10 DO n := n + 1; END_FOR;\n"
                               "FOR i := UPPER_BOUND(a, 1) TO -1 BY -2 DO\n  IF n > 3 THEN EXIT; END_IF\n"
                               "  FOR s.k[i] := 1 TO f(x := 2) BY n * 2 DO CONTINUE; END_FOR\nEND_FOR\n"
                               "CASE n OF 1: FOR i := 1 TO 2 DO n := 0; END_FOR 2: n := 1; END_CASE;\n"
                               "END_FUNCTION_BLOCK\n",
                 "statement_list": "FOR i := 1 TO 3 BY 1 DO\n  x := i;\nEND_FOR\n",
                 "function_declaration": "FUNCTION F_Arrays : BOOL\nVAR_IN_OUT\n  a : ARRAY [*, *] OF LREAL;\nEND_VAR\n"
                                         "VAR_INPUT\n  b, c : ARRAY [0..N_MAX - 1, 1..GVL_X.Count] OF ST_S;\nEND_VAR\n"
                                         "VAR\n  d : ARRAY [-1..1] OF ARRAY [0..2] OF STRING;\nEND_VAR\nEND_FUNCTION\n",
                 "data_type_declaration": "TYPE ST_Arrays :\nSTRUCT\n  a : ARRAY [1..3] OF TIME;\n"
                                          "  b : ARRAY [*] OF E_Mode;\nEND_STRUCT\nEND_TYPE\n"}
        cases["iec_source"] += ("VAR_GLOBAL\n  g, h : ARRAY [1..2] OF INT;\nEND_VAR\n"
                                "FUNCTION_BLOCK FB_Blocks\nVAR_OUTPUT q : ARRAY [1..2] OF BOOL; END_VAR\n"
                                "VAR_TEMP t : ARRAY [1..2] OF WORD; END_VAR\n"
                                "VAR_EXTERNAL g : ARRAY [1..2] OF INT; END_VAR\nq[1] := g[2] > 0;\nEND_FUNCTION_BLOCK\n")
        for rule, text in cases.items():
            with self.subTest(rule=rule):
                self.assertEqual(oracle.compare(text, rule), ("same", None))
        self.assertEqual(oracle.compare("FOR i := 1 TO 3 DO END_FOR;\n", "statement_list")[0], "declined")
        self.assertEqual(oracle.compare("PROGRAM P\nVAR a : ARRAY [1..2] OF INT := [1, 2]; END_VAR\nEND_PROGRAM\n")[0],
                         "declined")

    def test_the_conformance_suite_takes_the_fast_path(self):
        paths = CORPORA["conformance accept"]
        self.assertTrue(paths)
        declined = [os.path.relpath(p, REPO) for p in paths if self.results[p][0] != "same"]
        self.assertEqual(declined, [])


if __name__ == "__main__":
    unittest.main(verbosity=2)
