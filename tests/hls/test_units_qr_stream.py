"""The streaming QR unit (backends/hls/include/fgc_qr_stream.h, units/qr_stream.py) against the
paper's unit (fgc_qr.h) and against its own price.

A C++ driver runs qr_step and qrs_step on the same random stacked matrices (40 % zeros, double)
for 1, 3 and 8 stages, with the cycle counters of fgc_cycles.h; the conditional and the new
factor must agree to 1e-13 (the same reflections, the same sign rule, sums in another order),
and the counted cycles must equal qr_stream_loops' price exactly (the same loops, the same
region arithmetic). The driver is also compiled without FGC_COUNT_CYCLES (the synthesis view)
warning-free.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from fgc_backends.cost.operators import table
from fgc_backends.hls.units.qr_stream import qr_stream_loops

INCLUDE = Path(__file__).resolve().parents[2] / "backends" / "hls" / "include"

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

MAX_COLS = 32

DRIVER = r"""
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include "fgc_qr.h"
#include "fgc_qr_stream.h"

template <int N>
struct cfg {
    typedef double T;
    static const int MAX_ROWS = 60, MAX_COLS = 32, MAX_F = 16, N_UNITS = N;
    static const int LOCAL_COLS = fgc_units::ceil_div(MAX_COLS, N_UNITS);
    static const int PARTIALS = 4, FOLD_LAT = 4 * 2 + 3;  // the float32 table's latencies
    static const int ADD_LAT = 4, MUL_LAT = 3, DIV_LAT = 15, SQRT_LAT = 15;
    static constexpr double SINGULAR_EPS = 1e-12;
};

template <class C>
static void run(int rows, int f, int s, int stream) {
    typedef typename C::T T;
    const int cols = f + s + 1;
    static T dense[C::MAX_ROWS][C::MAX_COLS];
    static T work[C::N_UNITS][C::MAX_ROWS][C::LOCAL_COLS];
    static T cond[C::MAX_F * C::MAX_COLS], update[C::MAX_COLS * C::MAX_COLS];
    for (int i = 0; i < C::MAX_F * C::MAX_COLS; ++i) cond[i] = T(NAN);
    for (int i = 0; i < C::MAX_COLS * C::MAX_COLS; ++i) update[i] = T(NAN);
    for (int i = 0; i < rows; ++i)
        for (int c = 0; c < cols; ++c)
            if (std::scanf("%lf", &dense[i][c]) != 1) std::exit(3);
    fgc_units::qr_scatter<C>(dense, rows, cols, work);
    bool singular = false;
    if (stream) {
        fgc_units::qrs_step<C>(work, rows, f, s, cond, update, &singular);
    } else {
        fgc_units::qr_step<C>(work, rows, f, s, cond, update, &singular);
    }
#ifdef FGC_COUNT_CYCLES
    std::printf("%ld %d", fgc_cycles::total(), int(singular));
    fgc_cycles::reset();
#else
    std::printf("0 %d", int(singular));
#endif
    const int last = rows < f + s ? rows : f + s;
    const int nf = last - f > 0 ? last - f : 0;
    for (int i = 0; i < f * cols; ++i) std::printf(" %.17g", cond[i]);
    for (int i = 0; i < nf * (s + 1); ++i) std::printf(" %.17g", update[i]);
    std::printf("\n");
}

