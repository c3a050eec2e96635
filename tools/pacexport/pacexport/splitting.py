"""Cuts one ST file of the library into what both IDEs keep apart: the declaration and the body.

Each file holds one object (docs/naming.md): a TYPE, a FUNCTION, a FUNCTION_BLOCK, a PROGRAM or a
VAR_GLOBAL list. The cut is textual, so the comments and layout of the source reach the IDE as they
are; the structured interface comes from the parse of the declaration (declarations.py).
"""
import os
import re
from dataclasses import dataclass
from typing import Optional

from pacst.errors import StError
from pacst.lexcheck import tokenize

from .errors import ExportError

VAR_OPENERS = {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_INST", "VAR_STAT",
               "VAR_EXTERNAL"}
POU_KINDS = {"FUNCTION_BLOCK": "functionBlock", "FUNCTION": "function", "PROGRAM": "program"}
# The header comment that marks an object internal: (* Internal: a part of FB_PAC_Axis; ... *)
INTERNAL_MARKER = "Internal:"
END_OF = {"functionBlock": "END_FUNCTION_BLOCK", "function": "END_FUNCTION", "program": "END_PROGRAM",
          "dataType": "END_TYPE"}


def folder_of(source):
    """The object's folder in st/ (cmd, axis, types...): the folder it goes into in both exports."""
    return os.path.basename(os.path.dirname(os.path.abspath(source.path)))


@dataclass(frozen=True)
class SourceObject:
    path: str
    kind: str  # dataType, function, functionBlock, program or globalVars
    name: str
    doc: Optional[str]  # the header comment's words
    declaration: str  # a POU: up to its last END_VAR; a type or list: all of it
    body: Optional[str]  # a POU's statements, without END_...

    @property
    def internal(self):
        """The header says the object is internal (docs/public_api.md): a part of the public blocks that
        programs neither call nor use."""
        return any(line.startswith(INTERNAL_MARKER) for line in (self.doc or "").splitlines())


def read_source(path):
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as exc:
        raise ExportError(path, f"cannot read: {exc}") from None
    return split_source(path, text.replace("\r\n", "\n"))


def scan(path, text):
    """(tokens, comments) of `text` by the translator's lexer (pacst.lexcheck), which refuses what the
    portable subset has not (line comments, pragmas, nested comments): the export takes the library's
    sources, which the translator reads."""
    comments = []
    try:
        return tokenize(text, path, comments), comments
    except StError as exc:
        raise ExportError(path, f"{exc.line}:{exc.col}: {exc.message}") from None


def comment_body(comment_text):
    """The words of a `(* *)` comment (the only kind the lexer lets through) without its delimiters,
    continuation lines dedented."""
    lines = comment_text[2:-2].strip().splitlines()
    return "\n".join(line.strip() for line in lines)


def split_source(path, text):
    tokens, comments = scan(path, text)
    if not tokens:
        raise ExportError(path, "holds no declaration")
    first = tokens[0]
    header = [comment_body(c.text) for c in comments if c.end <= first.start]
    doc = "\n".join(header) or None
    keyword = first.upper
    start = len(text) - len(text.lstrip())
    if keyword == "VAR_GLOBAL":
        name = os.path.splitext(os.path.basename(path))[0]
        _expect_last(path, tokens, "END_VAR")
        return SourceObject(path, "globalVars", name, doc, text[start:].rstrip() + "\n", None)
    if keyword == "TYPE":
        _expect_one(path, tokens, "TYPE")
        _expect_last(path, tokens, "END_TYPE")
        return SourceObject(path, "dataType", _name(path, tokens), doc, text[start:].rstrip() + "\n", None)
    kind = POU_KINDS.get(keyword)
    if kind is None:
        raise ExportError(path, f"starts with '{first.text}', not TYPE, FUNCTION, FUNCTION_BLOCK, PROGRAM "
                                "or VAR_GLOBAL")
    _expect_one(path, tokens, keyword)
    end = _expect_last(path, tokens, END_OF[kind])
    decl_end = _declaration_end(path, text, tokens, first)
    body = _strip_blank_lines(text[decl_end:end.start])
    if not body:
        raise ExportError(path, f"{kind} without a body")
    return SourceObject(path, kind, _name(path, tokens), doc, text[start:decl_end] + "\n", body)


def _name(path, tokens):
    if len(tokens) < 2 or not re.fullmatch(r"[A-Za-z_]\w*", tokens[1].text):
        raise ExportError(path, f"no name after {tokens[0].text}")
    return tokens[1].text


def _expect_one(path, tokens, keyword):
    if sum(1 for t in tokens if t.upper == keyword) != 1:
        raise ExportError(path, f"more than one {keyword}: the export takes one object per file")


def _expect_last(path, tokens, keyword):
    if tokens[-1].upper != keyword:
        raise ExportError(path, f"does not end with {keyword}")
    return tokens[-1]


def _declaration_end(path, text, tokens, first):
    """The offset after the header line and the VAR blocks that follow it."""
    line_end = text.find("\n", first.start)
    decl_end = len(text) if line_end < 0 else line_end
    i = next((k for k, t in enumerate(tokens) if t.start >= decl_end), len(tokens))
    while i < len(tokens) and tokens[i].upper in VAR_OPENERS:
        j = next((k for k in range(i + 1, len(tokens)) if tokens[k].upper == "END_VAR"), None)
        if j is None:
            raise ExportError(path, f"{tokens[i].text} without END_VAR")
        decl_end = tokens[j].end
        i = j + 1
    return decl_end


def _strip_blank_lines(text):
    """Drops the empty lines around a body, keeping the indentation of its first line."""
    return re.sub(r"\A(?:[ \t]*\n)+", "", text).rstrip()
