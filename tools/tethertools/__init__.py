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

The tools are modules of the package too, each with a main() and the command
line of tools/NAME.py (a two-line launcher; `python3 -m tethertools.NAME` is the
same): compare_ccx and compare_runs (tether against CalculiX, two builds against
each other), make_gallery (docs/verification.md), the deck generators
make_{lame,cantilever,hertz,mindlin,ironing}_deck and make_verification_decks,
hertz_exact, the summaries {hertz,mindlin,ironing,lame}_summary, hertz_bench
(bench/hertz), ccx_reference (tests/verification/reference) and plot_lame.

The launchers in tools/ find the package beside them (Python puts a script's
folder on its path); everything else (tests, examples' plot scripts) runs with
tools/ on PYTHONPATH, which CTest sets. Pure Python: the tether build is not needed.
"""
