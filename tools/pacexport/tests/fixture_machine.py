"""A small machine of the tests' own: a PLC project with one PROGRAM MAIN and one function block, as
the TwinCAT export writes it, and the TwinCAT solution pacexport writes around it."""
import os

from pacexport.library import load_library
from pacexport.metadata import LibraryInfo
from pacexport.solution import write_solution
from pacexport.twincat import write_twincat
from tests import support

INFO = LibraryInfo("FixtureMachine", "Fixture machine", "1.0.0", "2020-01-02", "Nobody", "MIT",
                   "A program that counts scans.")
NAME = "FixtureSolution"
CYCLE_MS = 4
SOURCES = {
    "FB_Count.st": "(* SPDX-License-Identifier: MIT *)\n(* Counts the calls. *)\nFUNCTION_BLOCK FB_Count\n"
                   "VAR_OUTPUT\n  N : DINT;  (* calls so far *)\nEND_VAR\nN := N + 1;\nEND_FUNCTION_BLOCK\n",
    "MAIN.st": "(* SPDX-License-Identifier: MIT *)\nPROGRAM MAIN\nVAR\n  Count : FB_Count;\nEND_VAR\nCount();\n"
               "END_PROGRAM\n",
}


def write_machine(directory):
    """Writes the sources, the PLC project (<directory>/plc) and the solution (<directory>/solution);
    returns the path of the .sln."""
    paths = []
    for name, text in SOURCES.items():
        paths.append(os.path.join(directory, name))
        with open(paths[-1], "w", encoding="utf-8") as f:
            f.write(text)
    library = load_library(INFO, paths, [], support.cache())
    plc = os.path.join(directory, "plc")
    write_twincat(library, plc)
    out = os.path.join(directory, "solution")
    write_solution(plc, out, NAME, "MAIN", CYCLE_MS)
    return os.path.join(out, f"{NAME}.sln")
