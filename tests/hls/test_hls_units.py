"""The fixed HLS unit headers (backends/hls/include/fgc_qr.h, fgc_cpe.h) against numpy.

A small C++ driver (below) instantiates qr_step for N_UNITS in {1, 4, 8} and cpe_step for N_CPE in
{1, 5, 20} (one word a cycle through the cascade, and two: configurations 101, 105, 120), reads
cases on stdin and prints the flags, the conditional, the update rows and the cycles counted by
fgc_cycles.h. It is compiled twice: with FGC_COUNT_CYCLES (the cases run on it) and, syntax only,
without (the synthesis view of the macros must compile warning-free as well).
"""

from __future__ import annotations

import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from fgc_backends.cost.operators import table

INCLUDE = Path(__file__).resolve().parents[2] / "backends" / "hls" / "include"

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

DRIVER = r"""
#include <cmath>
#include <cstdio>
#include <vector>
#include "fgc_qr.h"
#include "fgc_cpe.h"
#include "fgc_backsub.h"

template <class TT, int N, bool STRICT>
struct qr_cfg {
    typedef TT T;
    static const int MAX_ROWS = 40, MAX_COLS = 25, MAX_F = 12, N_UNITS = N;
    static const int LOCAL_COLS = fgc_units::ceil_div(MAX_COLS, N_UNITS);
    static const int PARTIALS = 12, FOLD_LAT = 12 * 4 + 9;  // ADD_LAT ceil(log2 P) + MUL_LAT
    static const int ADD_LAT = 12, MUL_LAT = 9, DIV_LAT = 57, SQRT_LAT = 57;
    static constexpr double SINGULAR_EPS = STRICT ? 1e-12 : 1e-3;
};

template <class TT, int N, bool STRICT, int WORDS = 1>
struct cpe_cfg {
    typedef TT T;
    static const int MAX_W = 30, MAX_COLS = 31, MAX_F = 25, N_CPE = N, PARTIALS = 12;
    static const int STREAM_WORDS = WORDS;  // words a cycle through the cascade
    static const int N_COND = MAX_F * MAX_COLS, N_NF = MAX_W * MAX_COLS;
    static const int ADD_LAT = 12, MUL_LAT = 9, DIV_LAT = 57, SQRT_LAT = 57;
    static constexpr double SINGULAR_EPS = STRICT ? 1e-12 : 1e-3;
};

static void print(const char* tag, const double* x, int n) {
    std::printf("%s", tag);
    for (int i = 0; i < n; ++i) std::printf(" %.17g", x[i]);
    std::printf("\n");
}

// the cycles of what ran since the last call (the step, then its back-substitution)
static void cycles(const char* tag) {
#ifdef FGC_COUNT_CYCLES
    long serial = 0;
    for (const auto& r : fgc_cycles::log()) serial += r.cycles();
    std::printf("%s %ld %ld\n", tag, fgc_cycles::total(), serial);
    fgc_cycles::reset();
#else
    std::printf("%s 0 0\n", tag);
#endif
}

// structural: the keep rule by structure (qr_step_structural), each row's pattern read after the
// matrix (rows x cols 0 / 1)
template <class C>
static void run_qr(int rows, int f, int s, bool structural = false) {
    typedef typename C::T T;
    const int cols = f + s + 1;
    static T dense[C::MAX_ROWS][C::MAX_COLS];
    static T work[C::N_UNITS][C::MAX_ROWS][C::LOCAL_COLS];
    static T cond[C::MAX_F * C::MAX_COLS], update[C::MAX_COLS * C::MAX_COLS];
    for (int i = 0; i < C::MAX_F * C::MAX_COLS; ++i) cond[i] = T(NAN);
    for (int i = 0; i < C::MAX_COLS * C::MAX_COLS; ++i) update[i] = T(NAN);
    for (int i = 0; i < rows; ++i)
        for (int c = 0; c < cols; ++c) {
            double x;
            if (std::scanf("%lf", &x) != 1) std::exit(3);
            if (i < C::MAX_ROWS && c < C::MAX_COLS) dense[i][c] = T(x);
        }
    static fgc_units::qr_rowmask<C> mask[C::MAX_ROWS];
    for (int i = 0; structural && i < rows; ++i) {
        mask[i] = fgc_units::qr_mask_zero<C>();
        for (int c = 0; c < cols; ++c) {
            double x;
            if (std::scanf("%lf", &x) != 1) std::exit(3);
            if (x != 0.0) mask[i].w[c >> 6] |= 1ULL << (c & 63);
        }
    }
    fgc_units::qr_scatter<C>(dense, rows, cols, work);
    bool singular = false;
    if (structural)
        fgc_units::qr_step_structural<C>(work, rows, f, s, cond, update, &singular, mask);
    else
        fgc_units::qr_step<C>(work, rows, f, s, cond, update, &singular);
    cycles("cycles");
    int left = 0;  // words qr_step left non-zero in its banks (it leaves them zero)
    for (int u = 0; u < C::N_UNITS; ++u)
        for (int i = 0; i < C::MAX_ROWS; ++i)
            for (int l = 0; l < C::LOCAL_COLS; ++l) left += !(work[u][i][l] == T(0));
    std::printf("flags %d %d %d\n", 0, int(singular), left);
    const int last = rows < f + s ? rows : f + s;
    const int nf = last - f > 0 ? last - f : 0;
    std::vector<double> a(cond, cond + (cols <= C::MAX_COLS && f <= C::MAX_F ? f * cols : 0));
    std::vector<double> b(update, update + (cols <= C::MAX_COLS ? nf * (s + 1) : 0));
    print("cond", a.data(), int(a.size()));
    print("update", b.data(), int(b.size()));
    if (cols <= C::MAX_COLS && f <= C::MAX_F && !singular) {  // back-substitution, xs = 1, 2, ...
        T xs[C::MAX_COLS], x[C::MAX_F];
        for (int a2 = 0; a2 < s; ++a2) xs[a2] = T(a2 + 1);
        static T buf[C::MAX_F * C::MAX_COLS];
        T part[2][C::PARTIALS][C::MAX_F];
        hls::stream<T> xq, xo;  // (the streamed-S load's x and the solve's x out: unused here)
        fgc_units::cond_load<C>(cond, 0, f, s, xs, xs, -1, buf, part, 0, xq);
        fgc_units::cond_backsub<C>(buf, f, s, part, x, 0, xo, 0);
        std::vector<double> xd(x, x + f);
        print("x", xd.data(), f);
    } else {
        print("x", nullptr, 0);
    }
    cycles("backsub");
}

template <class C>
static void run_cpe(int f, int s, double mu) {
    typedef typename C::T T;
    const int w = f + s;
    static T H[C::MAX_W][C::MAX_COLS];
    static T cond[C::MAX_F * C::MAX_COLS], update[C::MAX_W * C::MAX_COLS];
    for (int i = 0; i < C::MAX_F * C::MAX_COLS; ++i) cond[i] = T(NAN);
    for (int i = 0; i < C::MAX_W * C::MAX_COLS; ++i) update[i] = T(NAN);
    for (int i = 0; i < w; ++i)
        for (int c = 0; c <= w; ++c) {
            double x;
            if (std::scanf("%lf", &x) != 1) std::exit(3);
            if (i < C::MAX_W && c < C::MAX_COLS) H[i][c] = T(x);
        }
    bool not_pd = false, singular = false;
    // the step's words as the kernel's assembly streams them (rows from the diagonal to the
    // gradient), then H left to cpe_step as the buffer between rounds (all zero)
    hls::stream<fgc_units::cpe_pair<T> > src;
    for (int i = 0; fgc_units::cpe_fits<C>(f, s) && i < w; ++i)
        for (int c = i; c <= w; c += 2) {
            fgc_units::cpe_pair<T> p = {H[i][c], c < w ? H[i][c + 1] : T(0)};
            src.write(p);
            H[i][c] = T(0);
            if (c < w) H[i][c + 1] = T(0);
        }
    fgc_units::cpe_step<C>(src, H, f, s, T(mu), cond, 0, update, 0, &not_pd, &singular);
    if (!src.empty()) std::exit(4);  // the cascade reads every word it is given
    cycles("cycles");
    const bool fits = w <= C::MAX_W && f <= C::MAX_F;
    int left = 0;  // words of H's upper triangle and gradient the cascade did not clear
    for (int i = 0; fits && i < w; ++i)
        for (int c = i; c <= w; ++c) left += H[i][c] != T(0);
    std::printf("flags %d %d %d\n", int(not_pd), int(singular), left);
    std::vector<double> a(cond, cond + (fits ? f * (w + 1) : 0));
    std::vector<double> b(update, update + (fits ? s * (s + 1) : 0));
    print("cond", a.data(), int(a.size()));
    print("update", b.data(), int(b.size()));
    if (fits && !singular) {  // back-substitution with xs = 1, 2, ...
        // read lane-local (xoff = 1: a solved step's x from its second entry on); xs is NaN,
        // so reading it instead would show
        T xs[C::MAX_COLS], xl[C::MAX_COLS + 1], x[C::MAX_F];
        for (int a2 = 0; a2 < s; ++a2) xs[a2] = T(NAN);
        xl[0] = T(NAN);
        for (int a2 = 0; a2 < s; ++a2) xl[1 + a2] = T(a2 + 1);
        static T buf[C::MAX_F * C::MAX_COLS];
        T part[2][C::PARTIALS][C::MAX_F];
        hls::stream<T> xq, xo;  // (the streamed-S load's x and the solve's x out: unused here)
        fgc_units::cond_load<C>(cond, 0, f, s, xs, xl, 1, buf, part, 0, xq);
        fgc_units::cond_backsub<C>(buf, f, s, part, x, 0, xo, 0);
        std::vector<double> xd(x, x + f);
        print("x", xd.data(), f);
    } else {
        print("x", nullptr, 0);
    }
    cycles("backsub");
}

int main() {
    char kind[8];
    int cfg;
    while (std::scanf("%7s %d", kind, &cfg) == 2) {
        int a, b, c;
        double mu;
        if (std::scanf("%d %d %d %lf", &a, &b, &c, &mu) != 4) return 2;
        if (kind[0] == 's') {  // the keep rule by structure
            switch (cfg) {
            case 4: run_qr<qr_cfg<double, 4, true> >(a, b, c, true); break;
            case 8: run_qr<qr_cfg<double, 8, true> >(a, b, c, true); break;
            case 40: run_qr<qr_cfg<float, 4, true> >(a, b, c, true); break;
            default: return 4;
            }
        } else if (kind[0] == 'q') {
            switch (cfg) {
            case 1: run_qr<qr_cfg<double, 1, true> >(a, b, c); break;
            case 4: run_qr<qr_cfg<double, 4, true> >(a, b, c); break;
            case 8: run_qr<qr_cfg<double, 8, true> >(a, b, c); break;
            case -4: run_qr<qr_cfg<double, 4, false> >(a, b, c); break;
            case 40: run_qr<qr_cfg<float, 4, true> >(a, b, c); break;
            default: return 4;
            }
        } else {
            switch (cfg) {
            case 1: run_cpe<cpe_cfg<double, 1, true> >(b, c, mu); break;
            case 5: run_cpe<cpe_cfg<double, 5, true> >(b, c, mu); break;
            case 20: run_cpe<cpe_cfg<double, 20, true> >(b, c, mu); break;
            case -5: run_cpe<cpe_cfg<double, 5, false> >(b, c, mu); break;
            case 50: run_cpe<cpe_cfg<float, 5, true> >(b, c, mu); break;
            case 101: run_cpe<cpe_cfg<double, 1, true, 2> >(b, c, mu); break;
            case 105: run_cpe<cpe_cfg<double, 5, true, 2> >(b, c, mu); break;
            case 120: run_cpe<cpe_cfg<double, 20, true, 2> >(b, c, mu); break;
            default: return 4;
            }
        }
        std::fflush(stdout);
    }
    return 0;
}
"""

