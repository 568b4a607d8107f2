"""storage: word counts of the papers' storage steps, against closed forms and against numbers.

Structure claims are checked numerically at a random point: every entry the plan calls
structurally zero is exactly 0.0 in the assembled whitened A (or in H = AᵀA, g = Aᵀb), and (in H)
every other entry is not; every entry it calls ±W[i, r] has that magnitude exactly; every
shared-pair entry is the sign flip of its partner to ≤ 1e-12 relative.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from test_fuse import imu_window, lio_graph, random_values

from fgc.compiler.fuse import fuse
from fgc.compiler.storage import ChainLayout, factor_structure, plan_storage
from fgc.errors import StructureError
from fgc.frontend import noise

STATE = 15  # pose 6 + velocity 3 + bias 6


def layout(n: int, swap: int | None = None) -> ChainLayout:
    """Keyframe clusters (x_j, v_j, b_j); cluster ``swap`` lists its keys in another order."""
    return ChainLayout(tuple((f"v{j}", f"x{j}", f"b{j}") if j == swap else
                             (f"x{j}", f"v{j}", f"b{j}") for j in range(n)))


def with_diagonal_imu_noise(graph):
    """The same graph with a per-row (diagonal) IMU noise instead of GTSAM's full covariance."""
    sigma = noise.diagonal(np.linspace(0.01, 0.2, STATE))
    graph.factors = [dataclasses.replace(f, noise=sigma) if f.noise.dim == STATE else f
                     for f in graph.factors]
    return graph


def whitened(blocks, values) -> list:
    """(factor, whitened Jacobian block per factor variable, whitened residual) per factor."""
    out = []
    for b in blocks:
        r, jacs = b.evaluate(values)
        for f, m in zip(b.factors, b.type.members, strict=True):
            rows, w = slice(*m.rows), f.noise.sqrt_information
            out.append((f, [w @ jacs[p][rows] for p in m.positions], w @ r[rows]))
    return out


def hessian(blocks, values, keys: list) -> tuple[np.ndarray, np.ndarray]:
    """H = AᵀA and g = Aᵀb assembled in the order of ``keys``."""
    dims = {k: v.dim for b in blocks for k, v in zip(b.keys, b.type.variables, strict=True)}
    offset = dict(zip(keys, np.cumsum([0] + [dims[k] for k in keys]), strict=False))
    n = sum(dims.values())
    h, g = np.zeros((n, n)), np.zeros(n)
    for f, jacs, r in whitened(blocks, values):
        for a, ja in zip(f.keys, jacs, strict=True):
            sa = slice(offset[a], offset[a] + dims[a])
            g[sa] += ja.T @ r
            for b, jb in zip(f.keys, jacs, strict=True):
                h[sa, offset[b]:offset[b] + dims[b]] += ja.T @ jb
    return h, g


# --------------------------------------------------------------------------------------------
# paper B: IMU window, Cholesky
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("n", [20, 80])
def test_imu_window_cholesky(n):
    plan = plan_storage(fuse(imu_window(n)), layout(n), "cholesky")
    big = STATE * n
    assert (plan.rows, plan.columns, plan.dense_words) == (big, big, big * big + big)
    assert plan.steps[0].words == n * STATE**2 + 2 * (n - 1) * STATE**2 + big
    assert plan.steps[1].words == n * STATE * (STATE + 1) // 2 + (n - 1) * STATE**2 + big
    # GTSAM's IMU covariance is full: whitening mixes every row, so H has no fixed zeros
    assert plan.steps[2].words == plan.steps[1].words and plan.steps[2].skipped_zero == 0
    assert all(s.index_words == 0 for s in plan.steps)


@pytest.mark.parametrize("diagonal", [False, True])
def test_hessian_zeros_match_numbers(diagonal):
    n = 6
    graph = imu_window(n)
    blocks = fuse(with_diagonal_imu_noise(graph) if diagonal else graph)
    plan = plan_storage(blocks, layout(n), "cholesky")
    keys = [k for c in layout(n).clusters for k in c]
    h, g = hessian(blocks, random_values(graph, np.random.default_rng(5)), keys)
    stored = np.zeros_like(h, dtype=bool)
    for c in range(n):  # lower triangle of diagonal blocks, and the block below each
        stored[STATE * c:STATE * (c + 2), STATE * c:STATE * (c + 1)] = True
    stored &= np.tril(np.ones_like(stored))
    zeros = int((stored & (h == 0)).sum() + (g == 0).sum())
    assert zeros == plan.steps[2].skipped_zero
    assert plan.steps[2].words == int((stored & (h != 0)).sum() + (g != 0).sum())
    assert (zeros > 0) == diagonal


