"""Literals: the `constant` subtree of an expression and the integer labels of CASE, in blark's shapes."""
import re

from .scanner import DATE_AND_TIME, Decline, node
from .vocabulary import BIT_STRING_TYPES, INTEGER_TYPES, OTHER_DATE_TYPES, REAL_TYPES

_WORD_HASH = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)#")
_BASE = re.compile(r"(2|8|16)#")
_DIGITS = {"2": re.compile(r"[01](_?[01])*"), "8": re.compile(r"[0-7][0-7_]*"),
           "16": re.compile(r"[0-9A-Fa-f][0-9A-Fa-f_]*")}
_DIGIT_TOKEN = {"2": "BIT_STRING", "8": "OCTAL_STRING", "16": "HEX_STRING"}
_INTEGER_TREE = {"2": "binary_integer", "8": "octal_integer", "16": "hex_integer"}
_BIT_STRING_TREE = {"2": "binary_bit_string_literal", "8": "octal_bit_string_literal",
                    "16": "hex_bit_string_literal"}
# The terminal of the type before `#` in a typed literal.
_TYPED_KINDS = {**{w: "INTEGER_TYPE_NAME" for w in INTEGER_TYPES},
                **{w: "BIT_STRING_TYPE_NAME" for w in BIT_STRING_TYPES},
                **{w: "REAL_TYPE_NAME" for w in REAL_TYPES}}
_INTEGER = re.compile(r"[0-9][0-9_]*")
_SIGNED = re.compile(r"[-+][0-9][0-9_]*")
_FIXED_POINT = re.compile(r"[0-9][0-9_]*\.[0-9][0-9_]*")
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
# A string without line breaks; `$` only in the escapes blark's grammar knows.
_STRING = re.compile(r"'([^$'\n]|\$[$LNPRTlnprt']|\$[0-9A-F][0-9A-F])*'")
# a WSTRING's: in double quotes, `$` followed by four hex digits
_WIDE_STRING = re.compile(r'"([^$"\n]|\$[$LNPRTlnprt"]|\$[0-9A-F]{4})*"')
_WORD_CHAR = re.compile(r"[A-Za-z0-9_.#]")
# Duration units, smallest last: each up to seconds may be followed by the next one; microseconds and
# nanoseconds are an LTIME's alone, and only as its one unit.
_UNITS = (("days", "d"), ("hours", "h"), ("minutes", "m"), ("seconds", "s"), ("milliseconds", "ms"),
          ("microseconds", "us"), ("nanoseconds", "ns"))
_CHAINED = 5  # the units before this index may take a next one
_UNDERSCORE = re.compile("_")
_UNIT = re.compile(r"ms|us|ns|[dhms]", re.IGNORECASE)


def _end_of_literal(s):
    """A literal must not run into a word or a further number: the text is then not the subset's."""
    if _WORD_CHAR.match(s.text, s.pos) and not s.text.startswith("..", s.pos):
        raise Decline("literal runs on")
    s.skip()


def _number(s, regex, kind):
    """The number `regex` reads at the position as a Token of `kind`, the literal ending there."""
    span = s.pattern(regex)
    if span is None:
        raise Decline(f"{kind} expected")
    tok = s.token(kind, *span)
    _end_of_literal(s)
    return tok


def _prefix(s, regex):
    """(Anon of the text matched at the position, its match), or (None, None); does not skip space."""
    m = regex.match(s.text, s.pos)
    if not m:
        return None, None
    anon = s.anon(s.pos, m.end())
    s.pos = m.end()
    return anon, m


