#!/usr/bin/env python3
"""tools/ironing_summary.py: the command line of tethertools.ironing_summary (its docstring says what and how)."""
from tethertools.ironing_summary import main

if __name__ == "__main__":
    raise SystemExit(main())
