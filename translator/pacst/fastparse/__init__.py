"""A recursive-descent parser of the portable ST subset that builds exactly the lark tree blark's
Earley parser builds for the same text (rule names, None placeholders, token types and values,
positions), so that blark's transform and everything after it in pacst stay as they are. It reads
in one pass what Earley needs thousands of items per line for; whatever it does not know, and every
syntax error, it declines (Decline), and blark's parser decides instead."""
from .declarations import Declarations
from .expressions import Expressions
from .literals import Literals
from .scanner import LEFT_TO_EARLEY, Decline, Scanner
from .statements import Statements
from .vocabulary import Vocabulary, grammar_facts

__all__ = ["Decline", "FastParser", "LEFT_TO_EARLEY", "grammar_facts"]


class FastParser:
    """Parses processed source text (blark's preprocessing done) to blark's tree, or declines."""

    def __init__(self, facts):
        """`facts`: grammar_facts() of blark's built parser."""
        vocabulary = Vocabulary(facts)
        expressions = Expressions(vocabulary, Literals(vocabulary))
        self._statements = Statements(expressions)
        self._declarations = Declarations(expressions, self._statements)
        # A POU's or type's declaration alone, as TwinCAT files and PLCopen XML keep it (blark gives it the
        # element's end and parses it from the element's own rule).
        self._elements = self._declarations.elements()

    def parse(self, text, start="iec_source"):
        """blark's tree of `text` from the start rule iec_source, statement_list (a POU's body alone, as
        TwinCAT keeps it) or the rule of one element (a FUNCTION_BLOCK, FUNCTION, PROGRAM or TYPE alone);
        raises Decline."""
        s = Scanner(text) if start in ("statement_list", "iec_source") or start in self._elements else None
        try:
            if s is None:
                raise Decline(f"start rule {start} not read here")
            if start == "statement_list":
                tree = self._statements.statement_list(s)
                if tree is None or not s.at_end():
                    raise Decline("not a statement list alone")
                return tree
            if start in self._elements:
                keyword, reader = self._elements[start]
                if s.peek_word() != keyword:
                    raise Decline(f"not a {keyword}")
                tree = reader(s)
                if not s.at_end():
                    raise Decline(f"more than one {keyword}")
                return tree
            return self._declarations.source(s)
        except RecursionError:
            raise Decline("nested too deeply") from None
        except Decline as exc:
            # where it declined, for decline_reasons.py
            exc.pos = s.pos if s is not None else 0
            raise