int main() {
    int n, stream, rows, f, s;
    while (std::scanf("%d %d %d %d %d", &n, &stream, &rows, &f, &s) == 5) {
        if (n == 1) run<cfg<1> >(rows, f, s, stream);
        else if (n == 3) run<cfg<3> >(rows, f, s, stream);
        else if (n == 8) run<cfg<8> >(rows, f, s, stream);
        else return 2;
    }
}
"""

SHAPES = [(9, 3, 2), (20, 6, 5), (5, 4, 3), (40, 15, 12), (3, 2, 0), (12, 5, 0)]


@pytest.fixture(scope="module")
def driver(tmp_path_factory):
    d = tmp_path_factory.mktemp("qrs")
    (d / "drv.cpp").write_text(DRIVER)
    flags = ["g++", "-std=c++14", "-Wall", "-Wextra", "-Werror", "-Wno-unknown-pragmas",
             f"-I{INCLUDE}", f"-I{INCLUDE / 'csim'}"]
    subprocess.run(flags + ["-fsyntax-only", str(d / "drv.cpp")], check=True)
    subprocess.run(flags + ["-O1", "-DFGC_COUNT_CYCLES", str(d / "drv.cpp"), "-o",
                            str(d / "drv")], check=True)
    return d / "drv"


def _cases():
    rng = np.random.default_rng(7)
    out = []
    for n in (1, 3, 8):
        for rows, f, s in SHAPES:
            a = rng.standard_normal((rows, f + s + 1))
            a[rng.random(a.shape) < 0.4] = 0.0
            out.append((n, rows, f, s, a))
    return out


def _run(driver, cases):
    text = ""
    for n, rows, f, s, a in cases:
        body = "\n".join(" ".join(f"{x:.17g}" for x in r) for r in a)
        for stream in (0, 1):
            text += f"{n} {stream} {rows} {f} {s}\n{body}\n"
    out = subprocess.run([str(driver)], input=text, capture_output=True, text=True, check=True)
    lines = out.stdout.splitlines()
    assert len(lines) == 2 * len(cases)
    return [(lines[2 * i].split(), lines[2 * i + 1].split()) for i in range(len(cases))]


def _rows(values, rows, f, s):
    """The conditional's f rows (w + 1 columns) and the new factor's rows (s + 1 columns)."""
    cols = f + s + 1
    nf = max(0, min(rows, f + s) - f)
    cond = np.asarray(values[:f * cols]).reshape(f, cols)
    update = np.asarray(values[f * cols:f * cols + nf * (s + 1)]).reshape(nf, s + 1)
    return list(cond) + list(update)


def test_the_streaming_unit_factors_as_the_papers_unit_and_costs_its_price(driver):
    """R is unique up to the sign of each row: where a pivot is rounding noise (a column the
    zeros make dependent), fgc_qr.h may meet an exact 0 and skip it while the stream meets 1e-17
    and negates the row; so rows are compared up to sign."""
    cases = _cases()
    ops = table("float32")
    for (n, rows, f, s, _), (old, new) in zip(cases, _run(driver, cases), strict=True):
        assert old[1] == new[1], (n, rows, f, s)  # the singular flag
        a, b = np.array(old[2:], dtype=float), np.array(new[2:], dtype=float)
        assert a.shape == b.shape and np.all(np.isfinite(b))
        tol = 1e-13 * max(1.0, np.max(np.abs(a), initial=0.0))
        for ra, rb in zip(_rows(a, rows, f, s), _rows(b, rows, f, s), strict=True):
            assert min(np.max(np.abs(ra - rb)), np.max(np.abs(ra + rb))) <= tol, (n, rows, f, s)
        price = sum(lp.cycles for lp in qr_stream_loops(rows, f + s + 1, f, n, ops,
                                                        local_cols=-(-MAX_COLS // n)))
        assert int(new[0]) == price, (n, rows, f, s)


def test_a_wrong_reflection_is_seen(driver):
    """The comparison can fail: a matrix changed in one entry factors differently."""
    n, rows, f, s, a = _cases()[3]
    b = a.copy()
    b[rows - 1, 0] += 1.0
    (old, _), (_, new) = _run(driver, [(n, rows, f, s, a), (n, rows, f, s, b)])
    diff = np.abs(np.array(old[2:], dtype=float) - np.array(new[2:], dtype=float))
    assert diff.max() > 1e-3


def test_more_stages_shorten_a_wide_step():
    ops = table("float32")
    cycles = [sum(lp.cycles for lp in qr_stream_loops(54, 31, 15, n, ops)) for n in (4, 8, 16)]
    assert cycles[0] > cycles[1] > cycles[2]


def test_one_pass_has_no_copy_and_each_extra_pass_one():
    ops = table("float32")
    names = [lp.name for lp in qr_stream_loops(20, 10, 5, 4, ops)]
    # k = 10 reflections on 4 stages: 3 passes
    assert sum(n.startswith("s_pass") and not n.endswith("first") for n in names) == 3
    assert sum(n.startswith("s_copy") for n in names) == 2
    names = [lp.name for lp in qr_stream_loops(20, 10, 5, 16, ops)]
    assert sum(n.startswith("s_pass") and not n.endswith("first") for n in names) == 1
    assert not any(n.startswith("s_copy") for n in names)


@pytest.mark.parametrize("n_u", [1, 3])
def test_the_plan_holds_n_u_stages_per_set_with_their_streams(n_u):
    from hls_programs import chain

    from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost, process_network
    from fgc_backends.hls.plan.model import PlanError

    program = chain(7, linear="qr")  # two-ended: two unit sets
    plan = build_plan(program, PlanOptions.of(program, units=n_u, qr_unit="stream"))
    procs, streams = process_network(plan)
    for s in range(2):
        for kind in ("evaluate", "dot", "tail"):
            assert plan.unit(f"qr{s}_{kind}").instances == n_u
        # per stage first/rest links (n_u + 1 each) and vd, vt, e, p, x, s, r, row
        assert sum(c.name.startswith(f"qr{s}_") for c in streams) == 10 * n_u + 2
        assert sum(p.startswith(f"qr{s}_") for p in procs) == 4 * n_u + 3
    householder = plan_cost(build_plan(program, PlanOptions.of(program, units=n_u)))
    stream = plan_cost(plan)
    stages = ("qr0_evaluate", "qr0_dot", "qr0_tail")
    stage_dsp = sum(d for name, d in stream.dsp_by_unit if name in stages)
    assert stage_dsp == n_u * 42  # float32 on the xc7z045: 12 adders, 6 multipliers a stage
    # the QR unit alone differs: every other unit (datapaths, back-substitution, LM) is the same
    assert stream.dsp != householder.dsp
    def others(cost):  # every unit but the QR units' stages / Evaluate and Update units
        return {n: d for n, d in cost.dsp_by_unit
                if not re.fullmatch(r"qr\d_(evaluate|update|dot|tail)", n)}
    assert others(stream) == others(householder)
    with pytest.raises(PlanError, match="qr_unit 'givens'"):
        build_plan(program, PlanOptions.of(program, qr_unit="givens"))
