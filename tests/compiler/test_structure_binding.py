"""A compiled design is bound to its structure: data of another graph with the same counts (same
variables, same factor types, other connectivity) is refused by every reader, naming both
structure fingerprints (or, in ``problem_data``, the first factor that differs).

Before the binding, ``problem_data(graph_b, program_a)`` and the emitted readers checked only the
counts, and the simulator "converged" on a problem that is neither A nor B.
"""

from __future__ import annotations

import dataclasses
import subprocess

import pytest

import fgc
from fgc.compile import compile_graph
from fgc.errors import DataError
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2
from fgc.ir.datafile import MAGIC, problem_data, read_data, write_data
from fgc.ir.program import Program, SolverConfig
from fgc_backends import hls, native, sim


def ring(edges: list[tuple[int, int]]) -> fgc.Graph:
    """Five Pose2 poses, a prior on x0 and one Between per edge (measured: 1 m along x)."""
    g = fgc.Graph()
    for i in range(5):
        g.add_variable(f"x{i}", Pose2(1.1 * i, 0.2 * (i % 2), 0.05 * i))
    g.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    for a, b in edges:
        g.add(BetweenFactor(f"x{a}", f"x{b}", Pose2(1.0, 0.0, 0.1), fgc.noise.isotropic(3, 0.1)))
    return g


EDGES_A = [(0, 1), (1, 2), (2, 3), (3, 4), (4, 0)]
EDGES_B = [(0, 2), (2, 1), (1, 3), (3, 4), (4, 1)]  # same counts and types, other keys


@pytest.fixture(scope="module")
def two():
    ga, gb = ring(EDGES_A), ring(EDGES_B)
    pa, pb = compile_graph(ga, SolverConfig()), compile_graph(gb, SolverConfig())
    return ga, gb, pa, pb


def test_same_counts_other_connectivity_have_other_fingerprints(two):
    ga, gb, pa, pb = two
    assert len(pa.variables) == len(pb.variables) and len(pa.factors) == len(pb.factors)
    assert [b.name for b in pa.blocks] == [b.name for b in pb.blocks]
    assert pa.structure_fingerprint != pb.structure_fingerprint
    assert pa.fingerprint != pb.fingerprint


def test_fingerprints_are_deterministic_and_separate_structure_from_design(two):
    ga, _, pa, _ = two
    again = compile_graph(ring(EDGES_A), SolverConfig())
    assert again.structure_fingerprint == pa.structure_fingerprint
    assert again.fingerprint == pa.fingerprint
    assert Program.from_json(pa.to_json()).fingerprint == pa.fingerprint
    chol = compile_graph(ga, SolverConfig(linear="cholesky", ordering="min-degree"))
    # another design of the same structure: one data file serves both
    assert chol.structure_fingerprint == pa.structure_fingerprint
    assert chol.fingerprint != pa.fingerprint
    assert compile_graph(ga, SolverConfig(precision="float32")).fingerprint != pa.fingerprint


def test_reversed_factor_is_another_structure():
    """Between(x1, x0) in place of Between(x0, x1): same key sets, same block, other meaning."""
    pa = compile_graph(ring(EDGES_A), SolverConfig())
    pr = compile_graph(ring([(1, 0), *EDGES_A[1:]]), SolverConfig())
    assert pa.structure_fingerprint != pr.structure_fingerprint
    with pytest.raises(DataError, match=r"factor 1 .* connects \['x1', 'x0'\], the compiled "
                                        r"Program connects \['x0', 'x1'\]"):
        problem_data(ring([(1, 0), *EDGES_A[1:]]), pa)


def test_problem_data_names_the_first_differing_factor(two):
    _, gb, pa, _ = two
    with pytest.raises(DataError, match=r"factor 1 \('.*', a BetweenFactor.*\) connects "
                                        r"\['x0', 'x2'\], the compiled Program connects "
                                        r"\['x0', 'x1'\]"):
        problem_data(gb, pa)


def test_data_files_carry_the_structure_fingerprint(two, tmp_path):
    ga, _, pa, _ = two
    data = problem_data(ga, pa)
    write_data(data, tmp_path / "a.txt")
    first = (tmp_path / "a.txt").read_text().splitlines()[0]
    assert first == f"{MAGIC} {pa.structure_fingerprint}"
    assert read_data(tmp_path / "a.txt").structure == pa.structure_fingerprint
    with pytest.raises(DataError, match="no structure fingerprint"):
        write_data(dataclasses.replace(data, structure=None), tmp_path / "none.txt")


def test_a_file_without_fingerprint_is_refused(two, tmp_path):
    ga, _, pa, _ = two
    write_data(problem_data(ga, pa), tmp_path / "a.txt")
    lines = (tmp_path / "a.txt").read_text().splitlines()
    old = tmp_path / "old.txt"
    old.write_text("\n".join(["FGCDATA 1", *lines[1:]]) + "\n")
    with pytest.raises(DataError, match=r":1: not an fgc data file"):
        read_data(old)
    with pytest.raises(DataError, match=r":1: not an fgc data file"):
        sim.run(pa, old, tmp_path / "out")


@pytest.mark.parametrize("in_process", [True, False])
def test_simulator_refuses_a_data_file_of_another_structure(two, tmp_path, in_process):
    _, gb, pa, pb = two
    data_b = problem_data(gb, pb)
    assert sim.run(pb, data_b).converged  # B's own design solves B
    write_data(data_b, tmp_path / "b.txt")
    with pytest.raises(DataError, match=rf"another structure: structure fingerprint "
                                        rf"'{pb.structure_fingerprint}', this simulator was "
                                        rf"compiled for '{pa.structure_fingerprint}'"):
        sim.run(pa, tmp_path / "b.txt", tmp_path / "out", in_process=in_process)


def test_sim_run_refuses_problem_data_of_another_structure(two):
    _, gb, pa, pb = two
    with pytest.raises(DataError, match=rf"fingerprint {pb.structure_fingerprint}, the "
                                        rf"compiled Program '.*' has "
                                        rf"{pa.structure_fingerprint}"):
        sim.run(pa, problem_data(gb, pb))


def test_hls_testbench_refuses_a_data_file_of_another_structure(two, tmp_path):
    """The check is host code in the testbench: the kernel stays synthesisable."""
    ga, gb, pa, pb = two
    project = hls.emit(pa, tmp_path / "hls")
    result = hls.run_csim(project, pa, problem_data(ga, pa))
    assert result.converged
    kernel = (project.directory / f"{project.name}.cpp").read_text()
    assert pa.structure_fingerprint not in kernel
    write_data(problem_data(gb, pb), tmp_path / "b.txt")
    tb = project.directory / f"tb_{project.name}"
    proc = subprocess.run([str(tb), str(tmp_path / "b.txt"), str(tmp_path / "r.txt")],
                          capture_output=True, text=True, check=False)
    assert proc.returncode == 2
    assert (f"another structure: structure fingerprint {pb.structure_fingerprint}, this "
            f"testbench was compiled for {pa.structure_fingerprint}") in proc.stderr


@pytest.mark.heavy
def test_native_library_refuses_data_of_another_structure(two):
    ga, gb, pa, pb = two
    solver = native.load(pa)
    assert solver.run(problem_data(ga, pa)).converged
    with pytest.raises(DataError, match=rf"fingerprint {pb.structure_fingerprint}.*"
                                        rf"{pa.structure_fingerprint}"):
        solver.run(problem_data(gb, pb))
