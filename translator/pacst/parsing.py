"""Parses ST files to blark's typed AST and caches it per file content.

The parse itself is the fast parser's (fastparse/), which builds exactly the tree blark's Earley
parser would; blark's Earley parser (several milliseconds per source line) parses only what the
fast parser declines: text outside the portable subset and every syntax error, so that refusals
keep blark's messages and positions. blark's preprocessing and transform run as they are.

A rebuild after touching one file re-parses only that file: the transformed AST of every other
file comes from a pickle keyed by the SHA-256 of its text and the versions of blark, of the lexical
checks, of the fast parser and of this cache format. The files
the cache does not hold are parsed in parallel, one process per core (docs/translation_time.md has the
timings). Building blark's Earley parser from its grammar costs about 0.4 s, so the built parser is
cached too, pickled beside the parses: loading it takes a tenth of that, and happens only when the
fast parser declines a file (the two facts of the grammar the fast parser needs are cached apart).
"""
import concurrent.futures
import gc
import hashlib
import importlib
import io
import multiprocessing
import os
import pickle
import re
import sys
import tempfile
import types

import blark
import lark
from blark import transform as tf
from blark.parse import new_parser, parse_source_code

from . import durations, lexcheck, rewrite, twincat
from .errors import StError
from .fastparse import Decline, FastParser, grammar_facts

_CACHE_FORMAT = 2
# Below about a second of parsing and transforming (the fast parser and blark's transform read about
# 130,000 characters a second together), starting worker processes costs more than it saves.
_PARALLEL_MIN_CHARS = 100_000


def _sources_version(modules):
    """The SHA-256 of the modules' own source. A cached parse stands for a text that passed the lexical
    checks (a cache hit skips them) and was parsed by the fast parser: changing either invalidates it."""
    h = hashlib.sha256()
    for path in modules:
        with open(path, "rb") as f:
            h.update(f.read())
    return h.hexdigest()


_FASTPARSE_DIR = os.path.join(os.path.dirname(__file__), "fastparse")
_SOURCES_VERSION = _sources_version([lexcheck.__file__] + sorted(
    os.path.join(_FASTPARSE_DIR, name) for name in os.listdir(_FASTPARSE_DIR) if name.endswith(".py")))


def _cache_key(text, user=False):
    """A parse is cached for the text and the mode: a user program passed laxer lexical checks."""
    h = hashlib.sha256()
    h.update(f"{_CACHE_FORMAT}|{blark.__version__}|{_SOURCES_VERSION}|{'user|' if user else ''}".encode())
    h.update(text.encode("utf-8"))
    return h.hexdigest()


def _parser_key():
    """What a built parser depends on: the grammar's text and the versions of blark, lark and Python."""
    h = hashlib.sha256()
    h.update(f"{_CACHE_FORMAT}|{blark.__version__}|{lark.__version__}|{sys.version}|".encode())
    with open(blark.GRAMMAR_FILENAME, "rb") as f:
        h.update(f.read())
    return "parser-" + h.hexdigest()


class _ParserPickler(pickle.Pickler):
    """Pickles lark's parser, which holds a module (its regular-expression module) by reference."""

    def reducer_override(self, obj):
        if isinstance(obj, types.ModuleType):
            return importlib.import_module, (obj.__name__,)
        return NotImplemented


class _FastFirst:
    """The parser parse_source_code is given: the fast parser, and blark's where that declines. blark's
    parser is loaded only then: the fast parser needs just two facts of its grammar, cached apart."""

    def __init__(self, cache_dir):
        # parse_source_code reads only which start rules there are.
        self.options = types.SimpleNamespace(start=["iec_source"])
        self._cache_dir = cache_dir
        self._earley = None
        key = "fastparse-" + _parser_key() if cache_dir else None
        facts = _cached_tree(cache_dir, key) if key else None
        if facts is None:
            facts = grammar_facts(self._earley_parser())
            if key:
                _store(cache_dir, key, pickle.dumps(facts, protocol=pickle.HIGHEST_PROTOCOL))
        self._fast = FastParser(facts)

    def _earley_parser(self):
        if self._earley is None:
            self._earley = _earley_parser(self._cache_dir)
        return self._earley

    def parse(self, text, start):
        try:
            return self._fast.parse(text, start)  # declines the start rules it does not read
        except Decline:
            pass
        return self._earley_parser().parse(text, start=start)


