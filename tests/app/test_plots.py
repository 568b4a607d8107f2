"""fgc.app.plots: each function returns its Figure and, given a path, writes it (non-trivial and
deterministic); honest axes; one clear error without matplotlib; ``fgc simulate --plot`` overlays
GTSAM's solution and the GPS fixes."""

from __future__ import annotations

import sys

import numpy as np
import pytest

from fgc.errors import FgcError
from fgc.frontend.geometry import Point3, Pose2, Pose3, Rot3

pytest.importorskip("matplotlib")

from fgc.app import plots  # noqa: E402

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


def _saved(func, tmp_path, name, *args, **kwargs):
    """Call a plot function with path=…, check it returned a Figure and wrote a PNG."""
    from matplotlib.figure import Figure

    path = tmp_path / name
    fig = func(*args, path=path, **kwargs)
    assert isinstance(fig, Figure)
    _assert_png(path)
    return fig


def _legend(fig) -> list[str]:
    return [t.get_text() for t in fig.axes[0].get_legend().get_texts()]


def test_plot_trajectory(tmp_path):
    gps = np.array([[10 * np.cos(0.3 * i), 10 * np.sin(0.3 * i) + 0.5, 0.0] for i in range(12)])
    fig = _saved(plots.plot_trajectory, tmp_path, "traj.png", _values(), _values(shift=0.2),
                 gps=gps)
    assert _legend(fig) == ["fgc", "GTSAM", "GPS", "start"]
    planar = {i: Pose2(float(i), float(i % 3), 0.0) for i in range(5)}
    assert _legend(_saved(plots.plot_trajectory, tmp_path, "planar.png", planar)) == [
        "fgc", "start"]


def test_figures_are_returned_without_saving(tmp_path):
    """A notebook gets the Figure; nothing is written without a path."""
    from matplotlib.figure import Figure

    fig = plots.plot_storage_steps(900, [600, 500])
    assert isinstance(fig, Figure) and list(tmp_path.iterdir()) == []
    fig.canvas.draw()  # drawable as returned (what a notebook's display does)


def test_plot_trajectory_reads_gtsam_values(tmp_path):
    gtsam = pytest.importorskip("gtsam")
    values = gtsam.Values()
    for i in range(6):
        values.insert(i, gtsam.Pose3(gtsam.Rot3(), np.array([float(i), float(i * i), 0.0])))
    values.insert(99, np.zeros(3))
    np.testing.assert_allclose(plots._positions(values)[:, 1], [i * i for i in range(6)])
    _saved(plots.plot_trajectory, tmp_path, "g.png", _values(), values)


def test_plot_latency_breakdown(tmp_path):
    units = {"General Calculation": 12000, "QR (Givens)": 30500, "back-substitution": 4200}
    fig = _saved(plots.plot_latency_breakdown, tmp_path, "lat.png", units)
    assert "model estimate" in fig.axes[0].get_title()
    with pytest.raises(FgcError, match="no units"):
        plots.plot_latency_breakdown({}, path=tmp_path / "empty.png")


def test_pareto_front_and_plot(tmp_path):
    pts = [dict(latency_ms=ms, dsp=d, label=f"u{k}") for k, (ms, d) in enumerate(
        [(3.0, 200), (2.1, 400), (1.5, 800), (2.5, 600), (1.2, 1600), (3.5, 150), (2.1, 400)])]
    assert plots.pareto_front(pts) == [5, 0, 1, 6, 2, 4]  # u3 dominated by u1; ties both kept
    assert plots.pareto_front(pts, x="latency_ms", y="dsp") == [4, 2, 1, 6, 0, 5]
    _saved(plots.plot_pareto, tmp_path, "pareto.png", pts)
    with pytest.raises(FgcError, match=r"points \[0\] lack"):
        plots.plot_pareto([{"dsp": 1}], path=tmp_path / "bad.png")


