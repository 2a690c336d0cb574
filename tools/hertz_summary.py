#!/usr/bin/env python3
"""tools/hertz_summary.py: the command line of tethertools.hertz_summary (its docstring says what and how)."""
from tethertools.hertz_summary import main

if __name__ == "__main__":
    raise SystemExit(main())
