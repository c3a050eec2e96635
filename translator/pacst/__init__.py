"""pacst: Structured Text (the portable subset of docs/st_subset.md) to C99 with MATIEC's interface."""

__version__ = "0.1.0"
