"""Plots a user can read (issue 35): landmarks and beacons drawn, a readable aspect for long
trajectories, and rotation-only problems drawn as attitude over the variables (``fgc simulate
--plot`` writes attitude.png for them, and says when a graph gets neither plot)."""

from __future__ import annotations

import numpy as np
import pytest

from fgc.frontend.geometry import Point2, Pose2, Rot3

pytest.importorskip("matplotlib")

from fgc.app import plots  # noqa: E402
from fgc.app.cli import main  # noqa: E402

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"

ROT3_SPEC = '''
import numpy as np
import fgc
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Rot3

def build(n: int = 6):
    g = fgc.Graph()
    step = Rot3.Expmap(np.array([0.02, -0.01, 0.3]))
    truth = [Rot3.identity()]
    for _ in range(1, n):
        truth.append(truth[-1].compose(step))
    for i, r in enumerate(truth):
        g.add_variable(f"r{i}", r.retract(np.array([0.05, -0.03, 0.04]) * (i % 2)))
    g.add(PriorFactor("r0", truth[0], noise.isotropic(3, 0.01)))
    for i in range(1, n):
        g.add(BetweenFactor(f"r{i - 1}", f"r{i}", step, noise.isotropic(3, 0.02)))
    return g
'''


def _png(path) -> None:
    data = path.read_bytes()
    assert data[:8] == PNG_MAGIC and len(data) > 5000


def _labels(fig) -> list[str]:
    return [t.get_text() for t in fig.axes[0].get_legend().get_texts()]


def test_landmarks_and_beacons_are_drawn(tmp_path):
    values = {f"x{i}": Pose2(float(i), 0.5 * i, 0.1) for i in range(8)}
    values |= {"b0": Point2(5.0, 5.0), "b1": Point2(-5.0, 8.0)}
    fig = plots.plot_trajectory(values, values, landmarks=values, gtsam_landmarks=values,
                                path=tmp_path / "t.png")
    _png(tmp_path / "t.png")
    assert _labels(fig) == ["fgc", "GTSAM", "landmarks (fgc)", "landmarks (GTSAM)", "start"]
    stars = [c for c in fig.axes[0].collections if c.get_label() == "landmarks (fgc)"]
    np.testing.assert_allclose(stars[0].get_offsets(), [[5.0, 5.0], [-5.0, 8.0]])
    assert fig.axes[0].get_aspect() == 1.0  # comparable extents: drawn to scale


def test_a_long_trajectory_is_not_squashed():
    long = {i: Pose2(100.0 * i, 0.3 * np.sin(i), 0.0) for i in range(20)}
    fig = plots.plot_trajectory(long)
    ax = fig.axes[0]
    assert ax.get_aspect() == "auto" and "axes not to scale" in ax.get_title()


def test_rotation_only_values_get_an_attitude_plot(tmp_path):
    step = Rot3.Expmap(np.array([0.0, 0.0, 0.5]))
    values = {f"r{i}": Rot3.identity() for i in range(1)}
    for i in range(1, 16):  # yaw passes ±180°: unwrapped, a straight line
        values[f"r{i}"] = values[f"r{i - 1}"].compose(step)
    fig = plots.plot_attitude(values, values, path=tmp_path / "a.png")
    _png(tmp_path / "a.png")
    yaw = fig.axes[0].get_lines()[2].get_ydata()
    np.testing.assert_allclose(np.diff(yaw), np.degrees(0.5), atol=1e-9)
    assert _labels(fig)[:3] == ["roll (fgc)", "pitch (fgc)", "yaw (fgc)"]


def test_simulate_plots_a_rotation_only_problem(tmp_path, capsys):
    spec = tmp_path / "attitude.py"
    spec.write_text(ROT3_SPEC)
    out = tmp_path / "plots"
    assert main(["simulate", str(spec), "--plot", str(out)]) == 0
    _png(out / "attitude.png")
    assert not (out / "trajectory.png").exists()
    text = capsys.readouterr().out
    assert f"plots → {out}: latency.png, storage.png, attitude.png" in text


def test_simulate_says_when_a_graph_gets_no_trajectory_or_attitude_plot(tmp_path, capsys):
    spec = tmp_path / "points.py"
    spec.write_text("import fgc\nfrom fgc.frontend import noise\nfrom fgc.frontend.factors "
                    "import BetweenFactor, PriorFactor\nfrom fgc.frontend.geometry import "
                    "Point2\n\ndef build():\n    g = fgc.Graph()\n    g.add_variable('a', "
                    "Point2(0.0, 0.0))\n    g.add_variable('b', Point2(1.0, 0.2))\n"
                    "    g.add(PriorFactor('a', Point2(0.0, 0.0), noise.isotropic(2, 0.1)))\n"
                    "    g.add(BetweenFactor('a', 'b', Point2(1.0, 0.0), "
                    "noise.isotropic(2, 0.1)))\n    return g\n")
    assert main(["simulate", str(spec), "--plot", str(tmp_path / "p")]) == 0
    assert "no trajectory or attitude plot" in capsys.readouterr().out


def test_a_rotation_only_stream_says_ate_is_not_applicable(tmp_path, capsys):
    """No positions, no ATE: the summary says so instead of printing "ATE rmse nan m"."""
    spec = tmp_path / "attitude.py"
    spec.write_text(ROT3_SPEC)
    assert main(["stream", str(spec), "--window", "3"]) == 0
    text = capsys.readouterr().out
    assert "ATE not applicable (no Pose2/Pose3 variables" in text and "nan" not in text
