"""User mode: forms of the TwinCAT 3 / CODESYS dialect that blark's grammar lacks, rewritten before parsing to
forms it has (docs/user_dialect.md). Every rewrite keeps each line where it is and every token before it at
its column, so that errors, `#line` directives and coverage still name the user's line:

- `PROGRAM INTERNAL MAIN` (an access specifier of a PROGRAM): the specifier blanked;
- `FUNCTION_BLOCK FB_Cnc IMPLEMENTS I_Hmi;` (a `;` after the heading): the `;` blanked;
- `List : FB_List := ();` (an FB instance with an empty initial value): `:= ()` blanked;
- `ARRAY [1..N] OF UINT(1..M)`, `METHOD GetOrder : UINT(0..M)` (a subrange as an array's element or a
  result, whose bounds blark's grammar does not read there): the range blanked, as pacst does not check a
  subrange's range anywhere;
- `RETURN(Done);` (CODESYS's conditional RETURN): `IF    (Done) THEN RETURN; END_IF;`, `RETURN` written over
  by `IF` and blanks, the rest of the statement after the `)`; `RETURN(Init := T <= 0);` (an assignment as its
  condition): `       Init := T <= 0 ; IF Init THEN RETURN; END_IF;`;
- `__NEW(POINTER TO T, n)` (n pointers, a type blark's grammar does not read as an argument): `POINTER TO `
  written over by `__PTRTO____`, one name with T's that system.new_assignment reads back;
- `LTIME#1S2US44NS` (microseconds and nanoseconds after another unit): durations.py;
- `F(x).Member`, `Get(i)^.Data.Count` (a member of a call's result, read): `()` after each member, which blark
  reads as a METHOD called on the result (`F(x).Member()`); the translator knows the member by its place
  (CALL_MEMBER among the file's rewrites). A member followed by an index, a `:=` or a bit number is left as it
  is: the syntax error says what to write instead.
- `FUNCTION Pack : ARRAY[1..4] OF USINT` (an ARRAY result, which blark's grammar reads for a METHOD but not for a
  FUNCTION; the array on the heading's line): `FUNCTION Pack VAR Pack : ARRAY[1..4] OF USINT; END_VAR`, a block
  the translator takes back as the result (ARRAY_RESULT among the file's rewrites, at the `ARRAY`, whose column
  in the parsed text tells the translator how far the rest of the line moved).
"""
from . import durations, lexcheck
from .errors import StError

# the prefix of `__NEW(POINTER TO T, n)`'s type, rewritten (the name blark reads: __PTRTO____T)
NEW_POINTER = "__PTRTO"
# the construct of a rewritten `F(x).Member`: its member's (line, column) among a file's rewrites
CALL_MEMBER = "a member of a call's result"
# the construct of a rewritten `FUNCTION F : ARRAY[...] OF T`: the (line, column) of its `ARRAY`
ARRAY_RESULT = "a FUNCTION's ARRAY result"
_ACCESS = {"ABSTRACT", "PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL", "FINAL"}


