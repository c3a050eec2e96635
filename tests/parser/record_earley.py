"""Writes earley_digests.txt, the record of Earley's trees that FastParser.Corpus compares the fast parser's
trees with (test_fast_parser_corpus.py): for every text that test compares from the corpora's files, the
digest of the tree blark's Earley parser builds for it (tree_oracle.tree_digest), keyed by the text and its
start rule, under the digest of blark's grammar and the versions of blark and lark. Only Earley's trees are
recorded; texts Earley refuses are left out. Run it after changing files of the corpora or the pins of blark
and lark (the test then parses with Earley what the record lacks, at several milliseconds a line):

  build/venv/bin/python tests/parser/record_earley.py [--cache DIR]

--cache: the build tree's cache of Earley's trees ($PAC_ORACLE_CACHE of the test), so that only the texts
it lacks are parsed."""
import argparse
import concurrent.futures
import os
import sys

import lark

from tree_oracle import RECORD, Oracle, record_grammar, text_key, tree_digest
import test_fast_parser_corpus as corpus

_ORACLE = None


def _digest(rule_and_source):
    """(key, digest of Earley's tree) of one text, or None when Earley refuses it."""
    global _ORACLE
    if _ORACLE is None:
        _ORACLE = Oracle(os.environ.get("PAC_ORACLE_CACHE"))
    rule, source = rule_and_source
    try:
        text = Oracle.processed(source)
        return text_key(text, rule), tree_digest(_ORACLE.earley_tree(text, rule))
    except Exception:  # blark's comment pass or Earley refuses the text: nothing to record
        return None


def main(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("--cache")
    args = parser.parse_args(argv)
    if args.cache:
        os.environ["PAC_ORACLE_CACHE"] = args.cache
    texts = sorted(corpus.corpus_texts(), key=lambda t: len(t[1]), reverse=True)  # longest first
    with concurrent.futures.ProcessPoolExecutor(max_workers=len(os.sched_getaffinity(0))) as pool:
        found = dict(entry for entry in pool.map(_digest, texts, chunksize=4) if entry)
    with open(RECORD, "w", encoding="utf-8") as f:
        f.write("# Digests of blark's Earley trees of FastParser.Corpus's texts: written by record_earley.py.\n")
        f.write(f"grammar {record_grammar()}\n")
        f.writelines(f"{key} {digest}\n" for key, digest in sorted(found.items()))
    print(f"record_earley: {len(found)} of {len(texts)} texts recorded (lark {lark.__version__})", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
