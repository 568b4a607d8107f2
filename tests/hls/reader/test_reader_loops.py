"""The second reader's loop rules (backends/hls/reader/loops.py, count.py): what Vitis would
build, read from the text alone. Each planted defect of issue 32 (a fold inside a pipelined
loop, a long write into an unpartitioned global, a data-dependent read-modify-write without
DEPENDENCE) makes the check fail, and its correction passes."""

from __future__ import annotations

import pytest

from fgc_backends.hls.reader import check, check_dsp, read_design, read_project

ADD_LATENCY = 4  # a float adder's stages in these snippets
DSP = {"add": 2, "mul": 3, "div": 0, "sqrt": 0, "special": 0}


FOLD = """
typedef float T;
template <class T, int P>
inline T fold_partials(T part[P]) {
#pragma HLS INLINE
    for (int step = 1; step < P; step *= 2) {
#pragma HLS UNROLL
        for (int i = 0; i < P; i += 2 * step) {
#pragma HLS UNROLL
            if (i + step < P) part[i] += part[i + step];
        }
    }
    return part[0];
}
void scale_rows(const T part[64][11], T tau, T out[64]) {
    for (int l = 0; l < 64; ++l) {
#pragma HLS PIPELINE II=1
        T p[11];
        for (int t = 0; t < 11; ++t) p[t] = part[l][t];
        out[l] = tau * fold_partials<T, 11>(p);
    }
}
void top(const T part[64][11], T tau, T out[64]) {
    scale_rows(part, tau, out);
}
"""


def test_a_fold_inside_a_pipelined_loop_holds_its_adders():
    """fold_partials<11> at II 1: 10 adders and a multiplier (23 DSP), not the 1 + 1 (5 DSP) a
    per-unit price assumes; the design check fails against 5 and passes against 23."""
    design = read_design([("fold.cpp", FOLD)], "top", ADD_LATENCY)
    (loop,) = design.loops
    assert dict(loop.ops) == {"add": 10, "mul": 1}
    assert dict(loop.instances) == {"add": 10, "mul": 1}
    assert design.dsp(DSP) == 23
    (issue,) = check_dsp(design, plan_dsp=5, dsp_of=DSP)
    assert issue.rule == "dsp_bound" and "at least 23" in issue.message
    assert check_dsp(design, plan_dsp=23, dsp_of=DSP) == []
    # at II 4 the same loop shares its adders: ceil(10 / 4)
    slower = read_design([("fold.cpp", FOLD.replace("II=1", "II=4"))], "top", ADD_LATENCY)
    assert dict(slower.loops[0].instances) == {"add": 3, "mul": 1}


WRITE_ROWS = """
typedef float T;
const int N_A = 20000;
T AB[N_A];
{partition}
void evaluate(const T rows[29][651]) {{
    for (int i = 0; i < 29; ++i) {{
#pragma HLS PIPELINE II=143
        T ab[651];
        for (int c = 0; c < 651; ++c) ab[c] = rows[i][c] * T(2);
        const int a0 = i * 651;
        for (int r = 0; r < 21; ++r) {{
            for (int c = 0; c < 31; ++c) AB[a0 + r * 31 + c] = ab[r * 31 + c];
        }}
    }}
}}
"""


def test_a_long_write_into_an_unpartitioned_global_bounds_the_ii():
    """651 words an iteration through AB's two ports: II >= 326, above the declared 143; the
    local ab is not judged (Vitis's throughput-driven partitioning); AB cyclic by 4 passes."""
    readings = read_project([("ab.cpp", WRITE_ROWS.format(partition=""))], ADD_LATENCY)
    (loop,) = readings
    assert ("AB", 651, 1) in loop.accesses and loop.ii_ports == 326
    (issue,) = check(readings)
    assert issue.rule == "ii_ports" and "'AB'" in issue.message and "II >= 326" in issue.message
    assert issue.file == "ab.cpp" and issue.line == 8  # the PIPELINE pragma
    fixed = WRITE_ROWS.format(partition="#pragma HLS ARRAY_PARTITION variable=AB cyclic factor=4")
    readings = read_project([("ab.cpp", fixed)], ADD_LATENCY)
    assert readings[0].ii_ports == 82 and check(readings) == []


