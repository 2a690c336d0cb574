"""Readers shared by the tools (comparison with CalculiX, verification gallery,
benchmarks, summaries), the examples' plot scripts and the tests: one reader
per file kind.

  tethertools.deck   ABAQUS/CalculiX decks: keyword cards (with *INCLUDE), nodes,
                     elements, sets, surfaces, the *HEADING's key=value pairs
  tethertools.dat    .dat files of tether and CalculiX (*NODE PRINT, *EL PRINT,
                     *CONTACT PRINT blocks)
  tethertools.sta    .sta files of tether and CalculiX (attempts, iterations,
                     tether's verdict) and tether's .msg (converged increments)
  tethertools.vtu    .pvd collections and .vtu files (standard library and NumPy;
                     checks sizes, finiteness and connectivity)

The scripts in tools/ import it directly (Python puts a script's folder on its
path); everything else (tests, examples' plot scripts) runs with tools/ on
PYTHONPATH, which CTest sets. Pure Python: the tether build is not needed.
"""
