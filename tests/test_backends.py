"""The backend contract (fgc_backends.CONTRACT): every registered backend offers a frozen
``Config``, ``emit(program, out_dir, config)`` and ``run(program, data, config)``; ``run``
returns the estimate as fgc values keyed like the Program, the same on every backend, and that
estimate is GTSAM's LM optimum of the same graph (not another fgc backend's: the oracle is
GTSAM's solve, 1e-6 on every pose coordinate in float64)."""

from __future__ import annotations

import dataclasses
import inspect

import numpy as np
import pytest

import fgc
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2
from fgc.interop.to_gtsam import to_gtsam, values_from_gtsam
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc.ir.result import FIELDS, SolveResult
from fgc_backends import BACKENDS, CONTRACT, load, names


def test_the_registry_names_every_backend_package():
    from pathlib import Path

    root = Path(load("sim").__file__).resolve().parent.parent
    packages = {p.parent.name for p in root.glob("*/__init__.py")}
    shared = {"cfamily", "cost"}  # layers the backends use, not backends
    assert set(names()) == packages - shared
    assert all(BACKENDS[n].name == n for n in names())
    assert BACKENDS["hls"].hardware and not BACKENDS["native"].hardware


@pytest.mark.parametrize("name", names())
def test_backend_offers_the_contract(name):
    backend = load(name)
    for attr in CONTRACT:
        assert hasattr(backend, attr), f"backend {name} lacks {attr}"
    assert dataclasses.is_dataclass(backend.Config)
    assert backend.Config.__dataclass_params__.frozen, f"{name}.Config is not frozen"
    emit = list(inspect.signature(backend.emit).parameters)
    run = list(inspect.signature(backend.run).parameters)
    assert emit[:3] == ["program", "out_dir", "config"], (name, emit)
    assert run[:2] == ["program", "data"] and "config" in run, (name, run)


def _chain() -> fgc.Graph:
    """A Pose2 loop with a perturbed start: five poses, odometry, one loop closure, a prior."""
    rng = np.random.default_rng(7)
    g = fgc.Graph()
    truth = [Pose2(np.cos(t), np.sin(t), t + np.pi / 2) for t in np.linspace(0, 4 * np.pi / 3, 5)]
    for i, p in enumerate(truth):
        dx, dy, dt = rng.normal(0, 0.1, 3)
        g.add_variable(i, Pose2(p.x() + dx, p.y() + dy, p.theta() + dt))
    noise = fgc.noise.diagonal([0.1, 0.1, 0.05])
    g.add(PriorFactor(0, truth[0], fgc.noise.isotropic(3, 0.01)))
    for i in range(4):
        g.add(BetweenFactor(i, i + 1, truth[i].between(truth[i + 1]), noise))
    g.add(BetweenFactor(4, 0, truth[4].between(truth[0]), noise))
    return g


@pytest.mark.parametrize("name", names())
def test_run_gives_gtsams_optimum_as_keyed_fgc_values(name, tmp_path):
    import gtsam

    graph = _chain()
    program = compile_graph(graph, SolverConfig(precision="float64"), name="contract")
    result = load(name).run(program, problem_data(graph, program))
    assert isinstance(result, SolveResult), (name, type(result))
    for field in FIELDS:
        assert hasattr(result, field), (name, field)
    assert result.status == "converged", (name, result.status, result.reason)
    problem = to_gtsam(graph)
    params = gtsam.LevenbergMarquardtParams()
    params.setRelativeErrorTol(1e-14)
    params.setAbsoluteErrorTol(1e-14)
    optimum = values_from_gtsam(graph, problem, gtsam.LevenbergMarquardtOptimizer(
        problem.graph, problem.values, params).optimize())
    values = result.user_values
    assert set(values) == set(graph.variables), name
    for key, want in optimum.items():
        got = values[key]
        assert isinstance(got, Pose2), (name, key, type(got))
        np.testing.assert_allclose(got.to_storage(), want.to_storage(), atol=1e-6,
                                   err_msg=f"{name} {key}")
