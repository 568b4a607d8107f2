"""fuse: the grouping rule, fused kernels against the members' own derivations, op counts.

Tolerance: a fused block's residual, Jacobians and costs equal the members' separately derived
``derive(type).evaluate`` (and ``NoiseModel.error``) to ≤ 1e-12 relative to max(1, |value|),
float64, at random points on the manifold (rotations uniform up to π) and at zero relative rotation.
The graph builders here are shared with ``test_storage.py``.
"""

from __future__ import annotations

import random

import numpy as np
import pytest

import fgc
from fgc.compiler.cache import cache_dir
from fgc.compiler.derive import derive
from fgc.compiler.fuse import OpCounts, block_type, fuse, group_factors
from fgc.frontend import noise
from fgc.frontend.factors import (
    BetweenFactor,
    CombinedImuFactor,
    GPSFactor,
    LidarOdometryFactor,
    PriorFactor,
)
from fgc.frontend.geometry import ImuBias, Pose3, Vector3
from fgc.frontend.preintegration import ImuParams, PreintegratedCombinedMeasurements

TOL = 1e-12
IMU_LIDAR = "CombinedImuFactor+LidarOdometryFactor"


# --------------------------------------------------------------------------------------------
# graph builders (real-looking data: random poses, preintegrated synthetic IMU samples)
# --------------------------------------------------------------------------------------------


def random_pim(rng: np.random.Generator) -> PreintegratedCombinedMeasurements:
    params = ImuParams.make_u(9.81, accelerometer_covariance=0.01 * np.eye(3),
                              gyroscope_covariance=1e-4 * np.eye(3),
                              integration_covariance=1e-8 * np.eye(3),
                              bias_acc_covariance=1e-6 * np.eye(3),
                              bias_omega_covariance=1e-8 * np.eye(3))
    pim = PreintegratedCombinedMeasurements(params, rng.normal(size=6) * 0.05)
    for _ in range(5):
        pim.integrate_measurement(rng.normal(size=3) + [0, 0, 9.81], rng.normal(size=3) * 0.3,
                                  0.01)
    return pim


def _keyframes(g: fgc.Graph, n: int, rng: np.random.Generator) -> None:
    """Keyframes j = 0…n−1 (pose x_j, velocity v_j, bias b_j) and priors on the first."""
    for j in range(n):
        g.add_variable(f"x{j}", Pose3.random(rng, 3.0))
        g.add_variable(f"v{j}", Vector3(rng.normal(size=3)))
        g.add_variable(f"b{j}", ImuBias(rng.normal(size=6) * 0.1))
    g.add(PriorFactor("x0", Pose3.random(rng), noise.diagonal([0.01] * 3 + [0.1] * 3)))
    g.add(PriorFactor("v0", Vector3(rng.normal(size=3)), noise.isotropic(3, 0.1)))
    g.add(PriorFactor("b0", ImuBias(np.zeros(6)), noise.diagonal([0.1] * 3 + [0.01] * 3)))


def imu_window(n: int, seed: int = 0) -> fgc.Graph:
    """Paper B's window: n 15-dim IMU states, CombinedImuFactors between consecutive ones."""
    rng = np.random.default_rng(seed)
    g = fgc.Graph()
    _keyframes(g, n, rng)
    for j in range(n - 1):
        g.add(CombinedImuFactor(f"x{j}", f"v{j}", f"x{j + 1}", f"v{j + 1}", f"b{j}",
                                f"b{j + 1}", random_pim(rng)))
    return g


def lio_graph(n: int, seed: int = 0) -> fgc.Graph:
    """Paper A's LIO window: GPS on every pose, IMU and LiDAR odometry between keyframes."""
    rng = np.random.default_rng(seed)
    g = fgc.Graph()
    _keyframes(g, n, rng)
    for j in range(n):
        g.add(GPSFactor(f"x{j}", rng.normal(size=3) * 5, noise.isotropic(3, 0.5)))
    for j in range(n - 1):
        g.add(CombinedImuFactor(f"x{j}", f"v{j}", f"x{j + 1}", f"v{j + 1}", f"b{j}",
                                f"b{j + 1}", random_pim(rng)))
        g.add(LidarOdometryFactor(f"x{j}", f"x{j + 1}", Pose3.random(rng, 0.5),
                                  noise.diagonal([0.01] * 3 + [0.05] * 3)))
    return g


def random_values(g: fgc.Graph, rng: np.random.Generator, same_rotation: bool = False) -> dict:
    """Random values for every variable; ``same_rotation`` gives all poses one rotation."""
    out = {k: type(v.initial).random(rng, 2.0) for k, v in g.variables.items()}
    if same_rotation:
        rot = out["x0"].rotation()
        out.update({k: Pose3(rot, v.t) for k, v in out.items() if isinstance(v, Pose3)})
    return out


