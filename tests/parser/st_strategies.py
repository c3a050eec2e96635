"""Hypothesis strategies that write ST text: expressions of random precedence, spacing and
parentheses over the subset's literals and variables, and statement nests of every kind the subset
has, so that the fast parser meets the ambiguities blark's grammar resolves (a sign that is an
operator or part of a literal, `1` as an integer or a boolean, labels against statements)."""
from hypothesis import strategies as st

LITERALS = ["0", "1", "7", "32767", "1_000", "16#FF", "16#0A8e", "2#1010", "8#17", "INT#5", "DINT#-5",
            "UINT#16#FF", "SINT#+3", "WORD#16#8000", "WORD#5", "BYTE#2#101", "DWORD#8#7", "BOOL#TRUE",
            "BOOL#FALSE", "BOOL#1", "BOOL#0", "TRUE", "FALSE", "true", "3.0", "1.0E5", "2.5e-3", "REAL#1.5",
            "LREAL#-0.5", "T#1S", "T#1m30s", "T#-5ms", "TIME#1h", "T#1.5s", "t#2d3h", "T#1h_30m", "T#100MS",
            "'abc'", "''", "'a$'b'", "'$$1$N'", "1E5", "10#5", "16#FFG", "T#1d30m", "LT#1s", "D#2020-01-01",
            '"wide"', '"a$"b"', "LTIME#1S0.5MS", "LT#5us", "T#5us"]
NAMES = ["a", "b", "Counter", "x_1", "fb.Q", "arr[i]", "arr[i, 2]", "s.Data[3].Field", "TRUE_X", "IF_1",
         "NOT_A", "Modulo",
         # the dialect's: a `^` (whose place in blark's tree depends on the fields after it), bit numbers
         "p^", "p^.a", "p^.a.b", "p^.a.b.c", "THIS^.x[1]^.y", "a[2]^.b", "s.p^.k", "w.3", "a.b[1].2", "p^ .a"]
BINARY = ["OR_ELSE", "AND_THEN", "OR", "XOR", "AND", "&", "=", "<>", "<", ">", "<=", ">=", "+", "-", "*",
          "/", "MOD", "**"]
UNARY = ["-", "+", "NOT ", "NOT", "- "]
# a line comment too (user programs), one holding what would open a block comment
SPACES = st.sampled_from(["", " ", "  ", "\n", " (* c *) ", " // c\n", "// (* c\n"])


def _call(args):
    return st.tuples(st.sampled_from(["f", "F_Pac", "fb.Method", "USINT_TO_WORD", "THIS^.M", "p^.a.M"]), args,
                     st.sampled_from([""] * 4 + ["^", ".Next()", ".Add(1).Add(2)", ".a.b()"])).map(
        lambda t: f"{t[0]}({t[1]}){t[2]}")


def expressions():
    leaves = st.sampled_from(LITERALS) | st.sampled_from(NAMES)

    def extend(inner):
        arg = (inner | st.tuples(st.sampled_from(["x", "IN", "Q"]), st.sampled_from([":=", "=>"]), inner)
               .map(lambda t: f"{t[0]} {t[1]} {t[2]}"))
        args = st.lists(arg, max_size=3).map(", ".join)
        return (st.tuples(inner, SPACES, st.sampled_from(BINARY), SPACES, inner).map("".join)
                | st.tuples(st.sampled_from(UNARY), inner).map("".join)
                | inner.map(lambda e: f"({e})")
                | _call(args))
    return st.recursive(leaves, extend, max_leaves=8)


def _labels():
    label = st.sampled_from(["1", "2", "-5", "+3", "0", "10..20", "-5..-2", "PAC_A", "PAC_B"] * 2 + ["16#F", "E.A"])
    return st.lists(label, min_size=1, max_size=3).map(", ".join)


def statements(expr):
    simple = (st.tuples(st.sampled_from(NAMES[:8]), expr).map(lambda t: f"{t[0]} := {t[1]};")
              | expr.map(lambda e: f"fb(IN := {e});")
              | st.sampled_from(["EXIT;", "RETURN;", "CONTINUE;", "fb();"] * 2 + [";", "a := 1;;", "a := b := 1;",
                                                                                "r REF= s.t;", "F(1).G();", "p^.a := 1;"]))

    def extend(body):
        bodies = st.lists(body, max_size=3).map(" ".join)
        return (st.tuples(expr, bodies, st.lists(st.tuples(expr, bodies), max_size=2), st.none() | bodies,
                          st.sampled_from(["END_IF;"] * 4 + ["END_IF", "END_IF;;"]))
                .map(lambda t: f"IF {t[0]} THEN {t[1]} "
                     + "".join(f"ELSIF {c} THEN {b} " for c, b in t[2])
                     + ("" if t[3] is None else f"ELSE {t[3]} ") + t[4])
                | st.tuples(expr, st.lists(st.tuples(_labels(), bodies), min_size=1, max_size=3),
                            st.none() | bodies)
                .map(lambda t: f"CASE {t[0]} OF " + " ".join(f"{l}: {b}" for l, b in t[1])
                     + ("" if t[2] is None else f" ELSE {t[2]}") + " END_CASE;")
                | st.tuples(expr, bodies).map(lambda t: f"WHILE {t[0]} DO {t[1]} END_WHILE;")
                | st.tuples(bodies, expr).map(lambda t: f"REPEAT {t[0]} UNTIL {t[1]} END_REPEAT;")
                | st.tuples(st.sampled_from(NAMES[:8]), expr, expr, st.none() | expr, bodies,
                            st.sampled_from(["END_FOR;"] * 3 + ["END_FOR", "END_FOR;;"]))
                .map(lambda t: f"FOR {t[0]} := {t[1]} TO {t[2]} " + ("" if t[3] is None else f"BY {t[3]} ")
                     + f"DO {t[4]} {t[5]}"))
    return st.recursive(simple, extend, max_leaves=6)


