"""`pacrelease cut VERSION`: the release commit and its annotated tag. CHANGELOG.md's Unreleased entries go
under `## [VERSION] - DATE`, st/library.json gets the version and the date (the exports carry both), the
Python packages' pyproject.toml the version; the files are committed and the commit is tagged `vVERSION`
with the section as the tag's message."""
import json
import os
import re
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


# The Python packages' `version = "..."` in their pyproject.toml, the library's version as
# st/library.json holds it: the release writes it, Release.Units holds them equal.
_PACKAGE_VERSION = re.compile(r'^version = "[^"]*"$', re.MULTILINE)


def python_packages(repo):
    """The tracked pyproject.toml files of the repository (translator/, tools/*/), sorted."""
    return sorted(git(repo, "ls-files", "--", "pyproject.toml", "*/pyproject.toml").split())


def package_version(text):
    """The `version` of a pyproject.toml's text, or None."""
    m = _PACKAGE_VERSION.search(text)
    return m.group(0).split('"')[1] if m else None


def with_package_version(text, version):
    """A pyproject.toml's text with its `version` set."""
    return _PACKAGE_VERSION.sub(f'version = "{version}"', text, count=1)


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
    packages = python_packages(repo)
    write(repo, CHANGELOG, text)
    write(repo, LIBRARY_JSON, library_json_text(info))
    for name in packages:
        write(repo, name, with_package_version(read(repo, name), version))
    git(repo, "add", CHANGELOG, LIBRARY_JSON, *packages)
    git(repo, "commit", "--quiet", "-m", f"Release {version} ({date}): CHANGELOG.md's Unreleased section "
                                         f"under [{version}], the version and date in st/library.json, "
                                         "the version in the Python packages")
    message = f"{info['name']} {version} ({date})\n\n{changelog.section(text, version)}"
    _annotated_tag(repo, tag, message)
    return tag


def _annotated_tag(repo, tag, message):
    result = subprocess.run(["git", "-C", repo, "tag", "--annotate", "--cleanup=verbatim", tag, "--file", "-"],
                            input=message, capture_output=True, text=True)
    if result.returncode != 0:
        raise ReleaseError(f"git tag {tag}: {result.stderr.strip()}")
