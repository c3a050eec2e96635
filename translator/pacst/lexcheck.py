"""Checks on the raw text that blark's grammar is too lenient for but MATIEC is not.

blark accepts `//` comments, pragmas, nested comments, `;;` and a missing `;` after END_IF;
MATIEC refuses them all (docs/st_subset.md, "Lexical rules"), so they are refused here
before parsing, with the exact position. The export (tools/pacexport) reads the library with the same
tokens: their offsets and the comments are where it cuts a file into declaration and body.
"""
import re

from . import durations
from .errors import StError

_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_NUMBER = re.compile(r"[0-9][0-9_]*(?:#[0-9A-Za-z_]+)?(?:\.[0-9_]+)?(?:[eE][+-]?[0-9_]+)?")
_TIME_PREFIX = {"T", "TIME", "LT", "LTIME", "D", "DATE", "TOD", "TIME_OF_DAY", "DT", "DATE_AND_TIME"}
_NEEDS_SEMICOLON = {"END_IF", "END_CASE", "END_WHILE", "END_REPEAT", "END_FOR", "END_STRUCT"}
_EMPTY_BEFORE = {";", "THEN", "ELSE", "DO", "REPEAT", ":"}
_PUNCT2 = (":=", "=>", "<=", ">=", "<>", "..", "**")
# A branch or loop body that one of these opens must not end at once (MATIEC needs a statement).
_OPENS_BRANCH = {"THEN": "THEN branch", "ELSE": "ELSE branch", "DO": "loop body", "REPEAT": "loop body",
                 ":": "CASE branch"}
_ENDS_BRANCH = {"ELSE", "ELSIF", "END_IF", "END_CASE", "END_WHILE", "END_FOR", "UNTIL"}


class Token:
    """A word, literal or punctuation outside comments: its text, line and column, and its offsets in
    the text (the export cuts a file into declaration and body at them)."""
    __slots__ = ("kind", "text", "line", "col", "start")

    def __init__(self, kind, text, line, col, start):
        self.kind = kind
        self.text = text
        self.line = line
        self.col = col
        self.start = start

    @property
    def end(self):
        return self.start + len(self.text)

    @property
    def upper(self):
        return self.text.upper()


class Comment:
    """A `(* *)` comment with its delimiters, and its offsets."""
    __slots__ = ("text", "start", "end")

    def __init__(self, text, start, end):
        self.text = text
        self.start = start
        self.end = end


# TwinCAT's operators, namespaces and pseudo types starting with '__' that user mode translates (system.py,
# expressions.py, compiler.py)
_TWINCAT_TRANSLATED = {"__ISVALIDREF", "__NEW", "__DELETE", "__SYSTEM", "__XINT", "__UXINT", "__XWORD"}
# and those it does not translate, and why
_TWINCAT_OPERATORS = {
    "__QUERYINTERFACE": "not translated; assign the instance to a variable of the INTERFACE and call through it",
    "__QUERYPOINTER": "not translated; assign the instance to a variable of the INTERFACE and call through it",
    "__TRY": "exception handling (__TRY, __CATCH, __FINALLY, __ENDTRY) is not translated: the test runtime stops the "
             "test at the ST line of a fault; keep the code between __TRY and __CATCH",
    "__CATCH": "exception handling is not translated: keep the code between __TRY and __CATCH",
    "__FINALLY": "exception handling is not translated: keep the code between __TRY and __CATCH",
    "__ENDTRY": "exception handling is not translated: keep the code between __TRY and __CATCH",
}

def _check_underscores(digits, file, line, col):
    """No leading, doubled or trailing `_` inside a number (MATIEC's lexer refuses them)."""
    parts = digits.split("#") if "#" in digits else re.split(r"[.eE+-]", digits)
    for part in parts:
        if part and (part.startswith("_") or part.endswith("_") or "__" in part):
            raise StError(file, line, col, f"malformed number '{digits}': no leading, doubled or trailing '_'")


def _check_real_point(digits, file, line, col):
    """A REAL literal has a decimal point: MATIEC reads `1E5` as no literal at all."""
    if "#" not in digits and "." not in digits and re.search(r"[eE]", digits):
        with_point = re.sub(r"([eE])", r".0\1", digits, count=1)
        raise StError(file, line, col, f"REAL literal '{digits}' without a decimal point: MATIEC refuses it, "
                                       f"write {with_point}")


