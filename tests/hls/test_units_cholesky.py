"""The Cholesky unit (backends/hls/units/cholesky.py): the cascade's round depth by hand, the
emitted multifrontal design and the what-if whole-matrix designs."""

from __future__ import annotations

import pytest
from hls_programs import chain

from fgc_backends.cost.operators import FLOAT32
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
from fgc_backends.hls.units.cholesky import cpe_round_depth, cpe_step_loops


@pytest.fixture(scope="module")
def program():
    return chain(5, linear="cholesky", cpe=2)


def test_a_round_is_as_deep_as_its_pivoting_cpes_plus_the_others_fill():
    # float32 on the xc7z045 at 143 MHz: sqrt 15 + div 15 + mul 3 + add 4 = 37 per CPE with a
    # pivot; 1 per idle CPE; feed 2, drain 2, status 1
    assert cpe_round_depth(2, 3, FLOAT32) == 2 * 37 + 1 + 5
    assert cpe_round_depth(3, 3, FLOAT32) == 3 * 37 + 5


def test_a_step_runs_one_round_per_cpe_pivots():
    loops = cpe_step_loops(5, 2, 2, FLOAT32, name="s")
    rounds = [lp for lp in loops if "_round" in lp.name]
    assert len(rounds) == 3  # ⌈5 / 2⌉
    w = 7
    assert rounds[0].trip == w * (w + 1) // 2 + w


def test_the_emitted_design_assembles_factors_and_stores_each_step(program):
    plan = build_plan(program)
    names = [ph.name for ph in plan.phases]
    assert names.index("hgc") < names.index("assemble") < names.index("cholesky") \
        < names.index("store")
    assert plan.unit("cpe").instances == 2
    assert sum(c.name.startswith("cpe_link") for c in plan.channels) == 3  # #CPE + 1
    assert {"gram", "frontal", "frontal_b", "cond", "nf"} <= {m.name for m in plan.memories}


@pytest.mark.parametrize("storage", ["dense", "blocked"])
def test_a_what_if_whole_matrix_design_has_its_own_phases(program, storage):
    plan = build_plan(program, PlanOptions.of(program, hessian_storage=storage))
    names = {ph.name for ph in plan.phases}
    assert {"cholesky", "cholesky_scalar", "trisolve"} <= names
    assert "assemble" not in names
    assert sum(c.name.startswith("cpe_fifo") for c in plan.channels) == 2
    # a chain's envelope is narrower than the dense triangle
    if storage == "blocked":
        dense = plan_cost(build_plan(program, PlanOptions.of(program, hessian_storage="dense")))
        assert plan_cost(plan).cycles < dense.cycles
