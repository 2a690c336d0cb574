"""Reader of `.dat` files in CalculiX's block layout (tether writes the same layout).

A block is a header line `<title> for set <SET> and time <T>` followed by rows
of whitespace-separated numbers. Contact headers are read too: ccx's `<title>
for all contact elements and time <T>` (`forall` in ccx's CELS header) and
`<title> for time <T>` (set ""), and tether's `<title> for pair <NAME> and time
<T>` (set NAME, e.g. `last_block(blocks, "contact state", "SLAVE-MASTER")`).

parse(text) / read(path) return a list of dicts with keys title, set, time and
rows (lists of floats), in file order.
"""
import re

_HEADER = re.compile(r"^\s*(?P<title>\S.*?)\s*for\s*set\s+(?P<set>\S+)\s+and\s+time\s+(?P<time>\S+)\s*$")
_CONTACT_HEADER = re.compile(
    r"^\s*(?P<title>\S.*?)\s*\bfor\s*(?:pair\s+(?P<set>\S+)\s+and\s+|all\s+contact\s+elements\s+and\s+)?"
    r"time\s*(?P<time>[-+0-9.]\S*)\s*$")


def _number(token):
    return float(token.replace("D", "E").replace("d", "e"))


def parse(text, strict=True):
    """Blocks of a .dat text, in file order.

    strict: a line that is neither a header nor numbers is an error (ValueError
    naming the line); not strict: such a line (ccx rarely prints a warning into
    its .dat) ends the current block and is skipped.
    """
    blocks, current = [], None
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        header = _HEADER.match(line) or _CONTACT_HEADER.match(line)
        if header:
            current = {"title": header["title"].strip(), "set": header["set"] or "", "time": _number(header["time"]),
                       "rows": []}
            blocks.append(current)
            continue
        if current is None:
            if strict:
                raise ValueError(f"line {number}: data before any block header: {line!r}")
            continue
        try:
            current["rows"].append([_number(t) for t in line.split()])
        except ValueError:
            if strict:
                raise ValueError(f"line {number}: not a row of numbers: {line!r}") from None
            current = None
    return blocks


def read(path, strict=True):
    """parse() of the file at `path`."""
    with open(path) as f:
        return parse(f.read(), strict)


def blocks_of(blocks, title_start, set_name=None):
    """Blocks whose title starts with `title_start` (and for set `set_name`), in file order (case-insensitive)."""
    t = title_start.lower()
    return [b for b in blocks
            if b["title"].lower().startswith(t) and (set_name is None or b["set"].upper() == set_name.upper())]


def last_block(blocks, title_start, set_name):
    """The last block whose title starts with `title_start` for set `set_name`; KeyError when there is none."""
    found = blocks_of(blocks, title_start, set_name)
    if not found:
        raise KeyError(f"no '{title_start}' block for set {set_name}")
    return found[-1]


def pick(blocks, title_start, set_name=None, time=None):
    """The last block (or the last one at `time`, to 1e-6 relative) whose title starts with
    `title_start` for set `set_name` (None: any set); None when there is none."""
    found = blocks_of(blocks, title_start, set_name)
    if time is not None:
        found = [b for b in found if abs(b["time"] - time) <= 1e-6 * max(1.0, abs(time))]
    return found[-1] if found else None


def slave_rows(max_node, rows):
    """{deck node id: (press, tang1)} of contact stress (CSTR) rows. CalculiX prints
    the ids of its one-layer 3D expansion of a 2D mesh (2D node n -> nk + 3 (n - 1)
    + 1..3 with nk = `max_node`, the highest node id of the deck): they are mapped
    back and the layers averaged."""
    acc = {}
    for r in rows:
        node = int(r[0])
        if node > max_node:
            node = (node - max_node - 1) // 3 + 1
        acc.setdefault(node, []).append((r[1], r[2]))
    return {n: (sum(v[0] for v in vals) / len(vals), sum(v[1] for v in vals) / len(vals)) for n, vals in acc.items()}
