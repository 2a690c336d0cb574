#!/usr/bin/python3
"""Plane-strain Hertz benchmark: generates the decks, runs CalculiX and tether, compares with the exact solution.

    hertz_bench.py [CASE ...] [--codes ccx,tether] [--workdir DIR] [--results FILE.md]
                   [--json FILE.json] [--ccx-reference FILE.json [--reference-from OLD.json]]
                   [--from-json OLD.json --results FILE.md]
                   [--ccx-max 230k]
                   [--tether build/bin/tether] [--ccx ccx] [--timeout 3600] [--threads 1]
                   [--increments 10] [--seat DELTA] [--wait-load 1.0 --wait-max 900]

A CASE is SIZE[/ELEMENT][/rigid]: 2k, 25k, 230k, 1M (target displacement dofs,
tools/make_hertz_deck.py --dofs), e.g. 25k, 2k/CPE8, 25k/CPE4/rigid. Default:
2k 25k 230k 1M with CPE4 on the elastic block.

For each case the deck is written once (WORK/CASE/hertz.inp, parameters in
hertz.json) and copied into WORK/CASE/ccx/ and WORK/CASE/tether/ (ccx writes
fixed-name scratch files, so each job has its own directory). The codes run one
after the other, never in parallel:
  ccx     `ccx -i hertz`                          (not for cases above --ccx-max)
  tether  `tether run hertz.inp -o DIR -q`
each under `/usr/bin/time -v` (wall time, user + system CPU, peak resident
memory) and killed after --timeout seconds, with OMP_NUM_THREADS=--threads.
Newton iterations: the sum of the ITRS column of the .sta (converged increments,
all steps) and, in brackets, all iterations including cut-back attempts (ccx:
the rows of its .cvg; tether: the sum of TOTITRS). The pressure figures come
from tools/hertz_summary.py on each code's .dat (its docstring says how).

A run that fails (exit status, timeout, no contact pressure) becomes a row
"CODE: failed (message)"; the script goes on with the next run. The table is
printed and written as Markdown to --results (with the machine, the load, the
versions and the command); --json writes everything; --ccx-reference merges
compact ccx records (one per case, with date, command and load) into a reference
file (bench/hertz/ccx_reference.json): records of the cases run replace the old
ones, the others are kept; --reference-from takes them from an earlier --json,
and --from-json rewrites --results from one (both without running anything).
--wait-load X waits (up to --wait-max s) before each run until the 1-minute load
average is below X (the machine is shared); the load at the start of each run is
recorded either way. Exit status 0 (failed runs are reported, not fatal), 2 bad
arguments or no deck could be generated.
"""
import argparse
import datetime
import json
import os
import platform
import re
import shutil
import signal
import subprocess
import sys
import time

from tethertools import hertz_summary
from tethertools import make_hertz_deck
import tethertools.sta

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # tools/: the scripts
ROOT = os.path.normpath(os.path.join(TOOLS, ".."))

# ----------------------------------------------------------------------------- runs
def run_timed(cmd, cwd, timeout, env):
    """Runs `cmd` in `cwd` under /usr/bin/time -v; dict(rc, wall, cpu, rss_kb, stdout, stderr, timed_out)."""
    gnu_time = "/usr/bin/time" if os.access("/usr/bin/time", os.X_OK) else None
    time_file = os.path.join(cwd, "time.txt")
    full = ([gnu_time, "-v", "-o", time_file] if gnu_time else []) + cmd
    load = os.getloadavg()[0]
    start = time.monotonic()
    with open(os.path.join(cwd, "stdout.txt"), "w") as out, open(os.path.join(cwd, "stderr.txt"), "w") as err:
        proc = subprocess.Popen(full, cwd=cwd, env=env, stdout=out, stderr=err, start_new_session=True)
        timed_out = False
        try:
            proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            os.killpg(proc.pid, signal.SIGKILL)  # the process group started here, nothing else
            proc.wait()
    result = {"rc": proc.returncode, "wall": time.monotonic() - start, "cpu": None, "rss_kb": None,
              "timed_out": timed_out, "load_at_start": load, "command": " ".join(cmd)}
    if gnu_time and os.path.exists(time_file):
        with open(time_file) as f:
            text = f.read()
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        result["rss_kb"] = int(m.group(1)) if m else None
        m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text)
        if m:
            parts = [float(p) for p in m.group(1).split(":")]
            result["wall"] = sum(p * 60 ** i for i, p in enumerate(reversed(parts)))
        user = re.search(r"User time \(seconds\): (\S+)", text)
        system = re.search(r"System time \(seconds\): (\S+)", text)
        if user and system:
            result["cpu"] = float(user.group(1)) + float(system.group(1))
        m = re.search(r"Exit status: (\d+)", text)
        if m and not timed_out:
            result["rc"] = int(m.group(1))
    for name in ("stdout", "stderr"):
        with open(os.path.join(cwd, name + ".txt"), errors="replace") as f:
            result[name] = f.read()
    return result


