"""Names an identifier of the library may not take (docs/st_subset.md, "Names")."""

C_KEYWORDS = {
    "AUTO", "BREAK", "CASE", "CHAR", "CONST", "CONTINUE", "DEFAULT", "DO", "DOUBLE", "ELSE", "ENUM",
    "EXTERN", "FLOAT", "FOR", "GOTO", "IF", "INLINE", "INT", "LONG", "REGISTER", "RESTRICT", "RETURN",
    "SHORT", "SIGNED", "SIZEOF", "STATIC", "STRUCT", "SWITCH", "TYPEDEF", "UNION", "UNSIGNED", "VOID",
    "VOLATILE", "WHILE", "BOOL", "CLASS", "NEW", "DELETE", "TEMPLATE", "THIS", "NAMESPACE", "OPERATOR",
}

# Upper-cased, these are macros of the C library or of MATIEC's headers: a member named so breaks the build.
C_MACROS = {
    "NULL", "EOF", "NAN", "INFINITY", "TRUE", "FALSE", "BUFSIZ", "ERRNO", "ASSERT", "STDIN", "STDOUT",
    "STDERR", "INT_MAX", "INT_MIN", "UINT_MAX", "CHAR_BIT", "RAND_MAX", "EXIT_SUCCESS", "EXIT_FAILURE",
    "HUGE_VAL", "FLT_MAX", "DBL_MAX", "M_PI", "SEEK_SET", "SEEK_CUR", "SEEK_END", "FILENAME_MAX",
    "EN", "ENO",
}

STANDARD_FUNCTIONS = {
    "ABS", "SQRT", "LN", "LOG", "EXP", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "ADD", "MUL", "SUB",
    "DIV", "MOD", "EXPT", "MOVE", "SHL", "SHR", "ROR", "ROL", "AND", "OR", "XOR", "NOT", "SEL", "MAX", "MIN",
    "LIMIT", "MUX", "GT", "GE", "EQ", "LE", "LT", "NE", "LEN", "LEFT", "RIGHT", "MID", "CONCAT", "INSERT",
    "REPLACE", "FIND", "TRUNC", "BCD_TO_INT", "INT_TO_BCD",
}

STANDARD_FB_NAMES = {"R_TRIG", "F_TRIG", "TON", "TOF", "TP", "SR", "RS", "CTU", "CTD", "CTUD", "RTC", "SEMA",
                     "PID", "RAMP", "INTEGRAL", "DERIVATIVE", "HYSTERESIS"}

TYPE_NAMES = {"BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "BYTE", "WORD",
              "DWORD", "LWORD", "REAL", "LREAL", "TIME", "LTIME", "STRING", "WSTRING", "DATE", "TOD",
              "DT", "TIME_OF_DAY", "DATE_AND_TIME", "ANY", "ANY_INT", "ANY_REAL", "ANY_NUM", "ANY_BIT"}


# MATIEC's lexer reserves the keywords of every IEC 61131-3 language and of configurations, not only
# ST's, in every context of a POU (measured: tests/conformance/matiec_verdicts/, ident_*.st). Words it reads as
# keywords only where a task or an IL operand may stand (PRIORITY, INTERVAL, SINGLE, Q, PT, IN...) stay free.
IEC_KEYWORDS = {
    "STEP", "END_STEP", "INITIAL_STEP", "TRANSITION", "END_TRANSITION", "ACTION", "END_ACTION", "FROM",
    "CONFIGURATION", "END_CONFIGURATION", "RESOURCE", "END_RESOURCE", "TASK", "ON", "WITH", "PROGRAM",
    "END_PROGRAM", "VAR_ACCESS", "VAR_CONFIG", "VAR_GLOBAL", "VAR_EXTERNAL", "READ_ONLY", "READ_WRITE", "AT",
    "RETAIN", "NON_RETAIN", "CONSTANT", "CONTINUE", "EXIT", "R_EDGE", "F_EDGE", "REF", "REF_TO", "DREF",
    "VOID", "ANY_DERIVED", "ANY_ELEMENTARY", "ANY_MAGNITUDE", "ANY_STRING", "ANY_DATE",
    "SAFEBOOL", "SAFEBYTE", "SAFEWORD", "SAFEDWORD", "SAFELWORD", "SAFESINT", "SAFEINT", "SAFEDINT",
    "SAFELINT", "SAFEUSINT", "SAFEUINT", "SAFEUDINT", "SAFEULINT", "SAFEREAL", "SAFELREAL", "SAFETIME",
    "SAFEDATE", "SAFETOD", "SAFEDT", "SAFETIME_OF_DAY", "SAFEDATE_AND_TIME", "SAFESTRING", "SAFEWSTRING",
}


def reserved_reason(name, user=False, c_name=True):
    """Why `name` may not be declared, or None when it may. A user program (`user`) may take the keywords
    of the other IEC languages (Step, Action...): pacst's C does not mind, only MATIEC's lexer does. A name that
    is never a C name alone (`c_name` False: a user program's enumeration value, E_TYPE__VALUE in C) may be a C
    keyword or macro too."""
    up = name.upper()
    if up in IEC_KEYWORDS and not user:
        return f"'{name}' is a keyword of IEC 61131-3 (SFC, IL or configurations) that MATIEC reserves"
    if up in C_KEYWORDS and c_name:
        return f"'{name}' is a C keyword in the generated code"
    if up in C_MACROS and c_name:
        return f"'{name}' upper-cased is a C macro or a name the generated code uses"
    if up in STANDARD_FUNCTIONS:
        return f"'{name}' is the name of a standard function"
    if up in STANDARD_FB_NAMES:
        return f"'{name}' is the name of a standard function block"
    if up in TYPE_NAMES:
        return f"'{name}' is the name of an elementary type"
    return None
