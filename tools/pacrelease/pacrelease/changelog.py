"""CHANGELOG.md as the release sees it: the Unreleased section, where changes collect, and the released
sections below it, newest first, each headed `## [major.minor.patch] - YYYY-MM-DD`."""
import re

UNRELEASED = "## [Unreleased]"
_RELEASED = re.compile(r"^## \[(\d+)\.(\d+)\.(\d+)\] - (\d{4}-\d{2}-\d{2})$")
VERSION = re.compile(r"^(\d+)\.(\d+)\.(\d+)$")


class ChangelogError(Exception):
    pass


def parse_version(text):
    """(major, minor, patch) of `text`, or ChangelogError: a release is numbered major.minor.patch."""
    m = VERSION.match(text)
    if not m or any(len(part) > 1 and part.startswith("0") for part in m.groups()):
        raise ChangelogError(f"'{text}' is not a version major.minor.patch (semantic versioning)")
    return tuple(int(part) for part in m.groups())


def latest_release(text):
    """(version, date) of the newest released section, or None before the first release."""
    for line in text.splitlines():
        m = _RELEASED.match(line.rstrip())
        if m:
            return ".".join(m.groups()[:3]), m.group(4)
    return None


def version_disagreement(text, version, released):
    """Why st/library.json's `version` and `released` disagree with the newest released section of
    CHANGELOG.md `text`, or None when they agree (the exports carry what the changelog last released)."""
    latest = latest_release(text)
    if latest is None:
        return f"CHANGELOG.md has no released section for st/library.json's version {version}"
    if latest != (version, released):
        return (f"st/library.json has {version} of {released}, CHANGELOG.md's latest release is "
                f"{latest[0]} of {latest[1]}")
    return None


def unreleased_body(text):
    """The text of the Unreleased section (without its heading), or ChangelogError."""
    lines = text.splitlines(keepends=True)
    starts = [i for i, line in enumerate(lines) if line.rstrip() == UNRELEASED]
    if len(starts) != 1:
        raise ChangelogError(f"CHANGELOG.md needs exactly one '{UNRELEASED}' heading, has {len(starts)}")
    end = next((i for i in range(starts[0] + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    return "".join(lines[starts[0] + 1:end])


def cut(text, version, date):
    """CHANGELOG.md with the Unreleased section's entries under `## [version] - date` and a new, empty
    Unreleased section above it. The version must follow the latest release."""
    new = parse_version(version)
    if not re.fullmatch(r"\d{4}-\d{2}-\d{2}", date):
        raise ChangelogError(f"date '{date}' is not YYYY-MM-DD")
    latest = latest_release(text)
    if latest is not None and new <= parse_version(latest[0]):
        raise ChangelogError(f"version {version} does not follow the latest release, {latest[0]}")
    if latest is not None and date < latest[1]:
        raise ChangelogError(f"date {date} is before the latest release's, {latest[1]}")
    if not unreleased_body(text).strip():
        raise ChangelogError("the Unreleased section of CHANGELOG.md is empty: nothing to release")
    return text.replace(f"{UNRELEASED}\n", f"{UNRELEASED}\n\n## [{version}] - {date}\n", 1)


def section(text, version):
    """The entries of the released section of `version` (for the tag's message)."""
    lines = text.splitlines(keepends=True)
    head = next((i for i, line in enumerate(lines) if line.startswith(f"## [{version}] - ")), None)
    if head is None:
        raise ChangelogError(f"CHANGELOG.md has no section for {version}")
    end = next((i for i in range(head + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    return "".join(lines[head + 1:end]).strip() + "\n"
