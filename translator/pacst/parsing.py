"""Parses ST files with blark and caches the typed AST per file content.

blark needs several milliseconds per source line, so a rebuild after touching one file re-parses
only that file: the transformed AST of every other file comes from a pickle keyed by the SHA-256
of its text and the versions of blark and of this cache format.
"""
import hashlib
import os
import pickle
import re
import tempfile

import blark
from blark.parse import parse_source_code

from . import lexcheck
from .errors import StError

_CACHE_FORMAT = 1


def _cache_key(text):
    h = hashlib.sha256()
    h.update(f"{_CACHE_FORMAT}|{blark.__version__}|".encode())
    h.update(text.encode("utf-8"))
    return h.hexdigest()


def _expected_keywords(exc):
    """The keywords (blark's `_THEN`-style terminals) the parser would have taken, when there are few."""
    names = getattr(exc, "expected", None) or getattr(exc, "allowed", None) or ()
    words = sorted(n[1:] for n in names if re.fullmatch(r"_[A-Z][A-Z_]*", n))
    return f": expected {' or '.join(words)}" if 0 < len(words) <= 3 else ""


def _end_of(text):
    """Line and column just past the last character: where an unexpected end of file is."""
    lines = text.split("\n")
    return len(lines), len(lines[-1]) + 1


def _syntax_error(exc, file, text=""):
    line = getattr(exc, "line", None) or 1
    col = getattr(exc, "column", None) or 1
    if line < 1 or col < 1:
        # lark reports -1:-1 where the input ended before the rule did (found by the damaged-input tests).
        line, col = _end_of(text)
    token = getattr(exc, "token", None)
    if token is not None and getattr(token, "type", "") == "$END":
        return StError(file, line, col, "syntax error: unexpected end of file")
    found = f" at '{token}'" if token not in (None, "") else ""
    if not found:
        # The lexer stopped at one character: name the whole word that starts there.
        at = getattr(exc, "pos_in_stream", None)
        m = re.compile(r"[A-Za-z_][A-Za-z0-9_]*").match(text, at) if at is not None else None
        char = m.group(0) if m else getattr(exc, "char", None)
        found = f" at '{char}'" if char else ""
    return StError(file, line, col, f"syntax error{found}{_expected_keywords(exc)}")


class SourceFile:
    """One parsed file: its path, text and blark SourceCode."""

    def __init__(self, path, text, tree):
        self.path = path
        self.text = text
        self.tree = tree


def parse_file(path, cache_dir=None):
    """Read, check lexically and parse `path`; raises StError with the position of the first fault."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as exc:
        raise StError(path, 1, 1, f"cannot read the file: {exc}") from None
    lexcheck.check(text, path)
    key = _cache_key(text)
    cached = os.path.join(cache_dir, key + ".pickle") if cache_dir else None
    if cached and os.path.exists(cached):
        try:
            with open(cached, "rb") as f:
                return SourceFile(path, text, pickle.load(f))
        except Exception:  # a corrupt cache entry is re-parsed, never trusted
            pass
    try:
        result = parse_source_code(text, fn=path)
    except Exception as exc:  # blark's own passes (comments, pragmas) raise on some damaged text
        line, col = _end_of(text)
        raise StError(path, line, col, f"syntax error: {exc}") from None
    if result.exception is not None:
        raise _syntax_error(result.exception, path, text)
    tree = result.transform()
    if cached:
        os.makedirs(cache_dir, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=cache_dir, suffix=".tmp")
        with os.fdopen(fd, "wb") as f:
            pickle.dump(tree, f, protocol=pickle.HIGHEST_PROTOCOL)
        os.replace(tmp, cached)
    return SourceFile(path, text, tree)