def cvg_iterations(path):
    """Rows of ccx's .cvg: every iteration, cut-back attempts included."""
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return sum(1 for line in f if len(line.split()) >= 5 and all(re.fullmatch(r"\d+", v) for v in line.split()[:4]))


def failure_message(code, run, workdir):
    if run["timed_out"]:
        return f"timed out after {run['wall']:.0f} s"
    text = run["stdout"] + "\n" + run["stderr"]
    if code == "ccx":
        errors = [l.strip() for l in text.splitlines() if "*ERROR" in l]
        if errors:
            return f"exit {run['rc']}: {errors[-1]}"
        if "Job finished" not in run["stdout"]:
            return f"exit {run['rc']}: no 'Job finished' (see {workdir}/stdout.txt)"
    lines = [l.strip() for l in run["stderr"].splitlines() if l.strip()] or \
            [l.strip() for l in run["stdout"].splitlines() if l.strip()]
    return f"exit {run['rc']}: {lines[-1] if lines else 'no message'}"


def wait_for_load(limit, max_wait):
    if limit is None:
        return
    start = time.monotonic()
    while os.getloadavg()[0] >= limit and time.monotonic() - start < max_wait:
        time.sleep(10)


# ----------------------------------------------------------------------------- cases
def parse_case(text, default_element):
    parts = text.split("/")
    size = parts[0]
    make_hertz_deck.parse_count(size)  # validates
    element, rigid = default_element, False
    for p in parts[1:]:
        if p.upper() in ("CPE4", "CPE8"):
            element = p.upper()
        elif p.lower() == "rigid":
            rigid = True
        else:
            raise argparse.ArgumentTypeError(f"{text}: unknown case part {p!r} (CPE4, CPE8 or rigid)")
    name = f"{size}_{element.lower()}" + ("_rigid" if rigid else "")
    return {"spec": text, "size": size, "element": element, "rigid": rigid, "name": name}


def generate(case, work, args):
    os.makedirs(work, exist_ok=True)
    deck, meta = os.path.join(work, "hertz.inp"), os.path.join(work, "hertz.json")
    argv = [deck, "--dofs", case["size"], "--element", case["element"], "--increments", str(args.increments),
            "--json", meta] + (["--rigid-flat"] if case["rigid"] else []) + (["--seat", str(args.seat)] if args.seat else [])
    start = time.monotonic()
    make_hertz_deck.main(argv)
    with open(meta) as f:
        info = json.load(f)
    info["generate_seconds"] = time.monotonic() - start
    info["generator_command"] = "tools/make_hertz_deck.py " + " ".join(
        os.path.basename(a) if a in (deck, meta) else a for a in argv)
    return deck, info


