"""Back-substitution (backends/hls/units/backsub.py): cond_backsub's loops by hand, one unit per
QR unit set."""

from __future__ import annotations

from hls_programs import chain

from fgc_backends.cost.operators import FLOAT32
from fgc_backends.hls.plan import build_plan
from fgc_backends.hls.units.backsub import backsub_loops


def test_cond_backsub_loops_by_hand():
    # float32 on the xc7z045 at 143 MHz: add 4, mul 3, div 15; PARTIALS = 4 interleaved sums,
    # folded in ⌈log₂ 4⌉ = 2
    loops = {lp.name: lp for lp in backsub_loops(2, 3, FLOAT32, name="b")}
    assert (loops["b_separator"].trip, loops["b_separator"].depth) == (6, 3 + 4)
    assert loops["b_fold"].depth == 4 * (1 + 2)
    assert loops["b_reciprocals"].depth == 15
    assert [n for n in loops if n.startswith("b_solve")] == ["b_solve1", "b_solve0"]
    assert loops["b_column1"].trip == 1


def test_one_backsub_unit_per_qr_unit_set():
    plan = build_plan(chain(7, linear="qr"))  # two-ended: two unit sets
    assert [u.name for u in plan.units if u.name.endswith("_backsub")] == ["qr0_backsub",
                                                                           "qr1_backsub"]
    cholesky = build_plan(chain(5, linear="cholesky", cpe=2))
    assert cholesky.unit("trisolve").instances == 1
    assert any(ph.name.startswith("backsub_level") for ph in cholesky.phases)
