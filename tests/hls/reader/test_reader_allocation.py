"""The second reader's ALLOCATION rule (backends/hls/reader/loops.py, ``ii_allocation``): a
pipelined loop issues one iteration's operations of a kind through that kind's instances
within its II, so an ``ALLOCATION ... limit=k`` in scope makes the II at least
``ceil(ops / k)``; and the typing of a ternary's condition inside a floating-point statement.
Each planted defect fails the check (the reader before this rule passed every one of them) and
its correction passes."""

from __future__ import annotations

from fgc_backends.hls.reader import check, read_project

ADD_LATENCY = 4

LIMITED = """
typedef float T;
void scale(const T a[64][8], const T s[8], T out[64][8]) {
#pragma HLS ALLOCATION operation instances=fmul limit=2
    for (int i = 0; i < 64; ++i) {
#pragma HLS PIPELINE II=%II%
        for (int c = 0; c < 8; ++c) out[i][c] = a[i][c] * s[c];
    }
}
"""


def test_a_loop_limited_to_fewer_multipliers_than_its_ii_needs_is_ii_short():
    """8 multiplies an iteration through 2 multipliers: II >= 4; the plan's II 2 is short."""
    (loop,) = read_project([("s.cpp", LIMITED.replace("%II%", "2"))], ADD_LATENCY)
    assert dict(loop.ops) == {"mul": 8}
    assert dict(loop.instances) == {"mul": 2}  # what the ALLOCATION lets Vitis bind
    assert loop.allocation == (("ALLOCATION in scale", "mul", 8, 2),)
    assert loop.ii_allocation == 4 and loop.ii_bound == 4
    (issue,) = check([loop])
    assert issue.rule == "ii_allocation" and issue.line == 6
    assert "8 mul operations" in issue.message and "2 instances" in issue.message
    assert "II >= 4" in issue.message
    # the correction: the II the limit allows
    (fixed,) = read_project([("s.cpp", LIMITED.replace("%II%", "4"))], ADD_LATENCY)
    assert fixed.allocation == () and fixed.ii_allocation == 4 and check([fixed]) == []


CALLEE = """
typedef float T;
T kernel(const T x[4], int b) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fmul limit=2
#pragma HLS ALLOCATION operation instances=fadd limit=1
    T r = T(0);
    if (b == 0) {
        r = x[0] * x[1] * x[2] * x[3] + x[0] * x[1] + x[2] * x[3];
    } else if (b == 1) {
        r = x[0] * x[1] * x[2] * x[3];
    } else {
        r = x[0] + x[1] + x[2];
    }
    return r;
}
void all(const T xs[32][4], T ys[32], const int kind[32]) {
    for (int i = 0; i < 32; ++i) {
#pragma HLS PIPELINE II=%II%
        ys[i] = kernel(xs[i], kind[i]);
    }
}
"""


def test_a_callee_under_allocation_shares_its_exclusive_branches():
    """A callee with its own ALLOCATION, its branches exclusive: the largest branch (5
    multiplies, 2 adds) goes through 2 multipliers and 1 adder, not the branches' sum (8, 4):
    II 3 holds, II 2 is short."""
    (loop,) = read_project([("k.cpp", CALLEE.replace("%II%", "2"))], ADD_LATENCY)
    assert loop.function == "all" and loop.ii_allocation == 3
    (issue,) = check([loop])
    assert issue.rule == "ii_allocation" and "ALLOCATION in kernel" in issue.message
    assert "5 mul operations" in issue.message and "II >= 3" in issue.message
    (fixed,) = read_project([("k.cpp", CALLEE.replace("%II%", "3"))], ADD_LATENCY)
    assert check([fixed]) == []


def test_an_early_return_makes_the_rest_of_the_function_its_else():
    """``if (c) { ...; return ...; } rest``: the branch and the rest are exclusive."""
    text = CALLEE.replace("""    } else if (b == 1) {""", """        return r;
    }
    if (b == 1) {""")
    (loop,) = read_project([("k.cpp", text.replace("%II%", "3"))], ADD_LATENCY)
    assert loop.ii_allocation == 3 and check([loop]) == []