FLAGS = ["-std=c++14", "-O1", "-ffp-contract=off", "-Wall", "-Wextra", "-Werror",
         "-Wno-unknown-pragmas", f"-I{INCLUDE}", f"-I{INCLUDE / 'csim'}"]

# the operator table whose latencies the driver's CFG constants above hold (ADD_LAT 12, MUL_LAT
# 9, DIV_LAT 57, SQRT_LAT 57: float64 above 150 MHz on the 7-series)
DRIVER_OPS = table("float64", "7series", 200.0)


def _build_driver(tmp_path_factory, defines=()):
    d = tmp_path_factory.mktemp("hls_units")
    src = d / "driver.cpp"
    src.write_text(DRIVER)
    exe = d / "driver"
    # the synthesis view of the counters (empty macros) only needs the front end's warnings
    for extra in (["-DFGC_COUNT_CYCLES", "-o", str(exe)], ["-fsyntax-only"]):
        r = subprocess.run(["g++", *FLAGS, *defines, *extra, str(src)], capture_output=True,
                           text=True)
        assert r.returncode == 0, r.stderr
    return exe


@pytest.fixture(scope="module")
def driver(tmp_path_factory):
    return _build_driver(tmp_path_factory)


@pytest.fixture(scope="module")
def driver_two_rows(tmp_path_factory):
    """The driver with fgc_qr.h's Update units two rows a cycle (FGC_QR_TWO_ROWS)."""
    return _build_driver(tmp_path_factory, ("-DFGC_QR_TWO_ROWS",))


