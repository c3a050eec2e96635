"""check_kept_library.py REPO: a program translated in user mode against a kept library's checked state (the copy
pacst gives each program after the first with the same library in one process, cli.checked_library) gets what a
translation from scratch gets: every refusal, every dialect use and every C file with its #line mapping. The
library here has a dialect use of its own (an StError), carried over in the copy; the programs are
one that translates, one that is refused and one that extends and calls the library's FBs."""
import argparse
import os
import sys
import tempfile

LIBRARY = {
    # a dialect use (the ';' after the heading) and an FB that programs extend and call
    "FB_Counter.st": "FUNCTION_BLOCK FB_Counter;\nVAR_INPUT\n  Step : INT := 1;\nEND_VAR\nVAR_OUTPUT\n"
                     "  Count : INT;\nEND_VAR\nCount := Count + Step;\nEND_FUNCTION_BLOCK\n",
    "E_Mode.st": "TYPE E_Mode : (MODE_IDLE, MODE_RUN);\nEND_TYPE\n",
    "GVL_Lib.st": "VAR_GLOBAL CONSTANT\n  LIB_LIMIT : INT := 10;\nEND_VAR\n",
}
PROGRAMS = {
    "Prg_Uses.st": "PROGRAM Prg_Uses\nVAR\n  C : Lib.FB_Counter;\n  M : Lib.E_Mode := MODE_RUN;\nEND_VAR\n"
                   "C(Step := Lib.GVL_Lib.LIB_LIMIT);\nEND_PROGRAM\n",
    "Prg_Refused.st": "PROGRAM Prg_Refused\nVAR\n  C : FB_Counter;\n  X : BOOL;\nEND_VAR\nX := C;\n"
                      "C(Step := 'text');\nEND_PROGRAM\n",
    # an FB of the library extended, and an instance of the library's copied (the C of an FB copy)
    "Prg_Extends.st": "FUNCTION_BLOCK FB_Twice EXTENDS Lib.FB_Counter\nSUPER^();\nSUPER^();\nEND_FUNCTION_BLOCK\n"
                      "PROGRAM Prg_Extends\nVAR\n  T : FB_Twice;\n  C : FB_Counter;\n  Copy : FB_Counter;\nEND_VAR\n"
                      "T(Step := 2);\nC();\nCopy := C;\nEND_PROGRAM\n",
}


def main(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("repo")
    args = parser.parse_args(argv)
    sys.path.insert(0, os.path.join(args.repo, "translator"))
    from pacst import cli  # noqa: E402
    from pacst.emit import Emitter  # noqa: E402
    from pacst.errors import StErrors  # noqa: E402
    from pacst.parsing import parse_files  # noqa: E402

    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        lib_dir = os.path.join(tmp, "Lib")
        os.makedirs(lib_dir)
        for folder, files in ((lib_dir, LIBRARY), (tmp, PROGRAMS)):
            for name, text in files.items():
                with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
                    f.write(text)
        namespaces = {"Lib": ("Lib", lib_dir)}
        library = parse_files([os.path.join(lib_dir, n) for n in sorted(LIBRARY)], None, 1, True)

        def translate(program):
            """(the refusals, the dialect uses, {output: text}) of the library with `program`, as strings."""
            sources = library + program
            try:
                comp, prog, _ = cli._translate_parsed(sources, [], True, (), namespaces)
            except StErrors as e:
                return [str(err) for err in e.errors], [], {}
            files = [src.path for src in sources]
            return [], sorted(str(e) for e in comp.dialect_uses), Emitter(comp, prog, tmp).outputs(files)

        kept_any = False
        for name in sorted(PROGRAMS):
            program = parse_files([os.path.join(tmp, name)], None, 1, True)
            cli._CHECKED = cli._CheckedLibraries()  # nothing kept: from scratch
            scratch = translate(program)
            translate(program)  # the library met a second time: kept
            kept_any = kept_any or bool(cli._CHECKED.kept)
            kept = translate(program)  # a copy of the kept state
            for what, a, b in zip(("refusals", "dialect uses", "C"), scratch, kept):
                if a != b:
                    problems.append(f"{name}: the {what} differ with the kept library:\n  {a}\n  {b}")
            print(f"{name}: {len(scratch[0])} refusal(s), {len(scratch[1])} dialect use(s), {len(scratch[2])} outputs")
        if not kept_any:
            problems.append("no library state was kept: the copies were not compared")
    print("\n".join(problems + [f"check_kept_library: {len(PROGRAMS)} programs, {len(problems)} problem(s)"]))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
