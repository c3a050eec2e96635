"""Command line: `pacst build` translates ST files to C; `pacst check` only checks them."""
import argparse
import os
import sys
import time

from .compiler import Compiler
from .emit import Emitter, remove_outputs, write_outputs, _stem
from .errors import StError, StErrors
from .parsing import parse_file


def _parse_all(files, cache_dir):
    sources, errors = [], []
    for path in files:
        try:
            sources.append(parse_file(path, cache_dir))
        except StError as e:
            errors.append(e)
    if errors:
        raise StErrors(errors)
    return sources


def translate(files, cache_dir=None):
    """Parse and compile `files` in declaration order; returns (compiler, program) or raises StErrors."""
    sources = _parse_all(files, cache_dir)
    comp = Compiler()
    program = comp.compile(sources)
    return comp, program


def _build(args):
    names = ["POUS.h", "pacst_iec.h"] + [_stem(f) + ".c" for f in args.files]
    try:
        comp, program = translate(args.files, args.cache)
    except StErrors as e:
        remove_outputs(args.out, names + ([os.path.basename(args.stamp)] if args.stamp else []))
        if args.stamp and os.path.exists(args.stamp):
            os.remove(args.stamp)
        for err in e.errors:
            print(err, file=sys.stderr)
        return 1
    written = write_outputs(args.out, Emitter(comp, program).outputs(args.files))
    if args.stamp:
        with open(args.stamp, "w", encoding="utf-8") as f:
            f.write(f"{time.time()}\n")
    if args.verbose:
        print(f"pacst: {len(args.files)} file(s), rewrote {', '.join(written) or 'nothing'}")
    return 0


def _check(args):
    # --separately: every file is a program of its own (the refusal snippets of the test suite).
    groups = [[f] for f in args.files] if args.separately else [args.files]
    failed = False
    for files in groups:
        try:
            translate(files, args.cache)
        except StErrors as e:
            failed = True
            for err in e.errors:
                print(err, file=sys.stderr)
    return 1 if failed else 0


def main(argv=None):
    parser = argparse.ArgumentParser(prog="pacst", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    build = sub.add_parser("build", help="translate ST files (in declaration order) to C")
    build.add_argument("--out", required=True, help="folder for POUS.h, pacst_iec.h and one .c per ST file")
    build.add_argument("--cache", help="folder for the per-file parse cache")
    build.add_argument("--stamp", help="file written after a successful build, removed after a refusal")
    build.add_argument("-v", "--verbose", action="store_true")
    build.add_argument("files", nargs="+")
    build.set_defaults(run=_build)
    check = sub.add_parser("check", help="check ST files against the portable subset, generate nothing")
    check.add_argument("--cache", help="folder for the per-file parse cache")
    check.add_argument("--separately", action="store_true", help="check each file as a program of its own")
    check.add_argument("files", nargs="+")
    check.set_defaults(run=_check)
    args = parser.parse_args(argv)
    return args.run(args)
