"""pacrelease: the changelog's sections, the version of st/library.json against CHANGELOG.md, a release cut
in a temporary clone of the repository, and the release archive built twice from one commit.

PACRELEASE_REPO names the repository, PACRELEASE_EXPORT_PYTHON the Python of pacexport's venv and
PACRELEASE_CACHE pacst's parse cache (set by CMake). A missing one is an error, never a skip."""
import io
import json
import os
import re
import subprocess
import tarfile
import tempfile
import unittest
import zipfile

from pacrelease import changelog
from pacrelease.archive import write_release
from pacrelease.cut import ReleaseError, cut_release, git, package_version, python_packages
from pacrelease.resolve import resolve

REPO = os.environ["PACRELEASE_REPO"]
EXPORT_PYTHON = os.environ["PACRELEASE_EXPORT_PYTHON"]
CACHE = os.environ["PACRELEASE_CACHE"]

LOG = """# Changelog

## [Unreleased]

### Fixed

- Something.

## [1.2.3] - 2026-01-02

- Older.
"""


def _read(repo, *parts):
    with open(os.path.join(repo, *parts), encoding="utf-8") as f:
        return f.read()


class Changelog(unittest.TestCase):
    def test_the_cut_moves_the_entries_under_the_version(self):
        text = changelog.cut(LOG, "2.0.0", "2026-02-03")
        self.assertEqual(changelog.latest_release(text), ("2.0.0", "2026-02-03"))
        self.assertEqual(changelog.unreleased_body(text).strip(), "")
        self.assertEqual(changelog.section(text, "2.0.0"), "### Fixed\n\n- Something.\n")
        self.assertEqual(changelog.section(text, "1.2.3"), "- Older.\n")

    def test_a_version_must_follow_the_latest_release(self):
        for version in ("1.2.3", "1.2.2", "0.9.0", "1.2", "v1.3.0", "1.02.0"):
            with self.subTest(version), self.assertRaises(changelog.ChangelogError):
                changelog.cut(LOG, version, "2026-02-03")
        with self.assertRaises(changelog.ChangelogError):
            changelog.cut(LOG, "1.2.4", "2026-01-01")  # before the latest release
        with self.assertRaises(changelog.ChangelogError):
            changelog.cut(LOG, "1.2.4", "3.2.2026")

    def test_nothing_to_release_is_refused(self):
        with self.assertRaises(changelog.ChangelogError):
            changelog.cut(changelog.cut(LOG, "1.3.0", "2026-02-03"), "1.3.1", "2026-02-03")

    def test_a_disagreeing_version_is_named(self):
        self.assertIsNone(changelog.version_disagreement(LOG, "1.2.3", "2026-01-02"))
        self.assertIsNotNone(changelog.version_disagreement(LOG, "1.3.0", "2026-01-02"))
        self.assertIsNotNone(changelog.version_disagreement(LOG, "1.2.3", "2026-01-03"))
        self.assertIsNotNone(changelog.version_disagreement("## [Unreleased]\n", "0.1.0", "2026-01-02"))


class Version(unittest.TestCase):
    def test_library_json_has_the_latest_released_version_of_the_changelog(self):
        info = json.loads(_read(REPO, "st", "library.json"))
        self.assertIsNone(changelog.version_disagreement(_read(REPO, "CHANGELOG.md"), info["version"],
                                                         info["released"]))

    def test_every_python_package_has_the_library_version(self):
        version = json.loads(_read(REPO, "st", "library.json"))["version"]
        packages = python_packages(REPO)
        self.assertIn("translator/pyproject.toml", packages)
        self.assertIn("tools/pacrelease/pyproject.toml", packages)
        for name in packages:
            with self.subTest(name):
                self.assertEqual(package_version(_read(REPO, name)), version)


def _show(repo, name):
    """A file of a commit, None where the commit has no such file."""
    result = subprocess.run(["git", "-C", repo, "show", name], capture_output=True, text=True)
    return result.stdout if result.returncode == 0 else None


def _released_versions(text):
    return [line.split("[")[1].split("]")[0] for line in text.splitlines()
            if line.startswith("## [") and not line.startswith(changelog.UNRELEASED)]


