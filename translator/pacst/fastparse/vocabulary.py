"""What the fast parser takes from the installed blark grammar at run time instead of restating it:
which words may be identifiers, and the name lark gave the anonymous real-literal pattern."""
import re

# The elementary type names of the subset, by the terminal blark's grammar gives each.
INTEGER_TYPES = frozenset("SINT INT DINT LINT USINT UINT UDINT ULINT".split())
REAL_TYPES = frozenset(("REAL", "LREAL"))
BIT_STRING_TYPES = frozenset("BOOL BYTE WORD DWORD LWORD".split())
DATE_TYPES = frozenset(("TIME", "LTIME"))
# Other date and time types: left to blark's parser.
OTHER_DATE_TYPES = frozenset("DATE LDATE TIME_OF_DAY TOD LTIME_OF_DAY LTOD DATE_AND_TIME DT LDATE_AND_TIME LDT".split())


def elementary_type(word):
    """The terminal of an elementary type name in a type specification, or None."""
    if word in INTEGER_TYPES or word in REAL_TYPES:
        return "NUMERIC_TYPE_NAME"
    if word in BIT_STRING_TYPES:
        return "BIT_STRING_TYPE_NAME"
    if word in DATE_TYPES:
        return "DATE_TYPE_NAME"
    return None


def grammar_facts(lark_parser):
    """What the fast parser needs of a built blark parser, as plain data (so that it can be cached
    without the parser): IDENTIFIER's pattern, and the name and pattern lark gave the anonymous
    terminal of real literals with a decimal point."""
    terminals = {t.name: t.pattern for t in lark_parser.terminals}
    names = [n for n, p in terminals.items() if n.startswith("__ANON") and p.type == "re"
             and re.fullmatch(p.to_regexp(), "1.5") and not re.fullmatch(p.to_regexp(), "1E5")]
    if len(names) != 1:
        raise RuntimeError(f"blark's grammar has changed: real literal terminals {names}")
    return {"identifier": terminals["IDENTIFIER"].to_regexp(), "real_terminal": names[0],
            "real_pattern": terminals[names[0]].to_regexp()}


class Vocabulary:
    """The words and terminals of blark's grammar that the fast parser needs, from grammar_facts."""

    def __init__(self, facts):
        self._identifier = re.compile(facts["identifier"])
        self.real_with_point = facts["real_terminal"]
        self.real_pattern = facts["real_pattern"]

    @staticmethod
    def is_type_word(word):
        """An elementary type's name (upper case), which IDENTIFIER's pattern does not exclude."""
        return elementary_type(word) is not None or word in OTHER_DATE_TYPES or word in ("STRING", "WSTRING")

    def is_identifier(self, word):
        m = self._identifier.match(word)
        return m is not None and m.end() == len(word)
