"""Writes the C that MATIEC's interface prescribes: POUS.h with every type and POU interface, and one
C file per ST file with its POUs' bodies. A file is rewritten only when its text changes, so a build
system recompiles only what a change really touched."""
import os
import shutil
import tempfile

from . import types as T
from . import varlen
from .body import program_instance
from .common import inout_parameter, inouts_by_reference

_HEADER_NAME = "pacst_iec.h"
ENUM_NAMES = "pacst_enum_names.h"
_INCLUDE_DIR = os.path.join(os.path.dirname(__file__), "include")


def _ret(pou):
    return pou.ret.cname if pou.ret is not None else "void"


def _last_member(program, owner):
    """The last METHOD, ACTION or PROPERTY accessor of `owner` in the program (its table follows it)."""
    members = [obj for kind, obj, _ in program.items if kind == "pou" and obj.owner is owner]
    return members[-1] if members else None


def _global_ctype(v):
    """The C type of a global: MATIEC's wrapper, or the FB's own struct for an FB instance (user mode)."""
    return v.type.cname if v.type.is_fb else f"__IEC_{v.type.cname}_t"


def _stem(path):
    return os.path.splitext(os.path.basename(path))[0]


# Stands for the directive that gives the lines after a POU's body back to the generated file; its number
# is known only once the whole file is laid out.
_BACK_TO_C = object()


def _c_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


