"""pacst: Structured Text (the portable subset of ../shared/st-portable-subset.md) to C99 with MATIEC's interface."""

__version__ = "0.1.0"
