#!/usr/bin/env python3
"""Regenerates the decks of the verification suite in tests/verification/decks/.

Every deck is written by tools/make_lame_deck.py, make_cantilever_deck.py or make_cgs4_deck.py
with the arguments listed below; the tests in tests/verification/ read them.
Usage: make_verification_decks.py [OUT_DIR]   (default: tests/verification/decks)
"""
import os
import subprocess
import sys

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # tools/: the scripts
DEFAULT_OUT = os.path.join(TOOLS, "..", "tests", "verification", "decks")

# deck name -> (generator, arguments)
DECKS = {
    # Lame thick cylinder, plane strain quarter ring (nr elements through the wall x nt around)
    "lame_cpe4_4x8": ("make_lame_deck.py", ["--type", "CPE4", "--nr", "4", "--nt", "8"]),
    "lame_cpe4_8x16": ("make_lame_deck.py", ["--type", "CPE4", "--nr", "8", "--nt", "16"]),
    "lame_cpe3_4x8": ("make_lame_deck.py", ["--type", "CPE3", "--nr", "4", "--nt", "8"]),
    "lame_cpe3_8x16": ("make_lame_deck.py", ["--type", "CPE3", "--nr", "8", "--nt", "16"]),
    "lame_cpe8_4x8": ("make_lame_deck.py", ["--type", "CPE8", "--nr", "4", "--nt", "8"]),
    "lame_cpe6_4x8": ("make_lame_deck.py", ["--type", "CPE6", "--nr", "4", "--nt", "8"]),
    # axisymmetric slice r in [a, b], z in [0, H] (nt = elements along z)
    "lame_cax4_8x2": ("make_lame_deck.py", ["--type", "CAX4", "--nr", "8", "--nt", "2"]),
    "lame_cax8_4x1": ("make_lame_deck.py", ["--type", "CAX8", "--nr", "4", "--nt", "1"]),
    "lame_cax6_4x1": ("make_lame_deck.py", ["--type", "CAX6", "--nr", "4", "--nt", "1"]),
    # thin disc, plane stress
    "lame_cps8_4x8": ("make_lame_deck.py", ["--type", "CPS8", "--nr", "4", "--nt", "8"]),
    # cantilever L/H = 10 under an end shear load
    "cantilever_cps8_10x1": ("make_cantilever_deck.py", ["--type", "CPS8", "--nx", "10", "--ny", "1"]),
    "cantilever_cps8_20x2": ("make_cantilever_deck.py", ["--type", "CPS8", "--nx", "20", "--ny", "2"]),
    "cantilever_cps8_40x4": ("make_cantilever_deck.py", ["--type", "CPS8", "--nx", "40", "--ny", "4"]),
    "cantilever_cps4_10x2": ("make_cantilever_deck.py", ["--type", "CPS4", "--nx", "10", "--ny", "2"]),
    "cantilever_cps4_20x4": ("make_cantilever_deck.py", ["--type", "CPS4", "--nx", "20", "--ny", "4"]),
    "cantilever_cps4_40x8": ("make_cantilever_deck.py", ["--type", "CPS4", "--nx", "40", "--ny", "8"]),
    "cantilever_cps4_80x16": ("make_cantilever_deck.py", ["--type", "CPS4", "--nx", "80", "--ny", "16"]),
    # decks run through CalculiX by tools/ccx_reference.py (every node printed)
    "ccx_lame_cpe8_4x8": ("make_lame_deck.py", ["--type", "CPE8", "--nr", "4", "--nt", "8", "--print-all"]),
    "ccx_lame_cpe4_8x16": ("make_lame_deck.py", ["--type", "CPE4", "--nr", "8", "--nt", "16", "--print-all"]),
    "ccx_lame_cax8_4x1": ("make_lame_deck.py", ["--type", "CAX8", "--nr", "4", "--nt", "1", "--print-all"]),
    # plane stress: ccx models CPS* as a one-layer 3D plate whose faces are free, which is plane
    # stress only for a thin plate (at T = H it is 2.3 % stiffer); hence T = H / 100 here
    "ccx_cantilever_cps8_20x2": ("make_cantilever_deck.py",
                                 ["--type", "CPS8", "--nx", "20", "--ny", "2", "--thickness", "0.01",
                                  "--print-all"]),
    "ccx_cantilever_cpe8_20x2": ("make_cantilever_deck.py",
                                 ["--type", "CPE8", "--nx", "20", "--ny", "2", "--print-all"]),
    # NAFEMS CGS-4: a block pushed up a slope (tan alpha 0.1, mu 0.3) on non-matching meshes; G = 40 as
    # modelled elsewhere, G = 0.4 the rigid limit (the formula's assumption)
    "cgs4_mortar_g40": ("make_cgs4_deck.py", ["--type", "SURFACE TO SURFACE", "--load", "40"]),
    "cgs4_mortar_g0.4": ("make_cgs4_deck.py", ["--type", "SURFACE TO SURFACE", "--load", "0.4"]),
    "cgs4_nts_g40": ("make_cgs4_deck.py", ["--type", "NODE TO SURFACE", "--load", "40"]),
}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else DEFAULT_OUT
    os.makedirs(out, exist_ok=True)
    for name, (script, args) in DECKS.items():
        subprocess.run([sys.executable, os.path.join(TOOLS, script), os.path.join(out, name + ".inp")] + args,
                       check=True)
    print(f"wrote {len(DECKS)} decks to {os.path.normpath(out)}")


if __name__ == "__main__":
    main()
