"""Reader of `.sta` files of tether and CalculiX."""


def read(path):
    """[(step, increment, attempt, iterations, converged)] of the attempt lines
    (ccx marks a failed attempt with a trailing U on the attempt number)."""
    out = []
    with open(path) as f:
        for line in f:
            t = line.split()
            if len(t) < 4 or not t[0].isdigit() or not t[1].isdigit():
                continue
            att = t[2]
            failed = att.endswith("U")
            try:
                out.append((int(t[0]), int(t[1]), int(att.rstrip("U")), int(t[3]), not failed))
            except ValueError:
                continue
    return out
