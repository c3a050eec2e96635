"""Statements: statement_list and its statements, each with the `;` that ends it (they count for the
positions, not for the tree)."""
import re

from .scanner import Decline, node

_LABEL_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*")
_REF_ASSIGNMENT = re.compile(r"REF=", re.I)
# a word that starts a literal (`T#1S`, `TRUE`), not a variable
_LITERAL_START = re.compile(r"[A-Za-z_][A-Za-z0-9_]*#|(TRUE|FALSE|NOT)\b", re.I)

# Words that end a statement list rather than start a statement.
_LIST_ENDS = frozenset(("END_IF", "ELSIF", "ELSE", "END_CASE", "END_WHILE", "UNTIL", "END_REPEAT",
                        "END_FUNCTION", "END_FUNCTION_BLOCK", "END_PROGRAM", "END_FOR", "END_METHOD",
                        "END_PROPERTY", "END_ACTION"))
_DECLINED = frozenset(("JMP", "END_FUNCTIONBLOCK"))


class Statements:
    """Reads statement lists over `expressions`."""

    def __init__(self, expressions):
        self._x = expressions
        self._keyworded = {"IF": self._if, "CASE": self._case, "WHILE": self._while,
                           "REPEAT": self._repeat, "FOR": self._for, "EXIT": self._bare("exit_statement", "EXIT"),
                           "CONTINUE": self._bare("continue_statement", "CONTINUE"),
                           "RETURN": self._bare("return_statement", "RETURN")}

    def _ends_list(self, s, in_case):
        if s.at_end():
            return True
        word = s.peek_word()
        if word in _DECLINED:
            raise Decline(f"{word} is not read here")
        if word in _LIST_ENDS:
            return True
        if in_case:
            # A CASE branch ends where the next label starts: a number, or a name followed by `:` or `,`.
            if s.peek_char().isdigit() or s.peek_punct() in ("-", "+"):
                return True
            if word is not None and _is_label(s):
                return True
        return False

    def statement_list(self, s, rule="statement_list", in_case=False):
        """Tree(rule) of the statements up to the word that ends the list, or None if there are none."""
        raw = []
        while not self._ends_list(s, in_case):
            raw.append(self.statement(s))
        return node(rule, raw) if raw else None

    def statement(self, s):
        word = s.peek_word()
        handler = self._keyworded.get(word)
        if handler is not None:
            return handler(s)
        if s.peek_punct() == ";":
            raise Decline("empty statement")
        target = self._x.variable(s)
        p = s.peek_punct()
        if p == ":=":
            raw = [target, s.token_to("ASSIGNMENT", s.pos + 2)]
            # `a := b := 0`: every variable before the last `:=` is a target too
            while True:
                start = s.pos
                if s.peek_word() is None or _LITERAL_START.match(s.text, s.pos):
                    break
                try:
                    chained = self._x.variable(s)
                except Decline:
                    s.pos = start
                    break
                if s.peek_punct() != ":=":
                    s.pos = start
                    break
                raw += [chained, s.token_to("ASSIGNMENT", s.pos + 2)]
            raw.append(self._x.expression(s))
            _end(s, raw, least=1)
            return node("assignment_statement", raw)
        if _REF_ASSIGNMENT.match(s.text, s.pos):
            raw = [target, s.token_to("REF_ASSIGNMENT", s.pos + 4), self._x.expression(s)]
            _end(s, raw, least=1)
            return node("reference_assignment_statement", raw)
        if p == "(":
            call = self._x.call(s, target)
            raw = [call]
            _end(s, raw, least=1)
            chained = call.data == "chained_function_call"
            return node("chained_function_call_statement" if chained else "function_call_statement", raw)
        raise Decline("statement not read here")

    def _bare(self, rule, word):
        def read(s):
            raw = [s.keyword(word)]
            _end(s, raw, least=1)
            return node(rule, raw)
        return read

    def _if(self, s):
        raw = [s.keyword("IF"), self._x.expression(s), s.keyword("THEN"), self.statement_list(s)]
        while s.peek_word() == "ELSIF":
            clause = [s.keyword("ELSIF"), self._x.expression(s), s.keyword("THEN"), self.statement_list(s)]
            raw.append(node("else_if_clause", clause))
        raw.append(self._else(s))
        raw.append(s.keyword("END_IF"))
        _end(s, raw, least=0)
        return node("if_statement", raw)

    def _else(self, s):
        if s.peek_word() != "ELSE":
            return None
        return node("else_clause", [s.keyword("ELSE"), self.statement_list(s)])

    def _case(self, s):
        raw = [s.keyword("CASE"), self._x.expression(s), s.keyword("OF")]
        elements = []
        while s.peek_word() not in ("ELSE", "END_CASE"):
            if s.at_end():
                raise Decline("unterminated CASE")
            elements.append(self._case_element(s))
        if not elements:
            raise Decline("CASE without branches")
        raw += [node("case_elements", elements), self._else(s), s.keyword("END_CASE")]
        _end(s, raw, least=0)
        return node("case_statement", raw)

    def _case_element(self, s):
        labels = [self._case_label(s)]
        while s.peek_punct() == ",":
            labels += [s.punct(","), self._case_label(s)]
        raw = [node("case_list", labels), s.punct(":"),
               self.statement_list(s, "case_element_statement_list", in_case=True)]
        return node("case_element", raw)

    def _case_label(self, s):
        if s.peek_char().isdigit() or s.peek_char() in "-+" and s.peek_char(1).isdigit():
            start = s.pos
            low = self._x.integer_value(s)
            if s.peek_punct() != "..":
                return low
            # A range: both bounds are expressions, read again as such.
            s.pos = start
            first = self._x.expression(s)
            dots = s.punct("..")
            return node("subrange", [first, dots, self._x.expression(s)])
        word = s.peek_word()
        if word is None:
            raise Decline("CASE label not read here")
        tok = self._x.dotted_name_token(s)  # `GVL_Station.STEP_DONE`, `E_Mode.AUTO`: one DOTTED_IDENTIFIER
        if s.peek_punct() in (".", ".."):
            raise Decline("CASE label not read here")
        return node("enumerated_value", [None, tok, None])

    def _while(self, s):
        raw = [s.keyword("WHILE"), self._x.expression(s), s.keyword("DO"), self._required_list(s),
               s.keyword("END_WHILE")]
        _end(s, raw, least=0)
        return node("while_statement", raw)

    def _repeat(self, s):
        raw = [s.keyword("REPEAT"), self._required_list(s), s.keyword("UNTIL"), self._x.expression(s),
               s.keyword("END_REPEAT")]
        _end(s, raw, least=0)
        return node("repeat_statement", raw)

    def _for(self, s):
        # `FOR i := a TO b [BY c] DO ... END_FOR`: the control variable and the three expressions sit in the
        # statement itself (blark's _for_list is inlined), BY's placeholder None when it is absent.
        raw = [s.keyword("FOR"), self._x.variable(s), s.punct(":="), self._x.expression(s), s.keyword("TO"),
               self._x.expression(s)]
        if s.peek_word() == "BY":
            raw += [s.keyword("BY"), self._x.expression(s)]
        else:
            raw.append(None)
        raw += [s.keyword("DO"), self._required_list(s), s.keyword("END_FOR")]
        _end(s, raw, least=0)
        return node("for_statement", raw)

    def _required_list(self, s):
        body = self.statement_list(s)
        if body is None:
            raise Decline("empty loop body")
        return body


def _is_label(s):
    """Whether the name at the position is followed by `:` (not `:=`) or `,`: a CASE label."""
    m = _LABEL_NAME.match(s.text, s.pos)
    if not m:
        return False
    save = s.pos
    try:
        s.pos = m.end()
        s.skip()
        return s.peek_punct() in (":", ",")
    finally:
        s.pos = save


def _end(s, raw, least):
    """The `;` that ends a statement (`least` 0: that may end one). A second one would be an empty
    statement, which blark may take either way and the subset refuses: declined."""
    if s.peek_punct() == ";":
        raw.append(s.punct(";"))
    elif least:
        raise Decline("expected ;")
    if s.peek_punct() == ";":
        raise Decline("empty statement")
