"""Validation against the TC6 XML v2.01 schema, which ships in the PyPI package plcrex.

The schema's target namespace is 2.01's (tc6_0201); CODESYS and TwinCAT write and read 2.00's
(tc6_0200), which the export uses. Version 2.01 changed no structure, so the schema is loaded with its
namespace set to 2.00's and validates the exported file exactly as written.
"""
import importlib.util
import os

from lxml import etree

from pacst.plcopen_names import NS, SCHEMA_NS

SCHEMA_FILE = ("data", "tc6", "tc6_xml_v201.xsd")


class SchemaUnavailable(Exception):
    pass


def schema_path():
    spec = importlib.util.find_spec("plcrex")  # finds the package without running its code
    if spec is None or not spec.submodule_search_locations:
        raise SchemaUnavailable("the package plcrex is not installed (tools/pacexport/requirements-nodeps.txt)")
    path = os.path.join(spec.submodule_search_locations[0], *SCHEMA_FILE)
    if not os.path.exists(path):
        raise SchemaUnavailable(f"plcrex has no {'/'.join(SCHEMA_FILE)}")
    return path


def load_schema():
    with open(schema_path(), "rb") as f:
        text = f.read().decode("utf-8")
    # The namespace appears as the target and as the prefix ppx that the schema's references use.
    if text.count(SCHEMA_NS) != 2:
        raise SchemaUnavailable(f"the schema names {SCHEMA_NS} {text.count(SCHEMA_NS)} times, not twice: "
                                "not the file this export was checked with")
    return etree.XMLSchema(etree.fromstring(text.replace(SCHEMA_NS, NS).encode("utf-8")))


def schema_errors(schema, data):
    """The schema's complaints about an XML document (bytes); empty when it is valid."""
    document = etree.fromstring(data)
    if schema.validate(document):
        return []
    return [f"line {e.line}: {e.message}" for e in schema.error_log]
