"""Emitted C++ builds for every graph the compiler accepts (a property test).

Random small graphs — every variable type, chains and loop closures (general graphs), every
``--solver`` (gn, lm) and ``--linear`` (qr, cholesky) — are compiled, emitted, and built with the
project's own Makefile under its strict flags (``-Werror``): the testbench (``make csim``, which
also runs it on the graph's data) and the native backend's library (``make native``). The
generator is seeded, so a failure names a reproducible case. g++ takes seconds per build, so the
default run holds a representative handful, the sweep (>= 60 graphs) is ``heavy``.
"""

from __future__ import annotations

import shutil

import numpy as np
import pytest

import fgc
from fgc.compile import compile_graph
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Point2, Point3, Pose2, Pose3, Rot2, Rot3, Vector3
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import native
from fgc_backends.hls import HlsBuildError, HlsConfig, emit, make, run_csim

pytestmark = pytest.mark.skipif(shutil.which("g++") is None or shutil.which("make") is None,
                                reason="needs g++ and make")


@pytest.fixture(autouse=True)
def project_flags(monkeypatch):
    """These builds use the projects' own flags (-O2 / -O3, -Werror: -Wmaybe-uninitialized and
    the like need the optimiser), not the suite's quicker FGC_CSIM_FLAGS / FGC_NATIVE_FLAGS
    (tests/conftest.py)."""
    monkeypatch.delenv("FGC_CSIM_FLAGS", raising=False)
    monkeypatch.delenv("FGC_NATIVE_FLAGS", raising=False)


TYPES = (Point2, Point3, Rot2, Rot3, Pose2, Pose3, Vector3)
SOLVERS = tuple((m, lin) for m in ("gn", "lm") for lin in ("qr", "cholesky"))


def random_graph(seed: int) -> tuple[fgc.Graph, SolverConfig, str]:
    """A connected graph of one random type: a chain of 2-9 variables, with probability 1/2 one
    to three loop closures; a prior on the first variable; a random solver."""
    rng = np.random.default_rng(seed)
    t = TYPES[seed % len(TYPES)]
    method, linear = SOLVERS[(seed // len(TYPES)) % len(SOLVERS)]
    n = int(rng.integers(2, 10))
    g = fgc.Graph()
    keys = [f"x{i}" for i in range(n)]
    for k in keys:
        g.add_variable(k, t.random(rng, 0.5))
    g.add(PriorFactor(keys[0], t.random(rng, 0.1), noise.isotropic(t.dim, 0.1)))
    edges = [(i, i + 1) for i in range(n - 1)]
    if n > 2 and rng.random() < 0.5:
        for _ in range(int(rng.integers(1, 4))):
            a, b = sorted(int(x) for x in rng.choice(n, size=2, replace=False))
            if b - a > 1 and (a, b) not in edges:
                edges.append((a, b))
    for a, b in edges:
        g.add(BetweenFactor(keys[a], keys[b], t.random(rng, 0.3), noise.isotropic(t.dim, 0.2)))
    what = f"seed {seed}: {t.__name__} n={n} edges={edges} --solver {method} --linear {linear}"
    return g, SolverConfig(method=method, linear=linear), what


def build_both(seed: int, tmp_path) -> None:
    graph, solver, what = random_graph(seed)
    program = compile_graph(graph, solver, name=f"g{seed}")
    project = emit(program, tmp_path / f"g{seed}", HlsConfig(scalar="double"))
    try:
        run_csim(project, program, problem_data(graph, program))
        project = native.emit(program, tmp_path / f"n{seed}", native.NativeConfig(scalar="double"))
        native.make(project)
    except (HlsBuildError, native.NativeBuildError) as exc:
        log = (project.directory / "build.log").read_text()
        pytest.fail(f"{what}: {exc}\n{log[-3000:]}")


# Representative: each type once, each solver choice at least once, chains and loops, and the
# two shapes a user found failing (Point2 chain of 3 with lm; Pose2 GN + QR chain of 7).
DEFAULT_SEEDS = (0, 8, 16, 24, 4, 12, 20)


@pytest.mark.parametrize("seed", DEFAULT_SEEDS)
def test_random_graph_builds(seed, tmp_path):
    build_both(seed, tmp_path)


def _chain(t, n: int) -> fgc.Graph:
    rng = np.random.default_rng(n)
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"x{i}", t.random(rng, 0.5))
    g.add(PriorFactor("x0", t.random(rng, 0.1), noise.isotropic(t.dim, 0.1)))
    for i in range(n - 1):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", t.random(rng, 0.3), noise.isotropic(t.dim, 0.2)))
    return g


@pytest.mark.parametrize("t, n, method, linear", [(Point2, 3, "lm", "qr"),
                                                   (Pose2, 7, "gn", "qr")])
def test_reported_failures_build(t, n, method, linear, tmp_path):
    """The two graphs reported (issue 16 item 7): a Point2 chain of 3 failed -Werror on the
    back-substitution (array-bounds / aggressive-loop-optimizations, xs[MAX_W] with MAX_W ==
    TILE); GN + QR on a Pose2 chain of 7 on an unused operand pointer in a step pattern."""
    graph = _chain(t, n)
    program = compile_graph(graph, SolverConfig(method=method, linear=linear), name="r")
    run_csim(emit(program, tmp_path / "hls", HlsConfig(scalar="double")), program,
             problem_data(graph, program))
    native.make(native.emit(program, tmp_path / "native", native.NativeConfig(scalar="double")))


def test_build_failure_is_one_line_naming_the_log(tmp_path):
    """A failing make is reported as one line pointing to build.log, not the compiler output."""
    graph = _chain(Point2, 2)
    program = compile_graph(graph, SolverConfig(), name="r")
    project = emit(program, tmp_path, HlsConfig(scalar="double"))
    source = project.directory / "r.cpp"
    source.write_text(source.read_text() + "\nthis is not C++;\n")
    with pytest.raises(HlsBuildError) as info:
        make(project, "csim")
    message = str(info.value)
    assert "\n" not in message and "internal error" in message
    assert str(project.directory / "build.log") in message
    assert "this is not C++" in (project.directory / "build.log").read_text()


@pytest.mark.heavy
@pytest.mark.parametrize("seed", range(100, 170))
def test_random_graph_builds_sweep(seed, tmp_path):
    build_both(seed, tmp_path)
