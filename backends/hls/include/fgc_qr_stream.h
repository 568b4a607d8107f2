// fgc_qr_stream.h: the streaming QR unit set (--qr-unit stream): one elimination step's frontal
// matrix factored by Householder reflections in a systolic chain of N_UNITS reflection stages,
// the matrix streamed through them column by column. The interface is fgc_qr.h's qr_step
// (qrs_step<CFG>: the same banks, arguments and outputs), so the kernel stacks and commits as
// for the paper's unit.
//
// ---- structure -------------------------------------------------------------------------------
//
// A pass takes reflections j0 ... j0 + N_UNITS - 1 (fewer in the last pass), one DATAFLOW region
// (qrs_pass) of free-running processes linked by streams, no stream going back:
//
//   qrs_source        columns j0 ... w of the banks, rows j0 ... rows - 1, column after column
//                     (one word a cycle) into stage 0;
//   qrs_eval<t>       stage t, reflection j = j0 + t: receives column j (its squared norm in
//                     PARTIALS interleaved partial sums as it arrives, the vector below the
//                     pivot on to the dot process and the tail), then alpha, v_0 and tau;
//   qrs_dot<t>        takes each later column's dot product v.x below the pivot as the column
//                     arrives (column j + 1's while the Evaluate still computes: the look-ahead)
//                     and forwards the column to the tail;
//   qrs_fold<t>       adds the pivot's term v_0 x_j, folds the partials, scales by tau;
//   qrs_tail<t>       applies the reflection to each column (x -= (tau v.x) v), the entry in
//                     row j (final: row j of R) to the collector, rows j + 1 ... to stage t + 1
//                     (column j + 1 to its Evaluate, the others to its dot process);
//   qrs_sink          what leaves the last stage (columns and rows from j0 + N_UNITS on) into
//                     the next pass's banks (copied back after the region);
//   qrs_collect       rows j0 ... of R (R_jj from the Evaluates, the rest from the tails) into
//                     cond or update, and the running scale.
//
// Stage t + 1 evaluates reflection j + 1 as soon as the first column leaves stage t, while
// stage t still updates the later columns: the Evaluate of reflection j + 1 overlaps the Update
// of reflection j, and no region drains between reflections of a pass. Every reflection touches
// rows j ... rows - 1 of its columns (structural zeros included: the stream has no row index).
//
// ---- arithmetic ------------------------------------------------------------------------------
//
// fgc_qr.h's: norm2 = x.x, alpha = -sign(x_0) sqrt(norm2), v_0 = x_0 - alpha, v_a = x_a below
// the pivot, tau = 1 / (norm2 - alpha x_0), x -= (tau v.x) v; a column whose norm2 is not above 0
// (all zero, or squares underflowing) is no reflection (tau = 0, R_jj = 0). A one-row reflection
// is the pivot row's negation to rounding (fgc_qr.h takes it exactly).
//
// ---- cycles ----------------------------------------------------------------------------------
//
// Every loop reports trip, II and depth to FGC_CYCLES; a loop that reads a stream another
// process's loop writes waits for it (FGC_WAIT), per column: loop names carry their column
// ("dot@7"). backends/hls/units/qr_stream.py prices the same loops (tests/hls/
// test_units_qr_stream.py holds the count to the price).
#ifndef FGC_QR_STREAM_H
#define FGC_QR_STREAM_H

#include <cmath>

#include "fgc_cycles.h"
#include "fgc_qr.h"
#include "hls_stream.h"

#ifdef FGC_COUNT_CYCLES
#include <cstdio>
#define QRS_CYCLES(process, instance, stem, index, trip, ii, depth)              \
    do {                                                                         \
        char qrs_name_[32];                                                      \
        std::snprintf(qrs_name_, sizeof qrs_name_, "%s@%d", stem, index);        \
        FGC_CYCLES(process, instance, qrs_name_, trip, ii, depth);               \
    } while (0)
