"""Reads the processed source one lexeme at a time and builds lark trees with the positions lark's
propagate_positions gives.

The fast parser must hand blark's transform exactly the tree blark's Earley parser builds, so every
node's meta is computed as lark computes it: from the first and the last child that takes up text,
including the anonymous tokens (`;`, `(`, keywords) that the tree itself leaves out.
"""
import bisect
import re

from lark import Token, Tree
from lark.tree import Meta


class Decline(Exception):
    """The text is not in what the fast parser knows (or not valid at all): blark's parser decides."""


# The reasons of the declines left to Earley on purpose (decline_reasons.py counts them): what Earley reads in more
# ways than one (it builds one of several trees, which the fast parser cannot foresee), or seldom written.
INITIAL_VALUE = "an array's or a structure's initial value"
LOCATED = "a located variable"
DATE_AND_TIME = "a date and time type or literal"
ARGUMENTS = "an FB instance's arguments or a subrange"
UNION = "a UNION"
STRING_TYPE = "a STRING type declaration"
TIME_CALL = "CODESYS's TIME() or LTIME()"
LEFT_TO_EARLEY = frozenset((INITIAL_VALUE, LOCATED, DATE_AND_TIME, ARGUMENTS, UNION, STRING_TYPE, TIME_CALL))


class Anon:
    """A token the tree leaves out (keywords, punctuation) but whose text still counts for positions."""

    __slots__ = ("start_pos", "end_pos", "line", "column", "end_line", "end_column")

    def __init__(self, start_pos, end_pos, line, column):
        self.start_pos, self.end_pos = start_pos, end_pos
        self.line, self.column = line, column
        self.end_line, self.end_column = line, column + end_pos - start_pos


_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_SPACE = re.compile(r"[ \t\f\r\n]+")
# The punctuation of the subset, longest first so that `<=` is not read as `<`.
_PUNCT = re.compile(r":=|=>|<>|<=|>=|\.\.|[-+*/=<>()\[\],;:.#^]")


def node(data, raw):
    """Tree `data` over `raw` (children, None placeholders and Anon tokens), positioned as lark does."""
    children = []
    first = last = None
    for item in raw:
        if item is None:
            children.append(None)
            continue
        if item.__class__ is Anon:
            span = item
        else:
            children.append(item)
            span = item if item.__class__ is not Tree else (None if item.meta.empty else item.meta)
        if span is not None:
            if first is None:
                first = span
            last = span
    meta = Meta()
    if first is not None:
        meta.empty = False
        meta.line = meta.container_line = first.line
        meta.column = meta.container_column = first.column
        meta.start_pos = meta.container_start_pos = first.start_pos
        meta.end_line = meta.container_end_line = last.end_line
        meta.end_column = meta.container_end_column = last.end_column
        meta.end_pos = meta.container_end_pos = last.end_pos
    return Tree(data, children, meta)


class Scanner:
    """The text, a position in it, and the reading of words, punctuation and patterns there."""

    def __init__(self, text):
        self.text = text
        self.pos = 0
        self._line_starts = [0] + [m.end() for m in re.finditer("\n", text)]
        self.skip()

    def skip(self):
        """Moves past white space, `(* *)` and `//` comments and pragmas; declines on what lark ignores otherwise."""
        text = self.text
        while True:
            m = _SPACE.match(text, self.pos)
            if m:
                self.pos = m.end()
            if text.startswith("(*", self.pos):
                end = text.find("*)", self.pos + 2)
                if end < 0:
                    raise Decline("unterminated comment")
                self.pos = end + 2
                continue
            if text.startswith("{", self.pos):
                # blark's grammar ignores a pragma ({attribute 'hide'}, as TwinCAT files carry them) like a
                # comment: up to the first `}`. Its optional trailing `;`s could also end a statement, so
                # a pragma followed by one is Earley's to read.
                end = text.find("}", self.pos + 1)
                if end < 0 or text.startswith(";", end + 1):
                    raise Decline("pragma")
                self.pos = end + 1
                continue
            if text.startswith("//", self.pos):  # a line comment (user mode), which lark ignores to the end of the line
                end = text.find("\n", self.pos)
                self.pos = len(text) if end < 0 else end
                continue
            return

    def at_end(self):
        return self.pos >= len(self.text)

    def line_col(self, pos):
        line = bisect.bisect_right(self._line_starts, pos)
        return line, pos - self._line_starts[line - 1] + 1

    def peek_word(self):
        """The upper-case word at the position, or None."""
        m = _WORD.match(self.text, self.pos)
        return m.group(0).upper() if m else None

    def peek_punct(self):
        m = _PUNCT.match(self.text, self.pos)
        return m.group(0) if m else None

    def peek_char(self, offset=0):
        at = self.pos + offset
        return self.text[at] if at < len(self.text) else ""

    def _take(self, end):
        start = self.pos
        self.pos = end
        self.skip()
        return start, end

    def anon(self, start, end):
        line, col = self.line_col(start)
        return Anon(start, end, line, col)

    def token(self, type_, start, end):
        line, col = self.line_col(start)
        return Token(type_, self.text[start:end], start, line, col, line, col + end - start, end)

    def token_to(self, type_, end):
        """The text from the position to `end` as a Token of `type_`; moves past it and the space after it."""
        return self.token(type_, *self._take(end))

    def keyword(self, word):
        """The keyword `word` (upper case) as an Anon, or Decline."""
        m = _WORD.match(self.text, self.pos)
        if not m or m.group(0).upper() != word:
            raise Decline(f"expected {word}")
        return self.anon(*self._take(m.end()))

    def keyword_token(self, word):
        """The keyword `word` (upper case) as a Token of type `word` (blark keeps a few), or Decline."""
        if self.peek_word() != word:
            raise Decline(f"expected {word}")
        return self.word_token(word)

    def word_token(self, type_):
        """The word at the position as a Token of `type_`."""
        m = _WORD.match(self.text, self.pos)
        if not m:
            raise Decline("expected a name")
        return self.token(type_, *self._take(m.end()))

    def punct(self, p):
        """The punctuation `p` as an Anon, or Decline."""
        if self.peek_punct() != p:
            raise Decline(f"expected {p}")
        return self.anon(*self._take(self.pos + len(p)))

    def pattern(self, regex):
        """(start, end) of `regex` matched at the position, or None; moves past it, not past the space
        after it (literals are read piece by piece)."""
        m = regex.match(self.text, self.pos)
        if not m:
            return None
        start, self.pos = self.pos, m.end()
        return start, m.end()

    def semicolons(self, raw, least=1):
        """Appends the `;` at the position to raw: at least `least` of them."""
        n = 0
        while self.peek_punct() == ";":
            raw.append(self.punct(";"))
            n += 1
        if n < least:
            raise Decline("expected ;")
