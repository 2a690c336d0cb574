#!/usr/bin/env python3
"""tools/compare_runs.py: the command line of tethertools.compare_runs (its docstring says what and how)."""
from tethertools.compare_runs import main

if __name__ == "__main__":
    raise SystemExit(main())
