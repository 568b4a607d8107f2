"""Results that go back into GTSAM (issue 35): a dataset's keys are the file's own (an int stays
an int, a landmark stays GTSAM's Symbol ``L(j)``), the ``.g2o`` export read by GTSAM's readers
gives back the same keys and values, the CSV has a header, and a result converts to a
``gtsam.Values`` under the user's keys.

Tolerance: values read back agree with the exported ones to 1e-12 (absolute, per translation
entry and per rotation angle / quaternion component): the export prints 17 significant digits, so
only the θ → (cos, sin) and rotation → quaternion conversions round."""

from __future__ import annotations

import csv
import io
import json

import gtsam
import numpy as np
import pytest

import fgc
from fgc.app.cli import main as cli_main
from fgc.app.specs import load_spec
from fgc.errors import FgcError
from fgc.frontend.geometry import Point2, Point3, Pose2, Pose3, Rot3
from fgc.interop.estimates import csv_text, g2o_text, graph_values, values_json
from fgc.interop.gtsam_data import gtsam_data_dir
from fgc.interop.to_gtsam import gtsam_key, value_from_gtsam, values_to_gtsam

TOL = 1e-12
READERS = {Pose2: "atPose2", Pose3: "atPose3", Point2: "atPoint2", Point3: "atPoint3"}


def _original(name: str):
    """GTSAM's own reading of a shipped example file: (graph, values, is3d)."""
    path = str(gtsam_data_dir() / name)
    graph, values = gtsam.load2D(path)
    if graph.size() == 0:
        graph, values = gtsam.load3D(path)
        return graph, values, True
    return graph, values, False


def _read_back(path, is3d: bool):
    """The export as GTSAM reads it: ``readG2o`` and the ``load2D``/``load3D`` of the file."""
    _, by_read_g2o = gtsam.readG2o(str(path), is3d)
    _, by_load = (gtsam.load3D if is3d else gtsam.load2D)(str(path))
    return by_read_g2o, by_load


def _assert_same(fgc_values: dict, gvalues) -> None:
    """Every fgc value equals the GTSAM value under its GTSAM key (tolerance TOL)."""
    for k, v in fgc_values.items():
        back = value_from_gtsam(type(v), getattr(gvalues, READERS[type(v)])(gtsam_key(k)))
        assert np.linalg.norm(np.atleast_1d(v.local(back))) <= TOL, k


@pytest.mark.parametrize("name", ["w100.graph", "pose3example.txt", "example.graph"])
def test_g2o_export_round_trips_through_gtsams_readers(name, tmp_path):
    """Export the values fgc read from the file, read the export with GTSAM: the same keys as
    GTSAM's reading of the original file (ints for poses, L(j) for example.graph's landmarks)
    and the same values."""
    _, original, is3d = _original(name)
    graph = load_spec(name, {})
    values = graph_values(graph, {k: v.initial for k, v in graph.variables.items()})
    assert all(isinstance(k, int) for k, v in values.items() if isinstance(v, (Pose2, Pose3)))
    out = tmp_path / "estimate.g2o"
    out.write_text(g2o_text(values))
    assert not any(line.startswith("#") for line in out.read_text().splitlines())
    for back in _read_back(out, is3d):
        assert set(back.keys()) == set(original.keys())
        _assert_same(values, back)
        _assert_same(values, original)


def test_a_landmark_file_keeps_gtsams_landmark_symbols():
    graph = load_spec("example.graph", {})
    _, original, _ = _original("example.graph")
    landmarks = [k for k, v in graph.variables.items() if v.type is Point2]
    assert landmarks and all(isinstance(k, str) and k.startswith("l") for k in landmarks)
    keys = original.keys()  # a gtsam.KeyVector
    symbols = {gtsam.Symbol(k) for k in keys if chr(gtsam.Symbol(k).chr()) == "l"}
    assert {gtsam_key(k) for k in landmarks} == {s.key() for s in symbols}


