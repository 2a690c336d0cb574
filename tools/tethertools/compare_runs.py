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

With --tolerance REL (for a change that alters results in the last bits, e.g.
sums taken in another order), a file that differs byte for byte still agrees
when
  * it is a result file, .dat, .pvd or .csv, whose words are the same and
    whose numbers differ by at most REL times the scale of their column (the
    same position in the rows under the same heading line), or by one unit in
    their last printed digit (values on either side of a rounding boundary,
    1.879408E+00 and 1.879407E+00);
  * or a .vtu whose data arrays differ by at most REL times the scale of each
    array (integer arrays exactly);
  * or a log, .sta or .msg, whose words and integers (increments, iterations,
    attempts, contact status counts: the path of the solution) are the same;
    its real numbers (the residual norms, round-off at convergence) are not
    compared.
The scale of a column or array is its largest magnitude, but at least 1e-6
times the largest magnitude in the file (a column of round-off zeros, such as
the gaps of closed contact nodes, is compared against the file's values).
Such cases are counted as "within tolerance"; binary files (restart files)
must still be identical.
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


NUMBER = re.compile(r"^[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")
TEXT_SUFFIXES = (".dat", ".sta", ".msg", ".pvd", ".csv", ".txt")
LOG_SUFFIXES = (".sta", ".msg")
INTEGER = re.compile(r"^[-+]?\d+$")
# A column's scale is at least this fraction of the largest magnitude in its file.
SCALE_FLOOR = 1e-6


def _last_digit(token):
    """The value of one unit in the last printed digit of a number token (1.879408E+00: 1e-6)."""
    mantissa, _, exponent = token.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 10.0 ** ((int(exponent) if exponent else 0) - decimals)


def _columns(text):
    """[(key, tokens)] per line: key = the last line with a word (the heading), tokens split at blanks/commas."""
    heading = ""
    out = []
    for line in text.splitlines():
        tokens = [t for t in re.split(r"[\s,;]+", line) if t]
        if any(not NUMBER.match(t) for t in tokens):
            heading = line
        out.append((heading, tokens))
    return out


def text_within(a, b, tol, log=False):
    """None when the texts agree within `tol` (see the module docstring; `log`:
    a .sta/.msg, whose real numbers are not compared), else the first difference."""
    ra, rb = _columns(a), _columns(b)
    if len(ra) != len(rb):
        return f"{len(ra)} vs {len(rb)} lines"
    scale = {}
    for heading, tokens in rb:
        for k, t in enumerate(tokens):
            if NUMBER.match(t):
                scale[(heading, k)] = max(scale.get((heading, k), 0.0), abs(float(t)))
    floor = SCALE_FLOOR * max(scale.values(), default=0.0)
    scale = {key: max(value, floor) for key, value in scale.items()}
    for n, ((ha, ta), (hb, tb)) in enumerate(zip(ra, rb)):
        if len(ta) != len(tb):
            return f"line {n + 1}: {len(ta)} vs {len(tb)} fields"
        for k, (x, y) in enumerate(zip(ta, tb)):
            if x == y:
                continue
            if not (NUMBER.match(x) and NUMBER.match(y)):
                return f"line {n + 1}: {x!r} vs {y!r}"
            if log and not (INTEGER.match(x) or INTEGER.match(y)):
                continue
            if log:
                return f"line {n + 1}: {x} vs {y}"
            difference = abs(float(x) - float(y))
            if difference > tol * scale[(hb, k)] and difference > 1.000001 * max(_last_digit(x), _last_digit(y)):
                return f"line {n + 1} field {k + 1}: {x} vs {y} (column scale {scale[(hb, k)]:.3e})"
    return None


def vtu_within(a, b, tol):
    """None when two .vtu files' data arrays agree within `tol` (per array), else the first difference."""
    import numpy as np
    from tethertools import vtu
    try:
        va, vb = vtu.check_vtu(a), vtu.check_vtu(b)
    except vtu.VtuError as e:
        return str(e)
    if (va["points"], va["cells"], va["time"]) != (vb["points"], vb["cells"], vb["time"]):
        return "sizes or time differ"
    floor = SCALE_FLOOR * max((float(np.max(np.abs(y))) for kind in ("point_data", "cell_data")
                               for y in vb[kind].values() if y.dtype.kind == "f" and y.size), default=0.0)
    for kind in ("point_data", "cell_data"):
        if sorted(va[kind]) != sorted(vb[kind]):
            return f"{kind} arrays differ"
        for name, x in va[kind].items():
            y = vb[kind][name]
            if x.dtype != y.dtype or x.shape != y.shape:
                return f"{name}: type or size differs"
            if x.dtype.kind != "f":
                if not np.array_equal(x, y):
                    return f"{name} differs"
                continue
            largest = max(float(np.max(np.abs(y))) if y.size else 0.0, floor)
            worst = float(np.max(np.abs(x - y))) if y.size else 0.0
            if worst > tol * largest:
                return f"{name}: differs by {worst:.3e} (largest {largest:.3e})"
    return None


def within_tolerance(before, after, name, tol):
    """None when file `name` of the two output directories agrees within `tol`, else why not."""
    a, b = os.path.join(before, name), os.path.join(after, name)
    if name.endswith(".vtu"):
        return vtu_within(a, b, tol)
    if not name.endswith(TEXT_SUFFIXES):
        return "binary file differs"
    with open(a, "rb") as fa, open(b, "rb") as fb:
        ta = normalised(name, fa.read(), before).decode("utf-8", errors="replace")
        tb = normalised(name, fb.read(), after).decode("utf-8", errors="replace")
    return text_within(ta, tb, tol, log=name.endswith(LOG_SUFFIXES))


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
    """Runs one case through both programs; returns (equal, files compared, within tolerance)."""
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
    near = []
    for name in files:
        why = None
        if args.tolerance is not None and not name.endswith("(only in one)"):
            why = within_tolerance(os.path.join(base, "before"), os.path.join(base, "after"), name, args.tolerance)
            if why is None:
                near.append(name)
                continue
        problems.append(name + (f" ({why})" if why else ""))
    status = "same" if not problems and not near else (
        f"within {args.tolerance:g}: " + ", ".join(near) if not problems else "DIFFERS: " + ", ".join(problems))
    print(f"{label}: exit {results['before'][0]}, {n} files: {status}", flush=True)
    return not problems, n, bool(near) and not problems


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
    p.add_argument("--tolerance", type=float, help="accept numbers within this relative difference (see above)")
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
    n_same = n_files = n_near = 0
    done = []
    for label, deck, options, _ in cases:
        if args.only and args.only not in label:
            continue
        same, n, near = compare_case(args, label, deck, options)
        n_same += same
        n_near += near
        n_files += n
        done.append(label)
        if options:
            continue
        for suffix, rst in restart_files(args, label, deck):
            same, n, near = compare_case(args, label + suffix, deck, [], restart_of=rst)
            n_same += same
            n_near += near
            n_files += n
            done.append(label + suffix)
    if args.tolerance is not None:
        print(f"{n_same} of {len(done)} cases agree: {n_same - n_near} byte for byte, {n_near} within "
              f"{args.tolerance:g} ({n_files} output files compared)")
    else:
        print(f"{n_same} of {len(done)} cases identical ({n_files} output files compared)")
    return 0 if n_same == len(done) else 1


if __name__ == "__main__":
    sys.exit(main())
