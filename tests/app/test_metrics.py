"""fgc.app.metrics: TUM files, ATE and RPE on hand-computable trajectories, and against evo.

Tolerances: hand-computed cases to 1e-12; evo (a test dependency) to 1e-9.
"""

from __future__ import annotations

import numpy as np
import pytest

from fgc.app.metrics import (
    Trajectory,
    as_trajectory,
    ate,
    quaternion_xyzw,
    read_tum,
    rotation_from_quaternion,
    rpe,
    write_tum,
)
from fgc.errors import FgcError
from fgc.frontend.geometry import Point3, Pose2, Pose3, Rot3


def _wiggly(n: int = 20, seed: int = 0) -> list[tuple[float, Pose3]]:
    """A non-degenerate 3-D trajectory: a helix with rotating orientation."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        a = 0.4 * i
        t = np.array([3 * np.cos(a), 3 * np.sin(a), 0.2 * i]) + 0.05 * rng.normal(size=3)
        out.append((0.1 * i, Pose3(Rot3.Expmap(np.array([0.1, -0.2, a])), t)))
    return out


def _transformed(traj, rot: np.ndarray, trans: np.ndarray, scale: float = 1.0):
    """Every pose left-multiplied by the similarity [s·R | t] (translation s·R·t + t)."""
    return [(t, Pose3(Rot3(rot @ p.r.R), scale * rot @ p.t + trans)) for t, p in traj]


ROT = Rot3.Expmap(np.array([0.3, -0.5, 1.2])).R
TRANS = np.array([4.0, -1.0, 2.5])


def test_identical_trajectories_have_zero_error():
    traj = _wiggly()
    for align in ("none", "se3", "sim3"):
        res = ate(traj, traj, align=align)
        assert res.rmse == pytest.approx(0.0, abs=1e-12) and res.max == pytest.approx(0, abs=1e-12)
        assert rpe(traj, traj, align=align).max == pytest.approx(0.0, abs=1e-12)


def test_pure_translation_offset():
    ref = _wiggly()
    est = [(t, Pose3(p.r, p.t + np.array([1.0, 2.0, 2.0]))) for t, p in ref]
    res = ate(est, ref)
    for stat in (res.rmse, res.mean, res.median, res.min, res.max):
        assert stat == pytest.approx(3.0, rel=1e-12)
    assert res.std == pytest.approx(0.0, abs=1e-12) and res.sse == pytest.approx(9.0 * len(ref))
    aligned = ate(est, ref, align="se3")
    assert aligned.rmse == pytest.approx(0.0, abs=1e-12)
    np.testing.assert_allclose(aligned.alignment.translation, [-1.0, -2.0, -2.0], atol=1e-12)
    np.testing.assert_allclose(aligned.alignment.rotation, np.eye(3), atol=1e-12)
    # a world-frame offset of every pose leaves relative motion unchanged
    assert rpe(est, ref).max == pytest.approx(0.0, abs=1e-12)


def test_rotated_and_scaled_copies_with_alignment():
    ref = _wiggly()
    rigid = _transformed(ref, ROT, TRANS)
    assert ate(rigid, ref).rmse > 1.0
    res = ate(rigid, ref, align="se3")
    assert res.rmse == pytest.approx(0.0, abs=1e-12)
    np.testing.assert_allclose(res.alignment.rotation, ROT.T, atol=1e-12)  # maps est onto ref
    assert rpe(rigid, ref).rmse == pytest.approx(0.0, abs=1e-12)  # RPE ignores a rigid motion
    scaled = _transformed(ref, ROT, TRANS, scale=2.0)
    assert ate(scaled, ref, align="se3").rmse > 0.5
    sim = ate(scaled, ref, align="sim3")
    assert sim.rmse == pytest.approx(0.0, abs=1e-12)
    assert sim.alignment.scale == pytest.approx(0.5, rel=1e-12)
    assert rpe(scaled, ref, align="sim3").max == pytest.approx(0.0, abs=1e-12)


def test_rpe_of_stretched_straight_line():
    """Steps of 1.1 m against 1 m: every frame-to-frame translation error is 0.1 m; Δ = 2 → 0.2."""
    ref = [(float(i), Pose3(Rot3.identity(), [float(i), 0.0, 0.0])) for i in range(6)]
    est = [(float(i), Pose3(Rot3.identity(), [1.1 * i, 0.0, 0.0])) for i in range(6)]
    res = rpe(est, ref)
    assert len(res.errors) == 5
    np.testing.assert_allclose(res.errors, 0.1, rtol=1e-12)
    np.testing.assert_allclose(rpe(est, ref, delta=2).errors, [0.2, 0.2], rtol=1e-12)  # 0-2, 2-4
    np.testing.assert_allclose(rpe(est, ref, delta=2, all_pairs=True).errors, [0.2] * 4,
                               rtol=1e-12)
    np.testing.assert_allclose(ate(est, ref).errors, 0.1 * np.arange(6), atol=1e-12)


def test_rpe_sees_a_heading_error():
    """Δ = 1 pair with a 90° yaw error on the first pose: ref step (1, 0, 0) in the body frame,
    estimated step rotated into (0, −1, 0), error ‖(−1, −1, 0)‖ = √2."""
    yaw = Rot3.Expmap(np.array([0.0, 0.0, np.pi / 2]))
    ref = [(0.0, Pose3()), (1.0, Pose3(Rot3.identity(), [1.0, 0.0, 0.0]))]
    est = [(0.0, Pose3(yaw, [0.0, 0.0, 0.0])), (1.0, Pose3(Rot3.identity(), [1.0, 0.0, 0.0]))]
    assert rpe(est, ref).errors[0] == pytest.approx(np.sqrt(2.0), rel=1e-12)


def test_tum_round_trip_and_format(tmp_path):
    traj = _wiggly(8)
    path = write_tum(tmp_path / "est.txt", traj)
    lines = path.read_text().splitlines()
    assert len(lines) == 8 and all(len(line.split()) == 8 for line in lines)
    assert all(float(line.split()[7]) >= 0 for line in lines)  # qw ≥ 0
    back = read_tum(path)
    np.testing.assert_allclose(back.poses, as_trajectory(traj).poses, atol=1e-15)
    np.testing.assert_array_equal(back.times, [t for t, _ in traj])


def test_trajectory_inputs():
    values = {"x0": Pose3(), "v0": Point3([1.0, 2.0, 3.0]), "x1": Pose3(Rot3.identity(), [1, 0, 0])}
    by_seq = as_trajectory(values, [10.0, 11.0])
    np.testing.assert_array_equal(by_seq.times, [10.0, 11.0])
    np.testing.assert_array_equal(by_seq.positions[1], [1.0, 0.0, 0.0])
    by_map = as_trajectory(values, {"x1": 5.0, "x0": 4.0})
    np.testing.assert_array_equal(by_map.positions[:, 0], [0.0, 1.0])
    assert len(as_trajectory(values)) == 2
    planar = as_trajectory([(0.0, Pose2(1.0, 2.0, np.pi / 2))])
    np.testing.assert_allclose(planar.poses[0, :3, :3], Rot3.Expmap([0, 0, np.pi / 2]).R,
                               atol=1e-15)
    with pytest.raises(FgcError, match="3 times for the 2 Pose3"):
        as_trajectory(values, [0.0, 1.0, 2.0])
    with pytest.raises(FgcError, match="paired by index"):
        ate(_wiggly(5), _wiggly(6))
    with pytest.raises(FgcError, match="differ by more than"):
        ate(_wiggly(5), [(t + 1.0, p) for t, p in _wiggly(5)])


@pytest.mark.parametrize("rotvec", [[0, 0, 0], [0.1, 0.2, 0.3], [np.pi, 0, 0], [0, 3.1, 0.2],
                                    [0.5, 0.5, -3.0]])
def test_quaternion_round_trip(rotvec):
    r = Rot3.Expmap(np.asarray(rotvec, float)).R
    q = quaternion_xyzw(r)
    assert q[3] >= 0 and np.linalg.norm(q) == pytest.approx(1.0)
    np.testing.assert_allclose(rotation_from_quaternion(q), r, atol=1e-15)


@pytest.mark.parametrize("relation", ["translation", "rotation"])
def test_matches_evo(tmp_path, relation):
    """ATE (none / se3 / sim3) and RPE (Δ = 1, 3; consecutive and all pairs), translation (m)
    and rotation angle (degrees), as evo computes them from the same TUM files (evo is a test
    dependency: ``pip install 'fgc[test]'``)."""
    from evo.core import metrics as evo_metrics
    from evo.tools import file_interface

    rng = np.random.default_rng(7)
    ref = _wiggly(25, seed=1)
    est = [(t, p.retract(0.05 * rng.normal(size=6))) for t, p in
           _transformed(ref, ROT, TRANS, scale=1.3)]
    ref_file, est_file = write_tum(tmp_path / "ref.txt", ref), write_tum(tmp_path / "est.txt", est)
    rel = (evo_metrics.PoseRelation.translation_part if relation == "translation"
           else evo_metrics.PoseRelation.rotation_angle_deg)
    for align in ("none", "se3", "sim3"):
        t_ref = file_interface.read_tum_trajectory_file(str(ref_file))
        t_est = file_interface.read_tum_trajectory_file(str(est_file))
        if align != "none":
            t_est.align(t_ref, correct_scale=align == "sim3")
        kw = {"align": align, "relation": relation}
        for name, ours, metric in [
            ("ape", ate(read_tum(est_file), read_tum(ref_file), **kw), evo_metrics.APE(rel)),
            ("rpe", rpe(read_tum(est_file), read_tum(ref_file), **kw),
             evo_metrics.RPE(rel, delta=1, delta_unit=evo_metrics.Unit.frames, all_pairs=True)),
            ("rpe3", rpe(read_tum(est_file), read_tum(ref_file), delta=3, **kw),
             evo_metrics.RPE(rel, delta=3, delta_unit=evo_metrics.Unit.frames)),
            ("rpe3all", rpe(read_tum(est_file), read_tum(ref_file), delta=3, all_pairs=True,
                            **kw),
             evo_metrics.RPE(rel, delta=3, delta_unit=evo_metrics.Unit.frames, all_pairs=True))]:
            metric.process_data((t_ref, t_est))
            stats = metric.get_all_statistics()
            assert ours.unit == ("m" if relation == "translation" else "deg")
            np.testing.assert_allclose(ours.errors, metric.error, rtol=1e-9, atol=1e-12,
                                       err_msg=f"{name} {align}")
            for key in ("rmse", "mean", "median", "std", "min", "max", "sse"):
                assert getattr(ours, key) == pytest.approx(stats[key], rel=1e-9), (name, key)


def test_rotation_error_of_a_known_rotation():
    """Every estimated pose turned by 30° about a fixed axis: ATE angle 30° everywhere; RPE 0."""
    ref = _wiggly()
    turn = Rot3.Expmap(np.radians(30.0) * np.array([0.0, 0.6, 0.8])).R
    est = [(t, Pose3(Rot3(p.r.R @ turn), p.t)) for t, p in ref]
    res = ate(est, ref, relation="rotation")
    np.testing.assert_allclose(res.errors, 30.0, rtol=1e-12)
    assert rpe(est, ref, relation="rotation").max > 1.0  # body-frame turn: relative poses change
    with pytest.raises(FgcError, match="relation"):
        ate(est, ref, relation="angle")


def test_trajectory_validates_shapes():
    with pytest.raises(FgcError, match="shape"):
        Trajectory(np.zeros(2), np.zeros((2, 3, 3)))