def test_plot_storage_steps_linear_axis(tmp_path):
    """A 20× reduction must look like one: linear axis from 0, bars as tall as their words,
    each step labelled with its ratio to dense."""
    fig = _saved(plots.plot_storage_steps, tmp_path, "s.png", 250000, [21000, 19000, 12500])
    ax = fig.axes[0]
    assert ax.get_yscale() == "linear" and ax.get_ylim()[0] == 0
    heights = [b.get_height() for b in ax.patches]
    assert heights == [250000, 21000, 19000, 12500]
    labels = [t.get_text() for t in ax.texts]
    assert labels[-1] == "12,500\n20.0× smaller"
    _saved(plots.plot_storage_steps, tmp_path, "t.png", 900, [("sparse", 600), ("seq", 500)])


def test_plot_accuracy_axis_is_in_error_units(tmp_path):
    sols = [{"label": "qr float32", "rotation": 3.1e-6, "translation": 2.0e-5},
            {"label": "cholesky float64", "rotation": 0.0, "translation": 1e-13}]
    fig = _saved(plots.plot_accuracy, tmp_path, "acc.png", sols)
    ax = fig.axes[0]
    assert ax.get_yscale() == "log" and "rad" in ax.get_ylabel() and "m" in ax.get_ylabel()
    assert [t.get_text() for t in ax.get_xticklabels()] == ["qr float32", "cholesky float64"]
    lo, hi = ax.get_ylim()
    assert lo <= 1e-18 and hi >= 2.0e-5  # every error, the exact 0 at the floor, is on the plot
    assert "0" in [t.get_text() for t in ax.texts]
    with pytest.raises(FgcError, match="finite"):
        plots.plot_accuracy([{"label": "x", "rotation": float("nan"), "translation": 0.0}])


def test_output_is_deterministic(tmp_path):
    for suffix in (".png", ".svg"):
        plots.plot_trajectory(_values(), gps=np.ones((3, 2)), path=tmp_path / f"a{suffix}")
        plots.plot_trajectory(_values(), gps=np.ones((3, 2)), path=tmp_path / f"b{suffix}")
        assert (tmp_path / f"a{suffix}").read_bytes() == (tmp_path / f"b{suffix}").read_bytes()
    svg = (tmp_path / "a.svg").read_text()
    assert "<dc:date>" not in svg and "Matplotlib v" not in svg


def test_errors(tmp_path, monkeypatch):
    with pytest.raises(FgcError, match="unsupported figure format '.jpg'"):
        plots.plot_storage_steps(10, [5], path=tmp_path / "s.jpg")
    assert list(tmp_path.iterdir()) == []
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # as if it were not installed
    with pytest.raises(FgcError, match=r'pip install "fgc\[plots\]"'):
        plots.plot_storage_steps(10, [5], path=tmp_path / "s.png")


def test_missing_matplotlib_is_one_error_everywhere(tmp_path, monkeypatch, capsys):
    """fgc report --html without matplotlib: exit 2 with the install hint (not a page that
    silently lacks its figures)."""
    from fgc.app.cli import main

    monkeypatch.setitem(sys.modules, "matplotlib", None)
    assert main(["report", "examples/range_beacons.py", "--iterations", "2",
                 "--html", str(tmp_path / "r.html")]) == 2
    assert 'pip install "fgc[plots]"' in capsys.readouterr().err


def test_simulate_plot_overlays_gtsam_and_gps(tmp_path, monkeypatch):
    """``fgc simulate --plot`` gives the trajectory plot GTSAM's solution (which differs from
    the initial estimate: it is solved) and the GPS fixes of the graph's GPSFactors."""
    from fgc.app.cli import main

    seen = {}
    real = plots.plot_trajectory

    def spy(fgc_values, gtsam_values=None, gps=None, **kw):
        seen.update(fgc=fgc_values, gtsam=gtsam_values, gps=gps)
        return real(fgc_values, gtsam_values, gps, **kw)

    monkeypatch.setattr(plots, "plot_trajectory", spy)
    assert main(["simulate", "examples/lio.py", "-p", "N=6", "--plot", str(tmp_path), "-q"]) == 0
    _assert_png(tmp_path / "trajectory.png")
    fgc_pos, ref_pos = plots._positions(seen["fgc"]), plots._positions(seen["gtsam"])
    assert fgc_pos.shape == ref_pos.shape == (6, 3)
    np.testing.assert_allclose(fgc_pos, ref_pos, atol=1e-2)  # float32 simulator vs GTSAM
    assert seen["gps"].shape == (6, 3)
