"""POUs, types and variable blocks: the top level of a file, in blark's shapes, with the TwinCAT 3 / CODESYS
elements (METHOD, PROPERTY, INTERFACE, EXTENDS and IMPLEMENTS, VAR_STAT and VAR_INST)."""
import re

from lark import Token

from .scanner import ARGUMENTS, DATE_AND_TIME, INITIAL_VALUE, LOCATED, STRING_TYPE, UNION, Decline, node
from .vocabulary import BIT_STRING_TYPES, INTEGER_TYPES, OTHER_DATE_TYPES, elementary_type

_ATTRIBUTES = frozenset(("RETAIN", "NON_RETAIN", "PERSISTENT", "CONSTANT"))
_ACCESS = frozenset(("ABSTRACT", "PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL", "FINAL"))
# blark's POINTER_TO and REFERENCE_TO: one terminal each, the space between the words part of its text
_POINTER_TO = re.compile(r"POINTER\s+TO\b", re.I)
_REFERENCE_TO = re.compile(r"REFERENCE\s+TO\b", re.I)
# Variable blocks: the rule of each, whether it has attributes, and whether its declarations sit in a
# var_body (else directly in the block, as VAR_INPUT's do).
_BLOCKS = {
    "VAR_INPUT": ("input_declarations", True, False),
    "VAR_OUTPUT": ("output_declarations", True, True),
    "VAR_IN_OUT": ("input_output_declarations", True, True),
    "VAR_TEMP": ("temp_var_decls", False, True),
    "VAR_STAT": ("static_var_declarations", True, True),
    "VAR_INST": ("var_inst_declaration", True, True),
}
# The variable blocks each kind of element may hold (blark's function_var_block, fb_var_declaration,
# program_var_declaration, method_var_declaration and interface_var_declaration); the others are declined.
_BLOCK_WORDS = {
    "function": frozenset(("VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_STAT")),
    "block": frozenset(("VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_STAT", "VAR_INST",
                        "VAR_EXTERNAL")),
    "program": frozenset(("VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_STAT", "VAR_EXTERNAL")),
    "interface": frozenset(("VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_EXTERNAL")),
}


