"""Repository.NoPathOutside: no tracked file names a path outside the repository, so a plain `git clone`
builds, tests and reads without anything beside it (docs/testing.md, "Self-contained"). Fails, naming file
and line, on
  - an absolute path under a root that belongs to one machine (a home, a work or scratch folder, a mount);
    the system's own roots (/usr, /etc, /dev, /proc, /bin, /lib, /sys) are the same on every Debian 12
    and allowed: ./run looks for Debian's packages there;
  - a path that climbs out of the repository: the folder of working material beside the clone (the
    pattern below), `${PROJECT_SOURCE_DIR}/..`, or a relative
    Markdown link that resolves outside the repository or to nothing;
  - the name of working material that was never part of the repository (the manual's text file, the
    old reading notes and portable-subset file, the verdict corpus under its outside name, task briefs).
Binary files and the fuzz corpus (random bytes) are not read. This file is the one place the patterns
are written down; it is exempt from them.
Usage: check_paths.py <repository root>"""
import os
import re
import subprocess
import sys

MACHINE_ROOTS = ["work", "home", "root", "Users", "mnt", "media", "srv", "opt", "tmp", "var/tmp", "scratch"]
RULES = [
    ("an absolute path of one machine",
     re.compile(r"(?<![\w.~$}/-])/(?:" + "|".join(map(re.escape, MACHINE_ROOTS)) + r")/")),
    ("a Windows drive path", re.compile(r"(?<![\w])[A-Za-z]:\\\\?[A-Za-z]")),
    ("a path beside the repository", re.compile(r"\.\./shared\b|\"\.\.\", \"shared\"")),
    ("a path above the source tree", re.compile(r"\$\{(?:PROJECT|CMAKE)_SOURCE_DIR\}/\.\.(?:/|\"|$)")),
    ("working material outside the repository",
     re.compile(r"\bNOTES\.md\b|\bbriefs/|st-portable-subset|matiec-verdicts|"
                r"pa-control-interfaces-manual\.txt|anpos2-positioning-device\.txt")),
]
SKIP_DIRS = ("tests/fuzz/corpus/",)
LINK = re.compile(r"\]\(([^)\s]+)\)")


def tracked_files(repo):
    try:
        out = subprocess.run(["git", "-C", repo, "ls-files", "-z"], check=True, capture_output=True).stdout
        return [name for name in out.decode().split("\0") if name]
    except (OSError, subprocess.CalledProcessError):  # not a git checkout: every file but build trees
        names = []
        for folder, dirs, files in os.walk(repo):
            dirs[:] = [d for d in dirs if d != ".git" and not d.startswith("build")]
            names += [os.path.relpath(os.path.join(folder, f), repo) for f in files]
        return names


def link_problem(repo, name, target):
    """Why a relative Markdown link of file `name` is wrong, or None."""
    if re.match(r"[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
        return None  # a URL or an anchor on the same page
    path = os.path.normpath(os.path.join(repo, os.path.dirname(name), target.split("#")[0]))
    if os.path.relpath(path, repo).startswith(".."):
        return "a link out of the repository"
    if not os.path.exists(path):
        return "a link to nothing"
    return None


def problems(repo):
    me = os.path.relpath(os.path.abspath(__file__), repo)
    for name in tracked_files(repo):
        if name == me or name.startswith(SKIP_DIRS):
            continue
        try:
            with open(os.path.join(repo, name), "rb") as f:
                data = f.read()
        except OSError:
            continue
        if b"\0" in data:
            continue  # binary
        text = data.decode("utf-8", errors="replace")
        for number, line in enumerate(text.splitlines(), 1):
            for what, pattern in RULES:
                found = pattern.search(line)
                if found:
                    yield f"{name}:{number}: {what}: '{found.group(0)}' in: {line.strip()[:160]}"
            if name.endswith(".md"):
                for target in LINK.findall(line):
                    why = link_problem(repo, name, target)
                    if why:
                        yield f"{name}:{number}: {why}: ({target})"


def main():
    repo = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
    found = list(problems(repo))
    for line in found:
        print(line)
    print(f"{len(found)} path(s) outside the repository" if found else "no path outside the repository")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