class RepositoryReleases(unittest.TestCase):
    """Every release of CHANGELOG.md resolves in a clone that has no tags, to a commit whose files say it."""

    def test_each_released_version_resolves_without_tags(self):
        with tempfile.TemporaryDirectory() as tmp:
            clone = os.path.join(tmp, "clone")
            subprocess.run(["git", "clone", "--quiet", "--shared", "--no-tags", "--no-checkout", REPO, clone],
                           check=True)
            git(clone, "checkout", "--quiet", git(REPO, "rev-parse", "HEAD").strip())
            self.assertEqual(git(clone, "tag", "--list").strip(), "")
            versions = _released_versions(_read(REPO, "CHANGELOG.md"))
            self.assertIn("1.0.0", versions)
            for version in versions:
                with self.subTest(version):
                    commit = resolve(clone, version)
                    self.assertEqual(resolve(clone, f"v{version}"), commit)
                    info = json.loads(git(clone, "show", f"{commit}:st/library.json"))
                    self.assertEqual(info["version"], version)
                    self.assertEqual(changelog.latest_release(git(clone, "show", f"{commit}:CHANGELOG.md")),
                                     (version, info["released"]))
                    # the first commit whose two files say so: its parent's do not both
                    parent = json.loads(_show(clone, f"{commit}~1:st/library.json") or "{}")
                    log = _show(clone, f"{commit}~1:CHANGELOG.md") or ""
                    self.assertFalse(parent.get("version") == version
                                     and changelog.latest_release(log) == (version, info["released"]))

    def test_a_version_never_released_and_a_cut_history_are_named(self):
        with self.assertRaisesRegex(ReleaseError, "no commit released 99.0.0"):
            resolve(REPO, "99.0.0")
        with self.assertRaisesRegex(ReleaseError, "neither a commit"):
            resolve(REPO, "not-a-version")
        with tempfile.TemporaryDirectory() as tmp:
            shallow = os.path.join(tmp, "shallow")
            subprocess.run(["git", "clone", "--quiet", "--depth", "1", "--no-tags", f"file://{REPO}", shallow],
                           check=True, capture_output=True)
            version = json.loads(_read(shallow, "st", "library.json"))["version"]
            with self.assertRaisesRegex(ReleaseError, "git fetch --unshallow"):
                resolve(shallow, version)


def _clone(into):
    subprocess.run(["git", "clone", "--quiet", "--shared", "--no-checkout", REPO, into], check=True)
    git(into, "checkout", "--quiet", git(REPO, "rev-parse", "HEAD").strip())  # the repository's commit
    git(into, "config", "user.name", "Release test")
    git(into, "config", "user.email", "release-test@example.invalid")
    # A change to release, whatever the Unreleased section of the cloned commit holds.
    text = _read(into, "CHANGELOG.md").replace("## [Unreleased]\n", "## [Unreleased]\n\n- A test entry.\n", 1)
    with open(os.path.join(into, "CHANGELOG.md"), "w", encoding="utf-8") as f:
        f.write(text)
    git(into, "commit", "--quiet", "-am", "a change to release")


def _entries(data):
    with zipfile.ZipFile(io.BytesIO(data)) as z:
        return z.infolist()


