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
from pacst import parsing  # noqa: E402 (tree_oracle puts the translator on the path)
from pacst.fastparse import LEFT_TO_EARLEY, Decline  # noqa: E402

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


# pac-test's dialect project (tools/pactest/tests/dialect): its ST and TwinCAT files as pac-test reads them, in user
# mode (a TwinCAT object's ST in place, a POU closed, the rewrites of pacst.rewrite), the texts its runs parse.
DIALECT_PROJECT = sorted(p for p in glob.glob(os.path.join(REPO, "tools", "pactest", "tests", "dialect", "*"))
                         if p.lower().endswith((".st",) + parsing.twincat.OBJECT_EXTENSIONS))


def _user_text(path):
    return parsing._read(path, user=True)[0]


def corpus_texts():
    """(start rule, source) of every text the tests below compare from the corpora's files: what
    record_earley.py records."""
    texts = []
    for path in sorted({p for paths in CORPORA.values() for p in paths}):
        with open(path, encoding="utf-8") as f:
            texts.append(("iec_source", f.read()))
    texts += [found for found in map(_body, _body_paths()) if found]
    texts += [found for found in map(_declaration, _declaration_paths()) if found]
    texts += [("iec_source", _user_text(path)) for path in DIALECT_PROJECT]
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

    def test_the_dialect_project_takes_the_fast_path(self):
        """pac-test's dialect project as its runs parse it: every text the fast parser reads has Earley's tree, and
        every text it declines holds a construct left to Earley on purpose (LEFT_TO_EARLEY), never one it reads
        (a METHOD, a pointer, an INTERFACE...): each such decline is Earley's time on every run's first parse."""
        self.assertGreater(len(DIALECT_PROJECT), 100)
        oracle = _oracle()
        fast = 0
        for path in DIALECT_PROJECT:
            text = _user_text(path)
            with self.subTest(path=os.path.relpath(path, REPO)):
                verdict, what = oracle.compare(text)
                self.assertNotEqual(verdict, "different", what)
                if verdict == "same":
                    fast += 1
                    continue
                with self.assertRaises(Decline) as declined:
                    oracle.fast.parse(oracle.processed(text))
                self.assertIn(str(declined.exception), LEFT_TO_EARLEY)
        print(f"dialect project as pac-test reads it: {fast} of {len(DIALECT_PROJECT)} files parsed fast", file=sys.stderr)

    def test_dialect_constructs_take_the_fast_path(self):
        """The TwinCAT 3 / CODESYS constructs the fast parser reads, with comments and pragmas inside them and
        nested, have Earley's tree; the same constructs damaged are declined (Earley gives the error)."""
        oracle = _oracle()
        same = {
            "iec_source": (
                "FUNCTION_BLOCK PUBLIC FB_A EXTENDS NS.FB_B IMPLEMENTS I_X, (* two *) NS.I_Y\n"
                "VAR\n  p : POINTER TO INT;\n  r : REFERENCE TO POINTER TO BYTE;  // a pointer's reference\n"
                "  q : POINTER TO POINTER TO ST_X := 0;\n  a : ARRAY [*] OF POINTER TO INT;\n  s : STRING(80);\n"
                "  w : WSTRING[3] := \"a$\"b\";\n  m : PA_CONTROL.MC_Power;\n  k : WORD := (K_A + 2);\nEND_VAR\n"
                "VAR_STAT n : INT; END_VAR\nVAR_INST {attribute 'x'} i : INT; END_VAR\n"
                "p^ := x.3; a[1]^ := 2; s.p^.k := f(1)^; THIS^.M(); pNode^.pNext^.Value := 1;\n"
                "x := THIS^.ipCounter.Count(); y := a^.b.c.d; z := a^.b[1]; SUPER^();\n"
                "Fluent.Add(1).Add(2) (* chained *).Add(3); v := F(7).Value(); r REF= s.t; a := b := c.d[1] := 0;\n"
                "x := __NEW(BYTE, 4) + SIZEOF(LREAL); d := LTIME#1S0.002044MS; e := LT#5us;\n"
                "CASE x OF 16#01: x := 1; GVL_S.STEP, E_A.B: x := 2; END_CASE\n"
                "END_FUNCTION_BLOCK\n"
                "METHOD PRIVATE FB_init : BOOL\nVAR_INPUT\n  bInitRetains : BOOL;\nEND_VAR\nVAR END_VAR\n"
                "FB_init := TRUE;\nEND_METHOD\n"
                "METHOD Empty\nEND_METHOD\n"
                "PROPERTY PUBLIC Count.Get : STRING(10)\nVAR\nEND_VAR\nCount := 'x';\nEND_PROPERTY\n"
                "INTERFACE I_Limited EXTENDS I_Counter, NS.I_Y\nVAR_INPUT x : INT; END_VAR\nEND_INTERFACE\n"
                "ACTION FB_A.Clear :\nx := 0;\nEND_ACTION\n"
                "FUNCTION F_Bump\nVAR_IN_OUT c : INT; END_VAR\nVAR F_Bump : REFERENCE TO INT; END_VAR\n"
                "c := c + 1;\nEND_FUNCTION\n"
                "TYPE E_A : (A := 1, B := 16#20, (* minus *) C := -3) DINT := E_A.A; END_TYPE\n"
                "TYPE ST_B EXTENDS NS.ST_A :\nSTRUCT\n  n : POINTER TO ST_B;\nEND_STRUCT\nEND_TYPE\n"
                "TYPE T_Alias : NS.T_Other; END_TYPE\n"),
            "function_block_method_declaration": "METHOD Add : POINTER TO INT\nVAR_INST k : INT; END_VAR\nAdd := 0;\nEND_METHOD\n",
            "interface_declaration": "INTERFACE I_Fluent\nEND_INTERFACE\n",
        }
        for rule, text in same.items():
            with self.subTest(rule=rule):
                self.assertEqual(oracle.compare(text, rule), ("same", None))
        for text in ("METHOD M : INT\nM := 1\nEND_METHOD\n",  # no `;`
                     "FUNCTION_BLOCK FB_A EXTENDS\nEND_FUNCTION_BLOCK\n",
                     "INTERFACE I_X\n",  # no END_INTERFACE (blark takes it, the fast parser does not)
                     "PROGRAM P\nx := p ^^;\nEND_PROGRAM\n",
                     "PROGRAM P\nF(1).A;\nEND_PROGRAM\n",
                     "PROGRAM P\nx := a.3.5;\nEND_PROGRAM\n",
                     "FUNCTION F : STRING(80)\nF := 'a';\nEND_FUNCTION\n",  # Earley: the length is an argument
                     "PROGRAM P\nVAR x : TIME := T#5us; END_VAR\nEND_PROGRAM\n",
                     "PROGRAM P\nVAR a : ARRAY [1..2] OF INT := [1, 2]; END_VAR\nEND_PROGRAM\n",
                     "PROGRAM P\nVAR a : ST_A := (B := 1); END_VAR\nEND_PROGRAM\n"):
            with self.subTest(text=text):
                self.assertEqual(oracle.compare(text)[0], "declined")

    def test_the_conformance_suite_takes_the_fast_path(self):
        paths = CORPORA["conformance accept"]
        self.assertTrue(paths)
        declined = [os.path.relpath(p, REPO) for p in paths if self.results[p][0] != "same"]
        self.assertEqual(declined, [])


if __name__ == "__main__":
    unittest.main(verbosity=2)
