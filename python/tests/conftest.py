"""Shared fixtures: where the repository's decks are."""
import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("TETHER_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def source():
    return SOURCE


def bar_deck(young=1000.0, force=10.0):
    """A bar [0, 4] x [0, 1] of 4 x 2 CPS4 (thickness 0.5), fixed on the left,
    pulled by `force` on the right in two increments: u(L) = F L / (E A),
    sigma_xx = F / A with A = 0.5."""
    lines = ["*HEADING", "bar", "*NODE, NSET=ALL"]
    for j in range(3):
        for i in range(5):
            lines.append(f"{j * 5 + i + 1}, {i}, {0.5 * j}")
    lines.append("*ELEMENT, TYPE=CPS4, ELSET=EALL")
    for j in range(2):
        for i in range(4):
            n1 = j * 5 + i + 1
            lines.append(f"{j * 4 + i + 1}, {n1}, {n1 + 1}, {n1 + 6}, {n1 + 5}")
    lines += ["*NSET, NSET=RIGHT", "5, 10, 15",
              "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{young}, 0.25",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL", "0.5",
              "*BOUNDARY", "1, 1, 2", "6, 1", "11, 1",
              "*STEP", "*STATIC", "0.5, 1.0",
              "*CLOAD", f"5, 1, {force / 4}", f"10, 1, {force / 2}", f"15, 1, {force / 4}",
              "*NODE PRINT, NSET=RIGHT", "U", "*EL PRINT", "S", "*END STEP"]
    return "\n".join(lines) + "\n"
