"""tools/tethertools: the one reader of decks, .dat, .sta/.msg and .vtu files the
tools, the examples and the tests use (run with PYTHONPATH=tools)."""
import os
import subprocess

import pytest

from tethertools import dat, deck, sta, vtu

DAT = """
 displacements (vx,vy,vz) for set B and time  0.5000000E+00

         2  1.000000E-01 -2.000000E-02  0.000000E+00

 displacements (vx,vy,vz) for set B and time  1.0000000E+00

         2  2.000000D-01 -4.000000D-02  0.000000E+00

 contact stress (slave node,press,tang1,tang2) for all contact elements and time  1.0000000E+00

        45  3.000000E+02  1.000000E+00  0.000000E+00
        46  1.000000E+02  3.000000E+00  0.000000E+00

 contact state for pair SLAVE-MASTER and time  1.0000000E+00

         7  1.000000E+00  0.000000E+00
"""


def test_dat_blocks_in_file_order():
    blocks = dat.parse(DAT)
    assert [(b["title"], b["set"], b["time"]) for b in blocks] == [
        ("displacements (vx,vy,vz)", "B", 0.5), ("displacements (vx,vy,vz)", "B", 1.0),
        ("contact stress (slave node,press,tang1,tang2)", "", 1.0), ("contact state", "SLAVE-MASTER", 1.0)]
    assert blocks[1]["rows"] == [[2, 0.2, -0.04, 0.0]]  # Fortran D exponents
    assert dat.last_block(blocks, "Displacements", "b")["time"] == 1.0
    assert dat.pick(blocks, "displacements", "B", time=0.5)["rows"][0][1] == 0.1
    assert dat.pick(blocks, "forces") is None
    assert len(dat.blocks_of(blocks, "contact")) == 2
    with pytest.raises(KeyError):
        dat.last_block(blocks, "forces", "B")


def test_dat_strict_and_lenient():
    text = DAT.replace("         7  1.000000E+00", " *WARNING in something\n         7  1.000000E+00")
    with pytest.raises(ValueError, match="not a row of numbers"):
        dat.parse(text)
    blocks = dat.parse(text, strict=False)
    assert blocks[-1]["rows"] == []  # the text ended the block
    with pytest.raises(ValueError, match="before any block header"):
        dat.parse("  1  2  3\n")


def test_slave_rows_maps_calculix_3d_ids_back():
    # nk = 44: 2D node 1 -> 45, 46, 47 (layers averaged).
    rows = dat.parse(DAT)[2]["rows"]
    assert dat.slave_rows(44, rows) == {1: (200.0, 2.0)}
    assert dat.slave_rows(100, rows) == {45: (300.0, 1.0), 46: (100.0, 3.0)}


def test_sta(tmp_path):
    path = tmp_path / "job.sta"
    path.write_text(" SUMMARY OF JOB INFORMATION:\n STEP INC ATT ITRS\n 1 1 1U 5 0.1\n 1 1 2 3 0.05\n 1 2 1 2 0.1\n")
    assert sta.read(path) == [(1, 1, 1, 5, False), (1, 1, 2, 3, True), (1, 2, 1, 2, True)]
    assert sta.iterations(path) == (5, 5, 2)  # converged attempts only; no TOTITRS column: ITRS
    assert sta.verdict(path) is None  # ccx writes no verdict line
    assert sta.iterations(tmp_path / "missing.sta") == (None, None, None)


