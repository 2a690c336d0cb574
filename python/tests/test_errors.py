"""Deck errors, model errors and analyses that do not complete."""
import pytest

import tether
from conftest import bar_deck


def test_input_error_names_file_and_line():
    deck = bar_deck().replace("*ELASTIC\n1000.0, 0.25", "*ELASTIC\n1000.0, 0.7")
    with pytest.raises(tether.InputError) as raised:
        tether.read_deck_string(deck, name="bar.inp")
    e = raised.value
    assert e.file == "bar.inp"
    assert e.line == deck.splitlines().index("1000.0, 0.7") + 1
    assert "0.7" in e.message or "Poisson" in e.message
    assert str(e).startswith(f"bar.inp:{e.line}: error: ")
    assert isinstance(e, tether.TetherError)


def test_missing_file_is_an_input_error(tmp_path):
    with pytest.raises(tether.InputError) as raised:
        tether.read_deck(tmp_path / "nothing.inp")
    assert "nothing.inp" in str(raised.value)


def test_model_error_from_a_model_that_cannot_be_solved():
    # A link between two nodes at the same place: valid input, refused when the model is discretized.
    deck = bar_deck().replace("*NSET, NSET=RIGHT", "*NODE\n99, 4., 0.\n*MPC\nLINK, 5, 99\n*NSET, NSET=RIGHT")
    job = tether.Job(tether.read_deck_string(deck, name="link.inp"))
    with pytest.raises(tether.ModelError, match="the two nodes coincide") as raised:
        job.run()
    assert "link.inp:" in raised.value.message


def test_an_analysis_that_stops_returns_a_summary_or_raises_with_check():
    # Nothing restrains the bar in x: singular at the first iteration.
    deck = bar_deck().replace("*BOUNDARY\n1, 1, 2\n6, 1\n11, 1\n", "*BOUNDARY\n1, 2\n")
    job = tether.Job(tether.read_deck_string(deck, name="free.inp"))
    summary = job.run()
    assert not summary.completed and not summary
    assert "not restrained" in summary.message
    assert job.results == []
    with pytest.raises(tether.SolverError, match="not restrained"):
        job.run(check=True)


def test_bad_options():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    with pytest.raises(ValueError, match="keep"):
        tether.Job(model, keep="some")
    with pytest.raises(ValueError):
        tether.Job(model, solver="gauss")
