"""Tests of the accelerator cost model (backends/cost).

Shape properties (monotone in n_u and #CPE, two-ended faster than serial, resources grow with
units, float64 dearer than float32), the calibration against paper B's published figures
(latency within ``LATENCY_TOLERANCE`` = 25 % per point, power within ``POWER_TOLERANCE`` = 10 %
per design), documentation of every parameter, and a JSON-able report.
"""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest
import sympy as sp

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.compiler.kernel import Kernel
from fgc.ir.program import KernelText, Program, SolverConfig
from fgc_backends.cost import (
    CostParams,
    Device,
    OperatorCost,
    OperatorCounts,
    OperatorTable,
    describe,
    estimate,
)
from fgc_backends.cost import calibration as cal
from fgc_backends.cost.kernels import critical_path
from fgc_backends.cost.qr import householder_sweep

imu_window = example("imu_window")
lio = example("lio")

UNITS = (1, 2, 4, 8)
CPES = (5, 10, 20, 40, 80, 120)


def with_solver(program: Program, **changes) -> Program:
    """The same Program with SolverConfig fields replaced (unit counts, precision)."""
    return dataclasses.replace(program, solver=dataclasses.replace(program.solver, **changes))


@pytest.fixture(scope="module")
def imu50() -> Program:
    """Paper B's calibration problem: N = 50, LM + Cholesky, 5 CPEs, float32."""
    config = SolverConfig(method="lm", linear="cholesky", cpe=5, precision="float32")
    return compile_graph(imu_window.build(N=50), config)


@pytest.fixture(scope="module")
def lio_chains() -> dict[str, Program]:
    """Paper A's LIO chain (N = 12) with serial and two-ended elimination, GN + QR, float32."""
    graph = lio.build(N=12)
    return {o: compile_graph(graph, SolverConfig(method="gn", linear="qr", ordering=o,
                                                 precision="float32"))
            for o in ("serial", "two-ended")}


def latency(program: Program, iterations: int = 1, **changes) -> float:
    return estimate(with_solver(program, **changes), iterations).latency_ms


# --------------------------------------------------------------------------------------------
# shape of the model
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("ordering", ["serial", "two-ended"])
def test_latency_falls_as_update_units_grow(lio_chains, ordering):
    times = [latency(lio_chains[ordering], units=u) for u in UNITS]
    assert all(a > b for a, b in zip(times, times[1:], strict=False)), times


def test_two_ended_beats_serial(lio_chains):
    for u in UNITS:
        serial = latency(lio_chains["serial"], units=u)
        two_ended = latency(lio_chains["two-ended"], units=u)
        assert two_ended < serial / 1.3, (u, serial, two_ended)


def test_latency_falls_as_cpes_grow(imu50):
    times = [latency(imu50, cpe=c) for c in CPES]
    assert all(a > b for a, b in zip(times, times[1:], strict=False)), times


def test_resources_grow_with_units(imu50, lio_chains):
    cholesky = [estimate(with_solver(imu50, cpe=c), 1).resources for c in CPES]
    qr = [estimate(with_solver(lio_chains["serial"], units=u), 1).resources for u in UNITS]
    for seq in (cholesky, qr):
        for small, big in zip(seq, seq[1:], strict=False):
            assert big.dsp > small.dsp and big.lut > small.lut and big.ff > small.ff


def test_a_cpe_adds_six_dsps_in_float32(imu50):
    """Paper B: "each CPE adds 6 DSPs"."""
    dsp = [estimate(with_solver(imu50, cpe=c), 1).resources.dsp for c in (20, 40, 80)]
    assert np.diff(dsp).tolist() == [6 * 20, 6 * 40]


def test_float64_costs_more_than_float32(imu50, lio_chains):
    for program in (imu50, lio_chains["two-ended"]):
        f32 = estimate(program, 1)
        f64 = estimate(with_solver(program, precision="float64"), 1)
        assert f64.cycles > f32.cycles
        for field in ("dsp", "bram", "lut", "ff"):
            assert getattr(f64.resources, field) > getattr(f32.resources, field), field
        assert f64.power_w > f32.power_w and f64.memory.word_bits == 64


def test_mixed_design_prices_only_the_linear_solver_wider(imu50, lio_chains):
    """float32 factor blocks with a float64 linear solver: the Hessian, linear and
    back-substitution units and their memories cost what float64 ones do, the factor blocks,
    state update and their memories what float32 ones do."""
    for program in (imu50, lio_chains["two-ended"]):
        f32 = estimate(program, 1)
        mixed = estimate(with_solver(program, linear_precision="float64"), 1)
        f64 = estimate(with_solver(program, precision="float64"), 1)
        for field in ("dsp", "lut", "ff"):
            assert (getattr(f32.resources, field) < getattr(mixed.resources, field)
                    < getattr(f64.resources, field)), field
        by32, bymix, by64 = (r.resources_by_unit for r in (f32, mixed, f64))
        assert bymix.factor == by32.factor and bymix.state_update == by32.state_update
        assert bymix.linear_solver == by64.linear_solver
        assert bymix.back_substitution == by64.back_substitution
        assert (mixed.memory.word_bits, mixed.memory.linear_bits) == (32, 64)
        assert "float32 (float64 linear solver)" in mixed.summary()


