"""fgc.plots: each figure is written, non-trivial and deterministic; clear errors without
matplotlib."""

from __future__ import annotations

import sys

import numpy as np
import pytest

from fgc.errors import FgcError
from fgc.geometry import Point3, Pose2, Pose3, Rot3

pytest.importorskip("matplotlib")

from fgc import plots  # noqa: E402

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def _values(n: int = 12, shift: float = 0.0) -> dict:
    out = {}
    for i in range(n):
        a = 0.3 * i
        out[f"x{i}"] = Pose3(Rot3.Expmap(np.array([0.0, 0.0, a])),
                             [10 * np.cos(a) + shift, 10 * np.sin(a), 0.0])
        out[f"v{i}"] = Point3([1.0, 0.0, 0.0])  # not a pose: ignored
    return out


def _assert_png(path) -> None:
    data = path.read_bytes()
    assert data[:8] == PNG_MAGIC and len(data) > 5000  # a drawn figure, not an empty canvas


def test_plot_trajectory(tmp_path):
    gps = np.array([[10 * np.cos(0.3 * i), 10 * np.sin(0.3 * i) + 0.5, 0.0] for i in range(12)])
    out = plots.plot_trajectory(tmp_path / "traj.png", _values(), _values(shift=0.2), gps=gps)
    _assert_png(out)
    planar = {i: Pose2(float(i), float(i % 3), 0.0) for i in range(5)}
    _assert_png(plots.plot_trajectory(tmp_path / "planar.png", planar))


def test_plot_trajectory_reads_gtsam_values(tmp_path):
    gtsam = pytest.importorskip("gtsam")
    values = gtsam.Values()
    for i in range(6):
        values.insert(i, gtsam.Pose3(gtsam.Rot3(), np.array([float(i), float(i * i), 0.0])))
    values.insert(99, np.zeros(3))
    np.testing.assert_allclose(plots._positions(values)[:, 1], [i * i for i in range(6)])
    _assert_png(plots.plot_trajectory(tmp_path / "g.png", _values(), values))


def test_plot_latency_breakdown(tmp_path):
    units = {"General Calculation": 12000, "QR (Givens)": 30500, "back-substitution": 4200}
    _assert_png(plots.plot_latency_breakdown(tmp_path / "lat.png", units))
    with pytest.raises(FgcError, match="no units"):
        plots.plot_latency_breakdown(tmp_path / "empty.png", {})


def test_pareto_front_and_plot(tmp_path):
    pts = [dict(latency_ms=ms, dsp=d, label=f"u{k}") for k, (ms, d) in enumerate(
        [(3.0, 200), (2.1, 400), (1.5, 800), (2.5, 600), (1.2, 1600), (3.5, 150), (2.1, 400)])]
    assert plots.pareto_front(pts) == [5, 0, 1, 6, 2, 4]  # u3 dominated by u1; ties both kept
    assert plots.pareto_front(pts, x="latency_ms", y="dsp") == [4, 2, 1, 6, 0, 5]
    _assert_png(plots.plot_pareto(tmp_path / "pareto.png", pts))
    with pytest.raises(FgcError, match=r"points \[0\] lack"):
        plots.plot_pareto(tmp_path / "bad.png", [{"dsp": 1}])


def test_plot_storage_steps(tmp_path):
    _assert_png(plots.plot_storage_steps(tmp_path / "s.png", 250000, [21000, 19000, 12500]))
    _assert_png(plots.plot_storage_steps(tmp_path / "t.png", 900, [("sparse", 600), ("seq", 500)]))


def test_output_is_deterministic(tmp_path):
    for suffix in (".png", ".svg"):
        a = plots.plot_trajectory(tmp_path / f"a{suffix}", _values(), gps=np.ones((3, 2)))
        b = plots.plot_trajectory(tmp_path / f"b{suffix}", _values(), gps=np.ones((3, 2)))
        assert a.read_bytes() == b.read_bytes()
    svg = (tmp_path / "a.svg").read_text()
    assert "<dc:date>" not in svg and "Matplotlib v" not in svg


def test_errors(tmp_path, monkeypatch):
    with pytest.raises(FgcError, match="unsupported figure format '.jpg'"):
        plots.plot_storage_steps(tmp_path / "s.jpg", 10, [5])
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # as if it were not installed
    with pytest.raises(FgcError, match=r"pip install 'fgc\[plots\]'"):
        plots.plot_storage_steps(tmp_path / "s.png", 10, [5])
