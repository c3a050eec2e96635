"""Expressions and variables: blark's chain of one rule per precedence level, each a flat list of
operands and operator tokens, down to unary_expression over a primary."""
import re

from .scanner import Decline, node

_NAME_THEN_ARROW = re.compile(r"[A-Za-z_][A-Za-z0-9_]*[ \t\f\r\n]*(:=|=>)")

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
        var = self.variable(s)
        if s.peek_punct() == "(":
            return self.function_call(s, var)
        return var

    def literal_label(self, s):
        """A CASE label's number: an integer_literal, not an expression."""
        if s.peek_char() in "-+":
            return self._literals.signed_integer_literal(s)
        return self._literals.integer_literal(s)

    def name_token(self, s, type_="IDENTIFIER"):
        """The name at the position as a Token of `type_` (IDENTIFIER, DOTTED_IDENTIFIER), or Decline
        for a keyword. An elementary type's name is declined too: outside the subset where a name
        stands, and which rule blark would make of it is left to blark."""
        word = s.peek_word()
        if word is None or not self._vocabulary.is_identifier(word) or self._vocabulary.is_type_word(word):
            raise Decline("identifier expected")
        return s.word_token(type_)

    def variable_name(self, s):
        return node("variable_name", [self.name_token(s), None])

    def variable(self, s):
        """variable_name, or multi_element_variable with its subscripts and fields."""
        name = self.variable_name(s)
        raw = [name]
        while True:
            p = s.peek_punct()
            if p == "[":
                sub = [s.punct("["), self.expression(s)]
                while s.peek_punct() == ",":
                    sub += [s.punct(","), self.expression(s)]
                sub += [s.punct("]"), None]
                if s.peek_punct() == "^":
                    raise Decline("dereference")
                raw.append(node("subscript_list", sub))
            elif p == ".":
                dot = s.punct(".")
                raw.append(node("field_selector", [None, dot, self.variable_name(s)]))
            elif p == "^":
                raise Decline("dereference")
            else:
                break
        return name if len(raw) == 1 else node("multi_element_variable", raw)

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
        if s.peek_punct() in ("^", "."):
            raise Decline("dereference or chained call")
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