SHARED = """
typedef float T;
T norm2(const T v[3]) {
#pragma HLS INLINE off
    return v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
}
void pairs(const T a[16][3], const T b[16][3], T out[16]) {
#pragma HLS ALLOCATION function instances=norm2 limit=1
    for (int i = 0; i < 16; ++i) {
#pragma HLS PIPELINE II=%II%
        out[i] = norm2(a[i]) + norm2(b[i]);
    }
}
"""


def test_two_call_sites_on_one_function_instance_need_two_cycles():
    """``ALLOCATION function instances=norm2 limit=1``: the loop's two calls an iteration go
    through one norm2 instance, a call a cycle at best: II >= 2."""
    (loop,) = read_project([("n.cpp", SHARED.replace("%II%", "1"))], ADD_LATENCY)
    assert loop.allocation == (("ALLOCATION function", "norm2", 2, 1),)
    (issue,) = check([loop])
    assert issue.rule == "ii_allocation" and "2 calls of norm2" in issue.message
    assert "II >= 2" in issue.message
    (fixed,) = read_project([("n.cpp", SHARED.replace("%II%", "2"))], ADD_LATENCY)
    assert check([fixed]) == []


TERNARY = """
typedef float T;
const int F = 15;
void slot(const T x[64], T out[16], int c) {
    for (int h = 0; h < 16; ++h) {
#pragma HLS PIPELINE II=1
        out[h] = %EXPR%;
    }
}
"""


def test_a_ternarys_integer_condition_is_no_float_adder():
    """``c + h < F ? x[c + h] : T(0)``: the condition's ``+`` is integer (c and h are declared
    int); the reader before read it as a float add. A float condition keeps its adder, and
    the branches' operators still count."""
    cases = {"c + h < F ? x[c + h] : T(0)": {},
             "x[h] + x[c] < T(0) ? x[c + h] : T(0)": {"add": 1},
             "c + h < F ? x[c + h] * x[h] : x[h] - T(1)": {"mul": 1, "add": 1},
             "c + 1 < F ? (h > 2 ? x[h] : x[h] + x[c]) : T(0)": {"add": 1}}
    for expr, ops in cases.items():
        (loop,) = read_project([("t.cpp", TERNARY.replace("%EXPR%", expr))], ADD_LATENCY)
        assert dict(loop.ops) == ops, expr


HOOKED = """
typedef float T;
const int ROWS = 64, UNITS = 4;
T WORK0[UNITS][ROWS];
T WORK1[UNITS][ROWS];
void stack(const T src[ROWS], T bank[UNITS][ROWS]) {
    for (int r = 0; r < ROWS; ++r) {
#pragma HLS PIPELINE II=1
        for (int u = 0; u < UNITS; ++u) bank[u][r] = src[r];
    }
}
struct Sets {
    static void stack_set(int u, const T src[ROWS]) {
        if (u == 0) stack(src, WORK0);
        if (u == 1) stack(src, WORK1);
    }
};
void top(const T src[ROWS]) {
%PARTITION%
    Sets::stack_set(0, src);
    Sets::stack_set(1, src);
}
"""


def test_a_global_passed_on_by_a_structs_member_is_that_global():
    """A struct's static member (the QR driver's hooks, ``QrSets::stack``) passes the globals
    WORK0 / WORK1 to ``stack``: its parameter is those globals, judged with their ports (four
    stores an iteration through two unpartitioned ports: II >= 2). The reader before took the
    parameter for a local of ``stack`` (its callers' members unread) and judged nothing."""
    readings = read_project([("h.cpp", HOOKED.replace("%PARTITION%", ""))], ADD_LATENCY)
    (loop,) = [r for r in readings if r.function == "stack"]
    assert loop.accesses in ((("WORK0", 4, 1),), (("WORK1", 4, 1),)) and loop.ii_ports == 2
    (issue,) = check(readings)
    assert issue.rule == "ii_ports" and "II >= 2" in issue.message
    partitioned = HOOKED.replace("%PARTITION%", "\n".join(
        f"#pragma HLS ARRAY_PARTITION variable=WORK{u} complete dim=1" for u in (0, 1)))
    readings = read_project([("h.cpp", partitioned)], ADD_LATENCY)
    (loop,) = [r for r in readings if r.function == "stack"]
    assert loop.ii_ports == 1 and check(readings) == []