@pytest.fixture(scope="module")
def lio() -> tuple[fgc.Graph, tuple]:
    g = lio_graph(5)
    return g, fuse(g)


# --------------------------------------------------------------------------------------------
# grouping
# --------------------------------------------------------------------------------------------


def test_lio_grouping(lio):
    g, blocks = lio
    names = [b.type.name for b in blocks]
    assert names.count(IMU_LIDAR) == 4 and names.count("GPSFactor") == 5
    assert sorted(n for n in names if n.startswith("Prior")) == [
        "PriorFactorImuBias", "PriorFactorPose3", "PriorFactorVector3"]
    assert len(blocks) == 3 + 5 + 4
    assert sorted(i for b in blocks for i in b.indices) == list(range(len(g.factors)))
    between = [b for b in blocks if b.type.name == IMU_LIDAR]
    for j, b in enumerate(between):
        assert b.keys == (f"x{j}", f"v{j}", f"x{j + 1}", f"v{j + 1}", f"b{j}", f"b{j + 1}")
        assert [m.positions for m in b.type.members] == [(0, 1, 2, 3, 4, 5), (0, 2)]
        assert b.type == between[0].type  # one block type for the whole chain
    for b in blocks:
        if b.type.name != IMU_LIDAR:
            assert len(b.keys) == 1 and len(b.factors) == 1  # unary factors stay alone


def test_grouping_is_deterministic():
    g = lio_graph(4)
    shuffled = fgc.Graph()
    for k, v in g.variables.items():
        shuffled.add_variable(k, v.initial)
    factors = list(g.factors)
    random.Random(3).shuffle(factors)
    for f in factors:
        shuffled.add(f)

    def summary(graph):
        return sorted((tuple(graph.factors[i].name for i in grp),
                       tuple(graph.factors[grp[0]].keys)) for grp in group_factors(graph))

    assert summary(g) == summary(shuffled)


@fgc.factor(name="TripleTranslation")
def triple(p: Pose3, q: Pose3, r: Pose3):
    """A three-pose factor, to exercise the subset rules."""
    return p.t + q.t - 2 * r.t


def test_grouping_rules():
    g = fgc.Graph()
    for k in "abcd":
        g.add_variable(k, Pose3.random(np.random.default_rng(ord(k))))
    n3, n6 = noise.isotropic(3, 1.0), noise.isotropic(6, 1.0)
    g.add(triple("a", "b", "c", noise=n3))  # 0: maximal {a, b, c}
    g.add(triple("b", "c", "d", noise=n3))  # 1: maximal {b, c, d}
    g.add(BetweenFactor("b", "c", Pose3(), n6))  # 2: {b, c} in two maximal sets: alone
    g.add(LidarOdometryFactor("b", "a", Pose3(), n6))  # 3: only in {a, b, c}: joins 0
    g.add(BetweenFactor("c", "b", Pose3(), n6))  # 4: same set as 2: joins 2
    g.add(GPSFactor("a", np.zeros(3), n3))  # 5: unary: alone
    g.add(GPSFactor("a", np.ones(3), n3))  # 6: unary, same key: alone too
    assert group_factors(g) == ((0, 3), (1,), (2, 4), (5,), (6,))
    blocks = fuse(g)
    assert blocks[0].type.members[1].positions == (1, 0)
    assert blocks[2].type.members[1].positions == (1, 0)


# --------------------------------------------------------------------------------------------
# fused kernels
# --------------------------------------------------------------------------------------------


def _close(a, b) -> bool:
    return np.max(np.abs(a - b), initial=0.0) <= TOL * max(1.0, np.max(np.abs(b), initial=0.0))


@pytest.mark.parametrize("same_rotation", [False, True])
def test_fused_block_equals_members(lio, same_rotation):
    g, blocks = lio
    rng = np.random.default_rng(11)
    for _ in range(3):
        values = random_values(g, rng, same_rotation)
        for b in blocks:
            r, jacs = b.evaluate(values)
            for f, m in zip(b.factors, b.type.members, strict=True):
                rows = slice(*m.rows)
                r_m, jacs_m = derive(f.type).evaluate([values[k] for k in f.keys], f.measured)
                assert _close(r[rows], r_m)
                for k, jac in enumerate(jacs):
                    want = jacs_m[m.positions.index(k)] if k in m.positions else 0 * jac[rows]
                    assert _close(jac[rows], want), (b.type.name, f.name, k)


