"""What the export's tests read: the build's configuration (PACEXPORT_CONFIG, written by CMake) and
the library and export it names. A missing dependency or configuration is an error, never a skip."""
import functools
import json
import os

from pacexport.cli import plcopen_file_name
from pacexport.library import load_library
from pacexport.metadata import read_library_info


@functools.lru_cache(maxsize=None)
def config():
    with open(os.environ["PACEXPORT_CONFIG"], encoding="utf-8") as f:
        return json.load(f)


def cache():
    """The translator's parse cache directory (pacst.parsing), which the export shares."""
    return config()["cache"]


@functools.lru_cache(maxsize=None)
def library():
    c = config()
    return load_library(read_library_info(c["library"]), c["sources"], c["global_lists"], cache())


def plcopen_path():
    return os.path.join(config()["out"], plcopen_file_name(library().info))


def plcopen_data():
    with open(plcopen_path(), "rb") as f:
        return f.read()


def twincat_dir():
    return os.path.join(config()["out"], "twincat")


def repo_file(*parts):
    return os.path.join(config()["repo"], *parts)