@pytest.fixture(params=[1, 2], ids=["rows1", "rows2"])
def qr_driver(request):
    """(driver, rows): fgc_qr.h's Update units one row a cycle, and two (FGC_QR_TWO_ROWS)."""
    name = "driver" if request.param == 1 else "driver_two_rows"
    return request.getfixturevalue(name), request.param


class Result:
    def __init__(self, lines):
        fields = {ln.split()[0]: ln.split()[1:] for ln in lines}
        flags = [int(x) for x in fields["flags"]]
        self.not_pd, self.singular = bool(flags[0]), bool(flags[1])
        self.left = flags[2] if len(flags) > 2 else 0  # cpe_step: H's words not cleared
        self.cond = np.array([float(x) for x in fields["cond"]])
        self.update = np.array([float(x) for x in fields["update"]])
        self.x = np.array([float(x) for x in fields.get("x", [])])
        self.cycles, self.serial = (int(x) for x in fields["cycles"])
        self.backsub = int(fields["backsub"][0])


def run(driver, cases):
    """cases: (kind, cfg, a, b, c, mu, matrix); one driver process for all of them."""
    text = []
    for kind, cfg, a, b, c, mu, m in cases:
        text.append(f"{kind} {cfg} {a} {b} {c} {mu!r}")
        text.append(" ".join(repr(float(x)) for x in np.asarray(m).ravel()))
    r = subprocess.run([str(driver)], input="\n".join(text) + "\n", capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert len(lines) == 6 * len(cases), r.stdout
    return [Result(lines[6 * i:6 * i + 6]) for i in range(len(cases))]


# ---- QR -----------------------------------------------------------------------------------------


def kernel_householder(a):
    """The kernel's householder() (kernel.cpp.jinja) in numpy, dense, same signs and skips."""
    w = a.copy()
    m, ncol = w.shape
    for j in range(min(m, ncol)):
        active = [i for i in range(j, m) if i == j or w[i, j] != 0]
        big = max(abs(w[i, j]) for i in active)
        if big == 0:
            continue
        v = np.array([w[i, j] / big for i in active])
        norm2 = float(v @ v)
        norm = math.sqrt(norm2)
        pivot = v[0]
        alpha = -norm if pivot >= 0 else norm
        v[0] = pivot - alpha
        tau = 1.0 / (norm2 - alpha * pivot)
        dots = v @ w[active, j + 1:]
        w[np.ix_(active, range(j + 1, ncol))] -= tau * np.outer(v, dots)
        w[active, j] = 0.0
        w[j, j] = alpha * big
    return w


def qr_expected(a, f, s):
    rows, w = a.shape[0], f + s
    r = kernel_householder(a)
    nf = max(0, min(rows, w) - f)
    cond = r[:f].ravel()
    upd = np.triu(r[f:f + nf, f:w + 1]).ravel()
    return cond, upd, r


def rand_stack(rng, rows, f, s):
    return rng.standard_normal((rows, f + s + 1))


@pytest.mark.parametrize("units", [1, 4, 8])
def test_qr_matches_kernel_and_numpy(qr_driver, units):
    driver, _ = qr_driver
    rng = np.random.default_rng(10 + units)
    shapes = [(12, 3, 4), (30, 6, 9), (9, 5, 5), (4, 2, 1), (40, 12, 12)]
    cases = [("qr", units, rows, f, s, 0.0, rand_stack(rng, rows, f, s))
             for rows, f, s in shapes]
    # a sparse stack: zero rows per column (the active-row lists) and an all-zero column
    sp = rand_stack(rng, 20, 5, 6)
    sp[rng.random(sp.shape) < 0.5] = 0.0
    sp[:, 7] = 0.0
    np.fill_diagonal(sp[:5, :5], 1.0 + rng.random(5))
    cases.append(("qr", units, 20, 5, 6, 0.0, sp))
    for (_, _, rows, f, s, _, a), res in zip(cases, run(driver, cases), strict=True):
        cond, upd, r = qr_expected(a, f, s)
        assert not res.singular
        assert res.left == 0  # qr_step leaves its banks zero (qr_stack writes only the rows)
        scale = np.abs(r).max()
        # zeros left of the diagonal are written too (the driver fills NaN before)
        got_cond, got_upd = res.cond.reshape(f, -1), res.update.reshape(-1, s + 1)
        np.testing.assert_allclose(got_cond.ravel(), cond, rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose(got_upd.ravel(), upd, rtol=0, atol=1e-12 * scale)
        cm = cond.reshape(f, -1)
        xs = np.arange(1, s + 1, dtype=float)
        x = np.linalg.solve(cm[:, :f], cm[:, f + s] - cm[:, f:f + s] @ xs)
        np.testing.assert_allclose(res.x, x, rtol=1e-9, atol=1e-9)
        if f + s == 11 and rows == 20:
            continue  # the zero column: rank deficient, where numpy's R differs (no skip)
        # numpy's R, up to the signs of its rows
        k = min(rows, f + s + 1)
        rn = np.linalg.qr(a, mode="r")[:k]
        ours = np.vstack([got_cond, np.hstack([np.zeros((len(got_upd), f)), got_upd])])
        n = ours.shape[0]
        sign = np.sign(np.diag(rn[:n])) * np.sign(np.diag(ours))
        np.testing.assert_allclose(ours, sign[:, None] * rn[:n], rtol=0, atol=1e-12 * scale)


def test_qr_singular_flags(qr_driver):
    driver, _ = qr_driver
    rng = np.random.default_rng(3)
    dep = rand_stack(rng, 15, 4, 3)
    dep[:, 2] = 2.0 * dep[:, 0] - dep[:, 1]  # a frontal column dependent on the others
    sep_dep = rand_stack(rng, 15, 4, 3)
    sep_dep[:, 5] = sep_dep[:, 4]  # rank deficient in the separator only: no concern of R
    few = rand_stack(rng, 3, 4, 2)  # fewer rows than frontal columns
    small = rand_stack(rng, 15, 3, 2)
    small[:, 1] *= 1e-6  # a pivot 1e-6 of the largest: fine at 1e-12, singular at 1e-3
    too_big = rand_stack(rng, 41, 2, 2)  # more rows than MAX_ROWS
    cases = [("qr", 4, 15, 4, 3, 0.0, dep), ("qr", 8, 15, 4, 3, 0.0, sep_dep),
             ("qr", 1, 3, 4, 2, 0.0, few), ("qr", 4, 15, 3, 2, 0.0, small),
             ("qr", -4, 15, 3, 2, 0.0, small), ("qr", 4, 41, 2, 2, 0.0, too_big)]
    res = run(driver, cases)
    assert [r.singular for r in res] == [True, False, True, False, True, True]
    # rank deficient or not, a step within the configuration leaves its banks zero
    assert [r.left for r in res[:5]] == [0] * 5


def test_qr_float32(qr_driver):
    driver, _ = qr_driver
    rng = np.random.default_rng(5)
    a = rand_stack(rng, 18, 4, 5).astype(np.float32).astype(np.float64)
    (res,) = run(driver, [("qr", 40, 18, 4, 5, 0.0, a)])
    cond, upd, r = qr_expected(a, 4, 5)
    got_cond, got_upd = np.triu(res.cond.reshape(4, -1)), np.triu(res.update.reshape(-1, 6))
    np.testing.assert_allclose(got_cond.ravel(), cond, rtol=0, atol=1e-4 * np.abs(r).max())
    np.testing.assert_allclose(got_upd.ravel(), upd, rtol=0, atol=1e-4 * np.abs(r).max())


# ---- Cholesky ---------------------------------------------------------------------------------


def spd_stack(rng, f, s, m_extra=3):
    w = f + s
    j = rng.standard_normal((w + m_extra, w))
    g = rng.standard_normal(w)
    h = np.zeros((w, w + 1))
    h[:, :w] = np.triu(j.T @ j)
    h[:, w] = g
    h[np.tril_indices(w, -1)] = 99.0  # left of the diagonal is not read
    return h


def cpe_expected(h, f, s, mu):
    w = f + s
    full = np.triu(h[:, :w])
    full = full + np.triu(full, 1).T
    full[:f, :f] += mu * np.eye(f)
    g = h[:, w]
    lf = np.linalg.cholesky(full[:f, :f])
    u = lf.T
    sm = np.linalg.solve(lf, full[:f, f:])
    d = np.linalg.solve(lf, g[:f])
    # fgc_cpe.h leaves each row as its pivot left it: row i of U scaled by U_ii = sqrt(d_i)
    cond = np.diag(np.diag(u)) @ np.hstack([u, sm, d[:, None]])
    schur = full[f:, f:] - sm.T @ sm
    gs = g[f:] - sm.T @ d
    upd = np.hstack([np.triu(schur), gs[:, None]])
    return cond, upd


# 101 / 105 / 120: 1 / 5 / 20 CPEs two words a cycle (STREAM_WORDS = 2)
@pytest.mark.parametrize("cpe", [1, 5, 20, 101, 105, 120])
def test_cpe_matches_numpy(driver, cpe):
    rng = np.random.default_rng(20 + cpe)
    shapes = [(3, 4, 0.0), (6, 9, 0.5), (25, 5, 1e-3), (12, 0, 0.0), (1, 1, 0.0), (20, 10, 2.0)]
    cases = [("cpe", cpe, 0, f, s, mu, spd_stack(rng, f, s)) for f, s, mu in shapes]
    for (_, _, _, f, s, mu, h), res in zip(cases, run(driver, cases), strict=True):
        cond, upd = cpe_expected(h, f, s, mu)
        assert not res.not_pd and not res.singular
        # one word a cycle the cascade leaves H (its buffer between rounds) clear; two a cycle
        # its later rounds read two words of H a cycle and clear none (the array's two ports)
        assert res.left == 0 or (cpe > 100 and f > cpe % 100)
        scale = max(np.abs(cond).max(), 1.0)
        # left of the diagonal nothing is written (the driver fills NaN there)
        got_cond = np.triu(res.cond.reshape(f, f + s + 1))
        got_upd = np.triu(res.update.reshape(s, s + 1))
        assert np.isnan(res.cond.reshape(f, -1)[np.tril_indices(f, -1)]).all()
        np.testing.assert_allclose(got_cond, cond, rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose(got_upd, upd, rtol=0, atol=1e-12 * scale)
        # back-substitution R x = d - S xs, xs = 1, 2, ... (read lane-local by cond_load)
        xs = np.arange(1, s + 1, dtype=float)
        x = np.linalg.solve(cond[:, :f], cond[:, f + s] - cond[:, f:f + s] @ xs)
        np.testing.assert_allclose(res.x, x, rtol=1e-10, atol=1e-10)


def test_cpe_flags(driver):
    rng = np.random.default_rng(7)
    indef = spd_stack(rng, 6, 3)
    indef[4, 4] = -50.0  # a negative diagonal entry in the frontal block
    sep_indef = spd_stack(rng, 4, 4)
    sep_indef[6, 6] = -50.0  # indefinite in the separator: not this step's concern
    tiny = np.zeros((3, 4))
    tiny[0, 0], tiny[1, 1], tiny[2, 2], tiny[:, 3] = 1.0, 1e-10, 1.0, 1.0
    cases = [("cpe", 5, 0, 6, 3, 0.0, indef), ("cpe", 20, 0, 4, 4, 0.0, sep_indef),
             ("cpe", 1, 0, 6, 3, 100.0, indef),  # mu makes it definite
             ("cpe", 5, 0, 2, 1, 0.0, tiny), ("cpe", -5, 0, 2, 1, 0.0, tiny),
             ("cpe", 5, 0, 26, 2, 0.0, np.eye(28, 29))]  # f > MAX_F
    got = [(r.not_pd, r.singular) for r in run(driver, cases)]
    assert got == [(True, True), (False, False), (False, False), (False, False),
                   (False, True), (True, True)]


def test_cpe_float32(driver):
    rng = np.random.default_rng(8)
    h = spd_stack(rng, 7, 5, m_extra=10).astype(np.float32).astype(np.float64)
    (res,) = run(driver, [("cpe", 50, 0, 7, 5, 0.1, h)])
    cond, upd = cpe_expected(h, 7, 5, 0.1)
    np.testing.assert_allclose(np.triu(res.cond.reshape(7, 13)), cond, rtol=0,
                               atol=1e-3 * np.abs(cond).max())


# ---- cycles -------------------------------------------------------------------------------------


def test_cycle_counts(driver):
    """The counters follow the plan's loop arithmetic; more units take fewer cycles."""
    ops = DRIVER_OPS
    la, lm, ld, ls = ops.add.latency, ops.mul.latency, ops.div.latency, ops.sqrt.latency
    assert (la, lm, ld, ls) == (12, 9, 57, 57)  # the driver's configuration
    rng = np.random.default_rng(1)
    h = spd_stack(rng, 10, 5)
    (one, five, twenty) = run(driver, [("cpe", c, 0, 10, 5, 0.0, h) for c in (1, 5, 20)])
    assert one.cycles > five.cycles > twenty.cycles > 0

    def loop(trip, ii, depth):
        return (trip - 1) * ii + depth if trip > 0 else 0

    # N_CPE = 20, one round (p0 = 0, w = 15, all 10 pivots): the region's slowest process plus the
    # others' fill, then the singularity scale and the pivot check
    w, f = 15, 10
    words = w * (w + 1) // 2 + w

    # every process is one stream of the words and the status word: the feed La + 2 deep (mu
    # added), a tap with a pivot 2 (its divide runs beside the stream), a CPE with a pivot
    # 2 Lm + La + 2 plus its wait for r (Ld - its row's w + 1 - p words, if more), the drain 2;
    # the 10 idle taps and CPEs run no iteration (the stream leaves at CPE 9's tail)
    def cpe(p):
        return 2 * lm + la + 2 + max(0, ld - (w + 1 - p))

    procs = ([(loop(words + 1, 1, la + 2), la + 2)]
             + [(loop(words + 1, 1, 2), 2)] * f
             + [(loop(words + 1, 1, cpe(p)), cpe(p)) for p in range(f)]
             + [(loop(words + 1, 1, 2), 2)])
    slow = max(range(len(procs)), key=lambda i: procs[i][0])
    region = procs[slow][0] + sum(fill for i, (_, fill) in enumerate(procs) if i != slow)
    assert region == words + la + 2 + 2 * f + sum(cpe(p) for p in range(f)) + 2
    # the scale (and the smallest pivot beside it), the pivot check: the smallest over the scale
    sequential = loop(f, 1, lm + ld + 2) + loop(1, 1, ld + 2)
    p = 12  # the driver's PARTIALS
    # cond_load: the f (w + 1) - f (f - 1) / 2 words R's upper triangle, S and d hold, two a
    # cycle, multiply-add deep (+ read and write); cond_backsub: per row the 2 P partial sums
    # folded beside the reciprocal, the row scaled by it (max(La (1 + ⌈log₂ 2P⌉), Ld) + Lm
    # deep), the triangle's columns r = f - 1 … 1 at max(r, Lm + La + 1) iterations each (chain
    # Lm + La; an iteration 2 Lm + La deep), x_0 a move (1)
    chain = lm + la
    load = loop(-(-(f * (w + 1) - f * (f - 1) // 2) // 2), 1, 2 + lm + la)
    rows = loop(f, 1, max(la * (1 + math.ceil(math.log2(2 * p))), ld) + lm)
    backsub = (load + rows + loop(sum(max(r, chain + 1) for r in range(1, f)), 1, lm + chain)
               + 1)
    assert twenty.cycles == region + sequential
    assert twenty.backsub == backsub

    a = rand_stack(rng, 20, 6, 6)
    q1, q4, q8 = run(driver, [("qr", u, 20, 6, 6, 0.0, a) for u in (1, 4, 8)])
    # more units take fewer cycles until the Evaluate's chain (column in, vector out) is the
    # critical path: on this small stack 4 units already reach it
    assert q1.cycles > q4.cycles > 0 and q1.cycles > q8.cycles
    # the overlap: a region costs less than its processes one after another
    assert q4.cycles < q4.serial


def test_cpe_no_frontal_columns(driver):
    """f = 0: no round runs; the update matrix is [H | g] as it came."""
    h = spd_stack(np.random.default_rng(9), 0, 4)
    (res,) = run(driver, [("cpe", 5, 0, 0, 4, 0.0, h)])
    assert not res.not_pd and not res.singular and res.cond.size == 0 and res.left == 0
    np.testing.assert_array_equal(np.triu(res.update.reshape(4, 5)), np.triu(h))


# ---- the plan prices what the units execute ---------------------------------------------------


@pytest.mark.parametrize("units", [1, 4, 8])
def test_plan_prices_the_qr_unit(qr_driver, units):
    """plan.qr_unit_loops (what plan.py's QR phases are made of) equals the counted cycles of
    qr_step on a sparse stack: structural zeros, a child's trapezoid, damping rows (the Update
    units one row a cycle and two)."""
    from fgc_backends.hls.units.qr import qr_unit_loops

    driver, qr_rows = qr_driver

    rng = np.random.default_rng(40 + units)
    f, s = 6, 7
    pattern = rng.random((14, f + s)) < 0.4
    trapezoid = np.zeros((4, f + s), dtype=bool)
    for i in range(4):
        trapezoid[i, f + i:] = True
    pattern = np.vstack([pattern, trapezoid, np.eye(f, f + s, dtype=bool)])
    a = np.where(pattern, rng.standard_normal(pattern.shape), 0.0)
    a = np.hstack([a, rng.standard_normal((len(a), 1))])
    (res,) = run(driver, [("qr", units, len(a), f, s, 0.0, a)])
    loops = qr_unit_loops(pattern, f, units, DRIVER_OPS, partials=12, qr_rows=qr_rows)
    assert res.cycles == sum(lp.cycles for lp in loops)


def _zero_in_value_stack(rng, f, s):
    """A stack whose pattern has rows and columns that are zero in value: a sparse block, a
    child's trapezoid, damping rows, two rows non-zero by structure but zero in value (a prior
    at its reset value, a row rounding emptied), a row that is zero in value from column f on
    although the fill makes it non-zero there, and a right-hand side zero on half the rows."""
    pattern = rng.random((14, f + s)) < 0.4
    pattern[:, 0] = True  # every sparse row active in reflection 0: they fill the separator
    trapezoid = np.zeros((4, f + s), dtype=bool)
    for i in range(4):
        trapezoid[i, f + i:] = True
    pattern = np.vstack([pattern, trapezoid, np.eye(f, f + s, dtype=bool)])
    rhs = np.ones(len(pattern), dtype=bool)
    rhs[::2] = False
    a = np.where(pattern, rng.standard_normal(pattern.shape), 0.0)
    a = np.hstack([a, np.where(rhs, rng.standard_normal(len(pattern)), 0.0)[:, None]])
    a[3] = 0.0  # non-zero by structure, zero in value
    a[15] = 0.0
    a[5, :] = 0.0
    a[5, 0] = 1.5  # only its pivot-column entry: zero in value where reflection 0 fills it
    return pattern, rhs, a


def test_the_keep_rule_by_structure_counts_the_plans_cycles(qr_driver):
    """qr_step_structural keeps the rows the pattern says, not the values: on a stack with rows
    non-zero by structure but zero in value it counts exactly what qr_unit_loops prices on the
    pattern (the value rule, qr_step, counts fewer there), and it computes the same factor."""
    from fgc_backends.hls.units.qr import qr_unit_loops

    driver, qr_rows = qr_driver
    rng = np.random.default_rng(77)
    f, s = 6, 7
    pattern, rhs, a = _zero_in_value_stack(rng, f, s)
    mask = np.hstack([pattern, rhs[:, None]]).astype(float)
    assert not np.any((a != 0) & (mask == 0))  # every value on the pattern
    both = np.hstack([a.ravel(), mask.ravel()])
    # n_u 4 and 8 in double, n_u 4 in float (cfg 40: the same latencies)
    cases = [(kind, cfg, len(a), f, s, 0.0, a if kind == "q" else both)
             for cfg in (4, 8, 40) for kind in ("q", "s")]
    res = run(driver, cases)
    for cfg, value, struct in zip((4, 8, 40), res[0::2], res[1::2], strict=True):
        plan = sum(lp.cycles for lp in qr_unit_loops(pattern, f, cfg % 10 or 4, DRIVER_OPS,
                                                     partials=12, qr_rows=qr_rows, rhs=rhs))
        assert struct.cycles == plan, cfg
        assert value.cycles < plan, cfg  # the value rule skips the rows zero in value
        assert struct.left == 0 and not struct.singular
        tol = 1e-5 if cfg == 40 else 1e-12
        np.testing.assert_allclose(struct.cond, value.cond, rtol=tol, atol=tol)
        np.testing.assert_allclose(struct.update, value.update, rtol=tol, atol=tol)
        np.testing.assert_allclose(struct.x, value.x, rtol=tol, atol=tol)
    cond, upd, _ = qr_expected(a, f, s)
    np.testing.assert_allclose(np.abs(res[1].cond), np.abs(cond), rtol=1e-9, atol=1e-9)


def test_plan_prices_the_cpe_rounds(driver):
    """plan.cpe_round_depth: a whole matrix as one step (f = n, s = 0), as plan.py's Cholesky
    phase prices it, equals the counted cycles for 1, 5 and 20 CPEs (idle CPEs included)."""
    from fgc_backends.hls.plan import Loop
    from fgc_backends.hls.units.cholesky import cpe_round_depth, cpe_wait

    ops = DRIVER_OPS
    n = 23
    h = spd_stack(np.random.default_rng(11), n, 0)
    results = run(driver, [("cpe", c, 0, n, 0, 0.5, h) for c in (1, 5, 20)])
    for c, res in zip((1, 5, 20), results, strict=True):
        rounds = []
        for r in range(-(-n // c)):
            m = n - r * c
            waits = sum(cpe_wait(p, n, ops) for p in range(r * c, min(n, r * c + c)))
            depth = cpe_round_depth(min(c, m), c, ops, waits)
            rounds.append(Loop("round", m * (m + 1) // 2 + m + 1, 1, depth))
            if r * c + c < n:  # the rows left back into H
                k = n - r * c - c
                rounds.append(Loop("back", (k * (k + 1) // 2 + k + 1) // 2, 1, 2))
        scalar = (Loop("scale", n, 1, ops.mul.latency + ops.div.latency + 2).cycles
                  + Loop("check", 1, 1, ops.div.latency + 2).cycles)
        assert res.cycles == sum(lp.cycles for lp in rounds) + scalar


def test_plan_prices_multifrontal_cpe_steps(driver):
    """plan.cpe_step_loops on steps with separators (the rounds stream the separator rows too,
    the last round has idle CPEs) and with no frontal columns."""
    from fgc_backends.hls.units.cholesky import cpe_step_loops

    ops = DRIVER_OPS
    rng = np.random.default_rng(12)
    shapes = [(7, 5, 5), (13, 9, 5), (3, 4, 20), (6, 9, 1), (0, 4, 5),
              (13, 9, 105), (6, 9, 101), (15, 15, 120), (2, 3, 105)]  # 1xx: two words a cycle
    cases = [("cpe", c, 0, f, s, 0.2, spd_stack(rng, f, s)) for f, s, c in shapes]
    for (f, s, c), res in zip(shapes, run(driver, cases), strict=True):
        lanes = 2 if c > 100 else 1
        assert res.cycles == sum(lp.cycles for lp in cpe_step_loops(f, s, c % 100, ops,
                                                                      lanes=lanes))
