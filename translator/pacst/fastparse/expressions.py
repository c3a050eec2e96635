"""Expressions and variables: blark's chain of one rule per precedence level, each a flat list of
operands and operator tokens, down to unary_expression over a primary."""
import re

from .scanner import TIME_CALL, Decline, node

_NAME_THEN_ARROW = re.compile(r"[A-Za-z_][A-Za-z0-9_]*[ \t\f\r\n]*(:=|=>)")
_DOTTED = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*(?![A-Za-z0-9_.])")
_DEREF_FIELD = re.compile(r"\^[ \t\f\r\n]*\.")
_TYPE_ARGUMENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*[ \t\f\r\n]*[,)]")
# CODESYS's TIME() and LTIME(), the time since the PLC started: a type's name called, left to blark
_CALL_WITHOUT_ARGUMENTS = re.compile(r"[A-Za-z_][A-Za-z0-9_]*[ \t\f\r\n]*\([ \t\f\r\n]*\)")
_BIT = re.compile(r"[0-9][0-9_]*")
# what may not follow a bit number (`w.3.5`, `w.3a`): Earley's to read or refuse
_RUNS_ON = re.compile(r"[A-Za-z0-9_#]|\.[0-9]")

# Precedence levels from the loosest: (rule, operator terminal, operators as words or punctuation).
# blark's rule names are shifted against their operators (and_then_expression joins with OR, ...):
# the tree must carry blark's names.
_LEVELS = (
    ("expression", "ASSIGNMENT", ()),  # ASSIGNMENT inside an expression: declined below
    ("assignment_expression", "LOGICAL_OR_ELSE", ("OR_ELSE",)),
    ("or_else_expression", "LOGICAL_AND_THEN", ("AND_THEN",)),
    ("and_then_expression", "LOGICAL_OR", ("OR",)),
    ("xor_expression", "LOGICAL_XOR", ("XOR",)),
    ("and_expression", "LOGICAL_AND", ("AND",)),
    ("comparison_expression", "EQUALS_OP", ("=", "<>")),
    ("equality_expression", "COMPARE_OP", ("<=", ">=", "<", ">")),
    ("add_expression", "ADD_OPERATOR", ("+", "-")),
    ("expression_term", "MULTIPLY_OPERATOR", ("MOD", "*", "/")),
)