#define QRS_WAIT(process, instance, on_process, on_instance, stem, index)        \
    do {                                                                         \
        char qrs_name_[32];                                                      \
        std::snprintf(qrs_name_, sizeof qrs_name_, "%s@%d", stem, index);        \
        FGC_WAIT(process, instance, on_process, on_instance, qrs_name_);         \
    } while (0)
#else
#define QRS_CYCLES(process, instance, stem, index, trip, ii, depth) ((void)0)
#define QRS_WAIT(process, instance, on_process, on_instance, stem, index) ((void)0)
#endif

namespace fgc_units {

// Columns j0 ... cols - 1, rows j0 ... rows - 1 of the banks into stage 0, one column a loop
// (column j0 to its Evaluate, the others to its dot process): trip rows - j0, II 1, depth 2.
template <class CFG>
void qrs_source(int j0, int rows, int cols,
                const typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                hls::stream<typename CFG::T>& first, hls::stream<typename CFG::T>& rest) {
    for (int c = j0; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
        for (int i = j0; i < rows; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
            const typename CFG::T x = work[c % CFG::N_UNITS][i][c / CFG::N_UNITS];
            if (c == j0) {
                first.write(x);
            } else {
                rest.write(x);
            }
        }
        QRS_CYCLES("qrs_source", 0, "src", c, rows - j0, 1, 2);
    }
}

// The Evaluate of stage U, reflection j: column j as it arrives (stage 0 from the source, stage
// U from the tail of stage U - 1), the words below the pivot to the dot process and the tail (v_a
// = x_a), the squares into PARTIALS interleaved partial sums; then alpha, v_0 and tau: v_0 and
// tau to the dot process, v_0 to the tail, R_jj = alpha to the collector.
template <class CFG, int U>
void qrs_eval(int j, int n, int rows, hls::stream<typename CFG::T>& in,
              hls::stream<typename CFG::T>& vd, hls::stream<typename CFG::T>& vt,
              hls::stream<typename CFG::T>& eq, hls::stream<typename CFG::T>& rq) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    static_assert(CFG::PARTIALS >= CFG::ADD_LAT, "PARTIALS >= ADD_LAT: the loops run at II 1");
    enum { DIST = CFG::PARTIALS };  // pragma constants: enums
    if (U >= n) return;  // past the pass's last reflection
    const int m = rows - j;
    T part[P];
#pragma HLS ARRAY_PARTITION variable=part complete
    for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
        part[t] = T(0);
    }
    T x0 = T(0);
    // trip m, II 1, depth Lm + La (a partial is met again P >= La iterations later)
    QRS_WAIT("qrs_eval", U, U == 0 ? "qrs_source" : "qrs_tail", U == 0 ? 0 : U - 1,
             U == 0 ? "src" : "axpy", j);
    for (int a = 0; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=DIST
        const T x = in.read();
        if (a == 0) {
            x0 = x;
        } else {
            vd.write(x);
            vt.write(x);
        }
        part[a % P] += x * x;
    }
    QRS_CYCLES("qrs_eval", U, "receive", j, m, 1, CFG::MUL_LAT + CFG::ADD_LAT);
    // fold, square root, v_0 beside alpha x_0, subtract, divide
    const T norm2 = fold_partials<T, P>(part);
    T alpha = T(0), v0 = T(0), tau = T(0);
    if (norm2 > T(0)) {
        const T norm = std::sqrt(norm2);
        alpha = x0 >= T(0) ? T(-norm) : norm;
        v0 = x0 - alpha;
        tau = T(1) / (norm2 - alpha * x0);
    }
    eq.write(v0);
    eq.write(tau);
    vt.write(v0);
    rq.write(alpha);
    FGC_CYCLES("qrs_eval", U, "evaluate", 1, 1,
               CFG::ADD_LAT * ceil_log2(P) + CFG::SQRT_LAT +
                   (CFG::ADD_LAT > CFG::MUL_LAT ? CFG::ADD_LAT : CFG::MUL_LAT) + CFG::ADD_LAT +
                   CFG::DIV_LAT);
}

