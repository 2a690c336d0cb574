"""Reader for `.dat` files in CalculiX's block layout (tether writes the same layout).

A block is a header line `<title> for set <SET> and time <T>` followed by rows
of whitespace-separated numbers. `read(path)` returns a list of dicts with
keys title, set, time and rows (lists of floats).

Contact headers are read too: ccx's `<title> for all contact elements and time
<T>` (`forall` in ccx's CELS header) and `<title> for time <T>` (set ""), and
tether's `<title> for pair <NAME> and time <T>` (set NAME, e.g.
`last_block(blocks, "contact state", "SLAVE-MASTER")`). A dynamic increment's
energies read as `energies (ALLKE,...) and time <T>` (set "").
"""
import re

_HEADER = re.compile(r"^\s*(?P<title>\S.*?)\s*for\s*set\s+(?P<set>\S+)\s+and\s+time\s+(?P<time>\S+)\s*$")
_CONTACT_HEADER = re.compile(
    r"^\s*(?P<title>\S.*?)\s*\bfor\s*(?:pair\s+(?P<set>\S+)\s+and\s+|all\s+contact\s+elements\s+and\s+)?"
    r"time\s*(?P<time>[-+0-9.]\S*)\s*$")
# A whole-model block of a dynamic increment: `energies (ALLKE,...) and time <T>` (set "").
_MODEL_HEADER = re.compile(r"^\s*(?P<title>energies\s*\(.*?\))\s+and\s+time\s+(?P<time>\S+)\s*$")


def _number(token):
    return float(token.replace("D", "E").replace("d", "e"))


def parse(text):
    """Blocks of a .dat text, in file order."""
    blocks, current = [], None
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        header = _HEADER.match(line) or _CONTACT_HEADER.match(line) or _MODEL_HEADER.match(line)
        if header:
            named = header.groupdict().get("set")
            current = {"title": header["title"], "set": named or "", "time": _number(header["time"]),
                       "rows": []}
            blocks.append(current)
            continue
        if current is None:
            raise ValueError(f"line {number}: data before any block header: {line!r}")
        current["rows"].append([_number(t) for t in line.split()])
    return blocks


def read(path):
    with open(path) as f:
        return parse(f.read())


def last_block(blocks, title_start, set_name):
    """The last block whose title starts with `title_start` for set `set_name` (case-insensitive)."""
    found = [b for b in blocks if b["title"].lower().startswith(title_start.lower()) and b["set"].upper() == set_name.upper()]
    if not found:
        raise KeyError(f"no '{title_start}' block for set {set_name}")
    return found[-1]
