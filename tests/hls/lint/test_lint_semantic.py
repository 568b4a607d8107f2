"""The semantic HLS lint (fgc_backends.hls.lint.semantic_issues, backends/hls/lint/semantic.py):
one small synthetic C++ snippet per rule that breaks it, and its corrected version that
passes."""

from __future__ import annotations

import pytest

from fgc_backends.hls.lint import SEMANTIC_RULES, semantic_issues

PRODUCER_CONSUMER = """
#include <hls_stream.h>
constexpr int N = 8;
typedef float T;
void produce(const T in[N], hls::stream<T>& out) {
    for (int i = 0; i < N; ++i) out.write(in[i]);
}
void consume(hls::stream<T>& in, T out[N]) {
    for (int i = 0; i < N; ++i) out[i] = in.read();
}
void scale(hls::stream<T>& in, hls::stream<T>& out) {
    for (int i = 0; i < N; ++i) out.write(T(2) * in.read());
}
"""


# rule -> (bad, good): the bad snippet breaks exactly that rule, the good one is its correction
CASES = {
    "dataflow": (PRODUCER_CONSUMER + """
bool check(hls::stream<T>& in) { return in.read() > T(0); }
void top(const T in[N], T out[N], int mode) {
#pragma HLS DATAFLOW
    hls::stream<T> s;
    produce(in, s);
    if (mode) consume(s, out);
}
""", PRODUCER_CONSUMER + """
void top(const T in[N], T out[N]) {
#pragma HLS DATAFLOW
    hls::stream<T> s;
    produce(in, s);
    consume(s, out);
}
"""),
    "channel": (PRODUCER_CONSUMER + """
void top(const T in[N], T out[N]) {
#pragma HLS DATAFLOW
    hls::stream<T> s;
    hls::stream<T> t;
    produce(in, s);
    scale(s, t);
    consume(s, out);
}
""", PRODUCER_CONSUMER + """
void top(const T in[N], T out[N]) {
#pragma HLS DATAFLOW
    hls::stream<T> s;
    hls::stream<T> t;
    produce(in, s);
    scale(s, t);
    consume(t, out);
}
"""),
    "pointer": ("""
constexpr int N = 4;
const float A[N] = {1, 2, 3, 4};
const float B[N] = {4, 3, 2, 1};
float pick(int which, int i) {
    const float* table = A;
    if (which) table = B;
    return table[i];
}
""", """
constexpr int N = 4;
const float A[N] = {1, 2, 3, 4};
const float B[N] = {4, 3, 2, 1};
float pick(int which, int i) {
    const float* table = A;
    const float a = table[i];
    return which ? B[i] : a;
}
"""),
    "function_pointer": ("""
typedef float T;
inline T twice(T x) { return T(2) * x; }
template <T (*F)(T)>
T apply(T x) { return F(x); }
T run(T x) { return apply<twice>(x); }
""", """
typedef float T;
inline T twice(T x) { return T(2) * x; }
T run(T x) { return twice(x); }
"""),
    "partition": ("""
constexpr int W = 32;
void f(float a[W][W]) {
#pragma HLS ARRAY_PARTITION variable=a cyclic factor=80 dim=2
    for (int i = 0; i < W; ++i) a[i][0] = 0;
}
""", """
constexpr int W = 32;
void f(float a[W][W]) {
#pragma HLS ARRAY_PARTITION variable=a cyclic factor=16 dim=2
    for (int i = 0; i < W; ++i) a[i][0] = 0;
}
"""),
    "pipeline": ("""
constexpr int N = 16;
void f(float a[N][N], float out[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        float s = 0;
        for (int j = 0; j < i; ++j) s += a[i][j];
        out[i] = s;
    }
}
""", """
constexpr int N = 16;
void f(float a[N][N], float out[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        float s = 0;
        for (int j = 0; j < N; ++j) s += j < i ? a[i][j] : 0.0f;
        out[i] = s;
    }
}
"""),
    "dsp": ("""
void f(const float a[8], float out[8]) {
#pragma HLS ALLOCATION operation instances=fmul limit=250
#pragma HLS ALLOCATION operation instances=fadd limit=100
    for (int i = 0; i < 8; ++i) out[i] = a[i] * a[i] + a[i];
}
""", """
void f(const float a[8], float out[8]) {
#pragma HLS ALLOCATION operation instances=fmul limit=200
#pragma HLS ALLOCATION operation instances=fadd limit=100
    for (int i = 0; i < 8; ++i) out[i] = a[i] * a[i] + a[i];
}
"""),
    "synthesis_macro": ("""
float f(float x) {
#ifndef __SYNTHESIS__
    return x + 1;
#else
    return x;
#endif
}
""", """
float f(float x) { return x; }  // __SYNTHESIS__ in a comment is not code
"""),
}


