#!/usr/bin/env python3
"""tools/make_verification_decks.py: the command line of tethertools.make_verification_decks (its docstring says what and how)."""
from tethertools.make_verification_decks import main

if __name__ == "__main__":
    raise SystemExit(main())
