"""Paper reproduction pieces: the plan's storage options (raw Jacobians whitened while stacking,
blocked Hessian) in words and cycles, hand-checked on a 3-pose Pose2 chain; the reports' hardware
figures are plan_cost's; bench/bench_papers.py's design search and table layout.

Cheap: the Pose2 chain and the range-beacons example compile in about a second from a warm cache.
"""

from __future__ import annotations

import importlib.util
import itertools
import json
import math
import sys
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.app.cli import EXIT_OK, build_parser, main
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2
from fgc.ir.program import SolverConfig
from fgc_backends.hls.plan import (
    PlanError,
    PlanOptions,
    build_plan,
    phase_groups,
    plan_cost,
    plan_power_w,
)
from fgc_backends.hls.units.cholesky import hessian_envelope
from fgc_backends.hls.units.datapath import raw_jacobian_words, whitening_macs

ROOT = Path(__file__).resolve().parent.parent
BEACONS = str(ROOT / "examples" / "range_beacons.py")
R_FULL = np.array([[10.0, 1.0, 2.0], [0.0, 20.0, 3.0], [0.0, 0.0, 30.0]])


def _chain(linear: str, **solver) -> fgc.ir.program.Program:
    """x0 -prior(isotropic)- x0 -between(full W)- x1 -between(full W)- x2, Pose2."""
    g = fgc.Graph()
    for i in range(3):
        g.add_variable(f"x{i}", Pose2(float(i), 0.1 * i, 0.0))
    g.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    for i in range(2):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0),
                            fgc.noise.sqrt_information(R_FULL)))
    method = "gn" if linear == "qr" else "lm"
    return compile_graph(g, SolverConfig(method=method, linear=linear, precision="float32",
                                         **solver))


@pytest.fixture(scope="module")
def qr_chain():
    return _chain("qr", units=2)


@pytest.fixture(scope="module")
def chol_chain():
    return _chain("cholesky", cpe=1)


def _ab_words(plan) -> int:
    return sum(m.words for m in plan.memories if m.name.startswith("ab_"))


def test_raw_jacobian_words_and_whitening_by_hand(qr_chain):
    prior, between = qr_chain.blocks
    # derive's structure: the prior's J has a fixed (0, 0, 1) last row; the between's J_i and
    # J_j each a fixed (0, 0, ∓1) last row
    assert prior.structure[0][2] == ("0", "0", "1")
    assert [blk[2] for blk in between.structure] == [("0", "0", "-1"), ("0", "0", "1")]
    # raw: residual 3 + the 'x' entries (6; 12) + W's parameters (isotropic 1; full 6)
    assert raw_jacobian_words(prior) == 3 + 6 + 1
    assert raw_jacobian_words(between) == 3 + 12 + 6
    # isotropic W: one multiply per non-zero entry: columns (2, 2, 3) + residual 3 = 10
    assert whitening_macs(prior) == 10
    # full upper-triangular W: row i mixes rows r ≥ i; a column with non-zeros (x, x, 0)
    # takes 2 + 1 + 0 = 3, (x, x, ±1) 3 + 2 + 1 = 6: per block 3 + 3 + 6, two blocks, and the
    # residual column 6 -> 30
    assert whitening_macs(between) == 30


def test_raw_storage_fewer_words_more_cycles(qr_chain):
    whitened = build_plan(qr_chain)
    raw = build_plan(qr_chain, PlanOptions.of(qr_chain, jacobian_storage="raw"))
    # whitened A, b dense: prior 3 × (1 + 3) = 12, betweens 2 × 3 × (1 + 6) = 42
    assert _ab_words(whitened) == 12 + 42
    assert _ab_words(raw) == 10 + 2 * 21
    cw, cr = plan_cost(whitened), plan_cost(raw)
    assert cr.words == cw.words - 2 and cr.bram36 <= cw.bram36
    # whiten_stack: 10 + 2 × 30 = 70 MACs on n_u = 2 lanes: 35 at II 1, depth mul + add (the
    # design's operator table: 3 + 4 on the xc7z045 at 143 MHz)
    ops = raw.target.ops(qr_chain.solver.precision)
    depth = ops.mul.latency + ops.add.latency
    phases = dict(cr.phase_cycles)
    assert "whiten_stack" not in dict(cw.phase_cycles)
    assert phases["whiten_stack"] == 34 + depth
    assert cr.cycles == cw.cycles + 34 + depth
    assert cr.linear_cycles == cw.linear_cycles + 34 + depth
    # its lanes are priced: n_u × (add 2 + mul 3) DSP
    assert cr.dsp == cw.dsp + 2 * 5
    # (QR: the gradient beside the datapaths, in factor_jacobian's region)
    assert [ph.name for ph in raw.phases][:4] == ["factor_jacobian", "whiten_stack",
                                                  "qr_stack_level0", "qr_level0"]


