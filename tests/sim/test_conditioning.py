"""The float32 conditioning warning (``fgc.ir.conditioning``) and the simulator's κ estimate.

κ is the condition number of the whitened Jacobian at the solution with rows and columns scaled
to unit norm; the simulator estimates it by power iteration along its Bayes net (12 iterations
each way). Checked here: the estimate against a dense SVD (within 10 %), and the warning firing
above 1/√eps32 for Cholesky and 1/eps32 for QR, and only for float32 runs.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import fgc
from fgc import Point2, Pose2, Vector2
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.interop.to_gtsam import linearize_factor
from fgc.ir.conditioning import (
    EPS32,
    IllConditionedWarning,
    float32_kappa_limit,
    float32_ok,
)
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import sim


@fgc.factor(name="projection")
def projection(point: Point2, *, a: Vector2, z: float):
    """z = a·point: one linear reading of a 2-D point."""
    return [a[0] * point[0] + a[1] * point[1] - z]


def _parallel_readings(eps: float) -> fgc.Graph:
    """Readings along (1, 1) and (1, 1 + eps): κ ≈ 4/eps."""
    g = fgc.Graph().add_variable("point", Point2([0.0, 0.0]))
    for a in ((1.0, 1.0), (1.0, 1.0 + eps)):
        g.add(projection("point", a=Vector2(a), z=float(np.dot(a, [2.0, -1.0])),
                         noise=fgc.noise.isotropic(1, 0.1)))
    return g


def _run(graph: fgc.Graph, precision: str, linear: str) -> sim.SimResult:
    program = compile_graph(graph, SolverConfig(linear=linear))
    return sim.run(program, problem_data(graph, program), precision=precision)


def test_limits_follow_from_float32_epsilon():
    assert float32_kappa_limit("qr") == pytest.approx(1 / EPS32)  # ≈ 8.4e6
    assert float32_kappa_limit("cholesky") == pytest.approx(EPS32**-0.5)  # ≈ 2.9e3
    assert float32_ok(None, "qr") is None and float32_ok(1e3, "cholesky")
    with pytest.raises(ValueError, match="unknown linear solver"):
        float32_kappa_limit("lu")
    # a float64 linear solver leaves only the float32 linearisation: QR's limit for both
    assert float32_kappa_limit("cholesky", "float64") == float32_kappa_limit("qr")
    assert float32_ok(4e4, "cholesky", "float64") and not float32_ok(4e4, "cholesky")


def test_cholesky_warns_where_qr_does_not():
    graph = _parallel_readings(1e-4)  # κ ≈ 4e4: between the two limits
    with pytest.warns(IllConditionedWarning, match=r"float32 cholesky: condition number"):
        chol = _run(graph, "float32", "cholesky")
    assert chol.warnings and chol.float32_ok is False and 3e4 < chol.condition < 5e4
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        qr = _run(graph, "float32", "qr")
        f64 = _run(graph, "float64", "cholesky")  # float64 runs never warn about float32
    assert qr.float32_ok and not qr.warnings
    assert f64.float32_ok is False and not f64.warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        program = compile_graph(graph, SolverConfig(linear="cholesky", precision="float32",
                                                    linear_precision="float64"))
        mixed = sim.run(program, problem_data(graph, program))
    assert mixed.float32_ok and not mixed.warnings and mixed.precision == "float32"
    point = mixed.values["point"]
    assert np.allclose(np.asarray(point), [2.0, -1.0], atol=1e-3)


def test_qr_warns_beyond_its_limit():
    with pytest.warns(IllConditionedWarning, match="float32 qr"):
        result = _run(_parallel_readings(1e-7), "float32", "qr")
    assert result.condition > float32_kappa_limit("qr")


def _loop() -> fgc.Graph:
    rng = np.random.default_rng(3)
    g = fgc.Graph()
    truth = [Pose2(np.cos(a) * 4, np.sin(a) * 4, a + np.pi / 2)
             for a in np.linspace(0, 2 * np.pi, 8, endpoint=False)]
    for i, pose in enumerate(truth):
        g.add_variable(f"p{i}", pose.retract(rng.normal(size=3) * 0.1))
    for i in range(len(truth)):
        j = (i + 1) % len(truth)
        g.add(BetweenFactor(f"p{i}", f"p{j}", truth[i].between(truth[j]),
                            fgc.noise.diagonal([0.1, 0.2, 0.02])))
    g.add(PriorFactor("p0", truth[0], fgc.noise.isotropic(3, 1e-3)))
    return g


def test_estimate_agrees_with_a_dense_svd():
    graph = _loop()
    result = _run(graph, "float64", "qr")
    values = {k: result.values[str(k)] for k in graph.variables}
    columns = {k: i * 3 for i, k in enumerate(graph.variables)}
    rows = []
    for f in graph.factors:
        a, _ = linearize_factor(f, [values[k] for k in f.keys])
        block = np.zeros((a.shape[0], 3 * len(columns)))
        for n, key in enumerate(f.keys):
            block[:, columns[key]:columns[key] + 3] = a[:, 3 * n:3 * n + 3]
        rows.append(block)
    jac = np.vstack(rows)
    jac /= np.linalg.norm(jac, axis=1, keepdims=True)
    jac /= np.linalg.norm(jac, axis=0, keepdims=True)
    s = np.linalg.svd(jac, compute_uv=False)
    assert result.condition == pytest.approx(s[0] / s[-1], rel=0.1)
