"""check_checked_library.py REPO: a library's checked state kept in a file (`pacst library`) and taken by `pacst build
--user --checked-library FILE`, as pac-test's runs take the build's for the PA-CONTROL library. With the file standing
for the library, the run parses none of the library's files and gets what a run without the file gets: the same
refusals, the same C of every file with its #line mapping, POUS.h and symbols.json with the same entries (the kept
library's declarations first). A stale file (a library file changed since), a damaged one and one whose library
files name a namespace their check did not have are not taken: the run parses and checks the library as without
the file. With a program that declares a name a library file uses (that file then is no longer the library's
alone) the run checks the files read from it again. A second library is declared on top of the kept one."""
import argparse
import json
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
# a library of its own namespace, checked in each run on top of the kept one
OTHER = {"FB_Flag.st": "FUNCTION_BLOCK FB_Flag\nVAR_OUTPUT\n  Q : BOOL;\nEND_VAR\nQ := NOT Q;\nEND_FUNCTION_BLOCK\n"}
PROGRAMS = {
    "Prg_Uses.st": "PROGRAM Prg_Uses\nVAR\n  C : Lib.FB_Counter;\n  M : Lib.E_Mode := MODE_RUN;\n  F : Other.FB_Flag;\n"
                   "END_VAR\nC(Step := Lib.GVL_Lib.LIB_LIMIT);\nF();\nEND_PROGRAM\n",
    "Prg_Refused.st": "PROGRAM Prg_Refused\nVAR\n  C : FB_Counter;\n  X : BOOL;\nEND_VAR\nX := C;\n"
                      "C(Step := 'text');\nEND_PROGRAM\n",
    "Prg_Extends.st": "FUNCTION_BLOCK FB_Twice EXTENDS Lib.FB_Counter\nSUPER^();\nSUPER^();\nEND_FUNCTION_BLOCK\n"
                      "PROGRAM Prg_Extends\nVAR\n  T : FB_Twice;\n  C : FB_Counter;\n  Copy : FB_Counter;\nEND_VAR\n"
                      "T(Step := 2);\nC();\nCopy := C;\nEND_PROGRAM\n",
    # shares MODE_RUN with E_Mode and sorts before E_Mode.st, whose file then uses a name of the program's (not taken)
    "E_Level.st": "TYPE E_Level : (LEVEL_LOW, MODE_RUN);\nEND_TYPE\n",
}


