#!/usr/bin/env python3
"""Runs decks through two builds of the `tether` program and compares the outputs.

For a change that must not alter any result (a refactor), run every deck
through the program built before the change and the one built after it:

  tools/compare_runs.py --before OLD/tether --after build/bin/tether --work DIR [--generate] [--extra DIR ...]

Cases (each run with `tether run DECK -o OUT -q`):
  * every deck of the repository: examples/*/*.inp, tests/decks/bad/*.inp,
    tests/verification/decks/*.inp, tests/analysis/decks/*.inp,
    tests/output/data/*.inp, tests/io/decks/*.inp, fuzz/seeds/*.inp (decks
    naming a user library are pointed at modules compiled into DIR/modules);
  * with --generate: small decks from tools/make_*_deck.py and the contact
    patch example's make_deck.py (Lame, Hertz, ironing, Cattaneo-Mindlin;
    needs gmsh), written into DIR/generated;
  * every *.inp of each --extra directory (e.g. decks written by the tests);
  * a few decks again with other solver options (--no-condense, --solver
    umfpack / cholmod / mumps), and restart cases: a deck with *RESTART, WRITE
    is continued from its restart file (each program from the file of the
    `before` run, so both read the same state).

Compared, per case: the exit code, stderr (output paths replaced), and every
file of the output directory byte for byte, except lines of timing in the
.msg and .sta ("time 0.12 s: ...") and the output directory's own path. Prints one line per differing case and a
summary; exit status 0 when all cases agree, 1 otherwise.
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TIMING = re.compile(rb"^\s*time [0-9.eE+-]+ s:.*$", re.MULTILINE)
TIMED_SUFFIXES = (".msg", ".sta")

# Generated decks: (name, tool, options). Small meshes so the set runs in minutes.
GENERATED = [
    ("lame_cpe8_nlgeom", "make_lame_deck.py", ["--type", "CPE8", "--nr", "4", "--nt", "8", "--nlgeom"]),
    ("lame_cax4", "make_lame_deck.py", ["--type", "CAX4", "--nr", "8", "--nt", "2"]),
    ("hertz_cpe4_2k", "make_hertz_deck.py", ["--dofs", "2k", "--element", "CPE4", "--no-seat"]),
    ("hertz_cpe8_2k_rigid", "make_hertz_deck.py", ["--dofs", "2k", "--element", "CPE8", "--rigid-flat", "--no-seat"]),
    ("hertz_cpe4_2k_seat_nlgeom", "make_hertz_deck.py", ["--dofs", "2k", "--seat", "1e-4", "--nlgeom"]),
    ("hertz_cpe4_2k_linear", "make_hertz_deck.py", ["--dofs", "2k", "--linear", "1e6", "--no-seat"]),
    ("ironing_short_mu03", "make_ironing_deck.py",
     ["--mu", "0.3", "--slide", "0.5", "--slide-increments", "5", "--master-size", "0.2", "--slave-size", "0.1"]),
    ("ironing_short_mu0", "make_ironing_deck.py",
     ["--mu", "0", "--slide", "0.5", "--slide-increments", "4", "--master-size", "0.2", "--slave-size", "0.1"]),
    ("mindlin_cpe4_coarse", "make_mindlin_deck.py", ["--dofs", "3k", "--element", "CPE4"]),
]

# Decks (by file name) run again with other options.
VARIANTS = {
    "fine_on_coarse.inp": [["--no-condense"], ["--solver", "umfpack"], ["--solver", "cholmod"], ["--solver", "mumps"]],
    "hertz_cpe4_2k.inp": [["--no-condense"], ["--solver", "mumps"]],
    "ironing_short_mu03.inp": [["--solver", "cholmod"], ["--no-condense"]],
    "rigid_link.inp": [["--solver", "cholmod"], ["--solver", "mumps"], ["--solver", "sparselu"]],
    "user_mpc.inp": [["--solver", "mumps"]],
    "lame.inp": [["--solver", "cholmod"]],
}


def build_modules(work):
    """Compiles the user-routine examples; returns {deck LIBRARY= text: absolute module path}."""
    out = os.path.join(work, "modules")
    os.makedirs(out, exist_ok=True)
    modules = {}
    for source, library in (("examples/user_constraint/equal_displacement.cpp", "libequal_displacement.so"),
                            ("examples/user_mpc/user_mpc.cpp", "libuser_mpc.so")):
        target = os.path.join(out, library)
        if not os.path.exists(target):
            subprocess.run(["g++", "-std=c++17", "-O2", "-shared", "-fPIC", "-I", os.path.join(ROOT, "src"),
                            os.path.join(ROOT, source), "-o", target], check=True)
        modules["LIBRARY=build/" + library] = "LIBRARY=" + target
    return modules


def repository_decks(work):
    patterns = ["examples/*/*.inp", "tests/decks/bad/*.inp", "tests/verification/decks/*.inp",
                "tests/analysis/decks/*.inp", "tests/output/data/*.inp", "tests/io/decks/*.inp", "fuzz/seeds/*.inp"]
    modules = build_modules(work)
    decks = []
    for pattern in patterns:
        for deck in sorted(glob.glob(os.path.join(ROOT, pattern))):
            with open(deck, encoding="utf-8", errors="replace") as f:
                text = f.read()
            if any(key in text for key in modules):
                # A copy next to nothing else, pointed at the compiled module.
                copy = os.path.join(work, "decks", os.path.relpath(deck, ROOT))
                os.makedirs(os.path.dirname(copy), exist_ok=True)
                for key, value in modules.items():
                    text = text.replace(key, value)
                with open(copy, "w", encoding="utf-8") as f:
                    f.write(text)
                deck = copy
            decks.append(deck)
    return decks


def generated_decks(work):
    out = os.path.join(work, "generated")
    os.makedirs(out, exist_ok=True)
    decks = []
    for name, tool, options in GENERATED:
        deck = os.path.join(out, name + ".inp")
        if not os.path.exists(deck):
            subprocess.run([sys.executable, os.path.join(ROOT, "tools", tool), deck] + options, check=True,
                           stdout=subprocess.DEVNULL)
        decks.append(deck)
    return decks


def normalised(path, data, out):
    """File contents as compared: the output directory's path (messages name
    files in it) as <OUT>, and timing lines of the logs left out."""
    data = data.replace(out.encode(), b"<OUT>")
    if path.endswith(TIMED_SUFFIXES):
        data = TIMING.sub(b"", data)
    return data


def run(program, deck, out, options, timeout):
    shutil.rmtree(out, ignore_errors=True)
    try:
        r = subprocess.run([program, "run", deck, "-o", out, "-q"] + options, capture_output=True, timeout=timeout)
        return r.returncode, r.stderr.replace(out.encode(), b"<OUT>")
    except subprocess.TimeoutExpired:
        return "timeout", b""


def differences(before, after):
    """Names of the files that differ between two output directories."""
    names = set()
    for d in (before, after):
        if os.path.isdir(d):
            names |= {os.path.relpath(os.path.join(p, f), d) for p, _, fs in os.walk(d) for f in fs}
    out = []
    for name in sorted(names):
        a, b = os.path.join(before, name), os.path.join(after, name)
        if not (os.path.exists(a) and os.path.exists(b)):
            out.append(name + " (only in one)")
            continue
        with open(a, "rb") as fa, open(b, "rb") as fb:
            if normalised(name, fa.read(), before) != normalised(name, fb.read(), after):
                out.append(name)
    return out, len(names)


def compare_case(args, label, deck, options, restart_of=None):
    """Runs one case through both programs; returns (equal, files compared)."""
    base = os.path.join(args.work, "runs", label)
    results = {}
    for which, program in (("before", args.before), ("after", args.after)):
        extra = list(options)
        if restart_of:
            extra += ["--restart", restart_of]
        results[which] = run(program, deck, os.path.join(base, which), extra, args.timeout)
    problems = []
    if results["before"][0] != results["after"][0]:
        problems.append(f"exit code {results['before'][0]} vs {results['after'][0]}")
    if results["before"][1] != results["after"][1]:
        problems.append("stderr differs")
    files, n = differences(os.path.join(base, "before"), os.path.join(base, "after"))
    problems += files
    status = "same" if not problems else "DIFFERS: " + ", ".join(problems)
    print(f"{label}: exit {results['before'][0]}, {n} files: {status}", flush=True)
    return not problems, n


def restart_files(args, label, deck):
    """Restart states to continue `deck` from, written by the `before` program:
    the end of the analysis (its own run), and, for a deck of several steps,
    the end of its first step (a copy of the deck cut after the first *END STEP;
    skipped when that copy does not run, e.g. for lack of its *INCLUDEd files)."""
    out = []
    stem = os.path.splitext(os.path.basename(deck))[0]
    saved = os.path.join(args.work, "restart_files")
    os.makedirs(saved, exist_ok=True)
    rst = os.path.join(args.work, "runs", label, "before", stem + ".rst")
    if os.path.exists(rst):
        shutil.copyfile(rst, os.path.join(saved, label + ".rst"))
        out.append(("_restarted_at_end", os.path.join(saved, label + ".rst")))
        with open(deck, encoding="utf-8", errors="replace") as f:
            text = f.read()
        end = re.search(r"^\*END STEP.*$", text, re.MULTILINE | re.IGNORECASE)
        if end and re.search(r"^\*STEP", text[end.end():], re.MULTILINE | re.IGNORECASE):
            first = os.path.join(saved, label + "_step1", stem + ".inp")
            os.makedirs(os.path.dirname(first), exist_ok=True)
            with open(first, "w", encoding="utf-8") as f:
                f.write(text[:end.end()] + "\n")
            result = run(args.before, first, os.path.join(saved, label + "_step1", "out"), [], args.timeout)
            step1 = os.path.join(saved, label + "_step1", "out", stem + ".rst")
            if result[0] == 0 and os.path.exists(step1):
                out.append(("_restarted_after_step1", step1))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--before", required=True)
    p.add_argument("--after", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--generate", action="store_true", help="also run generated decks (needs gmsh)")
    p.add_argument("--extra", action="append", default=[], help="a directory of more decks")
    p.add_argument("--only", help="run only cases whose label contains this")
    p.add_argument("--timeout", type=float, default=900)
    args = p.parse_args()
    args.work = os.path.abspath(args.work)

    decks = repository_decks(args.work)
    if args.generate:
        decks += generated_decks(args.work)
    for d in args.extra:
        decks += sorted(glob.glob(os.path.join(os.path.abspath(d), "*.inp")))

    cases = []  # (label, deck, options, restart file)
    for deck in decks:
        stem = os.path.relpath(deck, ROOT if deck.startswith(ROOT + os.sep) else args.work).replace(os.sep, "_")
        cases.append((stem, deck, [], None))
        for options in VARIANTS.get(os.path.basename(deck), []):
            cases.append((stem + "_" + "_".join(o.strip("-") for o in options), deck, options, None))
    n_same = n_files = 0
    done = []
    for label, deck, options, _ in cases:
        if args.only and args.only not in label:
            continue
        same, n = compare_case(args, label, deck, options)
        n_same += same
        n_files += n
        done.append(label)
        if options:
            continue
        for suffix, rst in restart_files(args, label, deck):
            same, n = compare_case(args, label + suffix, deck, [], restart_of=rst)
            n_same += same
            n_files += n
            done.append(label + suffix)
    print(f"{n_same} of {len(done)} cases identical ({n_files} output files compared)")
    return 0 if n_same == len(done) else 1


if __name__ == "__main__":
    sys.exit(main())
