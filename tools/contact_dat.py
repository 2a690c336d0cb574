"""Small readers shared by tools/mindlin_summary.py and tools/ironing_summary.py.

  read_deck(path)  -> Deck: node coordinates, node sets, element connectivity,
                      element-face surfaces and the *HEADING line's key=value pairs
                      of the decks written by tools/make_mindlin_deck.py and
                      tools/make_ironing_deck.py (not a general deck reader).
  read_dat(path)   -> list of blocks {title, set, time, rows} of a .dat written by
                      tether or CalculiX (node blocks `... for set S and time T`,
                      contact blocks `... for all contact elements and time T` and
                      tether's `... for pair P and time T`).
  read_sta(path)   -> list of (step, increment, attempt, iterations, converged) of a
                      .sta file of either code (ccx marks a failed attempt with a
                      trailing U on the attempt number).
  slave_rows(deck, rows) -> {deck node id: (press, tang)} from CSTR rows; ccx's ids of
                      its one-layer 3D expansion (2D node n -> nk + 3 (n - 1) + 1..3,
                      nk = highest node id of the deck) are mapped back and the
                      layers averaged.
"""
import re

_NODE_HEADER = re.compile(r"^\s*(?P<title>\S.*?)\s+for\s*set\s+(?P<set>\S+)\s+and\s+time\s+(?P<time>\S+)\s*$")
_CONTACT_HEADER = re.compile(
    r"^\s*(?P<title>\S.*?)\s*\bfor\s*(?:pair\s+(?P<set>\S+)\s+and\s+|all\s+contact\s+elements\s+and\s+)?"
    r"time\s*(?P<time>[-+0-9.]\S*)\s*$")


def _number(token):
    return float(token.replace("D", "E").replace("d", "e"))


def read_dat(path):
    blocks, current = [], None
    with open(path) as f:
        for line in f:
            if not line.strip():
                continue
            m = _NODE_HEADER.match(line) or _CONTACT_HEADER.match(line)
            if m:
                current = {"title": m["title"].strip(), "set": (m["set"] or "").upper(), "time": _number(m["time"]),
                           "rows": []}
                blocks.append(current)
                continue
            if current is None:
                continue
            try:
                current["rows"].append([_number(t) for t in line.split()])
            except ValueError:
                current = None  # some other text (ccx prints warnings into the .dat rarely)
    return blocks


def blocks_of(blocks, title_start, set_name=None):
    """Blocks whose title starts with title_start (and for set set_name), in file order."""
    t = title_start.lower()
    return [b for b in blocks if b["title"].lower().startswith(t) and (set_name is None or b["set"] == set_name.upper())]


def read_sta(path):
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


class Deck:
    def __init__(self, path):
        self.path = path
        self.xy, self.nsets, self.elements, self.surfaces, self.heading = {}, {}, {}, {}, {}
        self.etype = {}
        kw, params, name = None, {}, None
        with open(path) as f:
            lines = f.read().splitlines()
        i = 0
        while i < len(lines):
            line = lines[i].strip()
            i += 1
            if not line or line.startswith("**"):
                continue
            if line.startswith("*"):
                parts = [p.strip() for p in line[1:].split(",")]
                kw = parts[0].upper()
                params = {}
                for p in parts[1:]:
                    k, _, v = p.partition("=")
                    params[k.strip().upper()] = v.strip()
                if kw == "HEADING" and i < len(lines):
                    for tok in lines[i].split():
                        k, eq, v = tok.partition("=")
                        if eq:
                            self.heading[k] = v
                    i += 1
                if kw == "NSET":
                    name = params["NSET"].upper()
                    self.nsets.setdefault(name, [])
                elif kw == "SURFACE":
                    name = params["NAME"].upper()
                    self.surfaces[name] = []
                elif kw == "ELEMENT":
                    name = params.get("TYPE", "").upper()
                continue
            fields = [v.strip() for v in line.split(",") if v.strip()]
            if kw == "NODE":
                self.xy[int(fields[0])] = (float(fields[1]), float(fields[2]))
            elif kw == "NSET":
                self.nsets[name] += [int(v) for v in fields]
            elif kw == "ELEMENT":
                self.elements[int(fields[0])] = [int(v) for v in fields[1:]]
                self.etype[int(fields[0])] = name
            elif kw == "SURFACE":
                self.surfaces[name].append((int(fields[0]), int(fields[1].upper().lstrip("S"))))

    def number(self, key):
        return float(self.heading[key])

    def face_nodes(self, element, face):
        e = self.elements[element]
        nodes = [e[face - 1], e[face % 4]]
        if len(e) == 8:
            nodes.append(e[3 + face])
        return nodes

    def tributary_lengths(self, surface):
        """{node id: tributary length} of an element-face surface in the reference configuration
        (int N_a ds: half the face length per end node for 2-node faces; 1/6, 1/6, 2/3 for 3-node
        faces, straight-face approximation)."""
        out = {}
        for el, face in self.surfaces[surface.upper()]:
            nodes = self.face_nodes(el, face)
            (x1, y1), (x2, y2) = self.xy[nodes[0]], self.xy[nodes[1]]
            length = ((x2 - x1) ** 2 + (y2 - y1) ** 2) ** 0.5
            weights = [0.5, 0.5] if len(nodes) == 2 else [1 / 6, 1 / 6, 2 / 3]
            for n, w in zip(nodes, weights):
                out[n] = out.get(n, 0.0) + w * length
        return out


def slave_rows(deck, rows):
    """{deck node id: (press, tang1)} of CSTR rows; ccx's expanded 3D ids mapped back (layers averaged)."""
    nk = max(deck.xy)
    acc = {}
    for r in rows:
        node = int(r[0])
        if node > nk:
            node = (node - nk - 1) // 3 + 1
        acc.setdefault(node, []).append((r[1], r[2]))
    return {n: (sum(v[0] for v in vals) / len(vals), sum(v[1] for v in vals) / len(vals)) for n, vals in acc.items()}
