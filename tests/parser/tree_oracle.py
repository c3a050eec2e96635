"""The oracle of the fast parser: blark's Earley parser on the same text. Shared by the corpus and
the generated-input tests (test_fast_parser_*.py), and by record_earley.py, which writes the record of
Earley's trees the corpus test reads (earley_digests.txt)."""
import hashlib
import json
import os
import pickle
import sys
import tempfile

import blark
import lark

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "translator"))
from blark import util  # noqa: E402
from blark.parse import new_parser  # noqa: E402

from pacst.fastparse import Decline, FastParser, grammar_facts  # noqa: E402

_POSITIONS = ("line", "column", "end_line", "end_column", "start_pos", "end_pos")
_META = _POSITIONS + tuple("container_" + p for p in _POSITIONS)


def difference(fast, earley, path=""):
    """Where the two trees differ (a path and what), or None. lark's Token == compares only the text, so
    token types are compared here, and every position of every node and token."""
    if isinstance(fast, lark.Tree) and isinstance(earley, lark.Tree):
        here = f"{path}/{earley.data}"
        if fast.data != earley.data:
            return f"{here}: rule {fast.data}"
        if fast.meta.empty != earley.meta.empty:
            return f"{here}: meta empty {fast.meta.empty} vs {earley.meta.empty}"
        for attr in _META:
            a, b = getattr(fast.meta, attr, None), getattr(earley.meta, attr, None)
            if a != b:
                return f"{here}: {attr} {a} vs {b}"
        if len(fast.children) != len(earley.children):
            return f"{here}: {len(fast.children)} children vs {len(earley.children)}"
        for i, (a, b) in enumerate(zip(fast.children, earley.children)):
            found = difference(a, b, f"{here}[{i}]")
            if found:
                return found
        return None
    if isinstance(fast, lark.Token) and isinstance(earley, lark.Token):
        if (fast.type, fast.value) != (earley.type, earley.value):
            return f"{path}: token {fast.type}={fast.value!r} vs {earley.type}={earley.value!r}"
        for attr in _POSITIONS:
            if getattr(fast, attr) != getattr(earley, attr):
                return f"{path}: token {earley!r} {attr} {getattr(fast, attr)} vs {getattr(earley, attr)}"
        return None
    if fast is None and earley is None:
        return None
    return f"{path}: {fast!r:.60} vs {earley!r:.60}"


def _plain(item):
    """The tree as tuples: lark's Token pickles without its end positions, so trees are kept this way."""
    if isinstance(item, lark.Tree):
        meta = {a: getattr(item.meta, a) for a in _META if hasattr(item.meta, a)}
        return ("tree", item.data, item.meta.empty, meta, [_plain(c) for c in item.children])
    if isinstance(item, lark.Token):
        return ("token", item.type, str(item), tuple(getattr(item, a) for a in _POSITIONS))
    return None


def _from_plain(plain):
    if plain is None:
        return None
    if plain[0] == "token":
        _, type_, value, (line, column, end_line, end_column, start_pos, end_pos) = plain
        return lark.Token(type_, value, start_pos, line, column, end_line, end_column, end_pos)
    _, data, empty, attrs, children = plain
    meta = lark.tree.Meta()
    meta.empty = empty
    for name, value in attrs.items():
        setattr(meta, name, value)
    return lark.Tree(data, [_from_plain(c) for c in children], meta)


def tree_digest(tree):
    """A digest of the whole tree as _plain keeps it: every rule, token type and value, every position.
    Equal digests mean equal plain trees, which difference() finds no difference in."""
    return hashlib.sha256(json.dumps(_plain(tree), separators=(",", ":")).encode("utf-8")).hexdigest()[:32]


def text_key(text, start="iec_source"):
    """The record's key of a processed text parsed from the rule `start`."""
    return hashlib.sha256(f"{start}|{text}".encode("utf-8")).hexdigest()[:32]


