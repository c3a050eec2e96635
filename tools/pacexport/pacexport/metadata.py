"""The library's name and version: st/library.json, the one place they are written."""
import json
import re
from dataclasses import dataclass

from .errors import ExportError

_FIELDS = ("name", "title", "version", "released", "company", "license", "description")


@dataclass(frozen=True)
class LibraryInfo:
    name: str  # the IDE's project and library title, its default namespace
    title: str
    version: str  # major.minor.patch
    released: str  # YYYY-MM-DD of this version: the exports' only time stamp
    company: str  # also the author: the library's contributors
    license: str  # an SPDX identifier: LICENSE at the top of the repository, the first line of every ST file
    description: str

    @property
    def ide_version(self):
        """CODESYS and TwinCAT number a library with four parts: 0.1.0 is 0.1.0.0."""
        return self.version + ".0"

    @property
    def license_line(self):
        """The licence as every ST file's first comment and every export's metadata carry it."""
        return f"SPDX-License-Identifier: {self.license}"

    @property
    def timestamp(self):
        return self.released + "T00:00:00"


def read_library_info(path):
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, ValueError) as exc:
        raise ExportError(path, f"cannot read: {exc}") from None
    missing = [k for k in _FIELDS if not isinstance(data.get(k), str) or not data[k]]
    if missing:
        raise ExportError(path, f"needs the text fields {', '.join(missing)}")
    if not re.fullmatch(r"\d+\.\d+\.\d+", data["version"]):
        raise ExportError(path, f"version '{data['version']}' is not major.minor.patch")
    if not re.fullmatch(r"[A-Za-z0-9.+-]+", data["license"]):
        raise ExportError(path, f"license '{data['license']}' is not an SPDX identifier")
    if not re.fullmatch(r"\d{4}-\d{2}-\d{2}", data["released"]):
        raise ExportError(path, f"released '{data['released']}' is not YYYY-MM-DD")
    return LibraryInfo(**{k: data[k] for k in _FIELDS})
