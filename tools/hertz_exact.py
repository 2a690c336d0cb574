#!/usr/bin/env python3
"""tools/hertz_exact.py: the command line of tethertools.hertz_exact (its docstring says what and how)."""
from tethertools.hertz_exact import main

if __name__ == "__main__":
    raise SystemExit(main())