def test_tether_sta_and_msg(tmp_path):
    path = tmp_path / "job.sta"
    path.write_text(
        " tether 0.1.0  job job  dialect abaqus\n SUMMARY OF JOB INFORMATION:\n"
        "  STEP   INC  ATT  ITRS  TOTITRS      TOT TIME     STEP TIME      INC TIME      RESIDUAL\n"
        "     1     1    1     4        4  0.100000E+00  0.100000E+00  0.100000E+00  0.290034E-07\n"
        "     1     2    1    12       15  0.200000E+00  0.200000E+00  0.100000E+00  0.284849E-02\n"
        " THE ANALYSIS HAS NOT BEEN COMPLETED: step 1: a Python callback raised ValueError: boom\n")
    assert [a["total_iterations"] for a in sta.attempts(path)] == [4, 15]
    assert sta.iterations(path) == (16, 19, 2)
    assert sta.verdict(path) == (False, "step 1: a Python callback raised ValueError: boom")
    path.write_text(" THE ANALYSIS HAS COMPLETED SUCCESSFULLY: analysis complete\n")
    assert sta.verdict(path) == (True, "analysis complete")
    msg = tmp_path / "job.msg"
    msg.write_text("  step 1 increment 1 attempt 1: time 0.1, increment 0.1, 4 iterations, converged\n"
                   "  step 1 increment 2 attempt 1: time 0.2, increment 0.1, 9 iterations, not converged\n"
                   "  step 2 increment 1 attempt 2: time 1.5, increment 0.5, 2 iterations, converged\n")
    assert sta.converged_increments_in_msg(msg) == [(1, 1, 0.1), (2, 1, 1.5)]


def write_deck(tmp_path):
    (tmp_path / "mesh.inp").write_text(
        "*NODE, NSET=ALL\n1, 0., 0.\n2, 2., 0.\n3, 2., 2.\n4, 0., 2.\n5, 1., 0.\n6, 2., 1.\n7, 1., 2.\n8, 0., 1.\n"
        "*ELEMENT, TYPE=CPE8, ELSET=EALL\n1, 1, 2, 3, 4,\n5, 6, 7, 8\n")
    main = tmp_path / "main.inp"
    main.write_text(
        "*HEADING\nblock P=2000 R=10\n** a comment\n*INCLUDE, INPUT=mesh.inp\n"
        "*NSET, NSET=EVEN, GENERATE\n2, 8, 2\n*NSET, NSET=BOTH\nEVEN, 1\n*ELSET, ELSET=E1\nEALL\n"
        "*SURFACE, NAME=TOP\nE1, S3\n*SURFACE, NAME=PTS, TYPE=NODE\n3\n*STEP\n*STATIC\n*END STEP\n")
    return main


def test_keyword_line_continued(tmp_path):
    path = tmp_path / "cont.inp"
    path.write_text("*NODE PRINT, NSET=TOP,\n  FREQUENCY=2, TOTALS = YES\nU\n*EL  PRINT,ELSET=E\nS\n")
    c = deck.cards(path)
    assert [(p["_kw"], data) for p, data, _ in c] == [("*NODE PRINT", ["U"]), ("*EL PRINT", ["S"])]
    assert c[0][0]["FREQUENCY"] == "2" and c[0][0]["TOTALS"] == "YES" and c[1][0]["ELSET"] == "E"


def test_deck(tmp_path):
    d = deck.Deck(write_deck(tmp_path))
    assert d.heading == {"P": "2000", "R": "10"} and d.number("R") == 10.0 and d.number("E", 7.0) == 7.0
    with pytest.raises(KeyError):
        d.number("E")
    assert d.xy[6] == (2.0, 1.0) and d.max_node == 8 and d.node_labels == set(range(1, 9))
    assert d.elements == {1: ("CPE8", [1, 2, 3, 4, 5, 6, 7, 8])}  # continuation line
    assert d.nsets["EVEN"] == [2, 4, 6, 8] and d.nsets["BOTH"] == [2, 4, 6, 8, 1]
    assert d.elsets["E1"] == [1]
    assert d.surfaces["TOP"] == [(1, 3)] and d.node_surfaces["PTS"] == ["3"]
    assert d.face_nodes(1, 3) == [3, 7, 4]  # along the face: corner, mid-side, corner
    assert d.tributary_lengths("TOP") == pytest.approx({3: 2 / 6, 7: 4 / 3, 4: 2 / 6})
    assert {"*HEADING", "*NODE", "*ELEMENT", "*STEP", "*STATIC", "*END STEP"} <= d.keywords
    assert [p["_kw"] for p in d.params][:3] == ["*HEADING", "*NODE", "*ELEMENT"]
    assert deck.include_files(tmp_path / "main.inp") == ["mesh.inp"]
    assert deck.face_local_nodes("CPE6", 3) == [2, 5, 0]