def test_cli_run_exports_go_back_under_the_files_keys(tmp_path, capsys):
    """``fgc run w100.graph --values x.g2o --json r.json``: the JSON keys are the file's ints
    (with their GTSAM key), and GTSAM's reader of the .g2o gives the JSON's values back."""
    out, report = tmp_path / "w100_opt.g2o", tmp_path / "r.json"
    assert cli_main(["run", "w100.graph", "--backend", "sim", "--precision", "float64",
                     "--values", str(out), "--json", str(report)]) == 0
    capsys.readouterr()
    data = json.loads(report.read_text())
    assert sorted(e["key"] for e in data["values"].values()) == list(range(100))
    assert all(e["gtsam_key"] == e["key"] for e in data["values"].values())
    solved = {e["key"]: Pose2.from_storage(e["value"]) for e in data["values"].values()}
    by_read_g2o, by_load = _read_back(out, False)
    for back in (by_read_g2o, by_load):
        assert sorted(back.keys()) == list(range(100))
        _assert_same(solved, back)
    assert data["final_error_float64"] == pytest.approx(data["final_error"], rel=1e-9)


def test_result_gtsam_values_uses_the_graphs_keys():
    graph = fgc.Graph()
    graph.add_variable(7, Pose2(1.0, 2.0, 0.3))
    graph.add_variable("x1", Pose2(2.0, 2.0, 0.1))
    graph.add_variable("l5", Point2(4.0, 1.0))
    graph.add(fgc.factors.PriorFactor(7, Pose2(1.0, 2.0, 0.3), fgc.noise.isotropic(3, 0.1)))
    graph.add(fgc.factors.BetweenFactor(7, "x1", Pose2(1.0, 0.0, -0.2),
                                        fgc.noise.isotropic(3, 0.1)))
    graph.add(fgc.factors.PriorFactor("l5", Point2(4.0, 1.0), fgc.noise.isotropic(2, 0.1)))
    result = fgc.solve(graph)
    gv = result.gtsam_values()
    assert set(gv.keys()) == {7, gtsam.symbol("x", 1), gtsam.symbol("l", 5)}
    _assert_same(result.user_values, gv)
    assert gv.atPose2(7).theta() == pytest.approx(0.3, abs=1e-9)


def test_a_key_gtsam_cannot_hold_is_named():
    values = {"landmark": Point3(1.0, 2.0, 3.0), 3: Pose3(Rot3.identity(), np.zeros(3))}
    with pytest.raises(FgcError, match="variable 'landmark': no GTSAM key"):
        values_to_gtsam(values)
    gv = fgc.to_gtsam_values(values, keys={"landmark": gtsam.symbol("m", 0)})
    assert set(gv.keys()) == {3, gtsam.symbol("m", 0)}
    assert "gtsam_key" not in values_json(values)["landmark"]
    assert values_json(values)["3"] == {"key": 3, "type": "Pose3", "gtsam_key": 3,
                                        "value": [1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0, 0, 0, 0]}


def test_g2o_keeps_other_keys_in_comments_and_refuses_collisions():
    values = {0: Pose2(0.0, 0.0, 0.0), "a": Pose2(1.0, 0.0, 0.0), "l0": Point2(1.0, 1.0)}
    text = g2o_text(values)
    assert text.splitlines()[0] == "# fgc key 1 a"
    assert "VERTEX_XY 0 1 1" in text  # landmark L(0): a separate key space from pose 0
    with pytest.raises(FgcError, match="would both be vertex 1"):
        g2o_text({1: Pose2(0.0, 0.0, 0.0), "b": Pose2(1.0, 0.0, 0.0)})


def test_csv_has_a_header_naming_each_column():
    values = {0: Pose2(1.0, 2.0, 0.0), "l3": Point2(4.0, 5.0)}
    rows = list(csv.reader(io.StringIO(csv_text(values))))
    assert rows[0] == ["key", "type", "x", "y", "c", "s"]
    assert rows[1] == ["0", "Pose2", "1", "2", "1", "0"]
    assert rows[2] == ["l3", "Point2", "4", "5", "", ""]