def _rules(text: str) -> set[str]:
    return {i.rule for i in semantic_issues([("k.cpp", text)], part="xc7z045ffg900-2",
                                            scalar="float")}


def test_every_semantic_rule_has_a_case():
    assert set(CASES) == set(SEMANTIC_RULES)


@pytest.mark.parametrize("rule", sorted(CASES))
def test_rule_fails_on_the_bad_snippet_and_passes_the_corrected_one(rule):
    bad, good = CASES[rule]
    assert _rules(bad) == {rule}
    assert _rules(good) == set()


def test_issues_name_file_line_and_the_offender():
    bad = CASES["channel"][0]
    [issue] = semantic_issues([("k.cpp", bad)])
    assert issue.file == "k.cpp" and issue.rule == "channel"
    assert issue.line == bad[:bad.index("#pragma HLS DATAFLOW")].count("\n") + 1
    assert "'s' is read by 2 processes" in issue.message
    assert "scale (line" in issue.message and "consume (line" in issue.message
    [dsp] = semantic_issues([("k.cpp", CASES["dsp"][0])], part="xc7z045ffg900-2", scalar="float")
    assert "imply 950 DSP (fmul 250x3, fadd 100x2)" in dsp.message and "900" in dsp.message
    pointer = semantic_issues([("k.cpp", CASES["pointer"][0])])
    assert [i.message for i in pointer] == [
        "pointer 'table' in 'pick' is reassigned (HLS needs each pointer bound to one object)"]


def test_more_dataflow_and_pointer_violations():
    returns = PRODUCER_CONSUMER + """
bool count(hls::stream<T>& in, T out[N]) { consume(in, out); return true; }
void top(const T in[N], T out[N]) {
#pragma HLS DATAFLOW
    hls::stream<T> s;
    bool ok;
    produce(in, s);
    ok = count(s, out);
}
"""
    messages = [i.message for i in semantic_issues([("k.cpp", returns)])]
    assert any("uses a process's return value" in m for m in messages)
    assert any("process 'count' returns 'bool'" in m for m in messages)
    looped = PRODUCER_CONSUMER + """
void top(const T in[N], T out[N], int n) {
#pragma HLS DATAFLOW
    hls::stream<T> s[2];
    for (int u = 0; u < n; ++u) produce(in, s[u]);
}
"""
    assert "not a fully unrolled constant-bound loop" in str(semantic_issues([("k", looped)]))
    unrolled = PRODUCER_CONSUMER + """
void top(const T in[N], T out[2][N]) {
#pragma HLS DATAFLOW
    hls::stream<T> s[2];
    for (int u = 0; u < 2; ++u) {
#pragma HLS UNROLL
        scale_in(in, s[u]);
    }
}
void scale_in(const T in[N], hls::stream<T>& out) { produce(in, out); }
"""
    # 2 processes read `in` (one per unrolled copy): an input read twice is two consumers
    issues = semantic_issues([("k", unrolled)])
    assert [i.rule for i in issues] == ["channel"] and "'in' is read by 2" in issues[0].message
    returned = "const float* row(const float* a, int i) { return a + 4 * i; }\n"
    assert "returns a pointer" in str(semantic_issues([("k", returned)]))
    walked = "float sum(const float* a) { float s = 0; for (int i = 0; i < 4; ++i) " \
             "{ s += *a; ++a; } return s; }\n"
    assert "pointer 'a' in 'sum' is reassigned" in str(semantic_issues([("k", walked)]))
    # writing through a pointer or indexing it is not reassigning it
    through = "void set(float* a) { *a = 1; a[1] = 2; const float* b = a; (void)b; }\n"
    assert semantic_issues([("k", through)]) == []