def run_code(code, deck, work, args):
    d = os.path.join(work, code)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    shutil.copy(deck, os.path.join(d, "hertz.inp"))
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    wait_for_load(args.wait_load, args.wait_max)
    if code == "ccx":
        cmd = ["timeout", str(int(args.timeout) + 10), args.ccx, "-i", "hertz"]
    elif code == "tether-budget":
        cmd = [args.tether, "run", "hertz.inp", "-o", d, "-q", "--memory", f"{args.tether_memory:g}"]
    else:
        cmd = [args.tether, "run", "hertz.inp", "-o", d, "-q"]
    run = run_timed(cmd, d, args.timeout, env)
    row = {"code": code, "dir": d, **{k: v for k, v in run.items() if k not in ("stdout", "stderr")}}
    its, total, incs = tethertools.sta.iterations(os.path.join(d, "hertz.sta"))
    if code == "ccx":
        total = cvg_iterations(os.path.join(d, "hertz.cvg"))
    row.update(iterations=its, iterations_all=total, increments=incs)
    ok = run["rc"] == 0 and not run["timed_out"] and (code != "ccx" or "Job finished" in run["stdout"])
    if not ok:
        row["status"] = "failed"
        row["message"] = failure_message(code, run, d)
        return row
    try:
        summary = hertz_summary.summarise(os.path.join(d, "hertz.dat"), deck)
    except SystemExit as e:
        row.update(status="failed", message=f"no contact pressure: {e}")
        return row
    if "peak" not in summary:
        row.update(status="failed", message="no node in contact at the end")
        return row
    summary.pop("points", None)
    row["status"] = "ok"
    row["summary"] = summary
    try:
        hertz_summary.plot(hertz_summary.summarise(os.path.join(d, "hertz.dat"), deck), os.path.join(d, "pressure.png"), [code])
    except Exception as e:  # a missing matplotlib must not lose the figures
        row["plot_error"] = str(e)
    return row


# ----------------------------------------------------------------------------- report
def pct(v):
    return "–" if v is None else f"{100 * v:+.2f} %"


def fmt(v, spec):
    return "–" if v is None else format(v, spec)


def table(rows):
    head = ("| case | code | dofs | wall [s] | CPU [s] | Newton its (all) | incs | peak mem [MB] | "
            "p0 err (peak) | p0 err (fit) | a err (fit) | a err (edge) | force vs P/2 | pressure from | load |")
    out = [head, "|" + " --- |" * 15]
    for r in rows:
        case = r["case"]
        if r["status"] != "ok":
            out.append(f"| {case['spec']} | {r['code']} | {r['dofs']} | {fmt(r.get('wall'), '.1f')} | {fmt(r.get('cpu'), '.1f')} "
                       f"| | | {fmt(r['rss_kb'] / 1024 if r.get('rss_kb') else None, '.0f')} "
                       f"| {r['code']}: {r['status']} ({r.get('message', '')}) | | | | | | {fmt(r.get('load_at_start'), '.1f')} |")
            continue
        s = r["summary"]
        its = f"{r['iterations']} ({r['iterations_all']})" if r.get("iterations") is not None else "–"
        out.append(f"| {case['spec']} | {r['code']} | {r['dofs']} | {r['wall']:.1f} | {fmt(r.get('cpu'), '.1f')} | {its} | "
                   f"{fmt(r.get('increments'), 'd')} | {fmt(r['rss_kb'] / 1024 if r.get('rss_kb') else None, '.0f')} | "
                   f"{pct(s.get('peak_error'))} | {pct(s.get('p0_fit_error'))} | {pct(s.get('a_fit_error'))} | "
                   f"{pct(s.get('edge_error'))} | {pct(s.get('contact_force_error'))} | {s['source']} | "
                   f"{r['load_at_start']:.1f} |")
    return "\n".join(out)


def machine():
    cpu = platform.processor() or ""
    try:
        with open("/proc/cpuinfo") as f:
            m = re.search(r"model name\s*:\s*(.*)", f.read())
            cpu = m.group(1).strip() if m else cpu
    except OSError:
        pass
    mem = None
    try:
        with open("/proc/meminfo") as f:
            m = re.search(r"MemTotal:\s*(\d+)", f.read())
            mem = f"{int(m.group(1)) / 1024 / 1024:.0f} GB" if m else None
    except OSError:
        pass
    return {"cpu": cpu, "cores": os.cpu_count(), "memory": mem, "system": platform.platform(),
            "hostname": platform.node()}


