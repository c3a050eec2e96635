"""`pacrelease archive COMMIT`: the release folder and archives of a commit, the same bytes from the same
commit. The files come from the commit alone (`git archive`), the exports are written by that commit's
pacexport and pacst; the only time stamp is the release date of its st/library.json, entries are sorted,
owner and modes fixed."""
import gzip
import io
import json
import os
import shutil
import subprocess
import tarfile
import tempfile
import zipfile
from datetime import datetime, timezone

from .cut import ReleaseError
from .docs import render_page
from .resolve import resolve

# What a PLC programmer gets besides the exports and the docs.
TOP_FILES = ("CHANGELOG.md", "LICENSE")
# The example machine program (examples/), shipped when the commit has it.
EXAMPLES = "examples"
# pac-test's test vocabulary, which the example's tests call: shipped as the library PacTest (its
# library.json names it; the version, date, company and licence are the library's), when the commit has it.
VOCABULARY = "tools/pactest/st"
VOCABULARY_FOLDER = "pactest"


def _run(command, env_path, what):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(env_path), PYTHONDONTWRITEBYTECODE="1")
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    if result.returncode != 0:
        raise ReleaseError(f"{what} failed:\n{result.stderr.strip()}")
    return result.stdout


def _extract(repo, commit, into):
    data = subprocess.run(["git", "-C", repo, "archive", "--format=tar", commit], capture_output=True)
    if data.returncode != 0:
        raise ReleaseError(f"git archive {commit}: {data.stderr.decode(errors='replace').strip()}")
    with tarfile.open(fileobj=io.BytesIO(data.stdout)) as tar:
        tar.extractall(into)  # git's own archive of the repository


def _tree_files(root, under):
    """Relative paths (with '/') of the files below root/under, sorted."""
    found = []
    for folder, _, names in os.walk(os.path.join(root, under)):
        found += [os.path.relpath(os.path.join(folder, n), root).replace(os.sep, "/") for n in names]
    return sorted(found)


def _read(root, rel):
    with open(os.path.join(root, rel), "rb") as f:
        return f.read()


def _export(src, python, cache, out, folder="st", library_json=None):
    """The commit's pacexport on the ST of `folder` (the library, default), in the order the commit's pacst
    derives; a global list is a file named GVL_*.st."""
    files = [os.path.join(src, p) for p in _tree_files(src, folder) if p.endswith(".st")]
    lists = [p for p in files if os.path.basename(p).startswith("GVL_")]
    library = [p for p in files if p not in lists]
    cache_args = ["--cache", cache] if cache else []
    translator = os.path.join(src, "translator")
    order = _run([python, "-m", "pacst", "order", *cache_args, *library], [translator], "pacst order").split()
    gvl_args = [arg for path in lists for arg in ("--gvl", path)]
    library_json = library_json or os.path.join(src, folder, "library.json")
    _run([python, "-m", "pacexport", "export", "--library", library_json, "--out", out,
          *cache_args, *gvl_args, *order], [os.path.join(src, "tools", "pacexport"), translator], "pacexport export")


def release_files(src, python, cache, work):
    """{path in the release: bytes} of the extracted commit `src`."""
    export = os.path.join(work, "export")
    _export(src, python, cache, export)
    # The PLCopen file into plcopen/, the TwinCAT project as it is (twincat/).
    files = {rel if "/" in rel else "plcopen/" + rel: _read(export, rel) for rel in _tree_files(export, ".")}
    for name in TOP_FILES:
        files[name] = _read(src, name)
    for rel in ["README.md", "CHANGELOG.md", *_tree_files(src, "docs")]:
        if rel.endswith(".md"):
            files[rel[:-3] + ".html"] = render_page(_read(src, rel).decode("utf-8")).encode("utf-8")
        elif rel.startswith("docs/diagrams/") and rel.endswith(".svg"):
            files[rel] = _read(src, rel)
    if os.path.isdir(os.path.join(src, EXAMPLES)):
        for rel in _tree_files(src, EXAMPLES):
            files[rel] = _read(src, rel)
    files.update(_vocabulary_files(src, python, cache, work))
    return files


def _vocabulary_files(src, python, cache, work):
    """{path: bytes} of the vocabulary's library under pactest/, as the library's exports are laid out."""
    own = os.path.join(src, VOCABULARY, "library.json")
    if not os.path.exists(own):
        return {}
    with open(os.path.join(src, "st", "library.json"), encoding="utf-8") as f:
        info = json.load(f)
    with open(own, encoding="utf-8") as f:
        info.update(json.load(f))
    merged = os.path.join(work, "vocabulary-library.json")
    with open(merged, "w", encoding="utf-8") as f:
        json.dump(info, f)
    export = os.path.join(work, "vocabulary-export")
    _export(src, python, cache, export, VOCABULARY, merged)
    return {f"{VOCABULARY_FOLDER}/{rel if '/' in rel else 'plcopen/' + rel}": _read(export, rel)
            for rel in _tree_files(export, ".")}


def _epoch(date):
    return int(datetime.strptime(date, "%Y-%m-%d").replace(tzinfo=timezone.utc).timestamp())


def zip_bytes(folder, files, date):
    buf = io.BytesIO()
    stamp = tuple(int(x) for x in date.split("-")) + (0, 0, 0)
    with zipfile.ZipFile(buf, "w") as z:
        for rel in sorted(files):
            info = zipfile.ZipInfo(f"{folder}/{rel}", date_time=stamp)
            info.create_system = 3  # Unix, so that the mode below is read
            info.external_attr = 0o100644 << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, files[rel], compresslevel=9)
    return buf.getvalue()


def tar_gz_bytes(folder, files, date):
    raw = io.BytesIO()
    with tarfile.open(fileobj=raw, mode="w", format=tarfile.PAX_FORMAT) as tar:
        for rel in sorted(files):
            info = tarfile.TarInfo(f"{folder}/{rel}")
            info.size, info.mtime, info.mode = len(files[rel]), _epoch(date), 0o644
            info.uid = info.gid = 0
            info.uname = info.gname = "root"
            tar.addfile(info, io.BytesIO(files[rel]))
    out = io.BytesIO()
    with gzip.GzipFile(filename="", mode="wb", fileobj=out, compresslevel=9, mtime=0) as gz:
        gz.write(raw.getvalue())
    return out.getvalue()


def write_release(repo, name, out, python, cache=None):
    """Writes <out>/<name>-<version>/ and its .zip and .tar.gz of the commit, tag or version `name`
    (resolve.py); returns the folder's path."""
    with tempfile.TemporaryDirectory() as work:
        src = os.path.join(work, "src")
        _extract(repo, resolve(repo, name), src)
        with open(os.path.join(src, "st", "library.json"), encoding="utf-8") as f:
            info = json.load(f)
        folder = f"{info['name'].lower()}-{info['version']}"
        files = release_files(src, python, cache, work)
    target = os.path.join(out, folder)
    shutil.rmtree(target, ignore_errors=True)
    for rel, data in files.items():
        path = os.path.join(target, *rel.split("/"))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    with open(target + ".zip", "wb") as f:
        f.write(zip_bytes(folder, files, info["released"]))
    with open(target + ".tar.gz", "wb") as f:
        f.write(tar_gz_bytes(folder, files, info["released"]))
    return target