def test_blocked_hessian_by_hand(chol_chain):
    n = chol_chain.storage.columns
    # x1's rows reach back to x0 (between x0-x1), x2's to x1: lowest rows 5, 5, 5, 8 × 6
    assert hessian_envelope(chol_chain) == [5, 5, 5, 8, 8, 8, 8, 8, 8]
    dense = build_plan(chol_chain, PlanOptions.of(chol_chain, hessian_storage="dense"))
    blocked = build_plan(chol_chain, PlanOptions.of(chol_chain, hessian_storage="blocked"))

    def hessian_words(plan):
        return next(m.words for m in plan.memories if m.name == "hessian")

    assert hessian_words(dense) == n * (n + 1) // 2 + n == 54
    # envelope 6 + 5 + 4 + 6 + 5 + 4 + 3 + 2 + 1 = 36, plus g 9
    assert hessian_words(blocked) == 45

    def rounds(plan):
        return next(ph for ph in plan.phases if ph.name == "cholesky").processes[0].loops

    # #CPE 1: round 0 streams the envelope + g (45 words) instead of the triangle + g (54),
    # each round with its status word
    assert rounds(dense)[0].trip == 54 + 1 and rounds(blocked)[0].trip == 45 + 1
    assert [lp.trip for lp in rounds(blocked)] == [
        sum(lo - j + 1 for j, lo in enumerate(hessian_envelope(chol_chain)) if j >= r) + n - r + 1
        for r in range(n)]
    cd, cb = plan_cost(dense), plan_cost(blocked)
    assert cb.cycles < cd.cycles and cb.words == cd.words - 9


def test_storage_options_are_checked(qr_chain):
    with pytest.raises(PlanError, match="jacobian_storage must be one of whitened, raw"):
        build_plan(qr_chain, PlanOptions.of(qr_chain, jacobian_storage="packed"))
    with pytest.raises(PlanError, match="hessian_storage must be one of frontal, dense, blocked"):
        build_plan(qr_chain, PlanOptions.of(qr_chain, hessian_storage="sparse"))


def test_phase_groups_and_power(qr_chain):
    c = plan_cost(build_plan(qr_chain))
    groups = dict(phase_groups(c))
    assert sum(groups.values()) == c.cycles
    assert groups["qr"] == sum(v for k, v in c.phase_cycles if k.startswith("qr_level"))
    assert "qr_level0" not in groups and "factor_jacobian" in groups
    # power grows with the resources: more Update units, more watts
    more = plan_cost(build_plan(qr_chain, PlanOptions.of(qr_chain, units=8)))
    assert plan_power_w(more) > plan_power_w(c) > 0


# -- the reports print the plan ----------------------------------------------------------------


def _program_of(argv):
    from fgc.app.cli import _compile

    args = build_parser().parse_args(argv)
    return _compile(args, "float32")[1]


@pytest.mark.parametrize("extra", [[], ["--linear", "cholesky", "--cpe", "3"],
                                   ["--units", "1", "--clock", "100MHz"]])