def versions(args):
    out = {}
    ccx = shutil.which(args.ccx)
    if ccx:
        text = subprocess.run(["timeout", "60", ccx, "-v"], capture_output=True, text=True).stdout
        out["ccx"] = " ".join(l.strip() for l in text.splitlines() if "Version" in l) or "unknown"
    if os.access(args.tether, os.X_OK):
        text = subprocess.run([args.tether, "--version"], capture_output=True, text=True).stdout.strip()
        out["tether"] = text or "unknown"
    git = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    if git.returncode == 0:
        out["git"] = git.stdout.strip()
    gmsh = subprocess.run(["gmsh", "--version"], capture_output=True, text=True)
    out["gmsh"] = (gmsh.stdout + gmsh.stderr).strip()
    return out


def write_results(path, rows, decks, meta):
    lines = ["# Plane-strain Hertz benchmark: results", "",
             f"Written by `tools/hertz_bench.py` ({meta['date']}); command: `{meta['command']}`.", "",
             f"- machine: {meta['machine']['cpu']}, {meta['machine']['cores']} cores, {meta['machine']['memory']} "
             f"({meta['machine']['system']}); shared: the 1-minute load average at the start of each run is in the "
             "last column",
             "- versions: " + ", ".join(f"{k} {v}" for k, v in meta["versions"].items()),
             f"- threads: OMP_NUM_THREADS={meta['threads']}; timeout {meta['timeout']:g} s per run", "",
             "Exact (tools/hertz_exact.py): elastic block a = "
             f"{meta['exact']['elastic']['a']:.5g} mm, p0 = {meta['exact']['elastic']['p0']:.5g} MPa; rigid flat a = "
             f"{meta['exact']['rigid']['a']:.5g} mm, p0 = {meta['exact']['rigid']['p0']:.5g} MPa.", "",
             "## Decks", "",
             "| case | element | body | dofs | nodes | elements | h [mm] | h/a | core [mm] | slave nodes | generated in [s] |",
             "|" + " --- |" * 11]
    for case, info in decks:
        lines.append(f"| {case['spec']} | {info['element']} | {'rigid flat' if info['rigid_flat'] else 'elastic block'} | "
                     f"{info['dofs']} | {info['nodes']} | {info['elements']} | {info['h']:.4g} | {info['h_over_a']:.4f} | "
                     f"{info['core']:.4g} | {info['slave_nodes']} | {info['generate_seconds']:.1f} |")
    lines += ["", "## Runs", "", table(rows), "",
              "Columns: Newton its = sum of ITRS over the converged increments of all steps (in brackets all "
              "iterations, cut-back attempts included: ccx .cvg rows, tether TOTITRS); p0 err (peak) = largest nodal "
              "pressure vs p0; p0/a err (fit) = least squares of p² = A − B x² over the nodes with p ≥ peak/2; "
              "a err (edge) = where the Hertz profile through the last two nodes in contact vanishes (resolution: "
              "one element); force = integral of the nodal pressure vs P/2. See docs/hertz_benchmark.md.", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


# ----------------------------------------------------------------------------- main
def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("cases", nargs="*", default=["2k", "25k", "230k", "1M"])
    ap.add_argument("--element", default="CPE4", type=str.upper, choices=["CPE4", "CPE8"], help="default element of the cases")
    ap.add_argument("--codes", default="ccx,tether", help="comma-separated: ccx, tether (default both)")
    ap.add_argument("--workdir", default="/tmp/hertz_bench", help="where decks and runs go (default /tmp/hertz_bench)")
    ap.add_argument("--results", help="write the Markdown table here (e.g. bench/hertz/results.md)")
    ap.add_argument("--json", help="write all figures here")
    ap.add_argument("--ccx-reference", help="write the ccx figures here (bench/hertz/ccx_reference.json)")
    ap.add_argument("--from-json", metavar="RESULTS.json",
                    help="no runs: rewrite --results from an earlier --json file")
    ap.add_argument("--reference-from", metavar="RESULTS.json",
                    help="no runs: merge the ccx rows of an earlier --json file into --ccx-reference")
    ap.add_argument("--ccx-max", default="230k", type=make_hertz_deck.parse_count,
                    help="largest target size run in ccx (default 230k: ~260 s, 3.9 GB; 1M needs far more)")
    ap.add_argument("--tether", default=os.path.join(ROOT, "build", "bin", "tether"))
    ap.add_argument("--ccx", default="ccx")
    ap.add_argument("--tether-memory", type=float, metavar="MB",
                    help="also run tether with --memory MB (code 'tether-budget': MUMPS factors out of core "
                         "when they would not fit)")
    ap.add_argument("--timeout", type=float, default=3600, help="seconds per run (default 3600)")
    ap.add_argument("--threads", type=int, default=1, help="OMP_NUM_THREADS for both codes (default 1)")
    ap.add_argument("--increments", type=int, default=10, help="load increments (make_hertz_deck.py, default 10)")
    ap.add_argument("--seat", type=float, default=0.0, metavar="DELTA",
                    help="decks with a seating step (make_hertz_deck.py --seat; default: pure load control)")
    ap.add_argument("--wait-load", type=float, help="wait before each run until the 1-minute load is below this")
    ap.add_argument("--wait-max", type=float, default=900, help="longest wait for --wait-load [s] (default 900)")
    args = ap.parse_args(argv)
    if args.reference_from:
        if not args.ccx_reference:
            ap.error("--reference-from needs --ccx-reference")
        import_reference(args.ccx_reference, args.reference_from)
        return 0
    if args.from_json:
        if not args.results:
            ap.error("--from-json needs --results")
        with open(args.from_json) as f:
            data = json.load(f)
        decks = [(parse_case(d["case"], args.element), d) for d in data["decks"]]
        rows = [{**r, "case": parse_case(r["case"], args.element)} for r in data["runs"]]
        write_results(args.results, rows, decks, data["meta"])
        print(f"written: {args.results} (from {args.from_json})")
        return 0
    try:
        cases = [parse_case(c, args.element) for c in args.cases]
    except argparse.ArgumentTypeError as e:
        ap.error(str(e))
    codes = [c.strip() for c in args.codes.split(",") if c.strip()]
    if args.tether_memory is not None and args.tether_memory <= 0:
        ap.error("--tether-memory: a positive number of MB")
    if args.tether_memory and "tether-budget" not in codes:
        codes.append("tether-budget")
    if any(c not in ("ccx", "tether", "tether-budget") for c in codes):
        ap.error("--codes: ccx, tether and/or tether-budget (the last needs --tether-memory)")
    if "tether-budget" in codes and not args.tether_memory:
        ap.error("code tether-budget needs --tether-memory MB")
    args.tether = os.path.abspath(args.tether)
    meta = {"date": datetime.datetime.now().astimezone().isoformat(timespec="seconds"),
            "command": "tools/hertz_bench.py " + " ".join(argv if argv is not None else sys.argv[1:]),
            "machine": machine(), "versions": versions(args), "threads": args.threads, "timeout": args.timeout,
            "exact": {"elastic": make_hertz_deck.hertz_exact.hertz(), "rigid": make_hertz_deck.hertz_exact.hertz(rigid_flat=True)}}
    rows, decks = [], []
    for case in cases:
        work = os.path.join(os.path.abspath(args.workdir), case["name"])
        print(f"== {case['spec']}: generating the deck in {work}", flush=True)
        try:
            deck, info = generate(case, work, args)
        except Exception as e:  # gmsh missing or failing: report, go on
            print(f"   deck generation failed: {e}", file=sys.stderr)
            continue
        decks.append((case, info))
        for code in codes:
            row = {"case": case, "code": code, "dofs": info["dofs"]}
            if code == "ccx" and shutil.which(args.ccx) is None:
                row.update(status="failed", message=f"'{args.ccx}' not found")
            elif code == "ccx" and make_hertz_deck.parse_count(case["size"]) > args.ccx_max:
                row.update(status="skipped", message=f"above --ccx-max {args.ccx_max}")
            elif code.startswith("tether") and not os.access(args.tether, os.X_OK):
                row.update(status="failed", message=f"{args.tether} not found (build it: see README)")
            else:
                print(f"   {code} ...", end="", flush=True)
                row.update(run_code(code, deck, work, args))
                print(f" {row['status']} in {row.get('wall', 0):.1f} s"
                      + (f": {row['message']}" if row["status"] != "ok" else ""), flush=True)
            rows.append(row)
    if not decks:
        print("no deck could be generated", file=sys.stderr)
        return 2
    print()
    print(table(rows))
    if args.results:
        write_results(args.results, rows, decks, meta)
        print(f"\nwritten: {args.results}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"meta": meta, "decks": [{"case": c["spec"], **i} for c, i in decks],
                       "runs": [{**r, "case": r["case"]["spec"]} for r in rows]}, f, indent=2, default=str)
        print(f"written: {args.json}")
    if args.ccx_reference:
        merge_reference(args.ccx_reference, reference_records(rows, {c["spec"]: i for c, i in decks}, meta), meta)
    return 0


