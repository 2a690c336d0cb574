#!/usr/bin/env python3
"""tools/mindlin_summary.py: the command line of tethertools.mindlin_summary (its docstring says what and how)."""
from tethertools.mindlin_summary import main

if __name__ == "__main__":
    raise SystemExit(main())