# The one parser of this process (and of the workers it forks), from _parser().
_PARSER = None


def _earley_parser(cache_dir):
    """blark's parser: from the cache when it holds one for this grammar and these versions, else built
    (and then stored there)."""
    key = _parser_key() if cache_dir else None
    parser = _cached_tree(cache_dir, key) if key else None
    if parser is None:
        parser = new_parser()
        if key:
            buf = io.BytesIO()
            _ParserPickler(buf, protocol=pickle.HIGHEST_PROTOCOL).dump(parser)
            _store(cache_dir, key, buf.getvalue())
    return parser


def _parser(cache_dir):
    global _PARSER
    if _PARSER is None:
        _PARSER = _FastFirst(cache_dir)
    return _PARSER


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
    hint = _semicolon_hint(text, line, col) or _call_member_hint(text, line, col)
    return StError(file, line, col, f"syntax error{found}{_expected_keywords(exc)}{hint}")


_CALL_MEMBER = re.compile(r"\)\s*\^?\s*(?:\.\s*[A-Za-z_]\w*\s*(?:\(\s*\)\s*)?\^?\s*)+(?:\[[^\]]*\]\s*)?$")


def _call_member_hint(text, line, col):
    """When the error follows `F(x).Member` or `F(x)^.Member` (rewrite.py makes it `.Member()` where it is read;
    written to or indexed, blark's grammar reads it nowhere), what to write instead."""
    lines = text.split("\n")
    if not 1 <= line <= len(lines) or not _CALL_MEMBER.search(lines[line - 1][:col - 1]):
        return ""
    return (" (a member of a call's result, F(x).Member, is read but not indexed or assigned to here: assign the "
            "result to a variable of its type first, then index or assign its member)")


_NO_STATEMENT_END = re.compile(r"(?i)(?:\b(?:THEN|ELSE|DO|OF|REPEAT|AND|OR|XOR|NOT|MOD|STRUCT|END_VAR|VAR\w*)|"
                               r"[,(:=+\-*/<>&;])\s*$")
_NO_STATEMENT_LINE = re.compile(r"(?i)^\s*(?:PROGRAM|FUNCTION_BLOCK|FUNCTION|TYPE|VAR\w*|\{)")


def _semicolon_hint(text, line, col):
    """When the error is at the first word of a line and the line of code before it ends like a statement
    without its ';' (the error CODESYS names "expected ';'"), the question which line lacks it."""
    lines = text.split("\n")
    if not 1 < line <= len(lines) or lines[line - 1][:col - 1].strip():
        return ""
    for n in range(line - 1, 0, -1):
        code = re.sub(r"\(\*.*?\*\)|//.*$", "", lines[n - 1]).rstrip()
        if not code.strip():
            continue
        if _NO_STATEMENT_END.search(code) or _NO_STATEMENT_LINE.match(code) or "(*" in code or "*)" in code:
            return ""
        return f" (is the ';' at the end of line {n} missing?)"
    return ""


class SourceFile:
    """One parsed file: its path, text and blark SourceCode."""

    def __init__(self, path, text, tree, rewrites=()):
        self.path = path
        self.text = text
        self.tree = tree
        # user mode: (line, column, construct, column in the parsed text) of each rewrite.user_text made
        self.rewrites = rewrites