def import_reference(reference, results_json):
    """Merges the ccx rows of an earlier --json file into the reference file (no runs)."""
    with open(results_json) as f:
        data = json.load(f)
    decks = {d["case"]: d for d in data["decks"]}
    merge_reference(reference, reference_records(data["runs"], decks, data["meta"]), data["meta"])


def reference_records(rows, decks, meta):
    """Compact ccx records (one per case) with the run's context."""
    out = []
    for r in rows:
        if r["code"] != "ccx" or r.get("status") not in ("ok", "failed"):
            continue
        spec = r["case"]["spec"] if isinstance(r["case"], dict) else r["case"]
        info = decks.get(spec, {})
        s = r.get("summary", {})
        rec = {"case": spec, "element": info.get("element"), "body": "rigid flat" if info.get("rigid_flat") else "elastic block",
               "dofs": r["dofs"], "nodes": info.get("nodes"), "elements": info.get("elements"), "h": info.get("h"),
               "seat_mm": info.get("seat"), "increments_requested": info.get("increments"),
               "status": r["status"], "message": r.get("message"),
               "wall_s": round(r["wall"], 2) if r.get("wall") is not None else None,
               "cpu_s": round(r["cpu"], 2) if r.get("cpu") is not None else None,
               "peak_memory_mb": round(r["rss_kb"] / 1024, 1) if r.get("rss_kb") else None,
               "newton_iterations": r.get("iterations"), "newton_iterations_all": r.get("iterations_all"),
               "increments": r.get("increments"), "load_at_start": round(r.get("load_at_start", 0), 2),
               "peak_pressure": s.get("peak"), "peak_error": s.get("peak_error"),
               "p0_fit_error": s.get("p0_fit_error"), "a_fit_error": s.get("a_fit_error"),
               "a_edge_error": s.get("edge_error"), "contact_force_error": s.get("contact_force_error"),
               "pressure_from": s.get("source"),
               "date": meta["date"], "command": r.get("command"), "bench_command": meta["command"],
               "deck_command": info.get("generator_command")}
        out.append(rec)
    return out