// The dot process of stage U: each later column as it arrives, forwarded to the tail, v.x below
// the pivot in P partial sums (the first later column's while the Evaluate still computes v_0 and
// tau: the look-ahead), the partials and the column's pivot-row entry to the fold.
template <class CFG, int U>
void qrs_dot(int j, int n, int rows, int cols, hls::stream<typename CFG::T>& in,
             hls::stream<typename CFG::T>& vd, hls::stream<typename CFG::T>& pq,
             hls::stream<typename CFG::T>& xq) {
    typedef typename CFG::T T;
    if (U >= n) return;  // past the pass's last reflection
    const int P = CFG::PARTIALS;
    enum { DIST = CFG::PARTIALS };  // pragma constants: enums
    const int m = rows - j;
    T v[CFG::MAX_ROWS];
    // the vector below the pivot as the Evaluate receives it: trip m - 1, II 1, depth 1
    FGC_WAIT("qrs_dot", U, "qrs_eval", U, "receive");
    for (int a = 1; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
        v[a] = vd.read();
    }
    QRS_CYCLES("qrs_dot", U, "vector", j, m - 1, 1, 1);
    for (int c = j + 1; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
        T part[P];
#pragma HLS ARRAY_PARTITION variable=part complete
        for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
            part[t] = T(0);
        }
        T xj = T(0);
        // trip m, II 1, depth Lm + La
        QRS_WAIT("qrs_dot", U, U == 0 ? "qrs_source" : "qrs_tail", U == 0 ? 0 : U - 1,
                 U == 0 ? "src" : "axpy", c);
        for (int a = 0; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=DIST
            const T x = in.read();
            xq.write(x);
            if (a == 0) {
                xj = x;
            } else {
                part[a % P] += v[a] * x;
            }
        }
        QRS_CYCLES("qrs_dot", U, "dot", c, m, 1, CFG::MUL_LAT + CFG::ADD_LAT);
        // the partials, then x_j, to the fold: trip P + 1, II 1, depth 1
        for (int t = 0; t <= P; ++t) {
#pragma HLS PIPELINE II=1
            pq.write(t < P ? part[t] : xj);
        }
        QRS_CYCLES("qrs_dot", U, "send", c, P + 1, 1, 1);
    }
}

// The fold of stage U, per later column: the pivot's term v_0 x_j as one more leaf of the P
// partials' tree, the scale by tau; tau v.x to the tail. Not pipelined (a column every
// Lm + La ceil(log2 (P + 1)) + Lm cycles, under the dot's m + Lm + La).
template <class CFG, int U>
void qrs_fold(int j, int n, int cols, hls::stream<typename CFG::T>& pq,
              hls::stream<typename CFG::T>& eq, hls::stream<typename CFG::T>& sq) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    if (U >= n) return;  // past the pass's last reflection
    const T v0 = eq.read();
    const T tau = eq.read();
    for (int c = j + 1; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
        T leaves[P + 1];
#pragma HLS ARRAY_PARTITION variable=leaves complete
        // the partials and x_j as the dot process sends them: trip P + 1, II 1, depth 1
        QRS_WAIT("qrs_fold", U, "qrs_dot", U, "send", c);
        for (int t = 0; t <= P; ++t) {
#pragma HLS PIPELINE II=1
            leaves[t] = pq.read();
        }
        QRS_CYCLES("qrs_fold", U, "gather", c, P + 1, 1, 1);
        leaves[P] = v0 * leaves[P];
        sq.write(tau * fold_partials<T, P + 1>(leaves));
        FGC_WAIT("qrs_fold", U, "qrs_eval", U, "evaluate");
        QRS_CYCLES("qrs_fold", U, "fold", c, 1, 1,
                   CFG::MUL_LAT + CFG::ADD_LAT * ceil_log2(P + 1) + CFG::MUL_LAT);
    }
}

