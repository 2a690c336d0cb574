#!/usr/bin/env python3
"""tools/plot_lame.py: the command line of tethertools.plot_lame (its docstring says what and how)."""
from tethertools.plot_lame import main

if __name__ == "__main__":
    raise SystemExit(main())
