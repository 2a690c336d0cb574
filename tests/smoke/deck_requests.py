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
E -> strains, PEEQ -> equivalent plastic strain, PE -> plastic strains;
*CONTACT PRINT CSTR/CSTRESS -> contact stress, CDIS/CDISP ->
relative contact displacement (one block for all pairs, set ""), CFN/CFS ->
total normal/shear contact force per pair (no variables: CSTR, CDIS), and
the contact state block of every pair; *OUTPUT, HISTORY with *NODE OUTPUT / *ELEMENT OUTPUT
like the print requests (VARIABLE=PRESELECT there: the energies, no block of its own). A request with FREQUENCY=0
writes nothing; file requests (*NODE FILE, *OUTPUT, FIELD, ...) write no
.dat blocks. Variables tether does not print are left out (the reader warns).
"""
import tethertools.deck  # tools/ on PYTHONPATH (set by CTest)

_NODE_TITLES = {"U": ["displacements"], "RF": ["forces"], "V": ["velocities"], "A": ["accelerations"]}
_ELEMENT_TITLES = {"S": ["stresses"], "E": ["strains"], "PEEQ": ["equivalent plastic strain"],
                   "PE": ["plastic strains"]}
_CONTACT_TITLES = {"CSTR": "contact stress", "CSTRESS": "contact stress", "CDIS": "relative contact displacement",
                   "CDISP": "relative contact displacement"}
_CONTACT_PAIR_TITLES = {"CFN": "total normal contact force", "CFS": "total shear contact force"}
_CONSTRAINT_KEYWORDS = {"*EQUATION", "*MPC", "*CONSTRAINT", "*TIE", "*PERIODIC"}


def _blocks(path):
    """[(keyword upper, {PARAM: value}, [data lines])], *INCLUDE expanded (tethertools.deck.cards)."""
    return [(params["_kw"], params, data) for params, data, _ in tethertools.deck.cards(path)]


def _variables(data):
    return [v.strip().upper() for line in data for v in line.split(",") if v.strip()]


def _frequency(params, default=1):
    return int(params.get("FREQUENCY", default))


def read(path):
    steps, pairs, constraints = [], [], False
    current = None
    history = None  # (frequency) of the current *OUTPUT, HISTORY block, or "field"
    dynamic = False  # a *DYNAMIC step: energies in the .dat and JOB_energy.csv
    for keyword, params, data in _blocks(path):
        if keyword in _CONSTRAINT_KEYWORDS:
            constraints = True
        elif keyword == "*CONTACT PAIR":
            pairs.extend("-".join(s.strip().upper() for s in line.split(",")[:2]) for line in data)
        elif keyword == "*STEP":
            current, history = [], None
            steps.append(current)
        elif current is None:
            continue
        elif keyword == "*DYNAMIC":
            dynamic = True
            current.append(("energies", ""))  # at every step's end
        elif keyword == "*OUTPUT":
            # VARIABLE=PRESELECT on a history request means ABAQUS's whole-model energies: no .dat block
            # beyond the energies dynamic steps write anyway.
            history = _frequency(params) if "HISTORY" in params else "field"
        elif keyword in ("*NODE PRINT", "*NODE OUTPUT"):
            frequency = _frequency(params) if keyword == "*NODE PRINT" else history
            if frequency == "field" or frequency == 0:
                continue
            nset = params.get("NSET", "NALL").upper()
            totals = params.get("TOTALS", "NO").upper()
            for v in _variables(data):
                titles = _NODE_TITLES.get(v, [])
                if v == "RF" and totals == "ONLY":
                    titles = ["total force"]
                elif v == "RF" and totals == "YES":
                    titles = ["forces", "total force"]
                current += [(t, nset) for t in titles]
        elif keyword in ("*EL PRINT", "*ELEMENT OUTPUT"):
            frequency = _frequency(params) if keyword == "*EL PRINT" else history
            if frequency == "field" or frequency == 0:
                continue
            elset = params.get("ELSET", "EALL").upper()
            current += [(t, elset) for v in _variables(data) for t in _ELEMENT_TITLES.get(v, [])]
        elif keyword == "*CONTACT PRINT" and _frequency(params) > 0:
            for v in _variables(data) or ["CSTR", "CDIS"]:  # the reader's default
                if v in _CONTACT_TITLES:
                    current.append((_CONTACT_TITLES[v], ""))
                elif v in _CONTACT_PAIR_TITLES:
                    current += [(_CONTACT_PAIR_TITLES[v], p) for p in pairs]
            current += [("contact state", p) for p in pairs]
    return {"steps": steps, "contact_pairs": pairs, "constraints": constraints, "dynamic": dynamic}