def test_partition_resolves_constants_across_files():
    header = "#define MAX_W 32\nconstexpr int TILE = MAX_W / 4;\n"
    source = """
void f(float w[TILE][MAX_W]) {
#pragma HLS ARRAY_PARTITION variable=w cyclic factor=16 dim=1
#pragma HLS ARRAY_PARTITION variable=w cyclic factor=16 dim=2
}
"""
    [issue] = semantic_issues([("k.h", header), ("k.cpp", source)])
    assert issue.file == "k.cpp" and issue.line == 3
    assert "factor 16 exceeds dimension 1 of size 8 ('TILE')" in issue.message


def test_a_global_array_shared_by_two_processes_is_a_channel_with_two_writers():
    shared = """
constexpr int N = 8;
float BUF[N];
const float TABLE[N] = {0};
void fill(const float in[N]) { for (int i = 0; i < N; ++i) BUF[i] = in[i] + TABLE[i]; }
void clear() { for (int i = 0; i < N; ++i) BUF[i] = 0; }
void top(const float a[N], const float b[N]) {
#pragma HLS DATAFLOW
    fill(a);
    clear();
}
"""
    [issue] = semantic_issues([("k.cpp", shared)])
    assert issue.rule == "channel" and "'BUF' is written by 2 processes" in issue.message
    assert "global" in issue.message  # the const TABLE read by one is no channel issue
    fixed = shared.replace("    clear();\n", "")
    assert semantic_issues([("k.cpp", fixed)]) == []


def test_a_global_reached_through_shared_helpers_and_a_call_cycle():
    """The walk of the functions a process reaches is memoised per function (semantic.py's
    _global_uses): a helper reached again (put, get_into) gives its uses from the memo, and a
    walk a cycle cut short (pong inside ping) is not reused: third reaches put through pong →
    ping, which first's walk had cut. Findings as the plain walk gives them."""
    shared = """
constexpr int N = 8;
float BUF[N];
void put(int i, float v) { BUF[i] = v; }
void get_into(float o[N]) { for (int i = 0; i < N; ++i) o[i] = BUF[i]; }
void ping(int k, float o[N]);
void pong(int k, float o[N]) { if (k) ping(k - 1, o); else get_into(o); }
void ping(int k, float o[N]) { put(k, 1); pong(k, o); }
void first(float o[N]) { ping(3, o); }
void second(float o[N]) { put(0, 2); get_into(o); }
void third(float o[N]) { pong(1, o); }
void top(float a[N], float b[N], float c[N]) {
#pragma HLS DATAFLOW
    first(a);
    second(b);
    third(c);
}
"""
    messages = [i.message for i in semantic_issues([("k.cpp", shared)])]
    assert len(messages) == 3
    for what in ("written", "read"):
        assert any(f"'BUF' is {what} by 3 processes of the DATAFLOW region: first (line 14, "
                   "global), second (line 15, global), third (line 16, global)" in m
                   for m in messages), messages
    assert any("'BUF' is read and written by the same process first" in m for m in messages)
    # without the cycle's way back to put, third only reads: two writers
    acyclic = shared.replace("if (k) ping(k - 1, o); else ", "")
    messages = [i.message for i in semantic_issues([("k.cpp", acyclic)])]
    assert any("'BUF' is written by 2 processes" in m for m in messages), messages