RMW = """
typedef float T;
const int ROWS = 64, COLS = 8;
T BANK[ROWS][COLS];
void axpys(const int at[ROWS], const T v[ROWS], const T s[COLS], int n, int r) {
    for (int e = 0, l = 0, a = 0; e < n * r; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=512
#pragma HLS PIPELINE II=1
%DEPENDENCE%
        const T x = BANK[at[a]][l] - s[l] * v[a];
        BANK[at[a]][l] = x;
        if (a == n - 1) {
            a = 0;
            ++l;
        } else {
            ++a;
        }
    }
}
"""


def test_a_data_dependent_read_modify_write_needs_dependence():
    """BANK[at[a]][l] read and written at an address read from memory: Vitis assumes a carried
    dependence (II >= the adder's latency) unless a DEPENDENCE pragma says there is none."""
    readings = read_project([("rmw.cpp", RMW.replace("%DEPENDENCE%", ""))], ADD_LATENCY)
    assert readings[0].recurrence == ("BANK",)
    (issue,) = check(readings)
    assert issue.rule == "ii_recurrence" and f"II >= {ADD_LATENCY}" in issue.message
    free = RMW.replace("%DEPENDENCE%", "#pragma HLS DEPENDENCE variable=BANK inter false")
    assert check(read_project([("rmw.cpp", free)], ADD_LATENCY)) == []
    # a loop whose address moves with its own variable carries nothing
    moving = RMW.replace("BANK[at[a]][l]", "BANK[e % ROWS][l]").replace("%DEPENDENCE%", "")
    assert check(read_project([("rmw.cpp", moving)], ADD_LATENCY)) == []


def test_a_carried_scalar_sum_and_a_partitioned_unrolled_store():
    text = """
typedef float T;
const int N = 128;
T OUT[4][N];
#pragma HLS ARRAY_PARTITION variable=OUT complete dim=1
T dot(const T a[N], const T b[N]) {
    T sum = T(0);
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        sum += a[i] * b[i];
    }
    return sum;
}
void spread(const T a[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        for (int u = 0; u < 4; ++u) OUT[u][i] = a[i];
    }
}
"""
    readings = {r.function: r for r in read_project([("s.cpp", text)], ADD_LATENCY)}
    assert readings["dot"].recurrence == ("sum",) and readings["dot"].ii_bound == ADD_LATENCY
    # complete dim=1 of a [4][N] array: four banks, one store each an iteration
    assert readings["spread"].accesses == (("OUT", 4, 4),) and readings["spread"].ii_bound == 1


