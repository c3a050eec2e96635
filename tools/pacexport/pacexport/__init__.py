"""pacexport: writes the PA-CONTROL library as PLCopen XML and as TwinCAT 3 PLC files (docs/import.md)."""

__version__ = "0.1.0"
