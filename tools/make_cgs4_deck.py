#!/usr/bin/env python3
"""tools/make_cgs4_deck.py: the command line of tethertools.make_cgs4_deck (its docstring says what and how)."""
from tethertools.make_cgs4_deck import main

if __name__ == "__main__":
    raise SystemExit(main())