def test_stream_arrays_and_constant_declarations_in_a_dataflow_region():
    units = """
constexpr int N = 8;
constexpr int U = 2;
typedef float T;
void split(const T in[N], hls::stream<T> out[U]) {
    for (int i = 0; i < N; ++i) out[i % U].write(in[i]);
}
void work(hls::stream<T>& in, hls::stream<T>& out) {
    for (int i = 0; i < N / U; ++i) out.write(in.read());
}
void merge(hls::stream<T> in[U], T out[N]) {
    for (int i = 0; i < N; ++i) out[i] = in[i % U].read();
}
void top(const T in[N], T out[N]) {
#pragma HLS DATAFLOW
    const int half = N / 2;
    hls::stream<T> a[U];
    hls::stream<T> b[U];
#pragma HLS STREAM variable=a depth=4
    split(in, a);
    for (int u = 0; u < U; ++u) {
#pragma HLS UNROLL
        work(a[u], b[u]);
    }
    merge(b, out);
}
"""
    assert semantic_issues([("k.cpp", units)]) == []
    # a second reader of the stream array `a` (merge reads it too)
    twice = units.replace("merge(b, out);", "merge(a, out);")
    issues = semantic_issues([("k.cpp", twice)])
    assert [i.rule for i in issues] == ["channel"]
    assert "'a[u]' is read by 2 processes" in issues[0].message and "merge" in issues[0].message
    computed = units.replace("const int half = N / 2;", "const int half = in_size(in);")
    assert "dataflow" in {i.rule for i in semantic_issues([("k.cpp", computed)])}


def test_inlined_unit_recursion_enums_and_macros_in_a_dataflow_region():
    network = """
#define REGION(name) ((void)0)
typedef float T;
constexpr int N = 8;
struct Cfg { enum { UNITS = 2 }; };
void split(const T in[N], hls::stream<T> out[Cfg::UNITS]) {
    for (int i = 0; i < N; ++i) out[i % Cfg::UNITS].write(in[i]);
}
void work(hls::stream<T>& in, hls::stream<T>& out) {
    for (int i = 0; i < N / Cfg::UNITS; ++i) out.write(in.read());
}
void merge(hls::stream<T> in[Cfg::UNITS], T out[N]) {
    for (int i = 0; i < N; ++i) out[i] = in[i % Cfg::UNITS].read();
}
template <class CFG, int U, bool END = (U >= CFG::UNITS)>
struct units {
    static void run(hls::stream<T> a[CFG::UNITS], hls::stream<T> b[CFG::UNITS]) {
#pragma HLS INLINE
        work(a[U], b[U]);
        units<CFG, U + 1>::run(a, b);
    }
};
template <class CFG, int U>
struct units<CFG, U, true> {
    static void run(hls::stream<T>*, hls::stream<T>*) {
#pragma HLS INLINE
    }
};
void top(const T in[N], T out[N]) {
#pragma HLS DATAFLOW
    enum { DEPTH = 4 };
    hls::stream<T> a[Cfg::UNITS];
    hls::stream<T> b[Cfg::UNITS];
#pragma HLS STREAM variable=a depth=DEPTH
    REGION("top");
    split(in, a);
    units<Cfg, 0>::run(a, b);
    merge(b, out);
}
"""
    assert semantic_issues([("k.h", network)]) == []
    issues = semantic_issues([("k.h", network.replace("merge(b, out);", "merge(a, out);"))])
    assert [i.rule for i in issues] == ["channel"]
    assert "'a[U]' is read by 2 processes" in issues[0].message
    assert "work (line 19" in issues[0].message and "merge (line 38" in issues[0].message


FEEDBACK = """
constexpr int N = 8;
typedef float T;
void broadcast(const T v[N], hls::stream<T>& out) {
    for (int i = 0; i < N; ++i) out.write(v[i]);
}
void evaluate(hls::stream<T>& in, T v[N]) {
    for (int i = 0; i < N; ++i) v[i] = T(2) * in.read();
}
"""