def tokenize(text, file, comments=None, user=False):
    """Tokens without comments (appended to `comments` when it is a list); raises StError on what
    MATIEC's lexer would refuse. A user program (`user`) may also have `//` comments and pragmas
    (`{attribute 'qualified_only'}`), which TwinCAT and CODESYS write; pacst ignores the pragmas."""
    tokens = []
    i, line, col = 0, 1, 1
    n = len(text)

    def advance(upto):
        nonlocal i, line, col
        chunk = text[i:upto]
        nl = chunk.count("\n")
        if nl:
            line += nl
            col = len(chunk) - chunk.rfind("\n")
        else:
            col += len(chunk)
        i = upto

    while i < n:
        c = text[i]
        if c in " \t\r\n":
            advance(i + 1)
            continue
        if text.startswith("(*", i):
            start_line, start_col = line, col
            j = i + 2
            while True:
                end = text.find("*)", j)
                nested = text.find("(*", j)
                if end < 0:
                    raise StError(file, start_line, start_col, "comment is not closed with '*)'")
                if 0 <= nested < end:
                    advance(nested)
                    raise StError(file, line, col, "nested comment: MATIEC does not nest '(* *)' comments")
                break
            if comments is not None:
                comments.append(Comment(text[i:end + 2], i, end + 2))
            advance(end + 2)
            continue
        if user and text.startswith("//", i):
            end = text.find("\n", i)
            advance(n if end < 0 else end)
            continue
        if user and c == "{":
            end = text.find("}", i)
            if end < 0:
                raise StError(file, line, col, "pragma is not closed with '}'")
            advance(end + 1)
            continue
        if text.startswith("//", i):
            raise StError(file, line, col, "'//' comment: MATIEC accepts only '(* ... *)' comments")
        if text.startswith("/*", i):
            raise StError(file, line, col, "'/* */' comment: MATIEC accepts only '(* ... *)' comments")
        if c == "{":
            raise StError(file, line, col, "pragma '{...}': MATIEC copies or rejects pragmas; none are allowed")
        if c in "'\"":
            end = i + 1  # '$' escapes the next character, a quote included ('it$'s')
            while end < n and text[end] != c:
                end += 2 if text[end] == "$" else 1
            if end >= n:
                raise StError(file, line, col, "string literal is not closed")
            tokens.append(Token("string", text[i:end + 1], line, col, i))
            advance(end + 1)
            continue
        m = _IDENT.match(text, i)
        if m:
            word = m.group(0)
            if text.startswith("#", m.end()):
                # Typed literal or time literal: WORD#16#FF, INT#-5, T#1S500MS.
                if word.upper() in _TIME_PREFIX:
                    lit = re.compile(r"#-?[0-9A-Za-z_.]+").match(text, m.end())
                    finer = durations.finer_than_milliseconds(word, lit.group(0)) if user and lit else None
                    if finer is not None:
                        raise StError(file, line, col, finer)
                else:
                    lit = re.compile(r"#-?[0-9][0-9A-Za-z_#.]*(?:[eE][+-]?[0-9_]+)?|#[A-Za-z_][A-Za-z0-9_]*").match(
                        text, m.end())
                    if lit and (lit.group(0)[1:2].isdigit() or lit.group(0)[1:2] == "-"):
                        _check_underscores(lit.group(0)[1:].lstrip("-"), file, line, col)
                        _check_real_point(lit.group(0)[1:].lstrip("-"), file, line, col)
                    elif lit and word.upper() != "BOOL":  # E_Mode#MODE_RUN (BOOL#TRUE is a typed literal)
                        raise StError(file, line, col, f"qualified enumeration value '{text[i:lit.end()]}': write "
                                                       "the value alone (E#A and E.A are not accepted by every tool)")
                end = lit.end() if lit else m.end() + 1
                tokens.append(Token("literal", text[i:end], line, col, i))
                advance(end)
                continue
            if "__" in word and (not user or word.startswith("__") and word.upper() not in _TWINCAT_TRANSLATED
                                 and not word.startswith("__PTRTO_")):  # rewrite.py's __NEW(POINTER TO T, n)
                if user and word.upper() in _TWINCAT_OPERATORS:
                    raise StError(file, line, col, f"TwinCAT's {word}: {_TWINCAT_OPERATORS[word.upper()]}")
                raise StError(file, line, col, f"identifier '{word}' contains '__', which MATIEC reserves"
                              if not user else f"identifier '{word}' starts with '__', which TwinCAT and CODESYS "
                              "keep for their own names (__NEW, __SYSTEM) and C for its compiler: rename it without "
                              f"the leading '__' ({word.lstrip('_')})")
            if word.endswith("_") and not user:
                raise StError(file, line, col, f"identifier '{word}' ends with '_', which MATIEC refuses")
            tokens.append(Token("ident", word, line, col, i))
            advance(m.end())
            continue
        m = _NUMBER.match(text, i)
        if m:
            lit = m.group(0)
            if re.match(r"[0-9_]+\.\.", text[i:]):  # range 0..7: the number stops before '..'
                lit = re.match(r"[0-9_]+", text[i:]).group(0)
            _check_underscores(lit, file, line, col)
            _check_real_point(lit, file, line, col)
            tokens.append(Token("number", lit, line, col, i))
            advance(i + len(lit))
            continue
        two = text[i:i + 2]
        if two in _PUNCT2:
            tokens.append(Token("punct", two, line, col, i))
            advance(i + 2)
            continue
        tokens.append(Token("punct", c, line, col, i))
        advance(i + 1)
    return tokens


