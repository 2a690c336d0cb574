#!/usr/bin/env python3
"""tools/make_gallery.py: the command line of tethertools.make_gallery (its docstring says what and how)."""
from tethertools.make_gallery import main

if __name__ == "__main__":
    raise SystemExit(main())
