"""POUs, types and variable blocks: the top level of a file, in blark's shapes."""
from .scanner import Decline, node
from .vocabulary import elementary_type

_ATTRIBUTES = frozenset(("RETAIN", "NON_RETAIN", "PERSISTENT", "CONSTANT"))
# Variable blocks: the rule of each, whether it has attributes, and whether its declarations sit in a
# var_body (else directly in the block, as VAR_INPUT's do).
_BLOCKS = {
    "VAR_INPUT": ("input_declarations", True, False),
    "VAR_OUTPUT": ("output_declarations", True, True),
    "VAR_IN_OUT": ("input_output_declarations", True, True),
    "VAR_TEMP": ("temp_var_decls", False, True),
}


class Declarations:
    """Reads a whole file over `statements` and `expressions`."""

    def __init__(self, expressions, statements):
        self._x = expressions
        self._st = statements
        self._top = {"TYPE": self._type, "FUNCTION": self._function,
                     "FUNCTION_BLOCK": self._function_block, "VAR_GLOBAL": self._globals,
                     "PROGRAM": self._program}

    def elements(self):
        """The start rule of each element read alone: its first keyword and its reader."""
        return {"data_type_declaration": ("TYPE", self._type),
                "function_declaration": ("FUNCTION", self._function),
                "function_block_type_declaration": ("FUNCTION_BLOCK", self._function_block),
                "program_declaration": ("PROGRAM", self._program)}

    def source(self, s):
        items = []
        while not s.at_end():
            reader = self._top.get(s.peek_word())
            if reader is None:
                raise Decline("top-level element not read here")
            items.append(reader(s))
        if not items:
            raise Decline("empty file")
        return node("iec_source", items)

    def _identifier(self, s):
        return self._x.name_token(s)

    # Types

    def _type(self, s):
        raw = [s.keyword("TYPE"), None, self._type_declaration(s)]
        s.semicolons(raw, least=0)
        raw.append(s.keyword("END_TYPE"))
        _no_trailing_semicolon(s)
        return node("data_type_declaration", raw)

    def _type_declaration(self, s):
        name = self._identifier(s)
        colon = s.punct(":")
        word = s.peek_word()
        if s.peek_punct() == "(":
            return node("enumerated_type_declaration", [name, colon, self._enumeration(s)])
        if word == "STRUCT":
            return self._structure(s, name, colon)
        if word == "ARRAY":
            return node("array_type_declaration", [name, colon, self._array_spec_init(s)])
        raise Decline("type declaration not read here")

    def _enumeration(self, s):
        raw = [s.punct("(")]
        while True:
            raw.append(node("enumerated_value", [None, self._x.name_token(s, "DOTTED_IDENTIFIER"), None]))
            if s.peek_punct() != ",":
                break
            raw.append(s.punct(","))
        raw += [s.punct(")"), None]
        if s.peek_word() is not None or s.peek_punct() in (":=", "."):
            raise Decline("enumeration with a base type, values or a default")
        return node("enumerated_spec_init", [None, node("enumerated_specification", raw), None])

    def _structure(self, s, name, colon):
        raw = [name, None, colon, None, s.keyword("STRUCT")]
        s.semicolons(raw, least=0)
        while s.peek_word() != "END_STRUCT":
            names = self._var1_list(s)
            element = node("structure_element_declaration", [names, s.punct(":"), self._spec_init(s)])
            raw.append(element)
            s.semicolons(raw)
        raw.append(s.keyword("END_STRUCT"))
        return node("structure_type_declaration", raw)

    def _array(self, s):
        """array_specification: `ARRAY [a..b, *, ...] OF` an elementary or named type, a STRING or an
        ARRAY again (an array of arrays nests the specification itself)."""
        raw = [s.keyword("ARRAY"), s.punct("[")]
        while True:
            if s.peek_punct() == "*":
                raw.append(node("full_subrange", [s.punct("*")]))
            else:
                low = self._x.expression(s)
                dots = s.punct("..")
                raw.append(node("subrange", [low, dots, self._x.expression(s)]))
            if s.peek_punct() != ",":
                break
            raw.append(s.punct(","))
        raw += [s.punct("]"), s.keyword("OF")]
        word = s.peek_word()
        if word == "ARRAY":
            raw.append(self._array(s))
        elif word == "STRING":
            raw.append(self._string(s))
        else:
            raw.append(node("non_generic_type_name", [None, self._type_token(s)]))
        return node("array_specification", raw)

    def _array_spec_init(self, s):
        """array_spec_init of an array without an initial value (an array initialiser is blark's)."""
        spec = node("array_spec_init", [None, self._array(s), None])
        if s.peek_punct() == ":=":
            raise Decline("array initialiser")
        return spec

    # Variables

    def _var1_list(self, s):
        raw = []
        while True:
            raw.append(node("var1", [self._x.variable_name(s), None]))
            if s.peek_punct() != ",":
                return node("var1_list", raw)
            raw.append(s.punct(","))

    def _specification(self, s):
        if s.peek_word() == "STRING":
            return node("simple_specification", [self._string(s)])
        return node("simple_specification", [self._type_token(s)])

    def _string(self, s):
        tok = s.word_token("STRING")
        if s.peek_punct() in ("(", "["):
            raise Decline("sized STRING")
        return node("string_type_specification", [tok, None])

    def _type_token(self, s):
        """An elementary type's name as its terminal, or a named type's as IDENTIFIER. Anything else
        (POINTER TO, other date types, dotted names...) is left to blark; ARRAY is _array's."""
        kind = elementary_type(s.peek_word())
        tok = s.word_token(kind) if kind else self._x.name_token(s)
        if s.peek_punct() in ("(", "[", "."):
            raise Decline("type not read here")
        return tok

    def _spec_init(self, s):
        """simple_spec_init, or array_spec_init for an ARRAY."""
        if s.peek_word() == "ARRAY":
            return self._array_spec_init(s)
        raw = [self._specification(s)]
        if s.peek_punct() == ":=":
            raw.append(s.punct(":="))
            if s.peek_punct() in ("(", "["):
                raise Decline("initialiser not read here")
            raw.append(self._x.expression(s))
        else:
            raw.append(None)
        return node("simple_spec_init", raw)

    def _var_decl(self, s):
        names = self._var1_list(s)
        colon = s.punct(":")
        spec = self._spec_init(s)
        rule = "array_var_init_decl" if spec.data == "array_spec_init" else "var1_init_decl"
        return node(rule, [names, colon, spec])

    def _attributes(self, s, rule, kind, words):
        raw = []
        while s.peek_word() in words:
            raw.append(s.word_token(kind))
        return node(rule, raw) if raw else None

    def _var_body(self, s):
        raw = []
        s.semicolons(raw, least=0)
        while s.peek_word() != "END_VAR":
            raw.append(self._var_decl(s))
            s.semicolons(raw)
        return node("var_body", raw)

    def _external_block(self, s):
        raw = [s.keyword("VAR_EXTERNAL"), self._attributes(s, "variable_attributes", "VAR_ATTRIB", _ATTRIBUTES)]
        while s.peek_word() != "END_VAR":
            name, colon = self._identifier(s), s.punct(":")
            spec = self._array(s) if s.peek_word() == "ARRAY" else self._specification(s)
            decl = [name, colon, spec]
            s.semicolons(decl)
            raw.append(node("external_declaration", decl))
        raw.append(s.keyword("END_VAR"))
        if s.peek_punct() == ";":
            raise Decline("; after END_VAR")
        return node("external_var_declarations", raw)

    def _var_block(self, s, in_function):
        word = s.peek_word()
        if word == "VAR_EXTERNAL" and not in_function:
            return self._external_block(s)
        if word == "VAR":
            rule, attrs, body = ("function_var_declarations" if in_function else "var_declarations"), True, True
        elif word in _BLOCKS and not (in_function and word == "VAR_TEMP"):
            rule, attrs, body = _BLOCKS[word]
        else:
            return None
        raw = [s.keyword(word)]
        if attrs:
            raw.append(self._attributes(s, "variable_attributes", "VAR_ATTRIB", _ATTRIBUTES))
        if body:
            raw.append(self._var_body(s))
        else:
            while s.peek_word() != "END_VAR":
                raw.append(self._var_decl(s))
                s.semicolons(raw)
        raw.append(s.keyword("END_VAR"))
        if s.peek_punct() == ";":
            # `END_VAR;` before a body: the `;` may be the block's or an empty statement of the body.
            raise Decline("; after END_VAR")
        return node(rule, raw)

    def _var_blocks(self, s, in_function):
        blocks = []
        while True:
            block = self._var_block(s, in_function)
            if block is None:
                return blocks
            blocks.append(block)

    def _globals(self, s):
        raw = [s.keyword("VAR_GLOBAL"),
               self._attributes(s, "global_variable_attributes", "GLOBAL_VAR_ATTRIB", _ATTRIBUTES | {"INTERNAL"})]
        while s.peek_word() != "END_VAR":
            names = [self._identifier(s)]
            while s.peek_punct() == ",":
                names += [s.punct(","), self._identifier(s)]
            spec = node("global_var_spec", [node("global_var_list", names)])
            decl = [spec, s.punct(":"), self._spec_init(s)]
            s.semicolons(decl)
            raw.append(node("global_var_decl", decl))
        raw.append(s.keyword("END_VAR"))
        _no_trailing_semicolon(s)
        return node("global_var_declarations", raw)

    # POUs

    def _function(self, s):
        raw = [s.keyword("FUNCTION"), None, self._identifier(s), s.punct(":")]
        spec = self._specification(s)
        raw.append(node("indirect_simple_specification", [None, spec, None]))
        _no_trailing_semicolon(s)
        # `[ function_var_block+ ]` leaves no placeholder when absent: its content is an inlined rule.
        raw += self._var_blocks(s, in_function=True)
        raw += [self._st.statement_list(s), s.keyword("END_FUNCTION")]
        _no_trailing_semicolon(s)
        return node("function_declaration", raw)

    def _program(self, s):
        raw = [s.keyword("PROGRAM"), self._identifier(s)]
        blocks = self._var_blocks(s, in_function=False)
        for block in blocks:
            body = block.children[-1] if block.data == "var_declarations" else None
            if body is not None and not body.children:
                # An empty VAR block of a PROGRAM is an incomplete_located_var_declarations to blark.
                raise Decline("empty VAR block in a PROGRAM")
        raw.append(node("program_var_declarations", blocks))
        raw += [self._st.statement_list(s), s.keyword("END_PROGRAM")]
        _no_trailing_semicolon(s)
        return node("program_declaration", raw)

    def _function_block(self, s):
        raw = [s.keyword_token("FUNCTION_BLOCK"), None, self._identifier(s), None, None]
        if s.peek_word() in ("EXTENDS", "IMPLEMENTS"):
            raise Decline("inheritance")
        raw += self._var_blocks(s, in_function=False)
        raw += [self._st.statement_list(s), s.keyword_token("END_FUNCTION_BLOCK")]
        _no_trailing_semicolon(s)
        return node("function_block_type_declaration", raw)


def _no_trailing_semicolon(s):
    """A `;` after the end of a file's element (or after a FUNCTION's header) may belong to it or stand
    alone (an empty element or statement); which, blark's parser decides."""
    if s.peek_punct() == ";":
        raise Decline("; after the end of an element")
