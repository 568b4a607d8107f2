"""fgc.interop.datasets reads GTSAM's example files to GTSAM's graph, refuses what it would drop,
and
fgc.interop.estimates writes estimates (g2o / TUM / CSV, keyed JSON)."""

import json

import gtsam
import numpy as np
import pytest

from fgc.app.cli import main as cli_main
from fgc.errors import DataError
from fgc.interop.datasets import read_pose_graph
from fgc.interop.estimates import csv_text, g2o_text, tum_text, values_json
from fgc.interop.gtsam_data import gtsam_data_dir
from fgc.interop.to_gtsam import to_gtsam

SMALL = ["example.graph", "w100.graph", "w100_30.g2o", "pose2example.txt", "noisyToyGraph.txt",
         "pose3example.txt", "pose3example-offdiagonal.txt", "toyExample.g2o", "Klaus3.g2o",
         "pose3Localizationexample.txt"]


def _gtsam_read(name):
    path = str(gtsam_data_dir() / name)
    graph, values = gtsam.load2D(path)
    if graph.size() == 0:
        graph, values = gtsam.load3D(path)
    return graph, values


def _kinds(graph) -> dict:
    out: dict = {}
    for i in range(graph.size()):
        name = type(graph.at(i)).__name__
        out[name] = out.get(name, 0) + 1
    return out


@pytest.mark.parametrize("name", SMALL)
def test_small_files_read_to_gtsams_graph(name):
    """Same factors (count and kind) and the same measurements: GTSAM's error of the graph fgc
    built equals GTSAM's error of its own graph at GTSAM's values, to 1e-12 relative."""
    ggraph, gvalues = _gtsam_read(name)
    graph = read_pose_graph(gtsam_data_dir() / name)
    assert len(graph.factors) == ggraph.size()
    ours = to_gtsam(graph)
    assert _kinds(ours.graph) == _kinds(ggraph)
    e_ours, e_gtsam = ours.graph.error(ours.values), ggraph.error(gvalues)
    assert abs(e_ours - e_gtsam) <= 1e-12 * max(1.0, e_gtsam)


@pytest.mark.parametrize("name, message", [
    ("sphere_smallnoise.graph", r"sphere_smallnoise\.graph:2201: EDGE3 takes 29 fields after "
                                r"the tag .*, got 8 \(a field missing"),
    ("cityTrees_reduced_1k.g2o", r"cityTrees_reduced_1k\.g2o:1000: tag 'LANDMARK2'"),
    ("known_landmark_localization_3.g2o", r"localization_3\.g2o:\d+: EDGE_SE3_TRACKXYZ lines are "
                                          r"refused: .*BearingRangeFactor3D.*no fgc built-in"),
    ("example_with_vertices.g2o", r"16 vertices but no edge lines"),
])
def test_what_fgc_cannot_represent_is_refused_by_line(name, message):
    with pytest.raises(DataError, match=message):
        read_pose_graph(gtsam_data_dir() / name)


def test_vertexless_toro_file_chains_odometry(tmp_path):
    """EDGE3 lines only (like sphere2500.txt): initial values by odometry chaining make every
    between factor's error zero at the initial values; chordal initialisation is accepted."""
    lines = [f"EDGE3 {i} {i + 1} 1 0.1 0 0.05 -0.02 0.3 " + " ".join(
        "100" if r == c else "0" for r in range(6) for c in range(r, 6)) for i in range(4)]
    path = tmp_path / "chain.graph"
    path.write_text("\n".join(lines) + "\n")
    graph = read_pose_graph(path, key_prefix=None)
    assert list(graph.variables) == [0, 1, 2, 3, 4]  # int keys stay ints
    assert graph.error() == pytest.approx(0.0, abs=1e-20)
    assert len(read_pose_graph(path, init="chordal").factors) == 4


