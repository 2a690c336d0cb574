#!/usr/bin/env python3
"""tools/hertz_bench.py: the command line of tethertools.hertz_bench (its docstring says what and how)."""
from tethertools.hertz_bench import main

if __name__ == "__main__":
    raise SystemExit(main())
