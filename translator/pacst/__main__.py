from . import parsing
from .cli import main

# One translation a process: the parsed trees it loads live to its end (parsing.FREEZE_LOADED_TREES).
parsing.FREEZE_LOADED_TREES = True
raise SystemExit(main())