def user_text(text, path):
    """(`text` with the rewrites above, [(line, column, construct, column in the rewritten text) of each]); `text` as
    it is when it has none, or when its tokens are refused (the lexical check names what is wrong)."""
    try:
        tokens = lexcheck.tokenize(text, path, user=True)
    except StError:
        return text, []
    edits = []  # (start, end, replacement) in the text, in order, not overlapping
    uses = []
    opening = _openings(tokens)
    for k, tok in enumerate(tokens):
        up = tok.upper if tok.kind == "ident" else tok.text
        nxt = tokens[k + 1] if k + 1 < len(tokens) else None
        if up == "PROGRAM" and nxt is not None and nxt.kind == "ident":
            j = k + 1
            while j < len(tokens) and tokens[j].kind == "ident" and tokens[j].upper in _ACCESS:
                uses.append((tokens[j].line, tokens[j].col, f"PROGRAM {tokens[j].upper}"))
                edits.append((tokens[j].start, tokens[j].end, ""))
                j += 1
        elif up == "FUNCTION_BLOCK":
            j = k + 1
            while j < len(tokens) and tokens[j].line == tok.line and (
                    tokens[j].kind == "ident" or tokens[j].text in (",", ".")):
                j += 1
            if j < len(tokens) and tokens[j].text == ";" and tokens[j].line == tok.line \
                    and all(t.kind != "ident" or t.upper not in _KEYWORDS for t in tokens[k + 1:j]):
                uses.append((tokens[j].line, tokens[j].col, "a ';' after a FUNCTION_BLOCK's heading"))
                edits.append((tokens[j].start, tokens[j].end, ""))
        elif up == "FUNCTION" and _array_result(tokens, k):
            uses.append((tokens[k + 3].line, tokens[k + 3].col, ARRAY_RESULT))
            edits += _array_result_edits(tokens, k)
        elif up == ":=" and nxt is not None and nxt.text == "(" and k + 3 < len(tokens) \
                and tokens[k + 2].text == ")" and tokens[k + 3].text == ";":
            uses.append((tok.line, tok.col, "an empty initial value ':= ()'"))
            edits.append((tok.start, tokens[k + 2].end, ""))
        elif (up == "OF" or up == ":" and _in_heading(tokens, k)) and nxt is not None and nxt.kind == "ident" \
                and nxt.upper in _INTEGERS and k + 2 < len(tokens) and tokens[k + 2].text == "(":
            close = _closing(tokens, k + 2)
            if close is not None and any(t.text == ".." for t in tokens[k + 3:close]):
                uses.append((nxt.line, nxt.col, "a subrange type"))
                edits.append((tokens[k + 2].start, tokens[close].end, ""))
        elif up == "__NEW" and nxt is not None and nxt.text == "(" and k + 4 < len(tokens) \
                and tokens[k + 2].kind == "ident" and tokens[k + 2].upper == "POINTER" \
                and tokens[k + 3].kind == "ident" and tokens[k + 3].upper == "TO" and tokens[k + 4].kind == "ident" \
                and tokens[k + 4].line == tokens[k + 2].line:
            span = tokens[k + 4].start - tokens[k + 2].start
            uses.append((tokens[k + 2].line, tokens[k + 2].col, "__NEW(POINTER TO T, n)"))
            edits.append((tokens[k + 2].start, tokens[k + 4].start, NEW_POINTER.ljust(span, "_")))
        elif up == "RETURN" and nxt is not None and nxt.text == "(":
            close = _closing(tokens, k + 1)
            if close is not None and close + 1 < len(tokens) and tokens[close + 1].text == ";":
                uses.append((tok.line, tok.col, "RETURN(condition)"))
                target = _assigned(tokens, k + 1, close)
                if target is None:
                    edits.append((tok.start, tok.end, "IF"))
                    edits.append((tokens[close].end, tokens[close + 1].end, " THEN RETURN; END_IF;"))
                else:  # RETURN(Init := T <= 0): the assignment, then the RETURN on what it assigned
                    name = text[tokens[k + 2].start:tokens[target].start].strip()
                    edits.append((tok.start, nxt.end, ""))
                    edits.append((tokens[close].start, tokens[close + 1].end, f"; IF {name} THEN RETURN; END_IF;"))
        elif tok.text == ")" and k in opening and opening[k] > 0 and tokens[opening[k] - 1].kind == "ident" \
                and tokens[opening[k] - 1].upper not in _NO_CALL:
            members = _result_members(tokens, k)
            uses += [(m.line, m.col, CALL_MEMBER) for m in members]
            edits += [(m.end, m.end, "()") for m in members]
    more, used = durations.duration_edits(tokens)  # LTIME#1S2US44NS, T#1H500MS
    edits, uses = sorted(edits + more), uses + used
    if not edits:
        return text, []
    uses = _parsed_columns(text, edits, uses)
    out, at = [], 0
    for start, end, word in edits:
        out.append(text[at:start])
        # blanks keep the columns of what follows on the line; a longer replacement only moves the line's rest
        out.append(word + " " * max(0, end - start - len(word)))
        at = end
    out.append(text[at:])
    return "".join(out), uses


def _parsed_columns(text, edits, uses):
    """(line, column, construct, column in the rewritten text) of each use: a longer replacement before it on its
    line moves it there, where blark's tree has it."""
    grown = []  # (line, column, characters added) of each longer replacement
    for start, end, word in edits:
        if len(word) > end - start:
            line = text.count("\n", 0, start) + 1
            grown.append((line, start - text.rfind("\n", 0, start), len(word) - (end - start)))
    return [(line, col, what, col + sum(n for at_line, at_col, n in grown if at_line == line and at_col < col))
            for line, col, what in uses]


