#!/usr/bin/env python3
"""tools/compare_ccx.py: the command line of tethertools.compare_ccx (its docstring says what and how)."""
from tethertools.compare_ccx import main

if __name__ == "__main__":
    raise SystemExit(main())
