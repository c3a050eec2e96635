"""Which commit `pacrelease archive` builds: a commit or tag as git names it, or a version (`1.0.0`,
`v1.0.0`). A version is its tag where the tag exists, and otherwise its release commit found in the
history, because tags do not always travel (shallow clones, mirrors, forges that drop them): the
release commit is the one whose st/library.json and CHANGELOG.md's newest released section first say
that version, which is what `pacrelease cut` writes in one commit."""
import json
import os
import re
import subprocess

from . import changelog
from .cut import CHANGELOG, ReleaseError, git, tag_name

_VERSION_NAME = re.compile(r"^v?(\d+\.\d+\.\d+)$")
_FILES = (CHANGELOG, "st/library.json")


class _Objects:
    """Blobs of the repository read through one `git cat-file --batch`; None for a missing file."""

    def __init__(self, repo):
        self._proc = subprocess.Popen(["git", "-C", repo, "cat-file", "--batch"], stdin=subprocess.PIPE,
                                      stdout=subprocess.PIPE)

    def read(self, commit, path):
        self._proc.stdin.write(f"{commit}:{path}\n".encode())
        self._proc.stdin.flush()
        header = self._proc.stdout.readline().decode().split()
        if len(header) != 3:  # "<name> missing"
            return None
        data = self._proc.stdout.read(int(header[2]))
        self._proc.stdout.read(1)  # the newline after the object
        return data.decode("utf-8", errors="replace")

    def close(self):
        self._proc.stdin.close()
        self._proc.wait()
        self._proc.stdout.close()


def _released(objects, commit, version):
    """True when `commit` is released as `version`: its st/library.json has that version and CHANGELOG.md's
    newest released section is that version of the same date."""
    text = objects.read(commit, "st/library.json")
    try:
        info = json.loads(text) if text else {}
    except ValueError:
        return False
    if info.get("version") != version:
        return False
    log = objects.read(commit, CHANGELOG)
    return log is not None and changelog.version_disagreement(log, version, info.get("released")) is None


def release_commit(repo, version):
    """The commit that released `version` (major.minor.patch), found in the history of the branches, the
    remote branches and HEAD: released as `version` while none of its parents is. ReleaseError when none
    is (a version never released, or a shallow clone cut before it) or when several are."""
    # not --all: a stash is no release
    changed = git(repo, "log", "--full-history", "--format=%H %P", "--branches", "--remotes", "--tags", "HEAD",
                  "--", *_FILES).split("\n")
    shallow = _shallow_commits(repo)
    objects = _Objects(repo)
    try:
        found = []
        for line in filter(None, changed):
            commit, *parents = line.split()
            if _released(objects, commit, version) and not any(_released(objects, p, version) for p in parents):
                found.append(commit)
    finally:
        objects.close()
    found = sorted(set(found))
    if any(commit in shallow for commit in found):
        raise ReleaseError(f"the history of this clone is cut where {version} may have been released: "
                           f"fetch it (git fetch --unshallow) or the tag {tag_name(version)}")
    if not found:
        hint = " (a shallow clone: git fetch --unshallow)" if shallow else ""
        raise ReleaseError(f"no commit released {version}: no commit's st/library.json and CHANGELOG.md "
                           f"say {version}{hint}")
    if len(found) > 1:
        raise ReleaseError(f"{len(found)} commits released {version}: {', '.join(c[:12] for c in found)}; "
                           "name the one to build")
    return found[0]


def _shallow_commits(repo):
    """The commits whose parents a shallow clone does not have."""
    if git(repo, "rev-parse", "--is-shallow-repository").strip() != "true":
        return set()
    path = git(repo, "rev-parse", "--git-path", "shallow").strip()
    with open(os.path.join(repo, path), encoding="utf-8") as f:  # join keeps an absolute path as it is
        return set(f.read().split())


def resolve(repo, name):
    """The commit (its full id) that `name` names: a commit or tag git knows, else a version's tag or
    release commit."""
    m = _VERSION_NAME.match(name)
    candidates = [tag_name(m.group(1))] if m else []
    candidates.append(name)
    for candidate in candidates:
        result = subprocess.run(["git", "-C", repo, "rev-parse", "--verify", "--quiet", f"{candidate}^{{commit}}"],
                                capture_output=True, text=True)
        if result.returncode == 0:
            return result.stdout.strip()
    if m:
        return release_commit(repo, m.group(1))
    raise ReleaseError(f"'{name}' is neither a commit, a tag nor a version major.minor.patch")
