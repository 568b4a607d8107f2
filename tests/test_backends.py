"""The backend contract (fgc_backends.CONTRACT): every registered backend offers a frozen
``Config``, ``emit(program, out_dir, config)``, ``run(program, data, config)`` and
``stream(stream_program, config)`` (checked when the runner is made); ``run``
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
from fgc.compiler.stream import compile_stream
from fgc.errors import FgcError
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Point2, Pose2
from fgc.interop.to_gtsam import to_gtsam, values_from_gtsam
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc.ir.result import FIELDS, SolveResult
from fgc.ir.stream import FixedLag, Incremental
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
    stream = list(inspect.signature(backend.stream).parameters)
    assert stream[:2] == ["sp", "config"], (name, stream)


def _keyframes(swap: int | None = None, priors_at=(0,)) -> fgc.Graph:
    """A chain of six keyframes (a Pose2 and a Point2 each, tied by a range factor), priors on
    ``priors_at``; keyframe ``swap`` declares its Point2 first."""
    @fgc.factor
    def offset(pose: Pose2, point: Point2, *, measured: float):
        return [pose.range(point) - measured]

    g = fgc.Graph()
    for i in range(6):
        pose, point = (f"x{i}", Pose2(float(i), 0.0, 0.0)), (f"l{i}", Point2(float(i), 1.0))
        for key, value in ((point, pose) if i == swap else (pose, point)):
            g.add_variable(key, value)
    for i in priors_at:
        g.add(PriorFactor(f"x{i}", Pose2(float(i), 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
        g.add(PriorFactor(f"l{i}", Point2(float(i), 1.0), fgc.noise.isotropic(2, 0.1)))
    for i in range(5):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0),
                            fgc.noise.isotropic(3, 0.2)))
        g.add(BetweenFactor(f"l{i}", f"l{i + 1}", Point2(1.0, 0.0), fgc.noise.isotropic(2, 0.2)))
    for i in range(6):
        g.add(offset(f"x{i}", f"l{i}", measured=1.0, noise=fgc.noise.isotropic(1, 0.1)))
    return g


@pytest.mark.parametrize("policy", [FixedLag(2), Incremental(3)])
def test_stream_is_refused_when_its_runner_is_made(policy):
    """The contract's ``stream`` checks the StreamProgram when it makes the runner: a chain whose
    keyframe 3 declares its variables in another order streams on the simulator and is refused
    by the compiled backends (no template window can slide over it) before anything runs."""
    sp = compile_stream(_keyframes(swap=3), policy=policy)
    assert sp.slots.refusal.startswith("keyframe 3 has variables of types")
    data = problem_data(sp.graph, sp.program)
    runner = load("sim").stream(sp)
    assert runner.who == "simulator" and runner.run(data).converged
    for name in ("native", "hls"):
        with pytest.raises(FgcError, match="cannot stream this chain: keyframe 3 has variables"):
            load(name).stream(sp)


def test_the_stream_stage_is_frozen_and_backend_independent():
    """compile_stream → StreamProgram: the policy and the slot layout (each update's window, the
    template sizes) computed once, before any backend; the policies are frozen values."""
    sp = compile_stream(_keyframes(priors_at=(0, 5)), policy=Incremental(3, 4))
    assert sp.incremental and sp.window is None and sp.mode == "incremental"
    assert sp.slots.refusal is None
    assert [(u.keyframe, u.batch, u.first) for u in sp.slots.updates] == [
        (0, False, 0), (1, False, 0), (2, False, 0), (3, False, 1), (4, True, 0), (5, False, 3)]
    assert sp.slots.sizes == (3, 5)
    with pytest.raises(dataclasses.FrozenInstanceError):
        sp.policy.k = 4
    with pytest.raises(FgcError, match="at least 1 keyframe"):
        FixedLag(0)
    fixed = compile_stream(_keyframes(), policy=FixedLag(2))
    assert fixed.window == 2 and fixed.slots.sizes == (3,)
    assert [u.first for u in fixed.slots.updates] == [0, 0, 0, 1, 2, 3]


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