// The tail of stage U: reflection j applied to each later column; row j's entry to the
// collector, rows j + 1 ... to the next stage (column j + 1 to its Evaluate, the others to its
// dot process) or the sink.
template <class CFG, int U>
void qrs_tail(int j, int n, int rows, int cols, hls::stream<typename CFG::T>& xq,
              hls::stream<typename CFG::T>& vt, hls::stream<typename CFG::T>& sq,
              hls::stream<typename CFG::T>& first, hls::stream<typename CFG::T>& rest,
              hls::stream<typename CFG::T>& rowq) {
    typedef typename CFG::T T;
    if (U >= n) return;  // past the pass's last reflection
    const int m = rows - j;
    T v[CFG::MAX_ROWS];
    // the vector: the words below the pivot, then v_0 (after the Evaluate's end):
    // trip m, II 1, depth 1
    FGC_WAIT("qrs_tail", U, "qrs_eval", U, "evaluate");
    for (int a = 0; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
        v[a + 1 < m ? a + 1 : 0] = vt.read();
    }
    FGC_CYCLES("qrs_tail", U, "vector", m, 1, 1);
    for (int c = j + 1; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
        // tau v.x from the fold: every update of the column waits for it (1 cycle after)
        const T s = sq.read();
        QRS_WAIT("qrs_tail", U, "qrs_fold", U, "fold", c);
        QRS_CYCLES("qrs_tail", U, "scale", c, 1, 1, 1);
        // x -= s v: trip m, II 1, depth Lm + La
        for (int a = 0; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
            const T y = xq.read() - s * v[a];
            if (a == 0) {
                rowq.write(y);
            } else if (c == j + 1) {
                first.write(y);
            } else {
                rest.write(y);
            }
        }
        QRS_CYCLES("qrs_tail", U, "axpy", c, m, 1, CFG::MUL_LAT + CFG::ADD_LAT);
    }
}

// What leaves the last stage into the next pass's banks: column j1 (its first stream), then the
// others: trip rows - j1, then (cols - j1 - 1)(rows - j1), II 1, depth 2.
template <class CFG>
void qrs_sink(int j1, int rows, int cols, int k, hls::stream<typename CFG::T>& first,
              hls::stream<typename CFG::T>& rest,
              typename CFG::T qrs_next[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS]) {
    if (j1 >= k) return;
    QRS_WAIT("qrs_sink", 0, "qrs_tail", CFG::N_UNITS - 1, "axpy", j1);
    for (int i = j1; i < rows; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
        qrs_next[j1 % CFG::N_UNITS][i][j1 / CFG::N_UNITS] = first.read();
    }
    FGC_CYCLES("qrs_sink", 0, "sink_first", rows - j1, 1, 2);
    QRS_WAIT("qrs_sink", 0, "qrs_tail", CFG::N_UNITS - 1, "axpy", cols - 1);
    for (int c = j1 + 1, i = j1; c < cols;) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS * CFG::MAX_COLS
#pragma HLS PIPELINE II=1
        qrs_next[c % CFG::N_UNITS][i][c / CFG::N_UNITS] = rest.read();
        if (i == rows - 1) {
            i = j1;
            ++c;
        } else {
            ++i;
        }
    }
    FGC_CYCLES("qrs_sink", 0, "sink", (cols - j1 - 1) * (rows - j1), 1, 2);
}

// Rows j0 ... j0 + n - 1 of R: R_jj from the head, the rest from the tail, into cond (j < f) or
// update (f <= j < f + nf), their largest magnitude into the running scale. Per row: trip
// w + 1 - first, II 1, depth 2 (read, compare).
template <class CFG>
void qrs_collect(int j0, int n, int rows, int f, int s,
                 hls::stream<typename CFG::T> diag_in[CFG::N_UNITS],
                 hls::stream<typename CFG::T> row_in[CFG::N_UNITS],
                 typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
                 typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], typename CFG::T* scale) {
    typedef typename CFG::T T;
    const int w = f + s, cols = w + 1;
    const int last = rows < w ? rows : w;
    const int nf = last - f > 0 ? last - f : 0;
    T big = *scale;
    for (int t = 0; t < n; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::N_UNITS
        const int j = j0 + t;
        const int first = j < f ? 0 : f;
        T diag = T(0);
        for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
            if (u == t) diag = diag_in[u].read();
        }
        if (j + 1 < cols) {
            QRS_WAIT("qrs_collect", 0, "qrs_tail", t, "axpy", cols - 1);
        } else {
            FGC_WAIT("qrs_collect", 0, "qrs_tail", t, "vector");
        }
        for (int c = first; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
#pragma HLS PIPELINE II=1
            T x = T(0);
            if (c == j) {
                x = diag;
            } else if (c > j) {
                for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
                    if (u == t) x = row_in[u].read();
                }
            }
            if (j < f) {
                cond[j * cols + c] = x;
            } else if (j - f < nf) {
                update[(j - f) * (s + 1) + (c - f)] = x;
            }
            const T mag = qr_abs(x);
            big = mag > big ? mag : big;
        }
        QRS_CYCLES("qrs_collect", 0, "row", j, cols - first, 1, 2);
    }
    *scale = big;
}