def _read(path, user=False, cache_dir=None):
    try:
        with open(path, encoding="utf-8-sig" if user else "utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as exc:
        raise StError(path, 1, 1, f"cannot read the file: {exc}") from None
    if not user:
        return text, []
    if twincat.is_object_file(path):
        return rewrite.user_text(twincat.object_st(text, path), path)
    # An ST file's user text depends on its text alone (two passes of the lexer, about a fifth of a pac-test
    # translation's CPU from a warm cache): cached beside the parses.
    key = _read_key(text)
    read = _cached_tree(cache_dir, key)
    if read is None:
        read = rewrite.user_text(_closed_pou(text, path), path)
        if cache_dir:
            _store(cache_dir, key, pickle.dumps(read, protocol=pickle.HIGHEST_PROTOCOL))
    return read


# What an ST file's user text depends on besides the text: the modules that make it.
_READ_VERSION = _sources_version([__file__, rewrite.__file__, lexcheck.__file__, durations.__file__])


def _read_key(text):
    h = hashlib.sha256()
    h.update(f"{_CACHE_FORMAT}|{_READ_VERSION}|".encode())
    h.update(text.encode("utf-8"))
    return "read-" + h.hexdigest()


_POU_OPENERS = ("FUNCTION_BLOCK", "FUNCTION", "PROGRAM")


def _closed_pou(text, path):
    """A user's .st file of one POU without its END_ keyword (the TwinCAT and CODESYS editors keep it out,
    and programmers write their files so), closed after its last line as a TwinCAT object is; the lines
    stay the file's. A file with any END_ keyword of a POU, or with several POUs, is left as it is."""
    try:
        words = [t.upper for t in lexcheck.tokenize(text, path, user=True) if t.kind == "ident"]
    except StError:
        return text  # the check names what is wrong
    opened = [w for w in words if w in _POU_OPENERS]
    if len(opened) != 1 or any(w in ("END_" + k for k in _POU_OPENERS) for w in words):
        return text
    return f"{text}\nEND_{opened[0]}\n"


def _cache_folders(cache_dir):
    """The folders of `cache_dir`: one, or several joined by os.pathsep, of which the first is written and the
    others are only read (pac-test reads the build's cache, which holds the library, beneath a run's own)."""
    return [folder for folder in cache_dir.split(os.pathsep) if folder] if cache_dir else []


def _cached_entry(cache_dir, key):
    """(the cached object for `key`, its pickled bytes), or (None, None). A corrupt cache entry is built again,
    never trusted."""
    for folder in _cache_folders(cache_dir):
        try:
            with open(os.path.join(folder, key + ".pickle"), "rb") as f:
                pickled = f.read()
            return pickle.loads(pickled), pickled
        except Exception:
            continue
    return None, None


def _cached_tree(cache_dir, key):
    """The cached object (a tree, the parser or a file's user text) for `key`, or None."""
    return _cached_entry(cache_dir, key)[0]


def _store(cache_dir, key, pickled):
    folder = _cache_folders(cache_dir)[0]
    os.makedirs(folder, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=folder, suffix=".tmp")
    with os.fdopen(fd, "wb") as f:
        f.write(pickled)
    os.replace(tmp, os.path.join(folder, key + ".pickle"))


def _user_tree(cache_dir, text):
    """User mode, on a miss: the tree of the same text parsed outside user mode (the library's, by its build), once
    `text` passed user mode's lexical checks; kept under the user-mode key too, so that the next run skips them.
    The tree depends on the text alone: the two keys differ only in the checks a hit stands for."""
    tree, pickled = _cached_entry(cache_dir, _cache_key(text))
    if tree is not None:
        _store(cache_dir, _cache_key(text, True), pickled)
    return tree


def _parse_pickled(path, text):
    """(blark's transformed tree of `text` pickled, None), or (None, the file, line, column and message of
    its first syntax error): plain data, so that it crosses from a worker process as it is cached."""
    try:
        result = parse_source_code(text, fn=path, parser=_PARSER)
    except Exception as exc:  # blark's own passes (comments, pragmas) raise on some damaged text
        line, col = _end_of(text)
        return None, (path, line, col, f"syntax error: {exc}")
    if result.exception is not None:
        e = _syntax_error(result.exception, path, text)
        return None, (e.file, e.line, e.col, e.message)
    return pickle.dumps(result.transform(), protocol=pickle.HIGHEST_PROTOCOL), None


def default_jobs():
    """The cores this process may run on."""
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


def _parse_misses(misses, jobs, cache_dir):
    """{index: _parse_pickled's answer} for the (index, path, text) the cache did not hold. Several, and
    enough text, go to `jobs` forked workers, the longest text first so that no worker is left with a
    long file at the end; blark's parser is made once, before the fork."""
    if misses:
        _parser(cache_dir)
    if (jobs <= 1 or len(misses) <= 1 or sum(len(m[2]) for m in misses) < _PARALLEL_MIN_CHARS
            or "fork" not in multiprocessing.get_all_start_methods()):
        return {i: _parse_pickled(path, text) for i, path, text, _ in misses}
    ordered = sorted(misses, key=lambda m: len(m[2]), reverse=True)
    context = multiprocessing.get_context("fork")
    with concurrent.futures.ProcessPoolExecutor(max_workers=min(jobs, len(misses)), mp_context=context) as pool:
        futures = {i: pool.submit(_parse_pickled, path, text) for i, path, text, _ in ordered}
        return {i: future.result() for i, future in futures.items()}


def parse_files(paths, cache_dir=None, jobs=None, user=False):
    """Read, check lexically and parse every file of `paths`: for each, in order, its SourceFile or the
    StError of its first fault. The same trees as parse_file, whatever `jobs` (default: one per core).
    `user`: the files of a user program (laxer lexical checks; TwinCAT's .TcPOU, .TcGVL and .TcDUT read)."""
    results, misses = [], []
    with LoadingTrees():
        for i, path in enumerate(paths):
            try:
                text, rewrites = _read(path, user, cache_dir)
                tree = _cached_tree(cache_dir, _cache_key(text, user))
                if tree is None:
                    lexcheck.check(text, path, user)
                    tree = _user_tree(cache_dir, text) if user and cache_dir else None
            except StError as e:
                results.append(e)
                continue
            results.append(SourceFile(path, text, tree, rewrites) if tree is not None else None)
            if tree is None:
                misses.append((i, path, text, rewrites))
    if not misses:
        return results
    parsed = _parse_misses(misses, default_jobs() if jobs is None else jobs, cache_dir)
    with LoadingTrees():
        for i, path, text, rewrites in misses:
            pickled, error = parsed[i]
            if error is not None:
                results[i] = StError(*error)
                continue
            if cache_dir:
                _store(cache_dir, _cache_key(text, user), pickled)
            results[i] = SourceFile(path, text, pickle.loads(pickled), rewrites)
    return results


# Whether parse_files freezes the trees it loads (LoadingTrees): `python -m pacst` sets it, a process that runs one
# translation. A process that translates many programs in turn (a test suite) leaves it off: what is alive at a
# freeze and dies later as a cycle (a Compiler of the program before) would never be collected.
FREEZE_LOADED_TREES = False


class LoadingTrees:
    """Python's cyclic garbage collector off while parsed trees load, and their objects left out of its later passes
    (frozen): a library's trees are a few hundred thousand objects that live as long as the run, none of them
    garbage, over which the collector's passes cost more than the loads (about half of a library's `pacst build`,
    1 s of CPU). They hold no cycles, so dropped they are freed all the same. The garbage already there is
    collected first, so that the freeze keeps none of it. `always`: whatever FREEZE_LOADED_TREES says (the checked
    library's state, loaded once in a pacst process)."""

    def __init__(self, always=False):
        self._always = always

    def __enter__(self):
        self._enabled = (self._always or FREEZE_LOADED_TREES) and gc.isenabled()
        if self._enabled:
            gc.collect()
            gc.disable()

    def __exit__(self, exc_type, *exc):
        if self._enabled:
            if exc_type is None:
                gc.freeze()
            gc.enable()


def parse_file(path, cache_dir=None):
    """Read, check lexically and parse `path`; raises StError with the position of the first fault."""
    result = parse_files([path], cache_dir, jobs=1)[0]
    if isinstance(result, StError):
        raise result
    return result


class ParsedText:
    """One parse of parse_text: the code, blark's tree of it and its comments."""

    def __init__(self, code, tree, comments):
        self.code = code
        self.tree = tree
        self.comments = comments

    def items(self, comments=True):
        """blark's typed items; without comments their text is the canonical form of the code."""
        return tf.transform(source_code=self.code, tree=self.tree,
                            comments=list(self.comments) if comments else []).items


def parse_text(text, where, cache_dir=None, rule="iec_source"):
    """Parses `text` from the grammar rule `rule` with the parser and cache of parse_files, but without
    the lexical checks of the portable subset: for text the exports write and the IDEs read back (a
    pragma such as {attribute 'qualified_only'}, an object cut into declaration and body as TwinCAT keeps
    it), which the tests compare with the source. Raises StError at the first syntax error."""
    key = "text-" + _cache_key(f"{rule}|{text}")
    cached = _cached_tree(cache_dir, key)
    if cached is not None:
        return ParsedText(text, *cached)
    try:
        result = parse_source_code(text, starting_rule=rule, fn=where, parser=_parser(cache_dir))
    except Exception as exc:  # blark's own passes (comments, pragmas) raise on some damaged text
        line, col = _end_of(text)
        raise StError(where, line, col, f"syntax error: {exc}") from None
    if result.exception is not None:
        raise _syntax_error(result.exception, where, text)
    if cache_dir:
        _store(cache_dir, key, pickle.dumps((result.tree, result.comments), protocol=pickle.HIGHEST_PROTOCOL))
    return ParsedText(text, result.tree, result.comments)