def test_deck_node_lines_with_missing_coordinates(tmp_path):
    """A *NODE line may omit coordinates (CalculiX's test decks write `1` for the origin): they are 0."""
    path = tmp_path / "nodes.inp"
    path.write_text("*NODE, NSET=N\n1\n2 ,10,0.\n3, ,4.\n4, 5\n")
    d = deck.Deck(path)
    assert d.xy == {1: (0.0, 0.0), 2: (10.0, 0.0), 3: (0.0, 4.0), 4: (5.0, 0.0)}
    assert d.nsets["N"] == [1, 2, 3, 4]


def test_deck_counts_agree_with_tether(tmp_path):
    """On the repository's decks the reader finds the nodes and elements tether's own reader finds."""
    cli = os.environ.get("TETHER_CLI")
    if not cli:
        pytest.skip("TETHER_CLI not set")
    root = os.path.join(os.path.dirname(__file__), "..", "..")
    for name in ("examples/hertz/hertz.inp", "examples/lame/lame.inp", "examples/ironing/ironing.inp"):
        path = os.path.join(root, name)
        out = subprocess.run([cli, "check", path], capture_output=True, text=True, check=True).stdout
        d = deck.Deck(path)
        assert f"{len(d.xy)} nodes, {len(d.elements)} elements" in out, (name, out)


def test_vtu_of_a_tether_run(tmp_path):
    """The .pvd and .vtu files of a run read back with the mesh's sizes, labels and times."""
    cli = os.environ.get("TETHER_CLI")
    if not cli:
        pytest.skip("TETHER_CLI not set")
    root = os.path.join(os.path.dirname(__file__), "..", "..")
    subprocess.run([cli, "run", "-q", os.path.join(root, "examples/lame/lame.inp"), "-o", str(tmp_path)], check=True)
    listed = vtu.check_collection(tmp_path / "lame.pvd")
    d = deck.Deck(os.path.join(root, "examples/lame/lame.inp"))
    assert [t for _, t, _ in listed] == sorted(t for _, t, _ in listed) and listed
    last = listed[-1][2]
    assert last["points"] == len(d.xy) and last["cells"] == len(d.elements)
    assert sorted(int(n) for n in last["node_ids"]) == sorted(d.xy)
    assert last["time"] == pytest.approx(listed[-1][1])
    (tmp_path / "bad.pvd").write_text('<VTKFile type="Collection"><Collection>'
                                      '<DataSet timestep="1" file="none.vtu"/></Collection></VTKFile>')
    with pytest.raises(vtu.VtuError, match="does not exist"):
        vtu.check_collection(tmp_path / "bad.pvd")


def test_every_tool_is_a_module_of_the_package_with_a_launcher():
    """tools/NAME.py only launches tethertools.NAME.main (one package, no code outside it)."""
    import importlib

    tools = os.path.join(os.path.dirname(__file__), "..", "..", "tools")
    launchers = sorted(f[:-3] for f in os.listdir(tools) if f.endswith(".py"))
    assert "compare_ccx" in launchers and "make_gallery" in launchers and "hertz_bench" in launchers
    for name in launchers:
        assert callable(importlib.import_module("tethertools." + name).main), name
        with open(os.path.join(tools, name + ".py")) as f:
            code = [line for line in f if line.strip() and not line.startswith(("#", '"""'))]
        assert code == [f"from tethertools.{name} import main\n", 'if __name__ == "__main__":\n',
                        "    raise SystemExit(main())\n"], name
