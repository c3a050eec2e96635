"""The machine program of a wiring file compiled by MATIEC (the reference compiler): the library and the
user's PROGRAMs, global lists and FBs through `pacst matiec` (one ST file with the CONFIGURATION, RESOURCE
and a TASK per task of the wiring file) into iec2c, and MATIEC's C compiled. The test FBs stay out: they
call the asserts as statements and the vocabulary's FUNCTIONs write GVL_PacTest, both refused by MATIEC
(docs/user_tests.md, "On MATIEC"), so this proves the program MATIEC-clean but runs no test on it."""
import json
import os

from . import build, project


class MatiecProgram:
    def __init__(self, wiring, out, iec2c, matiec_lib, pacst_python=None, parse_cache=None):
        self.wiring, self.out, self.iec2c, self.matiec_lib = wiring, out, iec2c, matiec_lib
        # pacst as the host build runs it (its venv, its parse cache); this class writes no host
        self.pacst = build.HostBuild(wiring, None, out, coverage=False, pacst_python=pacst_python,
                                     parse_cache=parse_cache)._pacst
        self.st = os.path.join(out, "matiec", "program.st")
        self.c_dir = os.path.join(out, "matiec", "c")

    def _is_test(self, path):
        """A test FB's file: one POU per file, named as the file (docs/user_tests.md, "Your project")."""
        stem = os.path.splitext(os.path.basename(path))[0].upper()
        if self.wiring.test_names:
            return stem in {n.upper() for n in self.wiring.test_names}
        return stem.startswith(self.wiring.prefix.upper())

    def tasks(self):
        """pacst matiec's task list: each PROGRAM in its task, the wiring's cycle as the TASK's interval and
        the task's place in the wiring file as its priority."""
        return {program: {"task": task["name"], "interval": f"T#{task['cycle_ms']}MS", "priority": n}
                for n, task in enumerate(self.wiring.tasks, 1) for program in task["programs"]}

    def program_files(self):
        """The library, GVL_PAC and the user's sources but the test FBs, in declaration order."""
        files = project.library_sources() + [project.gvl_pac()] + self.wiring.sources
        sources = ["--sources", os.path.join(self.out, "plcopen")]
        ordered = self.pacst("order", "--user", *sources, *files).splitlines()
        return [f for f in ordered if not self._is_test(f)]

    def compile(self, cc="cc"):
        """pacst matiec, iec2c and the C compiler over the program; returns the object files. Raises
        build.BuildError with the tool's own message where one of them refuses."""
        os.makedirs(self.c_dir, exist_ok=True)
        tasks = os.path.join(self.out, "matiec", "tasks.json")
        with open(tasks, "w", encoding="utf-8") as f:
            json.dump(self.tasks(), f, indent=1)
        self.pacst("matiec", "--out", self.st, "--tasks", tasks, *self.program_files())
        build._run([self.iec2c, "-I", self.matiec_lib, "-T", self.c_dir, self.st], "iec2c")
        objects = []
        # PacResource.c includes POUS.c; PacConfig.c holds the globals
        for unit in ("PacResource.c", "PacConfig.c"):
            obj = os.path.join(self.c_dir, os.path.splitext(unit)[0] + ".o")
            build._run([cc, "-std=gnu99", "-fwrapv", "-w", "-I", self.c_dir, "-I", os.path.join(self.matiec_lib, "C"),
                        "-c", os.path.join(self.c_dir, unit), "-o", obj], f"compiling MATIEC's {unit}")
            objects.append(obj)
        return objects