// The N_UNITS stages, U = 0 ... N_UNITS - 1, as separate calls in the region; a stage past the
// pass's last reflection does nothing.
template <class CFG, int U, bool END = (U == CFG::N_UNITS)>
struct qrs_stages {
    typedef hls::stream<typename CFG::T> S;
    static void run(int j0, int n, int rows, int cols, S first[], S rest[], S vd[], S vt[],
                    S eq[], S pq[], S xq[], S sq[], S rq[], S rowq[]) {
#pragma HLS INLINE
        qrs_eval<CFG, U>(j0 + U, n, rows, first[U], vd[U], vt[U], eq[U], rq[U]);
        qrs_dot<CFG, U>(j0 + U, n, rows, cols, rest[U], vd[U], pq[U], xq[U]);
        qrs_fold<CFG, U>(j0 + U, n, cols, pq[U], eq[U], sq[U]);
        qrs_tail<CFG, U>(j0 + U, n, rows, cols, xq[U], vt[U], sq[U], first[U + 1], rest[U + 1],
                         rowq[U]);
        qrs_stages<CFG, U + 1>::run(j0, n, rows, cols, first, rest, vd, vt, eq, pq, xq, sq, rq,
                                    rowq);
    }
};

template <class CFG, int U>
struct qrs_stages<CFG, U, true> {
    typedef hls::stream<typename CFG::T> S;
    static void run(int, int, int, int, S*, S*, S*, S*, S*, S*, S*, S*, S*, S*) {
#pragma HLS INLINE
    }
};

