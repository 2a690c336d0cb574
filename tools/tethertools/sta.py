"""Reader of the status files of tether and CalculiX: `.sta` (one line per attempt,
then tether's verdict line) and tether's `.msg` (the message log).

A `.sta` attempt line is `STEP INC ATT ITRS [TOTITRS] TIME...`; ccx marks a failed
attempt with a trailing U on the attempt number. tether's last line is
`THE ANALYSIS HAS COMPLETED SUCCESSFULLY[: message]` or
`THE ANALYSIS HAS NOT BEEN COMPLETED: reason`.

  read(path)        [(step, increment, attempt, iterations, converged)]
  attempts(path)    the same as dicts, with total_iterations (TOTITRS, else ITRS)
  iterations(path)  (iterations of the converged attempts, TOTITRS of them, converged increments);
                    (None, None, None) when the file does not exist
  verdict(path)     (completed, message) of tether's verdict line; None when there is none
  converged_increments_in_msg(path)  [(step, increment, total time)] of the `.msg` lines
                    `step S increment I attempt A: time T, ... converged`
"""
import os
import re

_VERDICT = re.compile(r"^\s*THE ANALYSIS HAS (COMPLETED SUCCESSFULLY|NOT BEEN COMPLETED)\s*:?\s*(.*?)\s*$")
_MSG_CONVERGED = re.compile(r"^\s*step (\d+) increment (\d+) attempt \d+: time (\S+?),.*\d iterations, converged\s*$")


def attempts(path):
    """[{step, increment, attempt, iterations, total_iterations, converged}] of the attempt lines, in file order."""
    out = []
    with open(path, errors="replace") as f:
        for line in f:
            t = line.split()
            if len(t) < 4 or not t[0].isdigit() or not t[1].isdigit() or not t[3].isdigit():
                continue
            att = t[2]
            if not att.rstrip("U").isdigit():
                continue
            total = int(t[4]) if len(t) > 4 and t[4].isdigit() else int(t[3])
            out.append({"step": int(t[0]), "increment": int(t[1]), "attempt": int(att.rstrip("U")),
                        "iterations": int(t[3]), "total_iterations": total, "converged": not att.endswith("U")})
    return out


def read(path):
    """[(step, increment, attempt, iterations, converged)] of the attempt lines."""
    return [(a["step"], a["increment"], a["attempt"], a["iterations"], a["converged"]) for a in attempts(path)]


def iterations(path):
    """(sum of ITRS, sum of TOTITRS, count) over the converged attempts; (None, None, None) without the file."""
    if not os.path.exists(path):
        return None, None, None
    done = [a for a in attempts(path) if a["converged"]]
    return sum(a["iterations"] for a in done), sum(a["total_iterations"] for a in done), len(done)


def verdict(path):
    """(completed, message) of the last verdict line of a tether `.sta`; None when it has none
    (a ccx .sta, or a run that was killed)."""
    found = None
    with open(path, errors="replace") as f:
        for line in f:
            m = _VERDICT.match(line)
            if m:
                found = (m[1] == "COMPLETED SUCCESSFULLY", m[2])
    return found


def converged_increments_in_msg(path):
    """[(step, increment, total time)] of the converged attempts logged in a tether `.msg`."""
    out = []
    with open(path, errors="replace") as f:
        for line in f:
            m = _MSG_CONVERGED.match(line)
            if m:
                out.append((int(m[1]), int(m[2]), float(m[3])))
    return out