class Emitter:
    """`line_directives_dir`: the folder the C files go to. Given, every statement of a POU body is preceded
    by `#line` naming its ST line, so that compiler messages, debuggers, sanitizers and gcov show ST
    positions; the rest of the file (declarations, initialisation, entry and exit of a POU) keeps the
    generated file's own lines. The code itself is the same either way."""

    def __init__(self, comp, program, line_directives_dir=None, by_reference=True):
        self.comp = comp
        self.program = program
        self.line_directives_dir = line_directives_dir
        # The header declares each `_body_ref__`: false for the declarations of MATIEC's C, which has none.
        self.by_reference = by_reference

    # ------------------------------------------------------------------ header
    def _member_decl(self, var):
        t = var.type
        if t.is_fb:
            return f"  {t.cname} {var.cname};"
        return f"  __IEC_{t.cname}_t {var.cname};"

    def _type_decl(self, t):
        out = []
        if t.is_enum:
            values = ",\n".join(f"  {t.cvalue(v)}" + (f" = {n}" if t.numbered else "")
                                 for v, n in zip(t.values, t.numbers))
            out.append(f"typedef enum {{\n{values}\n}} {t.cname};")
        elif t.is_array:
            out.append(f"typedef struct {{ {t.elem.cname} table[{t.high - t.low + 1}]; }} {t.cname};")
        elif t.is_struct:
            members = "\n".join(f"  {m.type.cname} {m.cname};" for m in t.members)
            word = "union" if getattr(t, "union", False) else "struct"  # user mode: a UNION's members share memory
            out.append(f"typedef {word} {t.cname} {{\n{members}\n}} {t.cname};")  # tagged: a member may point at it
        elif t.is_pointer and t.target.is_struct:  # user mode: the struct may be incomplete yet (ST_Node.pNext)
            out.append(f"typedef struct {t.target.cname} *{t.cname};")
        elif t.is_pointer:  # user mode: POINTER TO / REFERENCE TO
            out.append(f"typedef {t.target.cname} *{t.cname};")
        elif t.kind == "vla":  # user mode: ARRAY [*], the caller's array's address and bounds
            out.append(varlen.c_declaration(t))
        elif t.kind == "interface":  # user mode: an FB instance's address and the table of its METHODs
            out.append(f"struct {t.cname}__VT;")
            out.append(f"typedef struct {{ void *inst; const struct {t.cname}__VT *vt; }} {t.cname};")
            slots = [f"  {_ret(p)} (*{p.cname})({', '.join(['void *data__'] + self._params(p))});"
                     for p in t.protos.values()]
            slots += [f"  const struct {b.cname}__VT *{b.cname}__BASE;" for b in t.bases]  # INTERFACE EXTENDS
            out.append(f"typedef struct {t.cname}__VT {{\n" + "\n".join(slots or ["  char none;"]) +
                       f"\n}} {t.cname}__VT;")
        out.append(f"typedef struct {{ {t.cname} value; BYTE flags; }} __IEC_{t.cname}_t;")
        out.append(f"static inline void __pacst_init_{t.cname}({t.cname} *v) {{")
        if t.is_enum:
            out.append(f"  *v = {t.cvalue(t.default)};")
        elif t.is_pointer:
            out.append("  *v = NULL;")
        elif t.kind == "vla":
            out.append(f"  *v = {varlen.default_c(t)};")
        elif t.kind == "interface":
            out.append("  v->inst = NULL;")
            out.append("  v->vt = NULL;")
        elif t.is_array:
            out.append(f"  long i;")
            if t.elem.is_fb:  # an array of FB instances (user mode): each initialised as the FB's init does
                out.append("  BOOL retain = FALSE;")
            out.append(f"  for (i = 0; i < {t.high - t.low + 1}; i++) {{")
            out += ["    " + line for line in self.comp.init_code(T.Var("e", "member", t.elem, None, None),
                                                                   "v->table[i]")]
            out.append("  }")
        elif getattr(t, "union", False):  # the memory zeroed: every member reads 0
            out.append("  memset(v, 0, sizeof *v);")
        else:
            for m in t.members:
                out += ["  " + line for line in self.comp.init_code(m, f"v->{m.cname}")]
        out.append("}")
        if t.is_struct:  # the value an omitted struct input of a FUNCTION takes
            out.append(f"static inline {t.cname} __pacst_default_{t.cname}(void) {{")
            out.append(f"  {t.cname} v;")
            out.append(f"  __pacst_init_{t.cname}(&v);")
            out.append("  return v;")
            out.append("}")
        return out

    def _pou_decl(self, pou):
        what = "PROGRAM" if pou.program else "FUNCTION_BLOCK" if pou.kind == "fb" else \
            "FUNCTION (native: the host defines it)" if pou.native else "FUNCTION"
        out = [f"/* {what} {pou.name} ({pou.file}) */"]
        if pou.kind == "fb":
            out.append("typedef struct {")
            out.append("  /* FB interface: EN, ENO, inputs, outputs and in-outs in declaration order */")
            out.append("  __IEC_BOOL_t EN;")
            out.append("  __IEC_BOOL_t ENO;")
            interface = [v for v in pou.vars if v.section in ("input", "output", "inout")]
            private = [v for v in pou.vars if v.section not in ("input", "output", "inout")]
            out += [self._member_decl(v) for v in interface]
            out.append("  /* private variables */")
            out += [self._member_decl(v) for v in private]
            out.append(f"}} {pou.cname};")
            out.append(f"void {pou.cname}_init__({pou.cname} *data__, BOOL retain);")
            out.append(f"void {pou.cname}_body__({pou.cname} *data__);")
            if inouts_by_reference(pou) and self.by_reference:
                out.append(f"void {pou.cname}_body_ref__({self._body_ref_params(pou)});")
            if pou.program:  # its one instance, which the host runs and other POUs may read (MAIN.x)
                out.append(f"extern {pou.cname} {program_instance(pou)};")
            out += [f"extern const {t.cname}__VT {t.vtable(pou.cname)};" for t in pou.interfaces]
            out += [f"extern __IEC_{v.type.cname}_t {v.csym};" for v in pou.statics]  # VAR_STAT
        else:
            out.append(self._function_signature(pou) + ";")
        return out

    @staticmethod
    def _body_ref_params(pou):
        """The C parameters of an FB's body that works on its VAR_IN_OUTs through their addresses."""
        return ", ".join([f"{pou.cname} *data__"] +
                         [f"{v.type.cname} *{inout_parameter(v)}" for v in inouts_by_reference(pou)])

    @staticmethod
    def _params(pou):
        """EN, ENO and the pins of a FUNCTION or METHOD as C parameters."""
        params = ["BOOL EN", "BOOL *__ENO"]
        for v in pou.vars:
            if v.section == "input":
                params.append(f"{v.type.cname} {v.cname}")
            elif v.section in ("output", "inout"):
                params.append(f"{v.type.cname} *{v.cname}")
        return params

    def _function_signature(self, pou):
        # A native FUNCTION is given the ST file and line of each call (docs/translator.md, "User programs").
        params = (["const char *file__", "int line__"] if pou.native else []) + self._params(pou)
        if pou.owner is not None:  # a METHOD or ACTION (user mode) works on its FB's instance
            params.insert(0, f"{pou.owner.cname} *data__")
        return f"{_ret(pou)} {pou.cfunc}({', '.join(params)})"

    def _vtables(self, pou):
        """Each INTERFACE's table of this FB's METHODs (user mode), through a function per METHOD that takes
        the instance as `void *`."""
        out = []
        for t in pou.interfaces:
            names = []
            for p in t.protos.values():
                m = pou.methods[p.cname] if p.accessor is None else pou.properties[p.name.upper()][p.accessor]
                thunk = f"{pou.cname}__{t.cname}__{p.cname}"
                pins = [v.cname for v in m.vars if v.section in ("input", "output", "inout")]
                call = f"{m.cfunc}(({pou.cname} *)data__, {', '.join(['EN', '__ENO'] + pins)})"
                out += [f"static {_ret(m)} {thunk}({', '.join(['void *data__'] + self._params(m))}) {{",
                        f"  {'return ' if m.ret is not None else ''}{call};", "}"]
                names.append(thunk)
            names += [f"&{b.vtable(pou.cname)}" for b in t.bases]
            out += [f"const {t.cname}__VT {t.vtable(pou.cname)} = {{{', '.join(names) or '0'}}};", ""]
        return out

    def _gvl_decl(self, gvl):
        out = [f"/* global variable list {gvl.name} ({gvl.file}) */"]
        out += [f"extern {_global_ctype(v)} {v.csym};" for v in gvl.vars]
        out.append(f"void {gvl.cname}__init__(void);")
        return out

    def _gvl_code(self, gvl):
        out = [f"{_global_ctype(v)} {v.csym};" for v in gvl.vars]
        out += ["", f"void {gvl.cname}__init__(void) {{", "  BOOL retain = FALSE;", "  (void)retain;"]
        for v in gvl.vars:
            if v.type.is_fb:  # an FB instance (user mode) is no wrapper
                out += ["  " + line for line in self.comp.init_code(v, v.csym)]
                continue
            out.append(f"  {v.csym}.flags = 0;")
            out += ["  " + line for line in self.comp.init_code(v, f"{v.csym}.value")]
        return out + ["}", ""]

    def _decl(self, kind, obj, emitted):
        """POUS.h's lines of one declared item; an inline array type shared by several is declared once."""
        if kind == "gvl":
            return self._gvl_decl(obj)
        if kind == "pou":
            return self._pou_decl(obj)
        if obj.cname in emitted:
            return []
        emitted.add(obj.cname)
        return self._type_decl(obj)

    def header(self, files):
        out = ["/* Generated by pacst from " + ", ".join(os.path.basename(f) for f in files) + ". Do not edit. */",
               "#ifndef __POUS_H", "#define __POUS_H", "", f'#include "{_HEADER_NAME}"', ""]
        if self.by_reference:  # C code may call <FB>_body_ref__ (pacst's C; MATIEC's has no such function)
            out += ["#define PACST_BODY_REF 1", ""]
        out += ["#ifdef __cplusplus", 'extern "C" {', "#endif", ""]
        emitted = set()
        # The globals last: their types may come from any file (a list declares no FB instances).
        items = [i for i in self.program.items if i[0] != "gvl"] + [i for i in self.program.items if i[0] == "gvl"]
        for kind, obj, _ in items:
            out += self._decl(kind, obj, emitted)
            out.append("")
        out += ["#ifdef __cplusplus", "}", ""]
        out += self._body_ref_overloads()
        out += ["#endif", "", "#endif /* __POUS_H */", ""]
        return "\n".join(out)

    def _body_ref_overloads(self):
        """For C++ callers: `pacst::BodyRef(&fb, &inout, ...)` runs `<FB>_body_ref__` whatever the FB's type, so that
        a template (the test rig's) can pass its own variable to an FB's VAR_IN_OUT instead of copying it into the
        member and back."""
        if not self.by_reference:
            return []
        pous = [obj for kind, obj, _ in self.program.items if kind == "pou" and inouts_by_reference(obj)]
        if not pous:
            return []
        out = ['extern "C++" {  // also where POUS.h is included inside extern "C" (pac/st_program.hpp)', "namespace pacst {"]
        for pou in pous:
            args = ", ".join(["data__"] + [inout_parameter(v) for v in inouts_by_reference(pou)])
            out.append(f"inline void BodyRef({self._body_ref_params(pou)}) {{ {pou.cname}_body_ref__({args}); }}")
        return out + ["}  // namespace pacst", "}", ""]

    # ------------------------------------------------------------------ bodies
    def _fb_code(self, pou):
        out = [f"{pou.cname} {program_instance(pou)};", ""] if pou.program else []
        out += [f"__IEC_{v.type.cname}_t {v.csym};" for v in pou.statics]
        out += [f"void {pou.cname}_init__({pou.cname} *data__, BOOL retain) {{",
               "  (void)retain;",
               "  data__->EN.value = TRUE;",
               "  data__->ENO.value = TRUE;"]
        for v in pou.statics:
            out += ["  " + line for line in self.comp.init_code(v, f"{v.csym}.value")]
        for v in pou.vars:
            target = f"data__->{v.cname}" if v.type.is_fb else f"data__->{v.cname}.value"
            out += ["  " + line for line in self.comp.init_code(v, target)]
        out.append("}")
        out.append("")
        by_reference = inouts_by_reference(pou)
        # The body of an FB that one ST call runs (a part of another FB) goes into that call where the compiler
        # sees both (one C unit): no entry, exit and argument passing in every scan. It stays a function of
        # the C interface too.
        inline = "PACST_INLINE_ONCE " if self.comp.fb_call_sites.get(pou.cname, 0) == 1 and not pou.program else ""
        if by_reference:  # the body works on the caller's variables; from C, on the members
            addresses = ", ".join(f"&data__->{v.cname}.value" for v in by_reference)
            out += [f"void {pou.cname}_body__({pou.cname} *data__) {{",
                    f"  {pou.cname}_body_ref__(data__, {addresses});", "}", ""]
            out.append(f"{inline}void {pou.cname}_body_ref__({self._body_ref_params(pou)}) {{")
        else:
            out.append(f"{inline}void {pou.cname}_body__({pou.cname} *data__) {{")
        out.append("  if (!data__->EN.value) {")
        out.append("    data__->ENO.value = FALSE;")
        out.append("    return;")
        out.append("  }")
        out.append("  data__->ENO.value = TRUE;")
        for v in pou.vars:
            if v.section == "temp":  # VAR_TEMP starts from its initial value in every call
                out += ["  " + line for line in self.comp.init_code(v, f"data__->{v.cname}.value")]
        out += self._body(pou)
        out += ["  goto __end;", "__end:", "  return;", "}", ""]
        return out

    def _function_statics(self, pou):
        """A FUNCTION's VAR_STAT (user mode): C variables of its file, and the lines that give them their initial
        values in its first call (TwinCAT gives them before the first scan: no other POU sees them before)."""
        if not pou.statics or pou.owner is not None:
            return [], []
        first = f"{pou.cname}__STAT__INITIALISED"
        out = [f"static __IEC_{v.type.cname}_t {v.csym};" for v in pou.statics] + [f"static BOOL {first};"]
        init = [f"  if (!{first}) {{", f"    {first} = TRUE;"]
        for v in pou.statics:
            init += ["    " + line for line in self.comp.init_code(v, f"{v.csym}.value")]
        return out, init + ["  }"]

    def _function_code(self, pou):
        if pou.ret is None:  # a METHOD or ACTION without a result (user mode)
            return self._procedure_code(pou)
        statics, init = self._function_statics(pou)
        out = statics + [self._function_signature(pou) + " {",
                         "  BOOL ENO = TRUE;",
                         f"  {pou.ret.cname} {pou.cname};"] + init
        for v in pou.vars:
            if v.section == "var":
                out.append(self._local(v))
        out += ["  " + line for line in self.comp.init_code(T.Var(pou.name, "result", pou.ret, None, None),
                                                             pou.cname)]
        for v in pou.vars:
            if v.section == "var":  # an FB instance of a METHOD's VAR: initialised in every call (user mode)
                out += ["  " + line.replace(", retain);", ", FALSE);") for line in self.comp.init_code(v, v.cname)]
        out += ["  if (!EN) {", "    if (__ENO != NULL) *__ENO = FALSE;", f"    return {pou.cname};", "  }"]
        # A FUNCTION's outputs are local to the call (IEC): they start from their initial value in every
        # call, and one left unassigned gives that value to the caller, as MATIEC's copy-out does.
        for v in pou.vars:
            if v.section == "output":
                out += ["  " + line for line in self.comp.init_code(v, f"(*{v.cname})")]
        out += self._body(pou)
        out += ["  goto __end;", "__end:", "  if (__ENO != NULL) *__ENO = ENO;", f"  return {pou.cname};", "}", ""]
        return out

    def _local(self, v):
        """The C declaration of a FUNCTION's or METHOD's VAR; in user mode one of a compound type (an FB instance
        in a METHOD) starts all zero, the flags of its IEC variables (forcing) too, before its init."""
        compound = v.type.is_fb or v.type.is_struct or v.type.is_array
        return f"  {v.type.cname} {v.cname}{' = {0}' if self.comp.user and compound else ''};"

    def _procedure_code(self, pou):
        statics, init = self._function_statics(pou)
        out = statics + [self._function_signature(pou) + " {", "  BOOL ENO = TRUE;"] + init
        for v in pou.vars:
            if v.section == "var":
                out.append(self._local(v))
        for v in pou.vars:
            if v.section == "var":  # an FB instance of a METHOD's VAR: initialised in every call (user mode)
                out += ["  " + line.replace(", retain);", ", FALSE);") for line in self.comp.init_code(v, v.cname)]
        out += ["  if (!EN) {", "    if (__ENO != NULL) *__ENO = FALSE;", "    return;", "  }"]
        for v in pou.vars:
            if v.section == "output":
                out += ["  " + line for line in self.comp.init_code(v, f"(*{v.cname})")]
        out += self._body(pou)
        return out + ["  goto __end;", "__end:", "  if (__ENO != NULL) *__ENO = ENO;", "}", ""]

    def _body(self, pou):
        """The body's lines; with line directives, each preceded by `#line` where the ST line does not simply
        follow from the one before."""
        if self.line_directives_dir is None:
            return list(pou.body_c)
        out = []
        st_file = _c_string(os.path.abspath(pou.file))
        next_line = None  # the ST line the compiler gives the next line of C
        for line in pou.body_c:
            if line.st_line != next_line:
                out.append(f"#line {line.st_line} {st_file}")
            out.append(line)
            next_line = line.st_line + 1
        return out + [_BACK_TO_C]

    def source(self, path):
        out = [f"{GENERATED_C}{os.path.basename(path)}. Do not edit. */", '#include "POUS.h"', ""]
        for kind, obj, file in self.program.items:
            if kind == "gvl" and file == path:
                out += self._gvl_code(obj)
            elif kind == "pou" and file == path and not obj.native:
                out += self._fb_code(obj) if obj.kind == "fb" else self._function_code(obj)
                if obj.owner is not None and obj is _last_member(self.program, obj.owner):
                    out += self._vtables(obj.owner)  # after the FB's METHODs
                elif obj.kind == "fb" and obj.interfaces and not obj.methods:
                    out += self._vtables(obj)
        if self.line_directives_dir is not None:
            c_file = _c_string(os.path.abspath(os.path.join(self.line_directives_dir, _stem(path) + ".c")))
            # The directive is on line i + 1, so the line after it is line i + 2 of the file.
            out = [f"#line {i + 2} {c_file}" if line is _BACK_TO_C else line for i, line in enumerate(out)]
        return "\n".join(out)

    def enum_names(self):
        """pacst_enum_names.h: every enumeration's value names in order, for C and C++ code that prints or
        reads them (the scenario program, test messages)."""
        out = ["/* Generated by pacst: the value names of every enumeration, in declaration order. Do not edit. */",
               "#ifndef PACST_ENUM_NAMES_H", "#define PACST_ENUM_NAMES_H", ""]
        for kind, obj, _ in self.program.items:
            if kind == "type" and obj.is_enum:
                names = ", ".join(f'"{v}"' for v in obj.values)
                out.append(f"static const char *const {obj.cname}__NAMES[] = {{{names}}};")
                out.append(f"#define {obj.cname}__COUNT {len(obj.values)}")
        out += ["", "#endif /* PACST_ENUM_NAMES_H */", ""]
        return "\n".join(out)

    def outputs(self, files):
        """{file name: text} of everything a build writes."""
        result = {"POUS.h": self.header(files), ENUM_NAMES: self.enum_names()}
        with open(os.path.join(_INCLUDE_DIR, _HEADER_NAME), encoding="utf-8") as f:
            result[_HEADER_NAME] = f.read()
        for path in files:
            if path not in self.comp.native_files:
                result[_stem(path) + ".c"] = self.source(path)
        return result