# Mostly the subset's declarations; a few outside it, which the fast parser must decline.
DECLARATIONS = ["a : INT;", "b : BOOL;", "c : E_Mode;", "w : WORD;", "a, b, c : UINT := 16#FF;", "a, b : DINT := 5;",
                "t : TON;", "w : WORD := WORD#16#8000;", "d : TIME := T#1S;", "s : STRING;", "s : STRING := 'x';",
                "r : LREAL := -1.5;", "e : E_Mode := PAC_A;", "arr : T_Arr;", "u : LTIME;"] * 3 + [
                "x : ARRAY[0..3] OF INT;", "x, y : ARRAY [*, *] OF LREAL;", "x : ARRAY[1..N - 1] OF ST_S;",
                "x : ARRAY[0..1] OF ARRAY[-1..+1] OF STRING;", "x : ARRAY [*] OF TON;"] * 2 + [
                "x : ARRAY[0..1] OF INT := [1, 2];", "x : ARRAY[0..1] OF STRING(10);", "p AT %IX0.0 : BOOL;",
                "q : DATE;",
                # the dialect's
                "p : POINTER TO INT;", "r : REFERENCE TO POINTER TO ST_S;", "s : STRING(80) := 'x';",
                "w : WSTRING[3];", "m : NS.FB_M;", "a : ARRAY [*] OF POINTER TO INT;", "p : POINTER TO STRING(5);",
                "k : WORD := (N + 1);", "f : FB_F(x := 1);", "s : ST_S := (a := 1);"]
BLOCKS = ["VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR", "VAR CONSTANT", "VAR RETAIN", "VAR_TEMP"] * 3 + [
    "VAR_STAT", "VAR_EXTERNAL", "VAR_EXTERNAL CONSTANT", "VAR_INST"]


def declarations():
    block = st.tuples(st.sampled_from(BLOCKS), st.lists(st.sampled_from(DECLARATIONS), max_size=3),
                      st.sampled_from(["END_VAR"] * 5 + ["END_VAR;"]))
    block = block.map(lambda t: f"{t[0]}\n  {' '.join(t[1])}\n{t[2]}")
    return st.lists(block, max_size=3).map("\n".join)


TYPES = ["TYPE E_Mode : (PAC_A, PAC_B); END_TYPE", "TYPE T_Arr : ARRAY[1..8] OF BYTE; END_TYPE",
         "TYPE E_Mode :\n(\n  PAC_A,\n  PAC_B\n);\nEND_TYPE", "TYPE T_Arr : ARRAY[-2..2, 0..1] OF ST_S;\nEND_TYPE",
         "TYPE ST_S : STRUCT a : INT; b : WORD := 16#1; END_STRUCT; END_TYPE"] * 2 + [
         "TYPE T_A : INT; END_TYPE", "TYPE E_B : (B1, B2) INT; END_TYPE", "TYPE ST_E : STRUCT END_STRUCT END_TYPE;",
         "TYPE E_C : (C1 := 1, C2 := 16#20, C3 := -3) DINT := E_C.C1; END_TYPE", "TYPE T_N : NS.T_M; END_TYPE",
         "TYPE ST_F EXTENDS NS.ST_S : STRUCT p : POINTER TO ST_F; END_STRUCT END_TYPE"]


def pous(expr):
    body = st.lists(statements(expr), max_size=4).map("\n".join)
    fb = st.tuples(declarations(), body).map(lambda t: f"FUNCTION_BLOCK FB_X\n{t[0]}\n{t[1]}\nEND_FUNCTION_BLOCK")
    fn = st.tuples(st.sampled_from(["INT", "BOOL", "T_Arr", "STRING"]), declarations(), body).map(
        lambda t: f"FUNCTION F_X : {t[0]}\n{t[1]}\n{t[2]}\nEND_FUNCTION")
    # User programs (pacst --user): PROGRAMs, with or without blocks and body.
    prg = st.tuples(declarations(), body).map(lambda t: f"PROGRAM PRG_X\n{t[0]}\n{t[1]}\nEND_PROGRAM")
    # The dialect's: a FUNCTION_BLOCK that extends and implements, its METHODs and PROPERTYs, INTERFACEs.
    heading = st.sampled_from(["FB_X", "FB_X EXTENDS FB_B", "PUBLIC FB_X IMPLEMENTS I_A, NS.I_B",
                               "FB_X EXTENDS NS.FB_B IMPLEMENTS I_A"])
    fb = fb | st.tuples(heading, declarations(), body).map(
        lambda t: f"FUNCTION_BLOCK {t[0]}\n{t[1]}\n{t[2]}\nEND_FUNCTION_BLOCK")
    member = st.tuples(st.sampled_from(["METHOD M", "METHOD PRIVATE M : INT", "METHOD M : POINTER TO INT",
                                        "PROPERTY P : BOOL", "PROPERTY PUBLIC P.Get : STRING(10)"]), declarations(), body)
    member = member.map(lambda t: f"{t[0]}\n{t[1]}\n{t[2]}\nEND_{t[0].split()[0]}")
    interface = st.tuples(st.sampled_from(["I_A", "I_A EXTENDS I_B, NS.I_C"]), declarations()).map(
        lambda t: f"INTERFACE {t[0]}\n{t[1]}\nEND_INTERFACE")
    types = st.lists(st.sampled_from(TYPES), max_size=2).map("\n".join)
    return st.tuples(types, st.lists(fb | fn | prg | member | interface, min_size=1, max_size=2).map("\n".join)).map(
        "\n".join)
