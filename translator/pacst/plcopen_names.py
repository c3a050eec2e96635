"""Names of PLCopen TC6 XML and of the CODESYS extensions (addData) that CODESYS and TwinCAT read and write:
the one list for pacst's PLCopen reader and pacexport's writer."""

# CODESYS 3.5 and TwinCAT 3.1 write and read TC6 XML under the namespace of version 2.00; version
# 2.01 (the schema CI validates against) is the same structure under its own namespace.
NS = "http://www.plcopen.org/xml/tc6_0200"
SCHEMA_NS = "http://www.plcopen.org/xml/tc6_0201"
XHTML = "http://www.w3.org/1999/xhtml"

CODESYS = "http://www.3s-software.com/plcopenxml/"
PLAIN_TEXT = CODESYS + "interfaceasplaintext"  # the declaration as text, comments and layout kept
ATTRIBUTES = CODESYS + "attributes"  # {attribute '...'} pragmas
GLOBAL_VARS = CODESYS + "globalvars"  # a global variable list outside any configuration
POU_INHERITANCE = CODESYS + "pouinheritance"  # an FB's EXTENDS and IMPLEMENTS, in its interface's addData
MIXED_ATTRIBUTES = CODESYS + "mixedattrsvarlist"  # the blocks (CONSTANT, RETAIN) of a list of several
OBJECT_ID = CODESYS + "objectid"  # an object's identity, which projectstructure refers to
PROJECT_STRUCTURE = CODESYS + "projectstructure"  # the folders of the POUs view
PROJECT_INFORMATION = CODESYS + "projectinformation"
LIBRARIES = CODESYS + "libraries"  # the library references of the POUs view
ENUM_VALUE_DOCUMENTATION = CODESYS + "enumvaluedocumentation"  # the comment of each enumeration value
BUILD_PROPERTIES = CODESYS + "buildproperties"  # LinkAlways of a global list
# What CODESYS writes as each data's handleUnknown: identities and the tree are dropped by an importer
# that does not know them, everything else is the implementation's.
DISCARDED = (OBJECT_ID, PROJECT_STRUCTURE)

POU_KEYWORDS = {"functionBlock": "FUNCTION_BLOCK", "function": "FUNCTION", "program": "PROGRAM"}


def q(tag):
    """A tag in the TC6 namespace."""
    return f"{{{NS}}}{tag}"
