"""Reader of ABAQUS/CalculiX decks for the tools: the model's geometry and
keywords as plain dicts. It reads what the tools need and trusts the deck
(tether's own reader validates; run `tether check` for that).

  cards(path)          [(params, data lines, file)] per keyword line (a keyword line
                       ending with a comma continues on the next), *INCLUDEs followed
                       (relative to the including file)
  parse_keyword(line)  {"_kw": "*NAME WITH SPACES", "PARAM": "value", ...}
  include_files(path)  the files a deck *INCLUDEs, relative to its folder
  Deck(path)           nodes, elements, sets, surfaces, heading, keywords
"""
import os
import re

NODES_PER_TYPE = {}
for _family in ("CPE", "CPS", "CAX"):
    NODES_PER_TYPE.update({f"{_family}3": 3, f"{_family}6": 6, f"{_family}4": 4, f"{_family}4R": 4,
                           f"{_family}8": 8, f"{_family}8R": 8})


def parse_keyword(line):
    """The keyword (upper case, blanks normalised) and parameters of a keyword line;
    parameter names upper case, values as written ("" for a flag)."""
    parts = [p.strip() for p in line.split(",")]
    params = {"_kw": "*" + " ".join(parts[0][1:].upper().split())}
    for p in parts[1:]:
        if not p:
            continue
        if "=" in p:
            k, v = p.split("=", 1)
            params[" ".join(k.split()).upper()] = v.strip()
        else:
            params[p.strip().upper()] = ""
    return params


def cards(path, _seen=None):
    """[(params, data lines, file)] of every keyword of the deck in order, the
    *INCLUDEd files' keywords in place of the *INCLUDE (each file once)."""
    seen = set() if _seen is None else _seen
    path = os.path.abspath(path)
    if path in seen:
        return []
    seen.add(path)
    out, current = [], None
    with open(path, errors="replace") as f:
        lines = iter(f.read().splitlines())
        for raw in lines:
            line = raw.strip()
            if not line or line.startswith("**"):
                continue
            if line.startswith("*"):
                while line.endswith(","):  # a keyword line continued on the next line
                    more = next(lines, "").strip()
                    if not more:
                        break
                    line += more
                params = parse_keyword(line)
                if params["_kw"] == "*INCLUDE" and "INPUT" in params:
                    inc = params["INPUT"]
                    out.extend(cards(inc if os.path.isabs(inc) else os.path.join(os.path.dirname(path), inc), seen))
                    current = None
                    continue
                current = (params, [], path)
                out.append(current)
            elif current is not None:
                current[1].append(line)
    return out


def include_files(deck):
    """Relative paths of the files *INCLUDEd by `deck` (recursively), relative to its folder."""
    out, base = [], os.path.dirname(os.path.abspath(deck))

    def walk(path):
        with open(path, errors="replace") as f:
            for raw in f:
                line = raw.strip()
                if line.upper().startswith("*INCLUDE"):
                    inc = parse_keyword(line).get("INPUT")
                    if not inc or os.path.isabs(inc):
                        continue
                    full = os.path.normpath(os.path.join(os.path.dirname(path), inc))
                    rel = os.path.relpath(full, base)
                    if rel not in out and os.path.exists(full):
                        out.append(rel)
                        walk(full)
    walk(deck)
    return out


def face_local_nodes(etype, face):
    """0-based local indices of the nodes of 2D face `face` (1-based, S1 = 1) of an
    element of type `etype`, ordered along the face: corner, [mid-side], corner."""
    n = NODES_PER_TYPE.get(etype.upper(), 0)
    corners = 3 if n in (3, 6) else 4
    out = [face - 1, face % corners]
    if n in (6, 8):
        out.insert(1, corners + face - 1)
    return out


