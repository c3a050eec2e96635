"""Words of Structured Text outside comments, strings and pragmas, with their positions.

The export cuts a source file into its declaration and its body as text, so that comments and layout
reach CODESYS and TwinCAT unchanged; a keyword inside a comment or a string must not cut it.
"""
import re
from dataclasses import dataclass

_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


@dataclass(frozen=True)
class Token:
    text: str
    start: int
    end: int

    @property
    def upper(self):
        return self.text.upper()


@dataclass(frozen=True)
class Comment:
    text: str  # with its delimiters
    start: int
    end: int


def _skip_to(text, pos, closer, what):
    end = text.find(closer, pos)
    if end < 0:
        raise ValueError(f"{what} opened at offset {pos} is not closed")
    return end + len(closer)


def _skip_string(text, pos):
    quote = text[pos]
    i = pos + 1
    while i < len(text):
        if text[i] == "$":  # IEC escape: $' $$ $N ...
            i += 2
            continue
        if text[i] == quote:
            return i + 1
        i += 1
    raise ValueError(f"string opened at offset {pos} is not closed")


def scan(text):
    """Returns (tokens, comments): the words and single characters outside comments, strings and
    pragmas (a string literal is one token), and the comments."""
    tokens, comments = [], []
    i = 0
    while i < len(text):
        c = text[i]
        if c.isspace():
            i += 1
        elif text.startswith("(*", i):
            end = _skip_to(text, i + 2, "*)", "comment")
            comments.append(Comment(text[i:end], i, end))
            i = end
        elif text.startswith("//", i):
            end = text.find("\n", i)
            end = len(text) if end < 0 else end
            comments.append(Comment(text[i:end], i, end))
            i = end
        elif c == "{":
            i = _skip_to(text, i + 1, "}", "pragma")
        elif c in "'\"":
            end = _skip_string(text, i)
            tokens.append(Token(text[i:end], i, end))
            i = end
        else:
            m = _WORD.match(text, i)
            end = m.end() if m else i + 1
            tokens.append(Token(text[i:end], i, end))
            i = end
    return tokens, comments


def comment_body(comment_text):
    """The words of a comment without its delimiters, continuation lines dedented."""
    if comment_text.startswith("(*"):
        inner = comment_text[2:-2]
    else:
        inner = comment_text[2:]
    lines = inner.strip().splitlines()
    return "\n".join(line.strip() for line in lines)