// One pass: reflections j0 ... j0 + n - 1 (n <= N_UNITS), one DATAFLOW region.
template <class CFG>
void qrs_pass(int j0, int n, int rows, int f, int s, int k,
              const typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
              typename CFG::T qrs_next[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
              typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
              typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], typename CFG::T* scale) {
#pragma HLS DATAFLOW
    enum { COL_DEPTH = 2 * CFG::MAX_ROWS };  // a column and the fold behind it
    enum { REST_DEPTH = 3 * CFG::MAX_ROWS };  // the columns behind the first, while it evaluates
    enum { P_DEPTH = 2 * (CFG::PARTIALS + 1) };  // two columns' partials and pivot-row entries
    hls::stream<typename CFG::T> first[CFG::N_UNITS + 1];
#pragma HLS STREAM variable=first depth=COL_DEPTH
    hls::stream<typename CFG::T> rest[CFG::N_UNITS + 1];
#pragma HLS STREAM variable=rest depth=REST_DEPTH
    hls::stream<typename CFG::T> vd[CFG::N_UNITS];
#pragma HLS STREAM variable=vd depth=CFG::MAX_ROWS
    hls::stream<typename CFG::T> vt[CFG::N_UNITS];
#pragma HLS STREAM variable=vt depth=CFG::MAX_ROWS
    hls::stream<typename CFG::T> eq[CFG::N_UNITS];
#pragma HLS STREAM variable=eq depth=2
    hls::stream<typename CFG::T> pq[CFG::N_UNITS];
#pragma HLS STREAM variable=pq depth=P_DEPTH
    hls::stream<typename CFG::T> xq[CFG::N_UNITS];
#pragma HLS STREAM variable=xq depth=COL_DEPTH
    hls::stream<typename CFG::T> sq[CFG::N_UNITS];
#pragma HLS STREAM variable=sq depth=2
    hls::stream<typename CFG::T> rq[CFG::N_UNITS];
#pragma HLS STREAM variable=rq depth=2
    hls::stream<typename CFG::T> rowq[CFG::N_UNITS];
#pragma HLS STREAM variable=rowq depth=CFG::MAX_COLS
    FGC_REGION("qrs_pass");
    qrs_source<CFG>(j0, rows, f + s + 1, work, first[0], rest[0]);
    qrs_stages<CFG, 0>::run(j0, n, rows, f + s + 1, first, rest, vd, vt, eq, pq, xq, sq, rq,
                            rowq);
    qrs_sink<CFG>(j0 + n, rows, f + s + 1, k, first[CFG::N_UNITS], rest[CFG::N_UNITS], qrs_next);
    qrs_collect<CFG>(j0, n, rows, f, s, rq, rowq, cond, update, scale);
    FGC_DRAINED(first, CFG::N_UNITS + 1);  // csim only (fgc_cycles.h)
    FGC_DRAINED(rest, CFG::N_UNITS + 1);
    FGC_DRAINED(vd, CFG::N_UNITS);
    FGC_DRAINED(vt, CFG::N_UNITS);
    FGC_DRAINED(eq, CFG::N_UNITS);
    FGC_DRAINED(pq, CFG::N_UNITS);
    FGC_DRAINED(xq, CFG::N_UNITS);
    FGC_DRAINED(sq, CFG::N_UNITS);
    FGC_DRAINED(rq, CFG::N_UNITS);
    FGC_DRAINED(rowq, CFG::N_UNITS);
}

// ---- the step ---------------------------------------------------------------------------------

template <class CFG>
void qrs_step(typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS], int rows,
              int f, int s, typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
              typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], bool* singular) {
#pragma HLS ARRAY_PARTITION variable=work complete dim=1
    typedef typename CFG::T T;
    const int cols = f + s + 1;
    if (rows < 0 || f < 0 || s < 0 || rows > CFG::MAX_ROWS || cols > CFG::MAX_COLS ||
        f > CFG::MAX_F) {
        *singular = true;  // outside the configuration: nothing is computed
        return;
    }
    const int k = rows < cols ? rows : cols;
    T next[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS];
#pragma HLS ARRAY_PARTITION variable=next complete dim=1
    T scale = T(0);
    enum { MAX_PASSES = CFG::MAX_COLS };
    for (int j0 = 0; j0 < k; j0 += CFG::N_UNITS) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_PASSES
        const int n = k - j0 < CFG::N_UNITS ? k - j0 : CFG::N_UNITS;
        qrs_pass<CFG>(j0, n, rows, f, s, k, work, next, cond, update, &scale);
        FGC_SEQUENTIAL();
        const int j1 = j0 + n;
        if (j1 < k) {
            // what is left back into the banks, N_UNITS words a cycle:
            // trip (rows - j1) LOCAL_COLS, II 1, depth 2
            for (int e = 0, i = j1, l = 0; e < (rows - j1) * CFG::LOCAL_COLS; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS * CFG::LOCAL_COLS
#pragma HLS PIPELINE II=1
                for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
                    const int c = l * CFG::N_UNITS + u;
                    if (c >= j1 && c < cols) work[u][i][l] = next[u][i][l];
                }
                if (l == CFG::LOCAL_COLS - 1) {
                    l = 0;
                    ++i;
                } else {
                    ++l;
                }
            }
            FGC_CYCLES("qrs_step", 0, "copy", (rows - j1) * CFG::LOCAL_COLS, 1, 2);
        }
    }
    *singular = qr_pivot_check<CFG>(cond, f, cols, k, scale);  // fgc_qr.h
}

}  // namespace fgc_units

#endif  // FGC_QR_STREAM_H