def test_a_global_partitioned_in_a_function_and_a_shared_function():
    """A global's ARRAY_PARTITION inside the function that uses it partitions the global
    (not an alias), and ``ALLOCATION function instances=g limit=1`` makes two call sites of g
    one RTL instance, also when one of them is in an INLINE callee."""
    text = """
typedef float T;
const int N = 64;
T BANKS[4][N];
void zero(T bank[4][N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        for (int u = 0; u < 4; ++u) bank[u][i] = T(0);
    }
}
T scale(T x, T y) {
    return x * y + y;
}
T top(T x, T y, bool p) {
#pragma HLS ARRAY_PARTITION variable=BANKS complete dim=1
#pragma HLS ALLOCATION function instances=scale limit=1
    zero(BANKS);
    if (p) return scale(x, y);
    return scale(y, x);
}
"""
    design = read_design([("s.cpp", text)], "top", ADD_LATENCY)
    (zero,) = [r for r in design.loops if r.function == "zero"]
    assert zero.accesses == (("BANKS", 4, 4),) and zero.ii_bound == 1
    assert dict(design.modules)["scale"] == 1
    unshared = text.replace("#pragma HLS ALLOCATION function instances=scale limit=1\n", "")
    assert dict(read_design([("s.cpp", unshared)], "top", ADD_LATENCY).modules)["scale"] == 2
    # the limit holds for the call sites of INLINE callees too (their code is the caller's:
    # LM control's cost hooks and try_steps inlined into optimize share one total_cost)
    inlined = text.replace("    if (p) return scale(x, y);\n    return scale(y, x);",
                           "    if (p) return via(x, y);\n    return scale(y, x);").replace(
        "T top(", "T via(T x, T y) {\n#pragma HLS INLINE\n    return scale(x, y);\n}\nT top(")
    assert "via(x, y);" in inlined and "#pragma HLS INLINE\n" in inlined
    assert dict(read_design([("s.cpp", inlined)], "top", ADD_LATENCY).modules)["scale"] == 1
    not_inlined = inlined.replace("#pragma HLS INLINE\n", "")
    assert dict(read_design([("s.cpp", not_inlined)], "top", ADD_LATENCY).modules)["scale"] == 2
    alias = text.replace("variable=BANKS complete", "variable=Q complete")
    (zero,) = [r for r in read_design([("s.cpp", alias)], "top", ADD_LATENCY).loops
               if r.function == "zero"]
    assert zero.ii_bound == 2  # four stores through one memory's two ports


CAPPED_RMW = """
typedef float T;
T ACC[16];
void bump(const int at[4], T v) {
#pragma HLS ALLOCATION operation instances=fadd limit=1
    ACC[at[0]] += v;
}
void run(const int at[4], const T v[64]) {
    for (int i = 0; i < 64; ++i) {
#pragma HLS PIPELINE II=1
        bump(at, v[i]);
    }
}
void top(const int at[4], const T v[64]) { run(at, v); }
"""


def test_a_capped_callee_keeps_its_read_modify_write():
    """ACC[at[0]] += v inside a function under ALLOCATION: the loop calling it at II 1 still
    carries the dependence (issue 32 part 3: the capped callee's record was dropped)."""
    (loop,) = read_project([("capped.cpp", CAPPED_RMW)], ADD_LATENCY)
    assert loop.recurrence == ("ACC",) and loop.ii_bound == ADD_LATENCY
    assert [i.rule for i in check([loop])] == ["ii_recurrence"]


DISTANCE = """
typedef float T;
void sums(const T v[256], T out[4]) {
    T acc[4];
    for (int i = 0; i < 256; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=acc inter true distance=D
        acc[0] += v[i];
    }
    out[0] = acc[0];
}
void top(const T v[256], T out[4]) { sums(v, out); }
"""


@pytest.mark.parametrize("distance, bound", [(1, 4), (2, 2), (4, 1), (8, 1)])
def test_a_declared_distance_bounds_the_ii_by_the_latency_over_it(distance, bound):
    """DEPENDENCE inter true distance=D on a carried sum: II >= ceil(adder latency / D)."""
    (loop,) = read_project([("d.cpp", DISTANCE.replace("=D", f"={distance}"))], ADD_LATENCY)
    assert loop.ii_bound == bound
    assert bool(check([loop])) == (bound > 1)


STORED = """
typedef float T;
void kept(const T v[256], T out[4]) {
    T w[8];
    int a = 0;
    for (int i = 0; i < 256; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=w inter true distance=D
        T x = w[a];
        if (i < 8) {
            x = v[i];
            w[i] = x;
        }
        out[0] = x;
        a = a == 7 ? 0 : a + 1;
    }
}
void top(const T v[256], T out[4]) { kept(v, out); }
"""


@pytest.mark.parametrize("distance, bound", [(1, 1), (2, 1)])
def test_a_stored_word_read_back_at_a_distance_is_no_adder_recurrence(distance, bound):
    """A word stored and read back D iterations later (an Update unit's vector, kept as the
    dot's first column takes it) recurs through the memory, not an adder: II >= ceil(1 / D);
    the same claim on a sum is the adder's (the test above)."""
    (loop,) = read_project([("s.cpp", STORED.replace("=D", f"={distance}"))], ADD_LATENCY)
    assert loop.recurrence == ("w",) and loop.ii_bound == bound
    assert not check([loop])


