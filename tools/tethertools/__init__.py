"""Readers shared by the tools (comparison with CalculiX, verification gallery,
benchmarks, summaries), the examples' plot scripts and the tests: one reader
per file kind.

  tethertools.deck   ABAQUS/CalculiX decks: keyword cards (with *INCLUDE), nodes,
                     elements, sets, surfaces, the *HEADING's key=value pairs
  tethertools.dat    .dat files of tether and CalculiX (*NODE PRINT, *EL PRINT,
                     *CONTACT PRINT blocks)
  tethertools.sta    .sta files of tether and CalculiX

The scripts in tools/ import it directly (their folder is on Python's path);
from elsewhere put tools/ on PYTHONPATH. Pure Python: the tether build is not needed.
"""
