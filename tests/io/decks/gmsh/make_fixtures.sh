#!/bin/sh
# Regenerates the Gmsh exports the reader tests read (gmsh -format inp): the
# .inp files are committed so the tests do not depend on Gmsh's version.
#   sh make_fixtures.sh            (needs gmsh)
#   plate_tri.inp    CPS3 + T3D2          plate_tri6.inp   CPS6 + T3D3
#   plate_quad4.inp  CPS4 + T3D2          plate_quad8.inp  CPS8 + T3D3
set -eu
cd "$(dirname "$0")"
gmsh -2 -format inp plate_tri.geo -o plate_tri.inp > /dev/null
gmsh -2 -format inp plate_tri.geo -order 2 -o plate_tri6.inp > /dev/null
gmsh -2 -format inp plate_quad.geo -o plate_quad4.inp > /dev/null
gmsh -2 -format inp plate_quad.geo -order 2 -setnumber Mesh.SecondOrderIncomplete 1 -o plate_quad8.inp > /dev/null