_INTEGERS = {"SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "BYTE", "WORD", "DWORD", "LWORD"}
# keywords that end a FUNCTION_BLOCK's heading: a `;` after one of them is no heading's
_KEYWORDS = {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_INST", "VAR_STAT", "VAR_EXTERNAL",
             "END_FUNCTION_BLOCK", "RETURN", "IF", "CASE", "FOR", "WHILE", "REPEAT", "EXIT", "CONTINUE"}


def _array_result(tokens, k):
    """Whether tokens[k] (FUNCTION) begins `FUNCTION Name : ARRAY` on one line."""
    heading = tokens[k + 1:k + 4]
    return len(heading) == 3 and heading[0].kind == "ident" and heading[1].text == ":" \
        and heading[2].kind == "ident" and heading[2].upper == "ARRAY" \
        and all(t.line == tokens[k].line for t in heading)


def _array_result_edits(tokens, k):
    """The edits that make `FUNCTION Name : ARRAY...` on tokens[k]'s line a block of its own,
    `FUNCTION Name VAR Name : ARRAY...; END_VAR`: the array's declaration stays where blark reads it."""
    last = k + 3
    while last + 1 < len(tokens) and tokens[last + 1].line == tokens[k].line:
        last += 1
    name, colon, end = tokens[k + 1], tokens[k + 2], tokens[last]
    close = " END_VAR" if end.text == ";" else "; END_VAR"
    return [(colon.start, colon.end, f"VAR {name.text} :"), (end.end, end.end, close)]


def _in_heading(tokens, k):
    """Whether tokens[k] stands in the heading of a FUNCTION, METHOD or PROPERTY (on its line, after it)."""
    j = k
    while j > 0 and tokens[j - 1].line == tokens[k].line:
        j -= 1
    return tokens[j].kind == "ident" and tokens[j].upper in ("FUNCTION", "METHOD", "PROPERTY")


def _assigned(tokens, k, close):
    """The index of the `:=` of `(Name := value)` between tokens[k] (the `(`) and tokens[close], when the
    parentheses hold an assignment to a variable (CODESYS's assignment as an expression), else None."""
    j = k + 1
    while j < close and (tokens[j].kind == "ident" or tokens[j].text in (".", "^")):
        j += 1
    return j if k + 1 < j < close and tokens[j].text == ":=" else None


# words before a `(` that opens no call
_NO_CALL = {"IF", "ELSIF", "WHILE", "UNTIL", "CASE", "RETURN", "THEN", "DO", "OF", "TO", "BY", "AND", "OR", "XOR",
            "NOT", "MOD", "AND_THEN", "OR_ELSE"}


def _openings(tokens):
    """{index of a `)`: index of the `(` it closes}."""
    pairs, stack = {}, []
    for j, tok in enumerate(tokens):
        if tok.text == "(":
            stack.append(j)
        elif tok.text == ")" and stack:
            pairs[j] = stack.pop()
    return pairs


def _result_members(tokens, k):
    """The member names read after the call that tokens[k] (a `)`) closes: `.A`, `^.A`, `.A.B`, up to a METHOD
    called on them (`.A.M(...)`) or the end of the chain; none when the chain goes on with what the rewrite cannot
    give blark (an index, a bit number) or is written to (`:=`)."""
    members, j = [], k + 1
    while True:
        d = j + 1 if j < len(tokens) and tokens[j].text == "^" else j
        if not (d + 1 < len(tokens) and tokens[d].text == "." and tokens[d + 1].kind == "ident"):
            break
        if d + 2 < len(tokens) and tokens[d + 2].text == "(":
            return members  # a METHOD called on the member: blark reads the chain on from there
        members.append(tokens[d + 1])
        j = d + 2
    after = [t.text for t in tokens[j:j + 2]]
    if after[:1] in (["["], [":="], ["."]) or after[:1] == ["^"] and after[1:] in (["["], [":="], ["."]):
        return []
    return members


def _closing(tokens, k):
    """The index of the `)` that closes the `(` at tokens[k], or None."""
    depth = 0
    for j in range(k, len(tokens)):
        if tokens[j].text == "(":
            depth += 1
        elif tokens[j].text == ")":
            depth -= 1
            if depth == 0:
                return j
    return None