def test_report_figures_are_plan_costs(tmp_path, capsys, extra):
    out = tmp_path / "r.json"
    argv = ["report", BEACONS, "--iterations", "3", *extra]
    assert main([*argv, "--json", str(out)]) == EXIT_OK
    capsys.readouterr()
    r = json.loads(out.read_text())["cost"]
    program = _program_of(argv)
    c = plan_cost(build_plan(program))
    assert r["iteration_cycles"] == c.cycles and r["cycles"] == 3 * c.cycles
    assert r["resources"] == {"dsp": c.dsp, "bram": c.bram36, "lut": c.lut, "ff": c.ff}
    assert r["clock_mhz"] == program.solver.clock_mhz
    assert r["latency_ms"] == pytest.approx(3 * c.latency_ms)
    assert r["fits"] == c.fits and r["memory_words"] == c.words
    assert r["power_w"] == pytest.approx(plan_power_w(c))
    assert r["cycles_by_unit"] == {k: 3 * v for k, v in phase_groups(c)}


def test_simulate_figures_are_plan_costs(tmp_path, capsys):
    out = tmp_path / "s.json"
    assert main(["simulate", BEACONS, "--json", str(out)]) == EXIT_OK
    text = capsys.readouterr().out
    s = json.loads(out.read_text())
    c = plan_cost(build_plan(_program_of(["simulate", BEACONS])))
    k = max(s["iterations"], 1)
    assert s["cycles"] == k * c.cycles and s["resources"]["dsp"] == c.dsp
    assert s["storage"]["plan_memory_words"] == c.words
    assert f"{k * c.cycles:,} cycles" in text and "(accelerator plan)" in text


# -- bench/bench_papers.py ---------------------------------------------------------------------


def _bench():
    if "bench_papers" in sys.modules:
        return sys.modules["bench_papers"]
    spec = importlib.util.spec_from_file_location("bench_papers",
                                                  ROOT / "bench" / "bench_papers.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["bench_papers"] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def test_best_design_is_the_fastest_that_fits(qr_chain):
    """bench_papers' best design is the search's: on the plan alone (no reads) the fastest
    design the plan fits, over n_u × unit sets × ALLOCATION scale × QR unit (Householder and
    the streaming unit) × back-substitution's width × the operators' binding."""
    from fgc_backends.hls.config import auto_backsub_lanes
    from fgc_backends.hls.plan.options import QR_UNITS

    bench = _bench()
    cfg = bench.Config(units=(1, 2, 4), unit_sets=(1, 2), alloc_scales=(1, 2), reads=0)
    result = bench.best_design({"qr": qr_chain}, cfg, linears=("qr",))
    assert len(result.rows) == (3 * 2 * 2 * len(QR_UNITS) * len(cfg.backsub_lanes)
                                * len(cfg.binds))
    brute = []
    for units in cfg.units:
        for sets in (1, 2):
            for scale in cfg.alloc_scales:
                for qr_unit in QR_UNITS:
                    for lanes, bind in itertools.product(cfg.backsub_lanes, cfg.binds):
                        c = plan_cost(build_plan(qr_chain, PlanOptions.of(
                            qr_chain, units=units, unit_sets=sets, qr_unit=qr_unit,
                            allocation=bench._scaled(scale), bind=bind,
                            backsub_lanes=auto_backsub_lanes(qr_chain) if lanes is None
                            else lanes)))
                        if c.fits:
                            brute.append(c.cycles)
    assert result.best.cycles == min(brute) and result.best.cost.fits
    assert result.best.verdict == "unread" and result.reads == 0


def test_gtsam_timing_and_table_layout():
    bench = _bench()
    g = fgc.Graph()
    for i in range(3):
        g.add_variable(f"x{i}", Pose2(float(i), 0.1 * i, 0.0))
    g.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    for i in range(2):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0),
                            fgc.noise.isotropic(3, 0.1)))
    times = bench.gtsam_ms_per_iteration(g, bench.Config(gtsam_iterations=2, gtsam_repeats=1))
    assert set(times) == {"MULTIFRONTAL_CHOLESKY", "MULTIFRONTAL_QR"}
    assert all(0 < fast <= med and math.isfinite(med) for med, fast in times.values())
    rows = [bench.Row("A (x)", "figure", "1.6×", "1.8×", "because")]
    assert bench.format_rows(rows).splitlines() == [
        "[A (x)] figure", "    published: 1.6×", "    fgc:       1.8×", "    why:       because"]
