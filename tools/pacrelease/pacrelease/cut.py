"""`pacrelease cut VERSION`: the release commit and its annotated tag. CHANGELOG.md's Unreleased entries go
under `## [VERSION] - DATE`, st/library.json gets the version and the date (the exports carry both), the
two files are committed and the commit is tagged `vVERSION` with the section as the tag's message."""
import json
import os
import subprocess

from . import changelog

CHANGELOG = "CHANGELOG.md"
LIBRARY_JSON = os.path.join("st", "library.json")


class ReleaseError(Exception):
    pass


def git(repo, *args):
    result = subprocess.run(["git", "-C", repo, *args], capture_output=True, text=True)
    if result.returncode != 0:
        raise ReleaseError(f"git {' '.join(args)}: {result.stderr.strip()}")
    return result.stdout


def read(repo, name):
    with open(os.path.join(repo, name), encoding="utf-8") as f:
        return f.read()


def write(repo, name, text):
    with open(os.path.join(repo, name), "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


def library_json_text(data):
    """st/library.json as it is kept: two spaces of indent, a final newline."""
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def tag_name(version):
    return f"v{version}"


def cut_release(repo, version, date):
    """Commits the release of `version` dated `date` (YYYY-MM-DD) in the git work tree `repo` and tags
    it; returns the tag's name. Refuses a work tree with changes, a version that does not follow the
    latest release, an empty Unreleased section and a tag that exists."""
    if git(repo, "status", "--porcelain", "--untracked-files=no").strip():
        raise ReleaseError("the work tree has uncommitted changes: commit them first")
    tag = tag_name(version)
    if git(repo, "tag", "--list", tag).strip():
        raise ReleaseError(f"tag {tag} exists")
    try:
        text = changelog.cut(read(repo, CHANGELOG), version, date)
    except changelog.ChangelogError as exc:
        raise ReleaseError(str(exc)) from None
    info = json.loads(read(repo, LIBRARY_JSON))
    info["version"], info["released"] = version, date
    write(repo, CHANGELOG, text)
    write(repo, LIBRARY_JSON, library_json_text(info))
    git(repo, "add", CHANGELOG, LIBRARY_JSON)
    git(repo, "commit", "--quiet", "-m", f"Release {version} ({date}): CHANGELOG.md's Unreleased section "
                                         f"under [{version}], the version and date in st/library.json")
    message = f"{info['name']} {version} ({date})\n\n{changelog.section(text, version)}"
    _annotated_tag(repo, tag, message)
    return tag


def _annotated_tag(repo, tag, message):
    result = subprocess.run(["git", "-C", repo, "tag", "--annotate", "--cleanup=verbatim", tag, "--file", "-"],
                            input=message, capture_output=True, text=True)
    if result.returncode != 0:
        raise ReleaseError(f"git tag {tag}: {result.stderr.strip()}")