BRANCHES = """
typedef float T;
template <int KIND>
void pick(const T a[8], T out[8]) {
    for (int i = 0; i < 8; ++i) {
#pragma HLS PIPELINE II=1
        if (KIND == 2) {
            out[i] = a[i] * a[i] + a[i];
        } else {
            out[i] = a[i] * T(3);
        }
    }
}
void top(const T a[8], T out[8], T o2[8]) { pick<2>(a, out); pick<0>(a, o2); }
"""


def test_only_the_branch_the_template_takes_is_built():
    loops = {dict(r.template)["KIND"]: r for r in read_project([("b.cpp", BRANCHES)],
                                                               ADD_LATENCY)}
    assert dict(loops[2].ops) == {"add": 1, "mul": 1}
    assert dict(loops[0].ops) == {"mul": 1}


HIDDEN = """
typedef float T;
const int N = 64;
T norm(T a, T b) { return a * a + b * b; }
void gate(const T x[N], const T y[N], T eps, T out[N], hls::stream<T>& s, bool hit[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        %BODY%
    }
}
void top(const T x[N], const T y[N], T eps, T out[N], hls::stream<T>& s, bool hit[N]) {
    gate(x, y, eps, out, s, hit);
}
"""


@pytest.mark.parametrize("body, ops", [
    # an if condition: two multiplies decide the branch (a float compare binds no DSP)
    ("if (x[i] * y[i] > eps * eps) out[i] = x[i]; else out[i] = y[i];", {"mul": 2}),
    # a ternary's condition inside a call's argument (a stream write)
    ("s.write(x[i] - y[i] > eps ? x[i] * T(2) : y[i]);", {"add": 1, "mul": 1}),
    # a boolean's initialiser
    ("const bool big = x[i] * x[i] + y[i] * y[i] > eps; hit[i] = big;", {"add": 1, "mul": 2}),
    # a float-returning call compared: its operators in the callee, read in place
    ("hit[i] = norm(x[i], y[i]) > eps;", {"add": 1, "mul": 2}),
    # integer arithmetic in a condition binds no floating-point operator
    ("if (i * 3 + 1 < N) out[i] = x[i];", {}),
])
def test_operators_outside_a_float_statement_are_read(body, ops):
    """Conditions, a ternary inside a call's arguments, a boolean's initialiser: a float
    operator there is an operator Vitis binds in the pipelined loop at II 1, and the plan must
    price it (the reader counted only float statements and missed them: check_dsp passed a
    plan of 0 DSP)."""
    text = HIDDEN.replace("%BODY%", body)
    design = read_design([("hidden.cpp", text)], "top", ADD_LATENCY)
    (loop,) = design.loops
    assert dict(loop.instances) == ops
    need = sum(n * DSP[k] for k, n in ops.items())
    assert design.dsp(DSP) == need
    assert bool(check_dsp(design, plan_dsp=0, dsp_of=DSP)) == (need > 0)


LOOP_CONDITION = """
typedef float T;
void scan(const T x[64], T eps, int out[1]) {
    int k = 0;
    for (int i = 0; i < 64 && x[i] * x[i] > eps; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=64
#pragma HLS PIPELINE II=1
        k += 1;
    }
    out[0] = k;
}
void top(const T x[64], T eps, int out[1]) { scan(x, eps, out); }
"""


def test_a_pipelined_loops_own_condition_is_read():
    """The multiply in a pipelined loop's condition runs every iteration: one multiplier."""
    (loop,) = read_project([("cond.cpp", LOOP_CONDITION)], ADD_LATENCY)
    assert dict(loop.instances) == {"mul": 1}