def merge_reference(path, records, run_meta):
    """Writes the records into the reference file, replacing those of the same case and keeping the others."""
    old = {"records": []}
    if os.path.exists(path):
        with open(path) as f:
            old = json.load(f)
    cases = {r["case"] for r in records}
    kept = [r for r in old.get("records", []) if r["case"] not in cases]
    head = dict(REFERENCE_META, machine=run_meta["machine"], ccx_version=run_meta["versions"].get("ccx"),
                threads=run_meta.get("threads"))
    with open(path, "w") as f:
        json.dump({**head, "records": kept + records}, f, indent=2)
    print(f"written: {path} ({len(records)} record(s) updated, {len(kept)} kept)")


REFERENCE_META = {
    "what": "CalculiX 2.20 on the plane-strain Hertz decks of tools/make_hertz_deck.py (half model, R 10 mm, "
            "E 200 GPa, nu 0.3, P 2000 N/mm); written by tools/hertz_bench.py --ccx-reference",
    "fields": "wall_s/cpu_s/peak_memory_mb from /usr/bin/time -v (cpu = user + system); newton_iterations = sum of ITRS "
              "in the .sta, _all = rows of the .cvg; errors relative to the exact a, p0 (tools/hertz_summary.py: peak "
              "= largest nodal CSTR pressure, fit = p^2 = A - B x^2 over p >= peak/2, edge = profile through the last "
              "two closed nodes); load_at_start = 1-minute load average of the shared machine",
}


if __name__ == "__main__":
    sys.exit(main())