class Deck:
    """The model of a deck as plain dicts (labels as in the deck, names upper case):

    xy {node: (x, y)}, max_node, elements {element: (type, [nodes])},
    element_types, nsets / elsets {NAME: [labels]} (NSET=/ELSET= of *NODE and
    *ELEMENT, GENERATE, set names inside sets), surfaces {NAME: [(element,
    face 1..)]} (element-face surfaces), node_surfaces {NAME: [node tokens]},
    heading {key: value} of `key=value` words on the *HEADING lines, cards (see
    cards()), keywords (set of "*NAME"), params (the keyword lines' parameters
    in order).
    """

    def __init__(self, path):
        self.path = path
        self.cards = cards(path)
        self.xy, self.elements, self.nsets, self.elsets = {}, {}, {}, {}
        self.surfaces, self.node_surfaces, self.heading = {}, {}, {}
        self.element_types, self.keywords, self.params = set(), set(), []
        for params, data, _ in self.cards:
            kw = params["_kw"]
            self.keywords.add(kw)
            self.params.append(params)
            if kw == "*HEADING":
                for line in data:
                    self.heading.update(re.findall(r"(\w+)=(\S+)", line))
            elif kw == "*NODE":
                self._nodes(params, data)
            elif kw == "*ELEMENT":
                self._elements(params, data)
            elif kw in ("*NSET", "*ELSET"):
                self._set(params, data, kw)
            elif kw == "*SURFACE":
                self._surface(params, data)
        self.max_node = max(self.xy) if self.xy else 0

    @property
    def node_labels(self):
        return set(self.xy)

    def _nodes(self, params, data):
        ids = []
        for line in data:
            t = line.split(",")
            ids.append(int(t[0]))
            # Empty or missing coordinates are 0, as CalculiX and tether read them (`7` alone is (0, 0)).
            self.xy[ids[-1]] = tuple(float(t[k]) if len(t) > k and t[k].strip() else 0.0 for k in (1, 2))
        if "NSET" in params:
            self.nsets.setdefault(params["NSET"].upper(), []).extend(ids)

    def _elements(self, params, data):
        etype = params.get("TYPE", "").upper()
        self.element_types.add(etype)
        ids = []
        n = NODES_PER_TYPE.get(etype)
        if n:  # continuation lines: read by the type's node count
            values = [int(v) for v in " ".join(data).replace(",", " ").split()]
            for i in range(0, len(values) - n, n + 1):
                self.elements[values[i]] = (etype, values[i + 1:i + 1 + n])
                ids.append(values[i])
        else:  # unknown type: one element a line
            for line in data:
                v = [int(x) for x in line.replace(",", " ").split()]
                self.elements[v[0]] = (etype, v[1:])
                ids.append(v[0])
        if "ELSET" in params:
            self.elsets.setdefault(params["ELSET"].upper(), []).extend(ids)

    def _set(self, params, data, kw):
        name = params.get("NSET" if kw == "*NSET" else "ELSET", "").upper()
        target = self.nsets if kw == "*NSET" else self.elsets
        members = target.setdefault(name, [])
        if "GENERATE" in params:
            for line in data:
                v = [int(x) for x in line.replace(",", " ").split()]
                members.extend(range(v[0], v[1] + 1, v[2] if len(v) > 2 else 1))
            return
        for token in " ".join(data).replace(",", " ").split():
            members.extend(self.ids(token, target))

    def _surface(self, params, data):
        name = params.get("NAME", "").upper()
        if params.get("TYPE", "ELEMENT").upper() == "ELEMENT":
            faces = self.surfaces.setdefault(name, [])
            for line in data:
                v = [x.strip() for x in line.split(",")]
                if len(v) < 2:
                    continue
                for element in self.ids(v[0], self.elsets):
                    faces.append((element, int(v[1].upper().lstrip("S"))))
        else:
            self.node_surfaces[name] = [line.split(",")[0].strip() for line in data]

    @staticmethod
    def ids(token, sets):
        """[label] for a number, else the members of the set named `token` ([] when unknown)."""
        token = token.strip()
        try:
            return [int(token)]
        except ValueError:
            return list(sets.get(token.upper(), []))

    def number(self, key, default=None):
        """The *HEADING's `key=value` as a float; `default` when absent (KeyError without a default)."""
        try:
            return float(self.heading[key])
        except (KeyError, ValueError):
            if default is None:
                raise KeyError(f"{self.path}: no {key}=number on the *HEADING line") from None
            return default

    def face_nodes(self, element, face):
        """Node labels of face `face` (1-based) of `element`, along the face: corner, [mid-side], corner."""
        etype, conn = self.elements[element]
        return [conn[k] for k in face_local_nodes(etype, face)]

    def tributary_lengths(self, surface):
        """{node: tributary length} of an element-face surface in the reference configuration
        (int N_a ds over straight faces: 1/2, 1/2 of a 2-node face; 1/6, 2/3, 1/6 of a 3-node face)."""
        out = {}
        for element, face in self.surfaces[surface.upper()]:
            nodes = self.face_nodes(element, face)
            (x1, y1), (x2, y2) = self.xy[nodes[0]], self.xy[nodes[-1]]
            length = ((x2 - x1) ** 2 + (y2 - y1) ** 2) ** 0.5
            weights = [0.5, 0.5] if len(nodes) == 2 else [1 / 6, 2 / 3, 1 / 6]
            for n, w in zip(nodes, weights):
                out[n] = out.get(n, 0.0) + w * length
        return out
