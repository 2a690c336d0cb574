#!/usr/bin/env python3
"""tools/ccx_reference.py: the command line of tethertools.ccx_reference (its docstring says what and how)."""
from tethertools.ccx_reference import main

if __name__ == "__main__":
    raise SystemExit(main())