HEADER = """
typedef float T;
T D[64];
void update(int c, const T base[8], const T shift[8]) {
    T local[8];
    for (int k = 0; k < 8; ++k) local[k] = base[k];
    for (int i = 0; i < 8; ++i) {
#pragma HLS PIPELINE II=1
        D[c * 8 + i] -= shift[i] + local[i];
    }
}
void top(const T base[8], const T shift[8]) { update(1, base, shift); }
"""


def test_the_loop_header_is_the_one_before_the_brace():
    """A brace-less loop earlier in the function (``for (k ...) local[k] = ...;``) is not the
    pipelined loop's header: D[c * 8 + i] moves with i, nothing is carried (fgc_stream.h's
    reexpress was read with k as its variable and flagged)."""
    (loop,) = read_project([("h.cpp", HEADER)], ADD_LATENCY)
    assert loop.recurrence == () and check([loop]) == []
    fixed = HEADER.replace("D[c * 8 + i] -=", "D[c * 8] -=")  # a fixed element: carried
    (loop,) = read_project([("h.cpp", fixed)], ADD_LATENCY)
    assert loop.recurrence == ("D",) and [i.rule for i in check([loop])] == ["ii_recurrence"]


SITES = """
typedef float T;
T S[64];
template <int N>
void matvec(const T m[64], const T v[8], T acc[8]) {
    for (int e = 0; e < 64; ++e) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=acc inter false
        const int k = e / 8, i = e % 8;
        acc[i] = (k == 0 ? T(0) : acc[i]) + m[i * 8 + k] * v[k];
    }
}
void top(const T v[8], T out[8]) {
    T local[64], row[8];
    for (int i = 0; i < 64; ++i) local[i] = v[i % 8];
    matvec<0>(S, v, out);        // m is S
    matvec<0>(local, v, S + 8);  // acc is S
    %THIRD%
}
"""


def test_each_call_site_binds_its_own_arrays():
    """matvec reads S through m at one call site and through acc at the other: an iteration
    touches S once or twice (its two ports: II 1), never three times (fgc_stream.h's
    kept_matvec was read with both parameters bound to KEPT_S); a site that passes S as both
    does take three accesses."""
    (loop,) = read_project([("s.cpp", SITES.replace("%THIRD%", ""))], ADD_LATENCY)
    assert loop.ii_ports == 1 and check([loop]) == []
    both = SITES.replace("%THIRD%", "matvec<0>(S, v, S + 8);")
    (loop,) = read_project([("s.cpp", both)], ADD_LATENCY)
    assert ("S", 3, 1) in loop.accesses and [i.rule for i in check([loop])] == ["ii_ports"]


SQUARE = """
typedef float T;
void sq(const T x[64], const T y[64], T a, T b, T out[64]) {
    for (int i = 0; i < 64; ++i) {
#pragma HLS PIPELINE II=1
        out[i] = %EXPR%;
    }
}
void top(const T x[64], const T y[64], T a, T b, T out[64]) { sq(x, y, a, b, out); }
"""


@pytest.mark.parametrize("expr, ops", [
    # a square printed as two copies (the kernel printer's (e)**2): e is built once
    ("(x[i]*a + y[i]*b)*(x[i]*a + y[i]*b)", {"add": 1, "mul": 3}),
    ("T(0.5)*((x[i]*a + b)*(x[i]*a + b))", {"add": 1, "mul": 3}),
    # two different products are both built
    ("(x[i]*a + b)*(y[i]*a + b)", {"add": 2, "mul": 3}),
])
def test_a_square_of_a_copied_subexpression_builds_it_once(expr, ops):
    """imu_window's cost kernel prints its whitened residual's squares as (e)*(e): the reader
    counted e twice (105 adds and 109 multiplies above the kernel's own count in factor_cost_0);
    the compiler's front end merges the identical expressions of a statement."""
    (loop,) = read_project([("sq.cpp", SQUARE.replace("%EXPR%", expr))], ADD_LATENCY)
    assert dict(loop.ops) == ops