PARTIAL_SUMS = """
typedef float T;
const int N = 256, P = 4;
T dot(const T a[N], const T b[N]) {
    T part[P];
#pragma HLS ARRAY_PARTITION variable=part complete
    for (int t = 0; t < P; ++t) part[t] = T(0);
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
%DEPENDENCE%
        part[i % %MOD%] += a[i] * b[i];
    }
    return part[0] + part[1] + part[2] + part[3];
}
"""


def _partial_sums(dependence: str, mod: str = "P") -> str:
    return PARTIAL_SUMS.replace("%DEPENDENCE%", dependence).replace("%MOD%", mod)


def test_inter_false_on_interleaved_partial_sums_is_refuted():
    """``part[i % P] +=`` under ``DEPENDENCE inter false``: each partial is read and written
    again P iterations later, a real distance-P dependence the claim hides (issue 32). The
    reader before took the claim and reported nothing; ``inter true distance=P`` is the truth
    and passes (P = 4 >= the adder's 4 stages: II 1). A modulus of 2 refutes II 1 too."""
    (loop,) = read_project([("d.cpp", _partial_sums(
        "#pragma HLS DEPENDENCE variable=part inter false"))], ADD_LATENCY)
    assert loop.false_claims == (("part", "[i%P]", 4, ADD_LATENCY),) and loop.ii_bound == 1
    (issue,) = check([loop])
    assert issue.rule == "dependence_false" and "'inter true distance=4'" in issue.message
    truth = _partial_sums("#pragma HLS DEPENDENCE variable=part inter true distance=P")
    (loop,) = read_project([("d.cpp", truth)], ADD_LATENCY)
    assert loop.false_claims == () and check([loop]) == []
    (loop,) = read_project([("d.cpp", _partial_sums(
        "#pragma HLS DEPENDENCE variable=part inter false", "2"))], ADD_LATENCY)
    assert loop.ii_dependence == 2 and loop.ii_bound == 2
    assert [i.rule for i in check([loop])] == ["dependence_false"]


def test_inter_false_on_a_fixed_element_and_a_data_dependent_one():
    """``acc[k]`` with k never moved by the loop: every iteration meets the last one (a
    compare and select: latency 1, so only the claim is wrong, not the II). ``G[col[i]]``: an
    address read from memory, unproven; reported only when asked (``strict``)."""
    fixed = """
typedef float T;
void running_max(const T g[64], T acc[4], int k) {
    for (int i = 0; i < 64; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=acc inter false
        acc[k] = g[i] > acc[k] ? g[i] : acc[k];
    }
}
"""
    (loop,) = read_project([("m.cpp", fixed)], ADD_LATENCY)
    assert loop.false_claims == (("acc", "[k]", 1, 1),) and loop.ii_bound == 1
    assert [i.rule for i in check([loop])] == ["dependence_false"]
    scatter = """
typedef float T;
T G[32];
void scatter(const T v[64], const int col[64]) {
    for (int i = 0; i < 64; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=G inter false
        G[col[i]] += v[i];
    }
}
"""
    (loop,) = read_project([("g.cpp", scatter)], ADD_LATENCY)
    assert loop.false_claims == () and loop.unproven_claims == (("G", "[col[i]]"),)
    assert check([loop]) == []
    assert [i.rule for i in check([loop], strict=True)] == ["dependence_unproven"]


UNITS = """
typedef float T;
const int N_UNITS = 2, ROWS = 32;
T WORK[N_UNITS][ROWS];
#pragma HLS ARRAY_PARTITION variable=WORK complete dim=1
template <int U>
void update(T bank[ROWS], const T v[ROWS]) {
    for (int r = 0; r < ROWS; ++r) {
#pragma HLS PIPELINE II=1
        bank[r] = bank[r] * v[r] + %EXTRA%;
    }
}
template <int U, bool END = (U == N_UNITS)>
struct units {
    static void run(T work[N_UNITS][ROWS], const T v[ROWS]) {
        update<U>(work[U], v);
        units<U + 1>::run(work, v);
    }
};
template <int U>
struct units<U, true> {
    static void run(T (*)[ROWS], const T*) {}
};
void top(const T v[ROWS]) {
    units<0>::run(WORK, v);
}
"""


