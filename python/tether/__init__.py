"""tether: nonlinear 2D finite elements with constraints and contact, from Python.

    import tether
    job = tether.Job(tether.read_deck("plate.inp"))
    summary = job.run()
    u = job.results[-1].U

See docs/python.md.
"""
import warnings as _warnings

import numpy as _np

from ._errors import DeckWarning, InputError, ModelError, ResourceError, SolverError, TetherError
from ._tether import (Boundary, ConcentratedLoad, Increment, IncrementReport, Interaction, Job, Material, Model,
                      Pressure, Section, Step, Summary, __version__)
from . import _tether

__all__ = ["read_deck", "read_deck_string", "Job", "Model", "Increment", "Summary", "IncrementReport", "Material",
           "Interaction", "Section", "Step", "ConcentratedLoad", "Boundary", "Pressure", "TetherError", "InputError", "ModelError",
           "SolverError", "ResourceError", "DeckWarning", "__version__"]


def _warn(found):
    for file, line, message in found:
        where = f"{file}:{line}" if line > 0 else file
        _warnings.warn(f"{where}: {message}", DeckWarning, stacklevel=3)


def read_deck(path):
    """Reads and validates an ABAQUS/CalculiX deck (``*INCLUDE`` relative to the including file).

    Raises InputError (file, line, message) on any error; the reader's warnings
    are issued as DeckWarning.
    """
    model, found = _tether.read_deck(str(path))
    _warn(found)
    return model


def read_deck_string(text, name="deck.inp"):
    """Reads a deck from a string; ``name`` is the file name in messages (``*INCLUDE`` relative to the working directory)."""
    model, found = _tether.read_deck_string(text, name)
    _warn(found)
    return model


def _to_meshio(self):
    """The increment as a ``meshio.Mesh``: reference points (z = 0), cells of
    the mesh, point data U, RF, S, E (stresses and strains averaged at the
    nodes; xx, yy, zz, xy) and cell data S_mean (mean of each element's
    integration points)."""
    import meshio

    points = _np.zeros((len(self.X), 3))
    points[:, :2] = self.X
    blocks = self._cell_blocks()
    stress = self.S
    labels = self.element_labels
    # Mean stress of each element, in the model's element order.
    _, first = _np.unique(labels, return_index=True)
    order = _np.sort(first)
    counts = _np.diff(_np.append(order, len(labels)))
    means = _np.add.reduceat(stress, order, axis=0) / counts[:, None] if len(labels) else _np.zeros((0, 4))
    return meshio.Mesh(
        points,
        [(kind, cells) for kind, cells, _ in blocks],
        point_data={"U": _np.array(self.U), "RF": _np.array(self.RF), "S": _np.array(self.S_nodal),
                    "E": _np.array(self.E_nodal)},
        cell_data={"S_mean": [means[elements] for _, _, elements in blocks]},
    )


Increment.to_meshio = _to_meshio
