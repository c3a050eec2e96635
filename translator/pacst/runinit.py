"""User mode: initial values TwinCAT and CODESYS compute when the variable is initialised, not when they compile:
a call (`Root : LREAL := SQRT(2.0);`, `Id : DINT := F_NextId(3);`, `Size : UDINT := SIZEOF(F_Name);`), a conversion
of a constant (`Limit : DINT := TO_DINT(MaxCount);`) and a FUNCTION's input (`p : POINTER TO BYTE := pSource;`).

Taken for a VAR of a FUNCTION_BLOCK, PROGRAM, FUNCTION or METHOD: the expression is translated as in the POU's body
and runs where the variable gets its initial value, an FB's when the instance is initialised (before the first
scan), a FUNCTION's and a METHOD's in every call; it reads the variables declared before it. A global list's is
computed when the list is initialised, from literals, named constants and calls (no variables), and a VAR_STAT's
likewise when it gets its initial value. An input's or a struct member's initial value stays one pacst computes when
it translates."""
from .common import _cls
from .errors import StError


def computed(comp, node, want):
    """The TE of `node`, the initial value of the variable being declared, computed when the variable is
    initialised; None where that is not taken (then the caller refuses it). Kept by node: the initial values are
    translated again where the C initialises them, outside the declaration."""
    if id(node) in comp.computed_inits:
        return comp.computed_inits[id(node)]
    pou, section = comp.declaring, comp.declaring_section
    if (pou is None and comp.gvl_declaring is not None or section == "stat") and \
            _cls(node) not in ("String", "WideString"):
        # a global list's: computed in the list's initialisation, before the first scan, from literals, named
        # constants and calls (TcUnit's HundredNanosecondToSecond : LREAL := 1.0 / 10000000.0); a VAR_STAT's
        # likewise where it gets its initial value (FsCommon's F_GetInf: fInf : LREAL := TO_LREAL('#Inf'))
        from .expressions import ExprCompiler
        try:
            te = ExprCompiler(comp, None).expr(node, want)
        except StError:
            return None
        comp.dialect(node, "an initial value computed when the variable is initialised")
        comp.computed_inits[id(node)] = te
        return te
    if pou is None or section != "var" or _cls(node) in ("String", "WideString"):
        return None
    from .body import BodyCompiler  # body imports the compiler's helpers
    try:
        te = BodyCompiler(comp, pou).ex.expr(node, want)
    except StError as e:
        if "undeclared name" not in e.message:
            raise
        raise StError(e.file, e.line, e.col, f"{e.message}: an initial value reads the variables declared before "
                                             "it (TwinCAT initialises in the order of declaration): declare it "
                                             "before, or assign this one in code") from None
    comp.dialect(node, "an initial value computed when the variable is initialised")
    comp.computed_inits[id(node)] = te
    return te