class Literals:
    """Reads literals; the real literal's pattern and terminal come from blark's grammar."""

    def __init__(self, vocabulary):
        self._real_type = vocabulary.real_with_point
        self._real = re.compile(vocabulary.real_pattern)

    def constant(self, s):
        """Tree('constant') of the literal at the position, or None when none starts there."""
        lit = self._literal(s)
        return None if lit is None else node("constant", [lit])

    def _literal(self, s):
        c = s.peek_char()
        if c.isdigit():
            return self._untyped_number(s)
        if c in "'\"":
            span = s.pattern(_STRING if c == "'" else _WIDE_STRING)
            if span is None:
                raise Decline("string not read here")
            tok = s.token("SINGLE_BYTE_CHARACTER_STRING" if c == "'" else "DOUBLE_BYTE_CHARACTER_STRING", *span)
            s.skip()
            return node("string_literal", [tok])
        m = _WORD_HASH.match(s.text, s.pos)
        if m:
            return self._typed(s, m.group(1).upper(), m)
        word = s.peek_word()
        if word in ("TRUE", "FALSE"):
            return self._boolean(s, [], word)
        return None

    def _boolean(self, s, raw, word):
        kind = "TRUE_VALUE" if word == "TRUE" else "FALSE_VALUE"
        return node(word.lower(), raw + [s.word_token(kind)])

    def _untyped_number(self, s):
        based = self._based(s, "integer_literal", [None])
        if based is not None:
            return based
        if self._real.match(s.text, s.pos):
            return node("real_literal", [None, _number(s, self._real, self._real_type)])
        return self.integer_literal(s)

    def based_integer(self, s):
        """integer_literal of a `2#`, `8#` or `16#` number at the position, or None."""
        return self._based(s, "integer_literal", [None])

    def _based(self, s, rule, raw):
        """The `2#`, `8#` or `16#` number at the position under `rule` ([type and `#`] or [None] in
        `raw`), or None when the position holds none."""
        anon, m = _prefix(s, _BASE)
        if anon is None:
            return None
        base = m.group(1)
        tok = _number(s, _DIGITS[base], _DIGIT_TOKEN[base])
        if rule == "integer_literal":
            return node(rule, raw + [node(_INTEGER_TREE[base], [anon, tok])])
        return node(_BIT_STRING_TREE[base], raw + [anon, tok])

    def integer_literal(self, s, raw=(None,)):
        """integer_literal of a decimal number, signed only after a type (`DINT#-5`)."""
        if raw[0] is not None and _SIGNED.match(s.text, s.pos):
            signed = _number(s, _SIGNED, "SIGNED_INTEGER")
            return node("integer_literal", list(raw) + [node("signed_integer", [signed])])
        return node("integer_literal", list(raw) + [node("integer", [_number(s, _INTEGER, "INTEGER")])])

    def signed_integer_literal(self, s):
        """integer_literal of a number with its sign (a CASE label's form)."""
        signed = _number(s, _SIGNED, "SIGNED_INTEGER")
        return node("integer_literal", [None, node("signed_integer", [signed])])

    def _typed(self, s, word, m):
        type_start, hash_end = s.pos, m.end()
        if word in ("T", "TIME"):
            return self._duration(s, hash_end, "duration")
        if word in ("LT", "LTIME"):
            return self._duration(s, hash_end, "lduration")
        if word == "BOOL":
            after = _NAME.match(s.text, hash_end)
            if after and after.group(0).upper() in ("TRUE", "FALSE"):
                anon = s.anon(type_start, hash_end)
                s.pos = hash_end
                return self._boolean(s, [anon], after.group(0).upper())
        kind = _TYPED_KINDS.get(word)
        if kind is None:
            raise Decline(DATE_AND_TIME if word in OTHER_DATE_TYPES or word == "D" else "typed literal of another type")
        raw = [s.token(kind, type_start, hash_end - 1), s.anon(hash_end - 1, hash_end)]
        s.pos = hash_end
        if kind == "REAL_TYPE_NAME":
            return node("real_literal", raw + [_number(s, self._real, self._real_type)])
        integer = kind == "INTEGER_TYPE_NAME"
        based = self._based(s, "integer_literal" if integer else "bit_string_literal", raw)
        if based is not None:
            return based
        if integer:
            return self.integer_literal(s, raw)
        return node("bit_string_literal", raw + [_number(s, _INTEGER, "INTEGER")])

    def _duration(self, s, hash_end, rule):
        raw = [s.anon(s.pos, hash_end - 1), s.anon(hash_end - 1, hash_end)]
        s.pos = hash_end
        if s.peek_char() == "-":
            raw.append(s.token("MINUS", s.pos, s.pos + 1))
            s.pos += 1
        else:
            raw.append(None)
        interval = self._interval(s, 0)
        if interval.data in ("microseconds", "nanoseconds") and rule != "lduration":
            raise Decline("microseconds or nanoseconds of a TIME")
        raw.append(interval)
        _end_of_literal(s)
        return node(rule, raw)

    def _interval(self, s, least_unit):
        """The interval at the position, whose first unit is `least_unit` or a later one (up to
        milliseconds after another unit)."""
        span = s.pattern(_FIXED_POINT)
        fixed = span is not None
        if not fixed:
            span = s.pattern(_INTEGER)
            if span is None:
                raise Decline("duration number expected")
        tok = s.token("FIXED_POINT" if fixed else "INTEGER", *span)
        unit_anon, m = _prefix(s, _UNIT)
        if unit_anon is None:
            raise Decline("duration unit expected")
        index = [u for _, u in _UNITS].index(m.group(0).lower())
        if index < least_unit or least_unit and index >= _CHAINED:
            raise Decline("duration units out of order")
        raw = [tok, unit_anon]
        if not fixed and index + 1 < _CHAINED:
            under, _ = _prefix(s, _UNDERSCORE)
            if under is not None or s.peek_char().isdigit():
                sub = self._interval(s, index + 1)
                if sub.data != _UNITS[index + 1][0]:
                    raise Decline("duration unit skipped")
                raw += ([under] if under is not None else []) + [sub]
        return node(_UNITS[index][0], raw)