def write_outputs(out_dir, outputs):
    """Write each file atomically, and only when its text changed; returns the names rewritten."""
    os.makedirs(out_dir, exist_ok=True)
    written = []
    for name, text in outputs.items():
        path = os.path.join(out_dir, name)
        try:
            with open(path, encoding="utf-8") as f:
                if f.read() == text:
                    continue
        except OSError:
            pass
        fd, tmp = tempfile.mkstemp(dir=out_dir, suffix=".tmp")
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, path)
        written.append(name)
    return written


GENERATED_C = "/* Generated by pacst from "


def remove_stale_c(out_dir, outputs):
    """User mode's folder is pacst's own: a C file an earlier run wrote for an ST file no longer given (renamed,
    deleted) would be compiled with this run's files and define its POUs twice."""
    for name in os.listdir(out_dir):
        if not name.endswith(".c") or name in outputs:
            continue
        path = os.path.join(out_dir, name)
        with open(path, encoding="utf-8", errors="replace") as f:
            if f.readline().startswith(GENERATED_C):
                os.remove(path)


def remove_outputs(out_dir, names):
    """After a refusal nothing generated may stay behind, so that no stale C is ever compiled."""
    for name in names:
        path = os.path.join(out_dir, name)
        if os.path.isdir(path):
            shutil.rmtree(path)
        elif os.path.exists(path):
            os.remove(path)