class Checker:
    def __init__(self, repo, tmp):
        sys.path.insert(0, os.path.join(repo, "translator"))
        from pacst import cli, parsing  # noqa: E402
        self.cli, self.parsing, self.tmp = cli, parsing, tmp
        self.lib = os.path.join(tmp, "Lib")
        self.other = os.path.join(tmp, "Other")
        self.kept = os.path.join(tmp, "kept", "Lib.pickle")
        self.problems = []

    def write(self, folder, files):
        os.makedirs(folder, exist_ok=True)
        for name, text in files.items():
            with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
                f.write(text)

    def pacst(self, *args):
        """(exit code, stdout, stderr, the paths parse_files was given) of `pacst ARGS` in this process."""
        import contextlib
        import io
        given = []
        real = self.cli.parse_files

        def recording(paths, *rest, **kw):
            given.extend(paths)
            return real(paths, *rest, **kw)
        out, err = io.StringIO(), io.StringIO()
        self.cli.parse_files = recording
        try:
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                code = self.cli.main(list(args))
        finally:
            self.cli.parse_files = real
        return code, out.getvalue(), err.getvalue(), given

    def library_files(self):
        return [os.path.join(self.lib, n) for n in sorted(os.listdir(self.lib))]

    def build(self, program, out, checked):
        files = self.library_files() + [os.path.join(self.other, n) for n in sorted(OTHER)] + \
            [os.path.join(self.tmp, program)]
        args = ["build", "--user", "-v", "--namespace", f"Lib={self.lib}", "--namespace", f"Other={self.other}",
                "--line-directives", "--out", out] + (["--checked-library", self.kept] if checked else []) + files
        code, stdout, stderr, parsed = self.pacst(*args)
        outputs = {}
        for name in sorted(os.listdir(out)) if os.path.isdir(out) else []:
            with open(os.path.join(out, name), encoding="utf-8") as f:
                text = f.read().replace(out, "OUT")
            if name == "POUS.h":  # the same declarations; the kept library's come first
                text = sorted(text.splitlines())
            elif name == "symbols.json":
                table = json.loads(text)
                text = {k: sorted(json.dumps(e, sort_keys=True) for e in v) if isinstance(v, list) else v
                        for k, v in table.items()}
            outputs[name] = text
        return code, stdout, stderr, parsed, outputs

    def compare(self, program, mode, what):
        """The build of `program` with the kept file against one without; `mode`: "taken" (the library neither
        parsed nor checked), "checked" (read from the file, checked again) or "parsed" (the file not taken)."""
        n = len(os.listdir(self.tmp))
        scratch = self.build(program, os.path.join(self.tmp, f"out{n}-scratch"), False)
        kept = self.build(program, os.path.join(self.tmp, f"out{n}-kept"), True)
        said = next((line for line in kept[1].splitlines() if "the checked library" in line), "")
        expected = {"taken": f"{len(LIBRARY)} file(s) taken, not parsed or checked",
                    "checked": f"{len(LIBRARY)} file(s) read from it and checked again", "parsed": "not taken"}[mode]
        if expected not in said:
            self.problems.append(f"{program} ({what}): expected '{expected}', pacst said '{said}'")
        parsed_lib = [p for p in kept[3] if p.startswith(self.lib + os.sep)]
        if len(parsed_lib) != (len(self.library_files()) if mode == "parsed" else 0):
            self.problems.append(f"{program} ({what}): the library's files parsed: {parsed_lib}")
        for label, a, b in (("exit code", scratch[0], kept[0]), ("refusals", scratch[2], kept[2]),
                            ("outputs", scratch[4], kept[4])):
            if a != b:
                self.problems.append(f"{program} ({what}): the {label} differ with the kept file:\n  {a}\n  {b}")
        print(f"{program} ({what}): exit {kept[0]}, {len(kept[4])} outputs; {said}")

    def run(self):
        self.write(self.lib, LIBRARY)
        self.write(self.other, OTHER)
        self.write(self.tmp, PROGRAMS)
        code, _, err, _ = self.pacst("library", "--namespace", f"Lib={self.lib}", "--out", self.kept,
                                    *self.library_files())
        if code != 0 or not os.path.exists(self.kept):
            return [f"pacst library failed: {err}"]
        for program in sorted(PROGRAMS):
            self.compare(program, "checked" if program == "E_Level.st" else "taken", "a kept file of this library")
        with open(self.kept, "rb") as f:
            kept = f.read()
        # stale: a library file changed after the file was kept (the C of FB_Counter's initial value changes)
        self.write(self.lib, {"FB_Counter.st": LIBRARY["FB_Counter.st"].replace(":= 1;", ":= 3;")})
        self.compare("Prg_Uses.st", "parsed", "a library file changed")
        self.write(self.lib, LIBRARY)
        with open(self.kept, "wb") as f:  # damaged: cut in the middle
            f.write(kept[:len(kept) // 2])
        self.compare("Prg_Uses.st", "parsed", "the kept file damaged")
        # a library file naming a namespace its check did not have (Other, given to the run): not taken
        self.write(self.lib, {"F_Twice.st": "FUNCTION F_Twice : INT\nVAR_INPUT\n  Other : INT;\nEND_VAR\n"
                                            "F_Twice := Other * 2;\nEND_FUNCTION\n"})
        self.pacst("library", "--namespace", f"Lib={self.lib}", "--out", self.kept, *self.library_files())
        self.compare("Prg_Uses.st", "parsed", "a namespace the check did not have")
        return self.problems


def main(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("repo")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        problems = Checker(args.repo, tmp).run()
    print("\n".join(problems + [f"check_checked_library: {len(PROGRAMS)} programs, {len(problems)} problem(s)"]))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