class Release(unittest.TestCase):
    """Both commands on a temporary clone of the repository: the work tree itself is never touched."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.clone = os.path.join(cls.tmp.name, "clone")
        _clone(cls.clone)
        cls.info = json.loads(_read(cls.clone, "st", "library.json"))
        major = int(cls.info["version"].split(".")[0])
        cls.version, cls.date = f"{major + 1}.0.0", "2099-12-31"
        cls.tag = cut_release(cls.clone, cls.version, cls.date)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_cut_commits_changelog_and_library_json(self):
        changed = git(self.clone, "show", "--name-only", "--format=", "HEAD").split()
        self.assertEqual(sorted(changed), sorted(["CHANGELOG.md", "st/library.json", *python_packages(self.clone)]))
        for name in python_packages(self.clone):
            self.assertEqual(package_version(_read(self.clone, name)), self.version, name)
        info = json.loads(_read(self.clone, "st", "library.json"))
        self.assertEqual((info["version"], info["released"]), (self.version, self.date))
        self.assertEqual({k: v for k, v in info.items() if k not in ("version", "released")},
                         {k: v for k, v in self.info.items() if k not in ("version", "released")})
        text = _read(self.clone, "CHANGELOG.md")
        self.assertIsNone(changelog.version_disagreement(text, self.version, self.date))
        self.assertEqual(changelog.unreleased_body(text).strip(), "")
        self.assertIn("- A test entry.", changelog.section(text, self.version))
        self.assertEqual(git(self.clone, "status", "--porcelain").strip(), "")

    def test_the_tag_is_annotated_on_the_release_commit(self):
        self.assertEqual(self.tag, f"v{self.version}")
        self.assertEqual(git(self.clone, "cat-file", "-t", self.tag).strip(), "tag")
        self.assertEqual(git(self.clone, "rev-parse", f"{self.tag}^{{commit}}"), git(self.clone, "rev-parse", "HEAD"))
        message = git(self.clone, "tag", "--list", "--format=%(contents)", self.tag)
        self.assertIn(f"{self.info['name']} {self.version} ({self.date})", message)
        self.assertIn("- A test entry.", message)

    def test_a_second_cut_and_a_changed_tree_are_refused(self):
        with self.assertRaises(ReleaseError):
            cut_release(self.clone, self.version, self.date)  # the tag exists
        with open(os.path.join(self.clone, "LICENSE"), "a", encoding="utf-8") as f:
            f.write("\n")
        try:
            with self.assertRaises(ReleaseError):
                cut_release(self.clone, f"{self.version.split('.')[0]}.1.0", self.date)
        finally:
            git(self.clone, "checkout", "--quiet", "--", "LICENSE")

    @classmethod
    def _tagless_release(cls):
        """The release of a clone without tags, named by its version as docs/release.md writes it, with the
        parse cache (written once, for the tests that read it)."""
        if getattr(cls, "tagless_release", None) is None:
            tagless = os.path.join(cls.tmp.name, "tagless-pages")
            subprocess.run(["git", "clone", "--quiet", "--no-tags", cls.clone, tagless], check=True)
            cls.tagless_release = write_release(tagless, cls.tag, os.path.join(cls.tmp.name, "c"), EXPORT_PYTHON, CACHE)
        return cls.tagless_release

    def test_the_archive_of_the_tag_is_reproducible_and_carries_the_version(self):
        # two builds, each of its own clone (with the tag and without), one with an empty parse cache and one
        # with the build's: byte for byte the same archives
        first = write_release(self.clone, self.tag, os.path.join(self.tmp.name, "a"), EXPORT_PYTHON)
        second = self._tagless_release()
        folder = f"{self.info['name'].lower()}-{self.version}"
        self.assertEqual(os.path.basename(first), folder)
        for suffix in (".zip", ".tar.gz"):
            with open(first + suffix, "rb") as f, open(second + suffix, "rb") as g:
                self.assertEqual(f.read(), g.read(), f"{folder}{suffix} differs between two builds")
        with open(first + ".zip", "rb") as f:
            entries = _entries(f.read())
        names = [e.filename for e in entries]
        self.assertEqual(names, sorted(names))
        rel = {n.split("/", 1)[1] for n in names}
        plcopen = f"plcopen/{self.info['name'].lower()}.xml"
        self.assertLessEqual({plcopen, f"twincat/{self.info['name']}.plcproj", "LICENSE", "CHANGELOG.md",
                              "CHANGELOG.html", "docs/import.html", "docs/release.html",
                              "docs/diagrams/cmd_ack.svg"}, rel)
        self.assertEqual({e.date_time for e in entries}, {(2099, 12, 31, 0, 0, 0)})
        self.assertEqual({e.external_attr >> 16 for e in entries}, {0o100644})
        with tarfile.open(first + ".tar.gz") as tar:
            members = tar.getmembers()
        self.assertEqual({(m.uid, m.gid, m.uname, m.gname, m.mode) for m in members}, {(0, 0, "root", "root", 0o644)})
        self.assertEqual([m.name for m in members], names)
        self.assertIn(f'version="{self.version}"', _read(first, *plcopen.split("/")))
        self.assertEqual(os.path.isdir(os.path.join(self.clone, "examples")),
                         any(r.startswith("examples/") for r in rel))
        # every library the example's TwinCAT project refers to is in the archive, but Beckhoff's own
        for path in sorted(r for r in rel if r.startswith("examples/") and r.endswith(".plcproj")):
            project = _read(first, *path.split("/"))
            for name, resolution in re.findall(r'<PlaceholderReference Include="([^"]+)">\s*'
                                               r'<DefaultResolution>([^<]*)</DefaultResolution>', project):
                if "(Beckhoff Automation GmbH)" not in resolution:
                    with self.subTest(path=path, library=name):
                        self.assertTrue(any(r.endswith(f"twincat/{name}.plcproj") for r in rel),
                                        f"{path} refers to {name}, which the archive does not hold")
        self.assertTrue("pactest/twincat/PacTest.plcproj" in rel, "no PacTest library in the archive")
        self.assertIn('version="' + self.version + '"', _read(first, "pactest", "plcopen", "pactest.xml"))

    def test_the_version_resolves_to_its_commit_with_and_without_the_tag(self):
        release = git(self.clone, "rev-parse", "HEAD").strip()
        self.assertEqual(resolve(self.clone, self.version), release)
        self.assertEqual(resolve(self.clone, self.tag), release)
        tagless = os.path.join(self.tmp.name, "tagless")
        subprocess.run(["git", "clone", "--quiet", "--no-tags", self.clone, tagless], check=True)
        self.assertEqual(git(tagless, "tag", "--list").strip(), "")
        git(tagless, "config", "user.name", "Release test")
        git(tagless, "config", "user.email", "release-test@example.invalid")
        git(tagless, "commit", "--quiet", "--allow-empty", "-m", "a commit after the release")
        self.assertEqual(resolve(tagless, self.version), release)
        self.assertEqual(resolve(tagless, self.tag), release)

    def test_rendered_pages_link_to_rendered_pages(self):
        first = self._tagless_release()
        self.assertEqual(os.path.basename(first), f"{self.info['name'].lower()}-{self.version}")
        page = _read(first, "docs", "import.html")
        self.assertIn('href="../CHANGELOG.html"', page)
        self.assertNotRegex(page, r'href="[^":]*\.md[#"]')
        self.assertIn("<table>", page)


if __name__ == "__main__":
    unittest.main()
