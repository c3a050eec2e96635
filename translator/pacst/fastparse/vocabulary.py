"""What the fast parser takes from the installed blark grammar at run time instead of restating it:
which words may be identifiers, and the names lark gave the anonymous real-literal patterns."""
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


class Vocabulary:
    """Read from a built blark (lark) parser's terminals."""

    def __init__(self, lark_parser):
        terminals = {t.name: t.pattern for t in lark_parser.terminals}
        ident = terminals["IDENTIFIER"]
        self._identifier = re.compile(ident.to_regexp())
        self.real_with_point = self._anonymous(terminals, "1.5", "1E5")

    @staticmethod
    def _anonymous(terminals, matches, not_matches):
        """The anonymous terminal that reads `matches` whole but not `not_matches`."""
        names = [n for n, p in terminals.items() if n.startswith("__ANON") and p.type == "re"
                 and re.fullmatch(p.to_regexp(), matches) and not re.fullmatch(p.to_regexp(), not_matches)]
        if len(names) != 1:
            raise RuntimeError(f"blark's grammar has changed: real literal terminals {names}")
        return names[0]

    @staticmethod
    def is_type_word(word):
        """An elementary type's name (upper case), which IDENTIFIER's pattern does not exclude."""
        return elementary_type(word) is not None or word in OTHER_DATE_TYPES or word in ("STRING", "WSTRING")

    def is_identifier(self, word):
        m = self._identifier.match(word)
        return m is not None and m.end() == len(word)