def test_a_row_of_a_partitioned_global_through_a_struct_recursion_is_one_bank():
    """``units<U>::run`` passes row U of WORK (partitioned in its first dimension: a bank a
    row) to ``update<U>``: its parameter is that one bank, two ports. Three accesses an
    iteration (``bank[r + 1]`` read beside ``bank[r]``) need II 2; the reader before read
    ``bank`` as a local and judged nothing. The same word read twice in one statement is one
    load (the front end merges them): II 1."""
    (loop,) = {r.line: r for r in read_project(
        [("u.cpp", UNITS.replace("%EXTRA%", "bank[(r + 1) % ROWS]"))], ADD_LATENCY)}.values()
    assert loop.accesses == (("WORK[]", 3, 1),) and loop.ii_ports == 2
    assert [i.rule for i in check([loop])] == ["ii_ports"]
    (loop,) = {r.line: r for r in read_project(
        [("u.cpp", UNITS.replace("%EXTRA%", "bank[r]"))], ADD_LATENCY)}.values()
    assert loop.accesses == (("WORK[]", 2, 1),) and check([loop]) == []


KERNEL = """
typedef float T;
namespace {
T factor(const T x[8]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fmul limit=%LIMIT%
    return x[0] * x[1] * x[2] * x[3] * x[4] * x[5] * x[6] * x[7];
}
}
void %NAME%_top(const T xs[16][8], T ys[16]) {
    for (int i = 0; i < 16; ++i) {
#pragma HLS PIPELINE II=%II%
        ys[i] = factor(xs[i]);
    }
}
"""


def test_each_kernel_reads_its_own_callees_allocation():
    """Two kernels of one design (the on-chip stream design's window and batch kernels) each
    define their own ``factor`` under their own ALLOCATION: a kernel's loop is judged by its
    own (7 multiplies through 4 at II 2 passes; through 1 at II 2 does not)."""
    def kernel(name, limit, ii):
        return (f"{name}.cpp", KERNEL.replace("%NAME%", name).replace("%LIMIT%", str(limit))
                .replace("%II%", str(ii)))

    readings = read_project([kernel("batch", 1, 7), kernel("window", 4, 2)], ADD_LATENCY)
    by_file = {r.file: r for r in readings}
    assert by_file["window.cpp"].ii_allocation == 2 and by_file["batch.cpp"].ii_allocation == 7
    assert check(readings) == []
    readings = read_project([kernel("batch", 4, 2), kernel("window", 1, 2)], ADD_LATENCY)
    (issue,) = check(readings)
    assert issue.file == "window.cpp" and "II >= 7" in issue.message


def test_a_row_of_a_global_also_partitioned_cyclic_in_its_rows_is_that_many_banks():
    """fgc_qr.h's next pivot column two rows a cycle: ``WORK`` partitioned complete in its
    first dimension and cyclic factor 2 in its rows, so row U (``work[U]``) is two memories,
    four ports: rows 2r and 2r + 1 read and written in one iteration fit II 1. Without the
    cyclic partition the same loop's four accesses need II 2 from one bank's two ports."""
    pairs = UNITS.replace("bank[r] = bank[r] * v[r] + %EXTRA%;",
                          "bank[2 * r] = bank[2 * r] * v[r];\n"
                          "        bank[2 * r + 1] = bank[2 * r + 1] * v[r];").replace(
        "r < ROWS; ++r", "r < ROWS / 2; ++r")
    (loop,) = read_project([("u.cpp", pairs)], ADD_LATENCY)
    assert loop.accesses == (("WORK[]", 4, 1),) and loop.ii_ports == 2
    assert [i.rule for i in check([loop])] == ["ii_ports"]
    two = pairs.replace("complete dim=1\n", "complete dim=1\n"
                        "#pragma HLS ARRAY_PARTITION variable=WORK cyclic factor=2 dim=2\n")
    (loop,) = read_project([("u.cpp", two)], ADD_LATENCY)
    assert loop.accesses == (("WORK[]", 4, 2),) and loop.ii_ports == 1
    assert check([loop]) == []