def test_cost_mode_equals_members(lio):
    g, blocks = lio
    rng = np.random.default_rng(12)
    values = random_values(g, rng)
    for b in blocks:
        r, costs = b.type.evaluate_cost([values[k] for k in b.keys],
                                        [f.measured for f in b.factors],
                                        [f.noise for f in b.factors])
        assert _close(r, b.evaluate(values)[0])
        for f, m, c in zip(b.factors, b.type.members, costs, strict=True):
            assert _close(np.array([c]), np.array([f.noise.error(r[slice(*m.rows)])]))
    total = sum(b.error(values) for b in blocks)
    want = sum(f.noise.error(derive(f.type).evaluate([values[k] for k in f.keys], f.measured)[0])
               for f in g.factors)
    assert abs(total - want) <= TOL * max(1.0, abs(total))


def test_robust_member_error():
    g = lio_graph(3)
    lidar = next(i for i, f in enumerate(g.factors) if f.type.name == "LidarOdometryFactor")
    f = g.factors[lidar]
    robust = fgc.Graph()
    for k, v in g.variables.items():
        robust.add_variable(k, v.initial)
    for i, h in enumerate(g.factors):
        robust.add(h if i != lidar else LidarOdometryFactor(
            *f.keys, Pose3.from_storage(f.measured["measured"]), noise.huber(0.5, f.noise)))
    values = random_values(robust, np.random.default_rng(13))
    total = sum(b.error(values) for b in fuse(robust))
    want = sum(f.noise.error(derive(f.type).evaluate([values[k] for k in f.keys], f.measured)[0])
               for f in robust.factors)
    assert robust.factors[lidar].noise.robust is not None
    assert abs(total - want) <= TOL * max(1.0, total)


def test_symbols_renamed_and_prefixed(lio):
    _, blocks = lio
    bt = next(b for b in blocks if b.type.name == IMU_LIDAR).type
    names = {str(s) for s in bt.kernel.inputs}
    assert {"pose_i__R00", "pose_j__tz", "m1_measured__R00", "m0_delta_t"} <= names
    assert not any(n.startswith(("x1__", "x2__", "measured__")) for n in names)
    assert [b.name for b in bt.variables] == ["pose_i", "vel_i", "pose_j", "vel_j", "bias_i",
                                              "bias_j"]
    assert {str(s) for s in bt.cost_kernel.inputs} - names == {
        str(s) for m in bt.members for s in m.noise_symbols}


def test_structure_comes_from_members(lio):
    _, blocks = lio
    block = next(b for b in blocks if b.type.name == IMU_LIDAR)
    bt = block.type
    imu, lidar = (derive(f.type) for f in block.factors)
    assert bt.structure[0][:15] == imu.structure[0]
    assert bt.structure[2][15:] == lidar.structure[1]
    assert all(code == "0" for row in bt.structure[1][15:] for code in row)  # vel_i in LiDAR rows
    m, pos = bt.residual_dim, bt.residual_dim
    for codes in bt.structure:
        for code in (c for row in codes for c in row):
            if code != "x":
                assert bt.kernel.outputs[pos] == int(code)
            pos += 1
    assert pos == len(bt.kernel.outputs) and m == 21


# --------------------------------------------------------------------------------------------
# op counts and caching
# --------------------------------------------------------------------------------------------


def test_op_counts(lio):
    _, blocks = lio
    for b in blocks:
        members = [derive(f.type) for f in b.factors]
        before = OpCounts()
        for sf in members:
            before += OpCounts.of(sf.kernel)
        assert b.ops.jacobian_before == before
        assert b.ops.jacobian_after.total <= before.total
        assert b.ops.cost_after.total <= b.ops.cost_before.total
        if len(members) == 1:
            assert b.ops.jacobian_after == before and b.ops.saving("cost") == 0.0
    ops = next(b for b in blocks if b.type.name == IMU_LIDAR).ops
    assert ops.saving("jacobian") > 0.0  # CSE shares intermediates across the two members
    assert ops.cost_before.total < ops.jacobian_before.total / 3  # no Jacobian in cost mode


def test_fused_kernel_is_cached(lio):
    import fgc.compiler.fuse as fuse_module

    _, blocks = lio
    block = next(b for b in blocks if b.type.name == IMU_LIDAR)
    bt = block.type
    assert list(cache_dir().glob(f"fuse-{IMU_LIDAR}-{bt.key}.pkl"))
    saved = dict(fuse_module._MEMO)
    fuse_module._MEMO.clear()
    try:
        specs = tuple((f.type, m.positions, f.noise.kind)
                      for f, m in zip(block.factors, bt.members, strict=True))
        again = block_type(specs)  # read back from disk
    finally:
        fuse_module._MEMO.update(saved)
    assert again is not bt and again == bt and again.ops == bt.ops
    assert again.kernel.outputs == bt.kernel.outputs