class Expressions:
    """Reads expressions, variables and function calls; literals come from `literals`."""

    def __init__(self, vocabulary, literals):
        self._vocabulary = vocabulary
        self._literals = literals

    def expression(self, s):
        return self._level(s, 0)

    def _operator(self, s, words):
        """The operator of `words` at the position, or None."""
        if not words:
            if s.peek_punct() == ":=":
                raise Decline("assignment inside an expression")
            return None
        w = s.peek_word()
        if w is not None:
            return w if w in words else None
        p = s.peek_punct()
        return p if p in words else None

    def _level(self, s, i):
        if i == len(_LEVELS):
            return self._unary(s)
        rule, terminal, words = _LEVELS[i]
        raw = [self._level(s, i + 1)]
        while True:
            op = self._operator(s, words)
            if op is None:
                return node(rule, raw)
            start = s.pos
            s.pos += len(op)
            raw.append(s.token(terminal, start, s.pos))
            s.skip()
            raw.append(self._level(s, i + 1))

    def _unary(self, s):
        op = None
        p = s.peek_punct()
        if p in ("-", "+"):
            op = p
        elif s.peek_word() == "NOT":
            op = s.text[s.pos:s.pos + 3]
        raw = [None]
        if op is not None:
            start = s.pos
            s.pos += len(op)
            raw[0] = s.token("UNARY_OPERATOR", start, s.pos)
            s.skip()
        raw.append(self._primary(s))
        return node("unary_expression", raw)

    def _primary(self, s):
        if s.peek_punct() == "(":
            raw = [s.punct("("), self.expression(s), s.punct(")")]
            return node("parenthesized_expression", raw)
        const = self._literals.constant(s)
        if const is not None:
            return const
        word = s.peek_word()
        if word is not None and self._vocabulary.is_type_word(word) and _TYPE_ARGUMENT.match(s.text, s.pos):
            # a type as an argument (`__NEW(BYTE, 4)`, `SIZEOF(LREAL)`): a variable_name to blark
            return node("variable_name", [s.word_token("IDENTIFIER"), None])
        if word in ("TIME", "LTIME") and _CALL_WITHOUT_ARGUMENTS.match(s.text, s.pos):
            raise Decline(TIME_CALL)
        var = self.variable(s)
        if s.peek_punct() == "(":
            return self.call(s, var)
        return var

    def literal_label(self, s):
        """A CASE label's number: an integer_literal, not an expression."""
        if s.peek_char() in "-+":
            return self._literals.signed_integer_literal(s)
        return self._literals.integer_literal(s)

    def integer_value(self, s):
        """An enumeration value's number: an integer_literal, decimal, signed or based (`16#20`)."""
        based = self._literals.based_integer(s)
        return based if based is not None else self.literal_label(s)

    def name_token(self, s, type_="IDENTIFIER"):
        """The name at the position as a Token of `type_` (IDENTIFIER, DOTTED_IDENTIFIER), or Decline
        for a keyword. An elementary type's name is declined too: outside the subset where a name
        stands, and which rule blark would make of it is left to blark."""
        word = s.peek_word()
        if word is None or not self._vocabulary.is_identifier(word) or self._vocabulary.is_type_word(word):
            raise Decline("identifier expected")
        return s.word_token(type_)

    def dotted_name_token(self, s):
        """A DOTTED_IDENTIFIER (`NS.I_Counter`, `Count.Get`): names joined by `.` without space, none a keyword or
        an elementary type's name."""
        m = _DOTTED.match(s.text, s.pos)
        if not m or not all(self._vocabulary.is_identifier(w.upper()) and not self._vocabulary.is_type_word(w.upper())
                            for w in m.group(0).split(".")):
            raise Decline("dotted name expected")
        return s.token_to("DOTTED_IDENTIFIER", m.end())

    def variable_name(self, s):
        return node("variable_name", [self.name_token(s), None])

    def variable(self, s):
        """variable_name, or multi_element_variable with its subscripts, fields and bit numbers (`w.3`); a `^`
        dereferences the name or the subscript before it, where blark's grammar puts it."""
        tok = self.name_token(s)
        # A `^` after the first name and before a `.` has two places in blark's grammar: the name's, or the
        # field_selector's after it. Earley's choice alternates with the number of subscripts and fields that
        # follow: odd, the name's; even, the field's.
        ambiguous = s.peek_punct() == "^" and _DEREF_FIELD.match(s.text, s.pos)
        deref = _dereferenced(s)
        raw = [None]
        while True:
            p = s.peek_punct()
            if p == "[":
                sub = [s.punct("["), self.expression(s)]
                while s.peek_punct() == ",":
                    sub += [s.punct(","), self.expression(s)]
                sub += [s.punct("]"), _dereferenced(s)]
                raw.append(node("subscript_list", sub))
            elif p == ".":
                selector = [s.punct("."), self._field(s)]
                if len(raw) == 1:
                    first = selector
                raw.append(node("field_selector", [None] + selector))
            else:
                break
        if ambiguous and len(raw) % 2:
            raw[1] = node("field_selector", [deref] + first)
            deref = None
        raw[0] = node("variable_name", [tok, deref])
        return raw[0] if len(raw) == 1 else node("multi_element_variable", raw)

    def _field(self, s):
        """The field after a `.`: a name, with its `^`, or a bit number."""
        if not s.peek_char().isdigit():
            return node("variable_name", [self.name_token(s), _dereferenced(s)])
        # a bit number: an INTEGER, which must not run on into a real number or a word
        span = s.pattern(_BIT)
        if span is None or _RUNS_ON.match(s.text, s.pos):
            raise Decline("bit number not read here")
        field = s.token("INTEGER", *span)
        s.skip()
        return field

    def call(self, s, callee):
        """function_call of `callee`, or chained_function_call when calls follow it (`F(1).Add(2).Add(3)`, and
        `F(x).Member()` as user mode rewrites a member of a call's result); the position at its `(`."""
        first = self.function_call(s, callee)
        if s.peek_punct() != ".":
            return first
        raw = [first]
        while s.peek_punct() == ".":
            raw.append(s.punct("."))
            member = self.variable(s)
            if s.peek_punct() != "(":
                raise Decline("member of a call's result")
            raw.append(self.function_call(s, member))
        return node("chained_function_call", raw)

    def function_call(self, s, callee):
        """function_call of `callee`, the position at its `(`."""
        raw = [callee, s.punct("(")]
        if s.peek_punct() == ")":
            raw.append(None)
        else:
            raw.append(self._param(s))
            while s.peek_punct() == ",":
                raw.append(s.punct(","))
                if s.peek_punct() == ")":
                    raise Decline("trailing comma")
                raw.append(self._param(s))
        raw.append(s.punct(")"))
        if s.peek_punct() == "^":
            raw.append(_dereferenced(s))  # `DEREFERENCED?`: no placeholder when absent
        if s.peek_punct() in ("^", "["):
            raise Decline("a call's result dereferenced or indexed")
        return node("function_call", raw)

    def _param(self, s):
        """A parameter: `name := value`, `name => variable`, or a value alone."""
        word = s.peek_word()
        if word is not None and word != "NOT" and _NAME_THEN_ARROW.match(s.text, s.pos):
            name = self.variable_name(s)
            arrow = s.peek_punct()
            op = s.punct(arrow)
            if s.peek_punct() in (",", ")"):
                raise Decline("empty parameter")
            if arrow == ":=":
                return node("param_assignment", [name, op, self.expression(s)])
            return node("output_parameter_assignment", [None, name, op, self.expression(s)])
        return node("param_assignment", [self.expression(s)])


def _dereferenced(s):
    """The DEREFERENCED token of a `^` at the position, or None."""
    if s.peek_punct() != "^":
        return None
    start = s.pos
    s.pos += 1
    tok = s.token("DEREFERENCED", start, s.pos)
    s.skip()
    return tok
