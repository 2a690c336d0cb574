#!/usr/bin/env python3
"""tools/make_cantilever_deck.py: the command line of tethertools.make_cantilever_deck (its docstring says what and how)."""
from tethertools.make_cantilever_deck import main

if __name__ == "__main__":
    raise SystemExit(main())