# --------------------------------------------------------------------------------------------
# paper A: LIO window, QR
# --------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def lio30():
    graph = lio_graph(30)
    return graph, fuse(graph)


def test_lio_qr_figures(lio30):
    _, blocks = lio30
    plan = plan_storage(blocks, layout(30), "qr")
    rows = 29 * 15 + 29 * 6 + 30 * 3 + 6 + 3 + 6  # IMU, LiDAR, GPS, three priors
    cols = 30 * STATE
    assert (plan.rows, plan.columns, plan.dense_words) == (rows, cols, rows * cols + rows)
    values = 29 * 15 * 31 + 29 * 6 * 13 + 30 * 3 * 7 + 6 * 7 + 3 * 4 + 6 * 7
    index = 29 * 6 + 29 * 2 + 30 + 3
    assert (plan.steps[0].words, plan.steps[0].index_words) == (values + index, index)
    assert (plan.steps[1].words, plan.steps[1].index_words) == (values, 0)
    s3 = plan.steps[2]
    assert s3.words == values + s3.noise_words - s3.skipped_zero - s3.skipped_known - \
        s3.skipped_pair
    assert s3.skipped_pair == 29 * 9  # the IMU velocity pair, rows the whitening keeps apart
    assert plan.ratio(1) < plan.ratio(2) < plan.ratio(3)


def test_qr_structure_matches_numbers(lio30):
    graph, blocks = lio30
    values = random_values(graph, np.random.default_rng(6))
    some = [b for b in blocks if len(b.factors) > 1][:3] + list(blocks[:5])
    for f, jacs, _ in whitened(some, values):
        st = factor_structure(f)
        w = f.noise.sqrt_information
        for k, jac in enumerate(jacs):
            # structural zeros are exact zeros (data may add zeros: e.g. W's entries vary)
            assert not ((jac != 0) & ~st.nonzero[k]).any(), (f.name, k)
            assert (jac != 0).sum() >= 0.95 * st.nonzero[k].sum(), (f.name, k)
            for i, a in zip(*np.nonzero(st.known[k]), strict=True):
                assert abs(jac[i, a]) in set(np.abs(w[i])), (f.name, k, i, a)
            for i, a in zip(*np.nonzero(st.shared[k]), strict=True):
                partner = next(jacs[q][i, a] for q in range(k)
                               if abs(abs(jacs[q][i, a]) - abs(jac[i, a])) <= 1e-12)
                assert abs(abs(partner) - abs(jac[i, a])) <= 1e-12 * max(1.0, abs(jac[i, a]))


def test_symmetric_pairs_are_proven_only(lio30):
    graph, blocks = lio30
    by_name = {f.type.name: f for b in blocks for f in b.factors}
    lidar = factor_structure(by_name["LidarOdometryFactor"])
    assert not any(m.any() for m in lidar.shared)  # J_i = −Jl⁻¹(ξ)·Ad(Z⁻¹) ≠ −J_j = −Jr⁻¹(ξ)
    imu = factor_structure(by_name["CombinedImuFactor"])
    shared = [int(m.sum()) for m in imu.shared]
    assert shared == [0, 0, 0, 9, 0, 0]  # vel_j rows 6..8 = −vel_i rows 6..8 (whitened)
    assert imu.shared[3][6:9].all()


def test_general_graph_keeps_index_words(lio30):
    _, blocks = lio30
    qr = plan_storage(blocks, None, "qr")
    assert qr.structure == "general" and qr.steps[1] == dataclasses.replace(
        qr.steps[0], name=qr.steps[1].name)
    chol = plan_storage(blocks, None, "cholesky")
    variable_pairs = 30 * 3 + 29 * 9  # inside each keyframe, and across consecutive ones
    assert chol.steps[1].index_words == variable_pairs
    assert chol.steps[0].index_words == 2 * variable_pairs


def test_inconsistent_slots_keep_index_words(lio30):
    _, blocks = lio30
    plan = plan_storage(blocks, layout(30, swap=4), "qr")
    # cluster 4 lists v4 first: IMU factors 3→4 and 4→5 and the prior/GPS patterns change
    assert plan.steps[1].index_words > 0


def test_errors(lio30):
    _, blocks = lio30
    with pytest.raises(ValueError, match="solver"):
        plan_storage(blocks, layout(30), "lu")
    with pytest.raises(StructureError, match="no cluster"):
        plan_storage(blocks, layout(29), "qr")
    clusters = list(layout(30).clusters)
    clusters[5], clusters[6] = clusters[6], clusters[5]
    with pytest.raises(StructureError, match="spans clusters"):
        plan_storage(blocks, ChainLayout(tuple(clusters)), "qr")
