"""What a deck asks the `.dat` to contain, read from the deck's keywords (smoke tier).

read(path) follows *INCLUDE (relative to the including file) and returns
  {"steps": [[(title, set), ...] per step: the blocks its print requests
             write at the step's last increment],
   "contact_pairs": ["SLAVE-MASTER", ...],
   "constraints": True when the deck has *EQUATION, *MPC, *CONSTRAINT, *TIE or *PERIODIC,
   "dynamic": True when a step is *DYNAMIC (its end writes the energies block;
              *NODE PRINT V -> velocities, A -> accelerations)}.

Titles are the leading words of tether's block headers (tools/tethertools/dat.py
splits them from the set and the time), as DatWriter documents them:
*NODE PRINT U -> displacements, RF -> forces (and total force with
TOTALS=YES; only total force with TOTALS=ONLY); *EL PRINT S -> stresses,
E -> strains, PEEQ -> equivalent plastic strain, PE -> plastic strains,
AC YIELD (ACYIELD) -> actively yielding, SDV -> internal state variables
(only when a *USER MATERIAL has *DEPVAR: a UMAT's state variables);
*CONTACT PRINT CSTR/CSTRESS -> contact stress, CDIS/CDISP ->
relative contact displacement (one block for all pairs, set ""), CFN/CFS ->
total normal/shear contact force per pair (no variables: CSTR, CDIS), and
the contact state block of every pair; *OUTPUT, HISTORY with *NODE OUTPUT / *ELEMENT OUTPUT
like the print requests (VARIABLE=PRESELECT there: the energies, no block of its own). A request with FREQUENCY=0
writes nothing; file requests (*NODE FILE, *OUTPUT, FIELD, ...) write no
.dat blocks. Variables tether does not print are left out (the reader warns).
A step that gives no request of a kind (node, element, contact) keeps the
previous step's requests of that kind, without V and A in a *STATIC step.
"""
import tethertools.deck  # tools/ on PYTHONPATH (set by CTest)

_NODE_TITLES = {"U": ["displacements"], "RF": ["forces"], "V": ["velocities"], "A": ["accelerations"]}
_ELEMENT_TITLES = {"S": ["stresses"], "E": ["strains"], "PEEQ": ["equivalent plastic strain"],
                   "PE": ["plastic strains"], "AC YIELD": ["actively yielding"]}
_CONTACT_TITLES = {"CSTR": "contact stress", "CSTRESS": "contact stress", "CDIS": "relative contact displacement",
                   "CDISP": "relative contact displacement"}
_CONTACT_PAIR_TITLES = {"CFN": "total normal contact force", "CFS": "total shear contact force"}
_CONSTRAINT_KEYWORDS = {"*EQUATION", "*MPC", "*CONSTRAINT", "*TIE", "*PERIODIC"}


def _blocks(path):
    """[(keyword upper, {PARAM: value}, [data lines])], *INCLUDE expanded (tethertools.deck.cards)."""
    return [(params["_kw"], params, data) for params, data, _ in tethertools.deck.cards(path)]


def _variables(data):
    names = [" ".join(v.split()).upper() for line in data for v in line.split(",") if v.strip()]
    return ["AC YIELD" if v == "ACYIELD" else v for v in names]  # tether's spelling of ABAQUS's variable


def _frequency(params, default=1):
    return int(params.get("FREQUENCY", default))


def _carry(steps):
    """Each step's blocks: its own, plus the previous step's of every kind it
    does not request (output requests stay in force until a step requests
    that kind again, as in ABAQUS and CalculiX)."""
    out, previous = [], {}
    for step in steps:
        kinds = {k: (v if v is not None else [b for b in previous.get(k, [])
                                               if step["dynamic"] or b[0] not in ("velocities", "accelerations")])
                 for k, v in step["kinds"].items()}
        out.append(step["always"] + [b for k in ("node", "element", "contact") for b in kinds[k]])
        previous = kinds
    return out


def read(path):
    steps, pairs, constraints = [], [], False
    current = None  # {"always": [...], "kinds": {"node"|"element"|"contact": None (none given) or [...]}}
    history = None  # (frequency) of the current *OUTPUT, HISTORY block, or "field"
    dynamic = False  # a *DYNAMIC step: energies in the .dat and JOB_energy.csv

    def kind(name):
        if current["kinds"][name] is None:
            current["kinds"][name] = []  # the first request of a kind replaces the carried ones
        return current["kinds"][name]

    cards = _blocks(path)
    keywords = {keyword for keyword, _, _ in cards}
    user_state = "*USER MATERIAL" in keywords and "*DEPVAR" in keywords
    for keyword, params, data in cards:
        if keyword in _CONSTRAINT_KEYWORDS:
            constraints = True
        elif keyword == "*CONTACT PAIR":
            pairs.extend("-".join(s.strip().upper() for s in line.split(",")[:2]) for line in data)
        elif keyword == "*STEP":
            current = {"always": [], "kinds": {"node": None, "element": None, "contact": None}, "dynamic": False}
            history = None
            steps.append(current)
        elif current is None:
            continue
        elif keyword == "*DYNAMIC":
            dynamic = current["dynamic"] = True
            current["always"].append(("energies", ""))  # at every step's end
        elif keyword == "*OUTPUT":
            # VARIABLE=PRESELECT on a history request means ABAQUS's whole-model energies: no .dat block
            # beyond the energies dynamic steps write anyway.
            history = _frequency(params) if "HISTORY" in params else "field"
        elif keyword in ("*NODE PRINT", "*NODE OUTPUT"):
            frequency = _frequency(params) if keyword == "*NODE PRINT" else history
            if frequency == "field":
                continue
            blocks = kind("node")
            if frequency == 0:
                continue
            nset = params.get("NSET", "NALL").upper()
            totals = params.get("TOTALS", "NO").upper()
            for v in _variables(data):
                titles = _NODE_TITLES.get(v, [])
                if v == "RF" and totals == "ONLY":
                    titles = ["total force"]
                elif v == "RF" and totals == "YES":
                    titles = ["forces", "total force"]
                blocks += [(t, nset) for t in titles]
        elif keyword in ("*EL PRINT", "*ELEMENT OUTPUT"):
            frequency = _frequency(params) if keyword == "*EL PRINT" else history
            if frequency == "field":
                continue
            blocks = kind("element")
            if frequency == 0:
                continue
            elset = params.get("ELSET", "EALL").upper()
            titles = dict(_ELEMENT_TITLES, SDV=["internal state variables"] if user_state else [])
            blocks += [(t, elset) for v in _variables(data) for t in titles.get(v, [])]
        elif keyword == "*CONTACT PRINT":
            blocks = kind("contact")
            if _frequency(params) == 0:
                continue
            for v in _variables(data) or ["CSTR", "CDIS"]:  # the reader's default
                if v in _CONTACT_TITLES:
                    blocks.append((_CONTACT_TITLES[v], ""))
                elif v in _CONTACT_PAIR_TITLES:
                    blocks += [(_CONTACT_PAIR_TITLES[v], p) for p in pairs]
            blocks += [("contact state", p) for p in pairs]
    steps = _carry(steps)
    return {"steps": steps, "contact_pairs": pairs, "constraints": constraints, "dynamic": dynamic}