def record_grammar():
    """What Earley's trees depend on: blark's grammar and the versions of blark and lark."""
    h = hashlib.sha256(f"{blark.__version__}|{lark.__version__}|".encode())
    with open(blark.GRAMMAR_FILENAME, "rb") as f:
        h.update(f.read())
    return h.hexdigest()[:32]


RECORD = os.path.join(os.path.dirname(os.path.abspath(__file__)), "earley_digests.txt")


def read_record(path=RECORD):
    """{text key: digest of Earley's tree} of the record, or {} when it was written for another grammar or
    other versions of blark and lark (every text is then parsed by Earley)."""
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
    except OSError:
        return {}
    entries = [line.split() for line in lines if line and not line.startswith("#")]
    if not entries or entries[0] != ["grammar", record_grammar()]:
        return {}
    return dict(entries[1:])


def _grammar_version():
    h = hashlib.sha256(f"{blark.__version__}|{lark.__version__}|{sys.version}|".encode())
    with open(blark.GRAMMAR_FILENAME, "rb") as f:
        h.update(f.read())
    return h.hexdigest()


class Oracle:
    """Both parsers on blark's processed text of an ST source. With `cache_dir`, Earley's trees are
    kept there (the build tree, never the repository), keyed by the text and blark's grammar and
    versions: a second run of the tests parses only what changed with Earley. With `record` ({text key:
    digest}, read_record()), a fast tree whose digest is the one recorded for its text is Earley's tree
    without parsing the text again; a text the record lacks, or whose fast tree has another digest, is
    parsed by Earley as without it. `audit(key)` True: that text is parsed by Earley even when recorded, and
    a record that differs from Earley's tree is a failure (the record is not Earley's)."""

    def __init__(self, cache_dir=None, record=None, audit=None):
        self.earley = new_parser()
        self.fast = FastParser(grammar_facts(self.earley))
        self._cache_dir = cache_dir
        self._grammar = _grammar_version() if cache_dir else None
        self._record = record or {}
        self._audit = audit or (lambda key: False)
        self.earley_parses = 0  # texts given to Earley (or to the build tree's cache of its trees)

    def earley_tree(self, text, start="iec_source"):
        self.earley_parses += 1
        if not self._cache_dir:
            return self.earley.parse(text, start=start)
        rule = "" if start == "iec_source" else f"{start}|"
        key = hashlib.sha256(f"{self._grammar}|{rule}{text}".encode("utf-8")).hexdigest()
        path = os.path.join(self._cache_dir, key + ".pickle")
        try:
            with open(path, "rb") as f:
                return _from_plain(pickle.load(f))
        except (OSError, pickle.UnpicklingError, EOFError):
            pass
        tree = self.earley.parse(text, start=start)
        os.makedirs(self._cache_dir, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=self._cache_dir, suffix=".tmp")
        with os.fdopen(fd, "wb") as f:
            pickle.dump(_plain(tree), f, protocol=pickle.HIGHEST_PROTOCOL)
        os.replace(tmp, path)
        return tree

    @staticmethod
    def processed(source):
        return util.find_and_clean_comments(source)[1]

    def compare(self, source, start="iec_source"):
        """("declined", None), ("same", None) or ("different", what): the fast parser's tree against
        Earley's, both from the rule `start`. A text Earley refuses must be declined."""
        try:
            text = self.processed(source)
        except Exception:  # blark's comment pass fails on unbalanced comments before any parser runs
            return "declined", None
        try:
            fast = self.fast.parse(text, start)
        except Decline:
            return "declined", None
        key = text_key(text, start) if self._record else None
        recorded = self._record.get(key) if key else None
        if recorded is not None and not self._audit(key) and tree_digest(fast) == recorded:
            return "same", None
        try:
            earley = self.earley_tree(text, start)
        except lark.exceptions.LarkError as exc:
            return "different", f"the fast parser accepted what Earley refuses: {exc}"
        if recorded is not None and tree_digest(earley) != recorded:
            return "different", (f"the record {os.path.basename(RECORD)} holds another tree than Earley's for "
                                 f"this text (key {key}): write it again with record_earley.py")
        found = difference(fast, earley)
        return ("different", found) if found else ("same", None)
