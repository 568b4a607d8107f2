"""The whole pipeline: Graph → Program; JSON round trip, determinism, structure errors."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2, Pose3
from fgc.ir.program import Program, ProgramError, SolverConfig

ROOT = Path(__file__).resolve().parents[2]

from fgc.app.specs import example  # noqa: E402

imu_window = example("imu_window")
pose_graph = example("pose_graph")


def _chain(n: int, prior: bool = True) -> fgc.Graph:
    rng = np.random.default_rng(0)
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"x{i}", Pose3.random(rng))
    for i in range(n - 1):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose3.random(rng, 0.1),
                            fgc.noise.isotropic(6, 0.1)))
    if prior:
        g.add(PriorFactor("x0", Pose3.identity(), fgc.noise.isotropic(6, 0.01)))
    return g


@pytest.mark.parametrize("build", [lambda: pose_graph.build(),
                                   lambda: pose_graph.build("pose3example.txt"),
                                   lambda: imu_window.build(N=6)])
def test_program_round_trips_through_json(build):
    program = compile_graph(build())
    text = program.to_json()
    again = Program.from_json(text)
    assert again == program
    assert again.to_json() == text
    for block, back in zip(program.blocks, again.blocks, strict=True):
        kernel = back.kernel.kernel()
        assert len(kernel.outputs) == len(block.kernel.outputs)
        assert type(block.kernel).of(kernel) == block.kernel  # srepr → sympy → srepr is exact


def test_compiling_twice_is_byte_identical():
    assert compile_graph(imu_window.build(N=5)).to_json() == \
        compile_graph(imu_window.build(N=5)).to_json()


def test_deterministic_across_hash_seeds(tmp_path):
    code = ("import sys; from fgc.app.specs import example; pose_graph = example('pose_graph'); "
            "from fgc.compile import compile_graph; "
            "sys.stdout.write(compile_graph(pose_graph.build('pose3example.txt')).to_json())")
    outs = []
    for seed in ("1", "2"):
        env = {"PYTHONHASHSEED": seed, "FGC_CACHE_DIR": str(tmp_path / seed),
               "PATH": "/usr/bin:/bin"}
        outs.append(subprocess.run([sys.executable, "-c", code], env=env, check=True,
                                   capture_output=True, text=True).stdout)
    assert outs[0] == outs[1] and len(outs[0]) > 1000


def test_chain_is_scheduled_two_ended():
    program = compile_graph(_chain(10))
    assert program.schedule.structure_class == "chain"
    assert program.schedule.num_sequential_steps <= 6


def test_unconstrained_variable_is_named():
    g = _chain(4)
    g.add_variable("lonely", Pose2(0.0, 0.0, 0.0))
    with pytest.raises(fgc.StructureError, match="lonely"):
        compile_graph(g)


def test_gauge_freedom_is_reported():
    with pytest.raises(fgc.StructureError, match="gauge|prior"):
        compile_graph(_chain(4, prior=False))


def test_window_beyond_maximum():
    with pytest.raises(fgc.StructureError, match="10"):
        compile_graph(_chain(10), max_variables=8)


def test_bad_solver_option_is_named():
    with pytest.raises(ProgramError, match="linear"):
        compile_graph(_chain(3), SolverConfig(linear="lu"))


def test_linear_precision_can_only_widen():
    with pytest.raises(ProgramError, match="linear_precision='float16'"):
        compile_graph(_chain(3), SolverConfig(linear_precision="float16"))
    with pytest.raises(ProgramError, match="narrower than precision=float64"):
        compile_graph(_chain(3), SolverConfig(precision="float64", linear_precision="float32"))
    mixed = compile_graph(_chain(3), SolverConfig(precision="float32", linear_precision="float64"))
    assert mixed.solver.mixed and mixed.solver.les_precision == "float64"
    assert Program.from_json(mixed.to_json()).solver == mixed.solver
    same = SolverConfig(precision="float32", linear_precision="float32")
    assert not same.mixed and not SolverConfig().mixed