def test_rejected_steps_add_solves_but_not_relinearisation(imu50):
    base = estimate(imu50, 3)
    more = estimate(imu50, 3, rejected=2)
    extra = more.solve + base.solve.scaled(-1)
    assert extra == more.rejected_step.scaled(2)
    assert more.rejected_step.factor_jacobian == 0 and more.rejected_step.hessian == 0
    assert more.rejected_step.factorization == base.iteration.factorization
    with pytest.raises(ValueError, match="rejected"):
        estimate(with_solver(imu50, method="gn"), 3, rejected=1)


# --------------------------------------------------------------------------------------------
# calibration against the papers
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("point", cal.PAPER_B_LATENCY, ids=lambda p: f"cpe{p.cpe}")
def test_paper_b_latency_within_tolerance(imu50, point):
    report = estimate(with_solver(imu50, cpe=point.cpe), cal.PAPER_B_ITERATIONS)
    error = cal.relative_error(report.latency_ms, point.ms)
    assert abs(error) <= cal.LATENCY_TOLERANCE, (report.latency_ms, point.ms)


def test_paper_b_linear_solve_dominates(imu50):
    """Paper B: the linear solve is 82.4 % of the time on average; at N = 50 it is more."""
    for c in (20, 40, 80):
        share = estimate(with_solver(imu50, cpe=c), cal.PAPER_B_ITERATIONS).linear_solve_fraction
        assert cal.PAPER_B_LINEAR_SOLVE_SHARE - 0.05 < share < 1.0


def test_paper_b_power_within_tolerance(imu50):
    for point in cal.PAPER_B_POWER:
        watts = estimate(with_solver(imu50, cpe=point.cpe), 1).power_w
        assert abs(cal.relative_error(watts, point.watts)) <= cal.POWER_TOLERANCE, point


def test_paper_b_designs_fit_the_device(imu50):
    for point in cal.PAPER_B_POWER:
        assert estimate(with_solver(imu50, cpe=point.cpe), 1).utilization.fits, point.name


# --------------------------------------------------------------------------------------------
# pieces
# --------------------------------------------------------------------------------------------


def test_critical_path_of_a_small_kernel():
    a, b, x = sp.symbols("a b x")
    text = KernelText.of(Kernel((a, b), ((x, a * b + a),), (x / b, a + b)))
    ops = CostParams().float32
    expected = ops.mul.latency + ops.add.latency + ops.div.latency
    assert critical_path(text, ops) == expected


def test_constant_denominator_is_a_multiply():
    a, b = sp.symbols("a b")
    ops = CostParams().float32
    assert critical_path(KernelText.of(Kernel((a,), (), (a / 2,))), ops) == ops.mul.latency
    assert critical_path(KernelText.of(Kernel((a, b), (), (-a / b,))), ops) == ops.div.latency


def test_balanced_reduction_is_shorter_than_a_chain():
    symbols = sp.symbols("a0:8")
    text = KernelText.of(Kernel(symbols, (), (sum(symbols),)))
    ops = CostParams().float32
    assert critical_path(text, ops, balanced=True) == 3 * ops.add.latency
    assert critical_path(text, ops, balanced=False) == 7 * ops.add.latency


def test_householder_sweep_of_a_dense_matrix():
    m, n = 6, 4
    sweep = householder_sweep(np.ones((m, n), dtype=bool), n)
    assert sweep == [(m - k, n - k - 1 + 1) for k in range(n)]


def test_householder_sweep_skips_known_zeros():
    pattern = np.array([[1, 0, 1], [1, 0, 0], [0, 1, 1]], dtype=bool)
    # column 0 reflects rows 0, 1 and updates column 2 and the right-hand side only (column 1
    # is zero in both); columns 1 and 2 then have one free row each: no reflection needed.
    assert householder_sweep(pattern, 3) == [(2, 2)]


def test_memory_words_come_from_the_plans(imu50, lio_chains):
    for program in (imu50, lio_chains["serial"]):
        memory = estimate(program, 1).memory
        assert memory.linear_system == program.storage.steps[-1].words
        assert memory.dense_linear_system == program.storage.dense_words
        assert memory.total > memory.linear_system


# --------------------------------------------------------------------------------------------
# parameters and report
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("cls", [CostParams, OperatorCost, OperatorCounts, OperatorTable, Device])
def test_every_parameter_is_documented(cls):
    table = describe(cls)
    for f in dataclasses.fields(cls):
        assert len(f.metadata.get("doc", "")) > 10, f"{cls.__name__}.{f.name} has no doc"
        assert f"`{f.name}`" in table


def test_report_is_json_able_and_consistent(imu50, lio_chains):
    for program in (imu50, lio_chains["two-ended"]):
        report = estimate(program, 4)
        data = json.loads(json.dumps(report.to_dict()))
        assert data["cycles"] == report.cycles == 4 * report.iteration.total
        assert data["solve"]["total"] == report.solve.total
        assert data["latency_ms"] == pytest.approx(report.cycles / 143e3)
        assert data["energy_mj"] == pytest.approx(report.power_w * report.latency_ms)
        assert report.resources == report.resources_by_unit.total


def test_default_iterations_are_the_solver_cap(lio_chains):
    program = with_solver(lio_chains["serial"], max_iterations=7)
    assert estimate(program).iterations == 7