class Declarations:
    """Reads a whole file over `statements` and `expressions`."""

    def __init__(self, expressions, statements):
        self._x = expressions
        self._st = statements
        self._top = {"TYPE": self._type, "FUNCTION": self._function,
                     "FUNCTION_BLOCK": self._function_block, "VAR_GLOBAL": self._globals,
                     "PROGRAM": self._program, "METHOD": self._method, "PROPERTY": self._property,
                     "INTERFACE": self._interface, "ACTION": self._action}

    def elements(self):
        """The start rule of each element read alone: its first keyword and its reader."""
        return {"data_type_declaration": ("TYPE", self._type),
                "function_declaration": ("FUNCTION", self._function),
                "function_block_type_declaration": ("FUNCTION_BLOCK", self._function_block),
                "program_declaration": ("PROGRAM", self._program),
                "function_block_method_declaration": ("METHOD", self._method),
                "function_block_property_declaration": ("PROPERTY", self._property),
                "interface_declaration": ("INTERFACE", self._interface),
                "action": ("ACTION", self._action)}

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
        extends = self._names(s, "EXTENDS", "extends")
        colon = s.punct(":")
        word = s.peek_word()
        if word == "STRUCT":
            return self._structure(s, name, extends, colon)
        if extends is not None:
            raise Decline("EXTENDS of a type other than a STRUCT")
        if s.peek_punct() == "(":
            return node("enumerated_type_declaration", [name, colon, self._enumeration(s)])
        if word == "ARRAY":
            return node("array_type_declaration", [name, colon, self._array_spec_init(s)])
        if word == "UNION":
            raise Decline(UNION)
        if word in ("STRING", "WSTRING"):
            raise Decline(STRING_TYPE)
        if word is not None and word not in ("STRING", "WSTRING", "POINTER", "REFERENCE"):
            # an alias of a named or elementary type; a STRING is a string_type_declaration to blark
            spec = self._spec_init(s)
            if spec.data == "simple_spec_init" and spec.children[-1] is None:
                return node("simple_type_declaration", [name, None, colon, spec])
        raise Decline("type declaration not read here")

    def _enumeration(self, s):
        """An enumeration type's values, each with its number or not, its base type (`) DINT`) and its default."""
        raw = [s.punct("(")]
        while True:
            value = [None, self._x.name_token(s, "DOTTED_IDENTIFIER")]
            if s.peek_punct() == ":=":
                value.append(s.punct(":="))
                if not (s.peek_char().isdigit() or s.peek_char() == "-" and s.peek_char(1).isdigit()):
                    raise Decline("enumeration value not a number")
                value.append(self._x.integer_value(s))
            else:
                value.append(None)
            raw.append(node("enumerated_value", value))
            if s.peek_punct() != ",":
                break
            raw.append(s.punct(","))
        raw.append(s.punct(")"))
        word = s.peek_word()
        raw.append(s.word_token("ENUM_DATA_TYPE_NAME") if word in INTEGER_TYPES or word in BIT_STRING_TYPES else None)
        spec = [None, node("enumerated_specification", raw)]
        if s.peek_punct() == ":=":
            spec += [s.punct(":="), node("enumerated_value", [None, self._x.dotted_name_token(s), None])]
        else:
            spec.append(None)
        if s.peek_word() is not None or s.peek_punct() in (":=", ".", "#"):
            raise Decline("enumeration not read here")
        return node("enumerated_spec_init", spec)

    def _structure(self, s, name, extends, colon):
        raw = [name, extends, colon, None, s.keyword("STRUCT")]
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
            pointers = self._indirection(s, "pointer_type")
            if pointers is not None and s.peek_word() in ("ARRAY", "STRING", "WSTRING"):
                raise Decline("pointer to an array or a STRING as an array's element")
            raw.append(node("non_generic_type_name", [pointers, self._type_token(s)]))
        return node("array_specification", raw)

    def _indirection(self, s, rule="indirection_type"):
        """indirection_type (`REFERENCE TO`, `POINTER TO` once or more, or both) or pointer_type (`POINTER TO`s
        alone), or None when the position holds none."""
        raw = []
        m = _REFERENCE_TO.match(s.text, s.pos)
        if m and rule == "indirection_type":
            raw.append(s.token_to("REFERENCE_TO", m.end()))
        while True:
            m = _POINTER_TO.match(s.text, s.pos)
            if not m:
                break
            raw.append(s.token_to("POINTER_TO", m.end()))
        if s.peek_word() in ("POINTER", "REFERENCE"):
            raise Decline("indirection not read here")
        return node(rule, raw) if raw else None

    def _array_spec_init(self, s, indirection=None):
        """array_spec_init of an array without an initial value (an array initialiser is blark's)."""
        spec = node("array_spec_init", [indirection, self._array(s), None])
        if s.peek_punct() == ":=":
            raise Decline(INITIAL_VALUE)
        return spec

    # Variables

    def _var1_list(self, s):
        raw = []
        while True:
            raw.append(node("var1", [self._x.variable_name(s), None]))
            if s.peek_word() == "AT":
                raise Decline(LOCATED)
            if s.peek_punct() != ",":
                return node("var1_list", raw)
            raw.append(s.punct(","))

    def _specification(self, s):
        if s.peek_word() in ("STRING", "WSTRING"):
            return node("simple_specification", [self._string(s)])
        return node("simple_specification", [self._type_token(s)])

    def _string(self, s):
        """A STRING or WSTRING, with its length in `()` or `[]` or without."""
        word = s.peek_word()
        tok = s.word_token(word)
        p = s.peek_punct()
        if p not in ("(", "["):
            return node("string_type_specification", [tok, None])
        close, rule = (")", "parenthesized_expression") if p == "(" else ("]", "bracketed_expression")
        length = node(rule, [s.punct(p), self._x.expression(s), s.punct(close)])
        return node("string_type_specification", [tok, node("string_spec_length", [length])])

    def _type_token(self, s):
        """An elementary type's name as its terminal, a named type's as IDENTIFIER, a qualified one
        (`PA_CONTROL.MC_Power`) as DOTTED_IDENTIFIER. Anything else (other date types, a subrange, an FB
        instance's arguments...) is left to blark; ARRAY is _array's."""
        word = s.peek_word()
        kind = elementary_type(word)
        if word in OTHER_DATE_TYPES:
            raise Decline(DATE_AND_TIME)
        if kind:
            tok = s.word_token(kind)
        elif s.peek_char(len(s.peek_word() or "")) == ".":
            tok = self._x.dotted_name_token(s)
        else:
            tok = self._x.name_token(s)
        if s.peek_punct() == "(":
            raise Decline(ARGUMENTS)
        if s.peek_punct() in ("[", "."):
            raise Decline("type not read here")
        return tok

    def _spec_init(self, s):
        """simple_spec_init, or array_spec_init for an ARRAY, either after an indirection (`POINTER TO`)."""
        indirection = self._indirection(s)
        if s.peek_word() == "ARRAY":
            return self._array_spec_init(s, indirection)
        if indirection is None:
            raw = [self._specification(s)]
        else:
            spec = self._specification(s)
            if _sized(spec):
                raise Decline("sized STRING after an indirection")  # its length could be input_param_args
            raw = [node("indirect_simple_specification", [indirection, spec, None])]
        if s.peek_punct() == ":=":
            raw.append(s.punct(":="))
            if s.peek_punct() == "[" or s.peek_punct() == "(" and not _elementary(raw[0]):
                # an array's or a structure's initial value, which Earley reads in more ways than one
                raise Decline(INITIAL_VALUE)
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

    def _var_block(self, s, kind):
        """The variable block at the position, of those an element of `kind` (_BLOCK_WORDS) holds, or None."""
        word = s.peek_word()
        if word not in _BLOCK_WORDS[kind]:
            return None
        if word == "VAR_EXTERNAL":
            return self._external_block(s)
        if word == "VAR":
            rule, attrs, body = ("function_var_declarations" if kind == "function" else "var_declarations"), True, True
        else:
            rule, attrs, body = _BLOCKS[word]
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

    def _var_blocks(self, s, kind):
        blocks = []
        while True:
            block = self._var_block(s, kind)
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
            if s.peek_word() == "AT":
                raise Decline(LOCATED)
            spec = node("global_var_spec", [node("global_var_list", names)])
            decl = [spec, s.punct(":"), self._spec_init(s)]
            s.semicolons(decl)
            raw.append(node("global_var_decl", decl))
        raw.append(s.keyword("END_VAR"))
        _no_trailing_semicolon(s)
        return node("global_var_declarations", raw)

    # POUs

    def _function(self, s):
        raw = [s.keyword("FUNCTION"), None, self._identifier(s)]
        if s.peek_punct() != ":":
            # no result type (a FUNCTION that writes its VAR_IN_OUT)
            return self._pou(s, raw + [None], "function", "END_FUNCTION", "function_declaration")
        raw.append(s.punct(":"))
        indirection = self._indirection(s)
        spec = self._specification(s)
        if _sized(spec):
            # `: STRING(80)`: Earley reads the length as the arguments (input_param_args) of the result type
            raise Decline("sized STRING as a FUNCTION's result")
        raw.append(node("indirect_simple_specification", [indirection, spec, None]))
        return self._pou(s, raw, "function", "END_FUNCTION", "function_declaration")

    def _pou(self, s, raw, kind, end, rule):
        """Tree `rule` of a POU whose heading is in `raw`: its variable blocks of `kind`, its body and `end`.
        (`[ function_var_block+ ]` leaves no placeholder when absent: its content is an inlined rule.)"""
        _no_trailing_semicolon(s)
        raw += self._blocks(s, kind)
        body = self._st.statement_list(s)
        raw += [body, s.keyword_token(end) if end == "END_FUNCTION_BLOCK" else s.keyword(end)]
        _no_trailing_semicolon(s)
        return node(rule, raw)

    def _program(self, s):
        raw = [s.keyword("PROGRAM"), self._identifier(s)]
        blocks = self._var_blocks(s, "program")
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
        raw = [s.keyword_token("FUNCTION_BLOCK"), self._access(s), self._identifier(s),
               self._names(s, "EXTENDS", "extends"), self._names(s, "IMPLEMENTS", "implements")]
        return self._pou(s, raw, "block", "END_FUNCTION_BLOCK", "function_block_type_declaration")

    def _access(self, s):
        """access_specifier (PUBLIC, ABSTRACT, ...), or None."""
        return self._attributes(s, "access_specifier", "ACCESS_SPECIFIER", _ACCESS)

    def _names(self, s, word, rule):
        """extends or implements: `word` and the (qualified) names after it, or None."""
        if s.peek_word() != word:
            return None
        raw = [s.keyword(word), self._x.dotted_name_token(s)]
        while s.peek_punct() == ",":
            raw += [s.punct(","), self._x.dotted_name_token(s)]
        return node(rule, raw)

    def _blocks(self, s, kind):
        """The variable blocks of a POU of `kind`. An empty VAR block of an INTERFACE could be another rule of
        blark's: declined (a METHOD's and a PROPERTY's are var_declarations, as a FUNCTION_BLOCK's)."""
        blocks = self._var_blocks(s, kind)
        if kind == "interface" and any(b.data == "var_declarations" and not b.children[-1].children for b in blocks):
            raise Decline("empty VAR block")
        return blocks

    def _method(self, s):
        """A METHOD: after its FUNCTION_BLOCK in a file, or alone in a TwinCAT file's form."""
        raw = [s.keyword("METHOD"), self._access(s), self._x.dotted_name_token(s), self._result(s)]
        return self._pou(s, raw, "block", "END_METHOD", "function_block_method_declaration")

    def _result(self, s):
        """The type after `:` of a METHOD or PROPERTY (an array's or a simple one), or None."""
        if s.peek_punct() != ":":
            return None
        s.punct(":")
        spec = self._spec_init(s)
        if spec.data == "simple_spec_init" and spec.children[-1] is not None:
            raise Decline("initial value of a result")
        return spec

    def _property(self, s):
        raw = [s.keyword("PROPERTY"), self._access(s), self._x.dotted_name_token(s), self._result(s), self._access(s)]
        return self._pou(s, raw, "block", "END_PROPERTY", "function_block_property_declaration")

    def _action(self, s):
        """An ACTION of a FUNCTION_BLOCK: `ACTION Name :` or `ACTION FB_X.Name :`, a body, END_ACTION."""
        raw = [s.keyword("ACTION"), self._x.dotted_name_token(s), s.punct(":"), self._st.statement_list(s),
               s.keyword("END_ACTION")]
        _no_trailing_semicolon(s)
        return node("action", raw)

    def _interface(self, s):
        raw = [s.keyword("INTERFACE"), self._identifier(s), self._names(s, "EXTENDS", "extends")]
        _no_trailing_semicolon(s)
        raw += self._blocks(s, "interface")
        raw.append(s.keyword("END_INTERFACE"))
        _no_trailing_semicolon(s)
        return node("interface_declaration", raw)


def _elementary(spec):
    """Whether the simple_specification `spec` is an elementary type's name (whose initial value in `()` is an
    expression, not a structure's)."""
    inner = spec.children[0]
    return inner.__class__ is Token and inner.type in ("NUMERIC_TYPE_NAME", "BIT_STRING_TYPE_NAME", "DATE_TYPE_NAME")


def _sized(spec):
    """Whether the simple_specification `spec` is a STRING or WSTRING with its length."""
    inner = spec.children[0]
    return inner.__class__ is not Token and inner.data == "string_type_specification" and inner.children[1] is not None


def _no_trailing_semicolon(s):
    """A `;` after the end of a file's element (or after a FUNCTION's header) may belong to it or stand
    alone (an empty element or statement); which, blark's parser decides."""
    if s.peek_punct() == ";":
        raise Decline("; after the end of an element")