def check(text, file, user=False):
    """Raise StError for the first lexical rule of the portable subset that `text` breaks. A user program
    (`user`) may have `//` comments and pragmas, and may leave out the `;` after END_IF and the like."""
    tokens = tokenize(text, file, user=user)
    in_type = False
    type_depth = 0  # STRUCT/UNION and parentheses open inside the current TYPE block
    pou = None  # the keyword that opened the current POU
    for k, tok in enumerate(tokens):
        up = tok.upper if tok.kind == "ident" else tok.text
        nxt = tokens[k + 1] if k + 1 < len(tokens) else None
        nxt_up = (nxt.upper if nxt.kind == "ident" else nxt.text) if nxt is not None else None
        if tok.kind == "punct" and tok.text == "**":
            raise StError(file, tok.line, tok.col, "'**': pacst's parser does not read the exponent operator: write "
                                                   "EXPT(a, b)" if user else
                          "'**' is not supported (blark has no exponent operator and pacst no EXPT): multiply, or "
                          "write a loop")
        if tok.kind == "punct" and tok.text == "&":
            raise StError(file, tok.line, tok.col, "'&' for AND: pacst's parser (blark) does not read it; write AND")
        if tok.kind == "punct" and tok.text == ":=" and nxt is not None and nxt.text == "[" and not user:
            raise StError(file, nxt.line, nxt.col, "array initial values are outside the portable subset: "
                                                   "initialise in code")
        if up in _OPENS_BRANCH and nxt is not None and nxt.kind == "ident" and nxt_up in _ENDS_BRANCH and not user:
            raise StError(file, nxt.line, nxt.col, f"empty {_OPENS_BRANCH[up]}: MATIEC needs at least one "
                                                   f"statement before {nxt_up}")
        if tok.kind == "ident" and up in ("FUNCTION", "FUNCTION_BLOCK", "PROGRAM", "END_FUNCTION",
                                          "END_FUNCTION_BLOCK", "END_PROGRAM"):
            pou = None if up.startswith("END_") else up
        if tok.kind == "ident" and up == "VAR_TEMP" and pou == "FUNCTION":
            raise StError(file, tok.line, tok.col, "a FUNCTION has no VAR_TEMP in the portable subset: use VAR")
        if in_type and type_depth == 0 and tok.text == ";" and nxt is not None and nxt_up != "END_TYPE":
            raise StError(file, nxt.line, nxt.col, "a second type in one TYPE block: write one type per "
                                                   "TYPE ... END_TYPE (TwinCAT and blark expect it)")
        if in_type and (up in ("STRUCT", "UNION") or tok.text == "("):
            type_depth += 1
        elif in_type and (up in ("END_STRUCT", "END_UNION") or tok.text == ")"):
            type_depth -= 1
        if tok.kind == "punct" and tok.text == ";" and k > 0:
            prev = tokens[k - 1]
            prev_text = prev.upper if prev.kind == "ident" else prev.text
            if prev_text in _EMPTY_BEFORE and not user:
                raise StError(file, tok.line, tok.col, "empty statement: MATIEC refuses ';;' and empty branches")
        if tok.kind == "ident" and up in _NEEDS_SEMICOLON and (nxt is None or nxt.text != ";") and not user:
            raise StError(file, tok.line, tok.col + len(tok.text),
                          f"missing ';' after {up}: MATIEC requires it")
        if tok.kind == "ident" and up == "TYPE":
            in_type, type_depth = True, 0
        elif tok.kind == "ident" and up == "END_TYPE":
            in_type = False
        elif in_type and tok.text == "(" and k > 0 and tokens[k - 1].text == ":" and not user:
            depth, j = 0, k
            while j < len(tokens):
                if tokens[j].text == "(":
                    depth += 1
                elif tokens[j].text == ")":
                    depth -= 1
                    if depth == 0:
                        break
                j += 1
            if j + 2 < len(tokens) and tokens[j + 1].kind == "ident" and tokens[j + 2].text == ";":
                base = tokens[j + 1]
                raise StError(file, base.line, base.col, f"enumeration with base type {base.text}: the portable "
                                                         "subset has plain value lists without base type")
            if j + 1 >= len(tokens) or tokens[j + 1].text != ";":
                close = tokens[min(j, len(tokens) - 1)]
                raise StError(file, close.line, close.col + 1, "missing ';' after an enumeration's ')': MATIEC requires it")
    return tokens