def test_a_channel_read_before_it_is_written_is_a_feedback():
    """fgc_qr.h before issue 18's fix: the reflector buffer read by the broadcast and written by
    the Evaluate of the same region, for the next invocation (and fgc_cpe.h's H, read by the feed
    and written back by the drain)."""
    old = FEEDBACK + """
void reflection(T v[N]) {
#pragma HLS DATAFLOW
    hls::stream<T> s;
    broadcast(v, s);
    evaluate(s, v);
}
"""
    [issue] = semantic_issues([("k.h", old)])
    assert issue.rule == "channel"
    assert "'v' is read by broadcast" in issue.message and "before evaluate" in issue.message
    # the fix: two buffers, one only read and one only written, swapped between invocations
    pingpong = FEEDBACK + """
void reflection(const T vin[N], T vout[N]) {
#pragma HLS DATAFLOW
    hls::stream<T> s;
    broadcast(vin, s);
    evaluate(s, vout);
}
void step(T va[N], T vb[N], int n) {
    for (int j = 0; j < n; ++j) {
#pragma HLS LOOP_TRIPCOUNT max=8
        if ((j & 1) == 0) {
            reflection(va, vb);
        } else {
            reflection(vb, va);
        }
    }
}
"""
    assert semantic_issues([("k.h", pingpong)]) == []
    # writer first, reader later: a forward channel, fine
    forward = FEEDBACK + """
void region(hls::stream<T>& in, hls::stream<T>& out) {
#pragma HLS DATAFLOW
    T v[N];
    evaluate(in, v);
    broadcast(v, out);
}
"""
    assert semantic_issues([("k.h", forward)]) == []


def test_a_channel_read_and_written_by_one_process_is_an_issue():
    both = FEEDBACK + """
void accumulate(const T in[N], T acc[N]) {
    for (int i = 0; i < N; ++i) acc[i] += in[i];
}
void region(const T in[N], T acc[N], hls::stream<T>& out) {
#pragma HLS DATAFLOW
    accumulate(in, acc);
    broadcast(acc, out);
}
"""
    issues = semantic_issues([("k.h", both)])
    assert {i.rule for i in issues} == {"channel"}
    assert any("'acc' is read and written by the same process accumulate" in i.message
               for i in issues)
    # a memory only one process reads and writes (an Update unit's bank) is its own, no channel
    own = both.replace("const T in[N], T acc[N], hls::stream<T>& out",
                       "const T in[N], const T other[N], T acc[N], hls::stream<T>& out")
    own = own.replace("    broadcast(acc, out);\n", "    broadcast(other, out);\n")
    assert semantic_issues([("k.h", own)]) == []


FORWARDED = PRODUCER_CONSUMER + """
struct NoX {
    T read() { return T(0); }
    void write(T) {}
};
template <int E, class XIN, class XOUT>
void end(const T in[N], XIN&& xin, XOUT&& xout, T out[N]) {
#pragma HLS INLINE
    for (int i = 0; i < N; ++i) {
        const T x = E == 1 ? xin.read() : in[i];
        if (E == 0) xout.write(x);
        out[i] = x;
    }
}
void end0(const T in[N], hls::stream<T>& x, T out[N]) { end<0>(in, NoX(), x, out); }
void end1(const T in[N], hls::stream<T>& x, T out[N]) { end<1>(in, x, NoX(), out); }
void region(const T in0[N], const T in1[N], T a[N], T b[N]) {
#pragma HLS DATAFLOW
    hls::stream<T> x;
    end0(in0, x, a);
    end1(in1, x, b);
}
"""


def test_a_forwarded_template_parameter_used_as_a_stream_is_a_channel():
    """fgc_backsub.h's backsub_end: an x side given as a forwarded template parameter (``XIN&&``,
    a stream or a value with no storage) is read and written as the stream it is: end 0 writes
    the region's x, end 1 reads it; the same stream on both sides of one end is two readers."""
    assert semantic_issues([("k.h", FORWARDED)]) == []
    both = FORWARDED.replace("end<0>(in, NoX(), x, out)", "end<0>(in, x, x, out)")
    issues = semantic_issues([("k.h", both)])
    assert {i.rule for i in issues} == {"channel"}
    assert any("'x' is read by 2 processes" in i.message for i in issues)
