#!/usr/bin/env python3
"""tools/lame_summary.py: the command line of tethertools.lame_summary (its docstring says what and how)."""
from tethertools.lame_summary import main

if __name__ == "__main__":
    raise SystemExit(main())
