"""What the damaged-input suites share: the seed (from PAC_HYPOTHESIS_SEED, or a new one, printed either
way so that a failing run can be repeated), Hypothesis settings without a database (nothing is written
into the source tree), and mutations of a valid text (delete, duplicate or move a span, insert junk)."""
import os
import random
import sys

from hypothesis import HealthCheck, settings, strategies as st

SEED = int(os.environ.get("PAC_HYPOTHESIS_SEED") or random.SystemRandom().randrange(2**32))
EXAMPLES = int(os.environ.get("PAC_HYPOTHESIS_EXAMPLES", "120"))
print(f"damaged inputs: PAC_HYPOTHESIS_SEED={SEED} PAC_HYPOTHESIS_EXAMPLES={EXAMPLES}", file=sys.stderr, flush=True)

SETTINGS = settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=False,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@st.composite
def mutated(draw, texts, junk):
    """One of `texts`, damaged by one to four edits; `junk` draws the text an insertion puts in."""
    text = draw(st.sampled_from(texts))
    for _ in range(draw(st.integers(1, 4))):
        n = len(text)
        a = draw(st.integers(0, n))
        b = draw(st.integers(a, min(n, a + 40)))
        edit = draw(st.sampled_from(["delete", "insert", "duplicate", "move", "truncate"]))
        if edit == "delete":
            text = text[:a] + text[b:]
        elif edit == "insert":
            text = text[:a] + draw(junk) + text[a:]
        elif edit == "duplicate":
            text = text[:b] + text[a:b] + text[b:]
        elif edit == "move":
            span, rest = text[a:b], text[:a] + text[b:]
            c = draw(st.integers(0, len(rest)))
            text = rest[:c] + span + rest[c:]
        else:
            text = text[:a]
    return text
