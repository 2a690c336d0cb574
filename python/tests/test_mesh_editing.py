"""The mesh and the sections from Python: read as NumPy, move nodes, new sets,
materials and sections, and run again (the bar of conftest: u(L) = F L / (E A))."""
import numpy as np
import pytest

import tether
from conftest import bar_deck

F, A = 10.0, 1.0 * 0.5  # load, cross-section (height 1 x thickness 0.5)


def tip(job):
    inc = job.results[-1]
    return inc.U[list(inc.node_labels).index(10), 0]


def test_mesh_as_numpy():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    assert model.element_nodes.shape == (8, 4) and model.element_nodes.dtype.kind == "i"
    assert model.element_nodes[0].tolist() == [1, 2, 7, 6]
    assert model.coordinates.shape == (15, 2) and model.coordinates[9].tolist() == [4.0, 0.5]
    assert model.node_sets["RIGHT"].tolist() == [5, 10, 15]
    [section] = model.sections
    assert (section.elset, section.material, section.thickness) == ("EALL", "STEEL", 0.5)
    assert section.element_labels.tolist() == list(range(1, 9))


def test_mixed_element_sizes_are_padded():
    deck = ("*NODE\n1, 0., 0.\n2, 1., 0.\n3, 1., 1.\n4, 0., 1.\n5, 2., 0.\n"
            "*ELEMENT, TYPE=CPS4, ELSET=EALL\n1, 1, 2, 3, 4\n*ELEMENT, TYPE=CPS3, ELSET=EALL\n2, 2, 5, 3\n"
            "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
            "*STEP\n*STATIC\n*END STEP\n")
    model = tether.read_deck_string(deck)
    assert model.element_nodes.tolist() == [[1, 2, 3, 4], [2, 5, 3, -1]]


def test_moving_nodes_changes_the_next_run():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    job = tether.Job(model, keep="last")
    assert job.run() and tip(job) == pytest.approx(F * 4 / (1000 * A), rel=1e-12)
    x = model.coordinates
    x[:, 0] *= 2  # twice as long
    model.coordinates = x
    assert job.run() and tip(job) == pytest.approx(F * 8 / (1000 * A), rel=1e-12)
    # A subset: the right end to x = 7 (the last column of elements gets shorter, not inverted).
    model.set_coordinates([5, 10, 15], [[7.0, 0.0], [7.0, 0.5], [7.0, 1.0]])
    assert model.coordinates[9].tolist() == [7.0, 0.5]
    assert job.run() and tip(job) == pytest.approx(F * 7 / (1000 * A), rel=1e-12)


def test_a_move_that_inverts_an_element_is_refused_and_changes_nothing():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    before = model.coordinates
    with pytest.raises(ValueError, match="element 1 would be inverted or degenerate"):
        model.set_coordinates([7], [[-1.0, 0.0]])  # past node 6, folding element 1
    with pytest.raises(ValueError, match=r"shape \(2, 2\)"):
        model.set_coordinates([7, 8], [1.0, 2.0])
    with pytest.raises(KeyError, match="no node 99"):
        model.set_coordinates([99], [[0.0, 0.0]])
    assert np.array_equal(model.coordinates, before)


def test_new_material_on_a_new_element_set():
    """Right half three times stiffer (nu = 0 in both, so the stress stays uniaxial and uniform)."""
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    model.materials["STEEL"].poisson = 0.0
    model.add_material("hard", copy_of="steel")
    model.materials["HARD"].young = 3000.0
    assert model.materials["STEEL"].young == 1000.0  # a copy
    right = [label for label, nodes in zip(model.element_labels, model.element_nodes)
             if model.coordinates[[list(model.node_labels).index(n) for n in nodes], 0].min() >= 2.0]
    model.add_element_set("right_half", right)
    assert model.element_sets["RIGHT_HALF"].tolist() == [3, 4, 7, 8]
    section = model.add_section("RIGHT_HALF", "HARD", thickness=0.5)
    assert section.element_labels.tolist() == [3, 4, 7, 8]
    assert model.sections[0].element_labels.tolist() == [1, 2, 5, 6]
    job = tether.Job(model)
    assert job.run()
    assert tip(job) == pytest.approx(F / A * (2 / 1000 + 2 / 3000), rel=1e-12)
    # The section's thickness and material are parameters too.
    section.thickness = 1.0
    model.sections[0].material = "HARD"
    assert job.run() and tip(job) == pytest.approx(F * (2 / (3000 * A) + 2 / (3000 * 1.0)), rel=1e-12)


def test_new_node_set_and_bad_edits():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    model.add_node_set("top", [15, 11, 12, 13, 14, 15])
    assert model.node_sets["TOP"].tolist() == [11, 12, 13, 14, 15]  # sorted, unique
    with pytest.raises(ValueError, match="node set TOP exists already"):
        model.add_node_set("TOP", [1])
    with pytest.raises(KeyError, match="no node 0"):
        model.add_node_set("OTHER", [0])
    with pytest.raises(KeyError, match="no element 9"):
        model.add_element_set("E9", [9])
    with pytest.raises(KeyError, match="no material NONE"):
        model.sections[0].material = "none"
    with pytest.raises(ValueError, match="exists already"):
        model.add_material("STEEL", copy_of="STEEL")
    with pytest.raises(KeyError, match="no element set NOPE"):
        model.add_section("NOPE", "STEEL")
    with pytest.raises(ValueError, match="thickness"):
        model.sections[0].thickness = 0.0