def test_verify_refuses_the_misread_it_once_passed(tmp_path, capsys):
    """Issue 34: example.graph with one landmark id written 144.7 was read by GTSAM with every
    field shifted, and `fgc verify` said PASSED because GTSAM misread it the same way; now the
    line is refused, exit 2, in one line naming file, line and field."""
    lines = (gtsam_data_dir() / "example.graph").read_text().splitlines()
    k = next(i for i, x in enumerate(lines) if x.startswith("BR 0 144 "))
    lines[k] = lines[k].replace("BR 0 144 ", "BR 0 144.7 ")
    path = tmp_path / "example.graph"
    path.write_text("\n".join(lines) + "\n")
    assert cli_main(["verify", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert f"example.graph:{k + 1}: BR landmark_id is '144.7', not a non-negative integer" in err


def test_comment_lines_do_not_stop_gtsams_reader(tmp_path):
    """GTSAM's load2D reads two ids from every line that is not a between edge, so a comment's
    words end its reading silently; fgc gives it the checked data lines alone and reads all."""
    lines = (gtsam_data_dir() / "example.graph").read_text().splitlines()
    path = tmp_path / "commented.graph"
    path.write_text("\n".join(["# example.graph, with comments"] + lines[:100]
                              + ["# the rest"] + lines[100:]) + "\n")
    ggraph, _ = gtsam.load2D(str(path))
    assert ggraph.size() == 0  # GTSAM's own reader: nothing after the first comment
    assert len(read_pose_graph(path).factors) == 516


def test_gtsam_reading_a_line_otherwise_is_refused_by_line(tmp_path, monkeypatch):
    """fgc compares GTSAM's factors with its own reading of each line: a GTSAM reader that read
    one measurement differently (here: made to) is a DataError naming that line."""
    path = tmp_path / "w.graph"
    path.write_text((gtsam_data_dir() / "w100_30.g2o").read_text())
    load2d = gtsam.load2D

    def misreading(name, *args):
        graph, values = load2d(name, *args)
        gf = graph.at(3)
        graph.replace(3, gtsam.BetweenFactorPose2(gf.keys()[0], gf.keys()[1],
                                                  gtsam.Pose2(1.0, 2.0, 0.3), gf.noiseModel()))
        return graph, values

    monkeypatch.setattr(gtsam, "load2D", misreading)
    edge4 = [i for i, x in enumerate(path.read_text().splitlines(), 1) if x.startswith("EDGE")][3]
    with pytest.raises(DataError, match=rf"w\.graph:{edge4}: GTSAM's reader made another "
                                        r"measurement of this EDGE2 line"):
        read_pose_graph(path)


@pytest.mark.heavy
@pytest.mark.parametrize("name", ["w20000.txt", "victoria_park.txt", "sphere2500.txt",
                                  "sphere2500_groundtruth.txt", "w10000.graph"])
def test_large_files_count(name):
    """The full sweep's large files (bench/datasets.py lists every file)."""
    ggraph, _ = _gtsam_read(name)
    graph = read_pose_graph(gtsam_data_dir() / name)
    assert len(graph.factors) == ggraph.size()
    assert _kinds(to_gtsam(graph).graph) == _kinds(ggraph)


# --------------------------------------------------------------------------------------------
# estimates out
# --------------------------------------------------------------------------------------------


def test_exports_match_gtsam_conventions():
    """g2o vertices and TUM quaternions agree with GTSAM's own (Pose3.rotation().toQuaternion,
    Pose2.theta) at a non-trivial estimate; int keys stay ints in the keyed JSON and CSV."""
    graph = read_pose_graph(gtsam_data_dir() / "pose3example.txt", key_prefix=None)
    _, gvalues = _gtsam_read("pose3example.txt")
    values = {k: v.initial for k, v in graph.variables.items()}
    for line, k in zip(tum_text(values).splitlines(), values, strict=True):
        t, x, y, z, qx, qy, qz, qw = map(float, line.split())
        pose = gvalues.atPose3(k)
        q = pose.rotation().toQuaternion()
        sign = 1.0 if q.w() >= 0 else -1.0
        np.testing.assert_allclose([qx, qy, qz, qw],
                                   sign * np.array([q.x(), q.y(), q.z(), q.w()]), atol=1e-12)
        np.testing.assert_allclose([x, y, z], pose.translation(), atol=1e-12)
        assert t == list(values).index(k)
    g2o = [line.split() for line in g2o_text(values).splitlines()]
    assert [int(f[1]) for f in g2o] == list(values) and g2o[0][0] == "VERTEX_SE3:QUAT"
    keyed = json.loads(json.dumps(values_json(values)))
    assert [v["key"] for v in keyed.values()] == [0, 1, 2, 3, 4]
    assert csv_text(values).splitlines()[2].startswith("1,Pose3,")
    g2d = read_pose_graph(gtsam_data_dir() / "w100.graph")
    v2 = {k: v.initial for k, v in g2d.variables.items()}
    rows = [line.split() for line in g2o_text(v2).splitlines() if not line.startswith("#")]
    _, gv2 = _gtsam_read("w100.graph")
    assert float(rows[7][4]) == pytest.approx(gv2.atPose2(7).theta(), abs=1e-12)


def test_cli_writes_values_and_marginals(tmp_path, capsys):
    out, report = tmp_path / "est.csv", tmp_path / "r.json"
    code = cli_main(["run", "pose3example.txt", "--backend", "sim", "--values", str(out),
                     "--marginals", "1", "--json", str(report)])
    assert code == 0
    printed = capsys.readouterr().out
    assert "ms" in printed and "marginal covariance of 1" in printed
    data = json.loads(report.read_text())
    assert [v["key"] for v in data["values"].values()] == list(range(5))  # the file's ids
    assert len(data["marginals"]["1"]["covariance"]) == 6
    assert len(out.read_text().splitlines()) == 1 + 5  # the header, then one row per pose
    assert cli_main(["run", "pose3example.txt", "--backend", "sim", "--values",
                     str(tmp_path / "x.bad")]) == 2
