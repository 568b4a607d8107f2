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
//   qrs_head<t>       stage t, reflection j = j0 + t: receives column j (its squared norm in
//                     PARTIALS interleaved partial sums as it arrives), evaluates alpha, v_0 and
//                     tau (square root, divide), then takes each later column's dot product
//                     v.x as the column arrives, forwards the column to its tail and hands it
//                     tau v.x;
//   qrs_tail<t>       applies the reflection to each column (x -= (tau v.x) v), the entry in
//                     row j (final: row j of R) to the collector, rows j + 1 ... to stage t + 1;
//   qrs_sink          what leaves the last stage (columns and rows from j0 + N_UNITS on) into
//                     the next pass's banks (copied back after the region);
//   qrs_collect       rows j0 ... of R (R_jj from the heads, the rest from the tails) into
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

template <class T>
inline T qrs_abs(T x) {
    return x < T(0) ? T(-x) : x;
}

// Columns j0 ... cols - 1, rows j0 ... rows - 1 of the banks into stage 0, one column a loop:
// trip rows - j0, II 1, depth 2 (read, write).
template <class CFG>
void qrs_source(int j0, int rows, int cols,
                const typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                hls::stream<typename CFG::T>& out) {
    for (int c = j0; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
        for (int i = j0; i < rows; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
            out.write(work[c % CFG::N_UNITS][i][c / CFG::N_UNITS]);
        }
        QRS_CYCLES("qrs_source", 0, "src", c, rows - j0, 1, 2);
    }
}

// The head of stage U: reflection j's Householder vector from column j, then each later column's
// tau v.x (stage 0 reads the source's stream, stage U the tail of stage U - 1).
template <class CFG, int U>
void qrs_head(int j, int rows, int cols, hls::stream<typename CFG::T>& in,
              hls::stream<typename CFG::T>& xq, hls::stream<typename CFG::T>& vq,
              hls::stream<typename CFG::T>& sq, hls::stream<typename CFG::T>& rq) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    static_assert(CFG::PARTIALS >= CFG::ADD_LAT, "PARTIALS >= ADD_LAT: the loops run at II 1");
    enum { DIST = CFG::PARTIALS };  // pragma constants: enums
    const int m = rows - j;
    T v[CFG::MAX_ROWS];
    T part[P];
#pragma HLS ARRAY_PARTITION variable=part complete
    for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
        part[t] = T(0);
    }
    T x0 = T(0);
    // column j as it arrives: the pivot, the vector below it (to the tail), the squares summed
    // into P partials (a partial is met again P >= La iterations later):
    // trip m, II 1, depth Lm + La
    QRS_WAIT("qrs_head", U, U == 0 ? "qrs_source" : "qrs_tail", U == 0 ? 0 : U - 1, "", j);
    for (int a = 0; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=DIST
        const T x = in.read();
        if (a == 0) {
            x0 = x;
        } else {
            v[a] = x;
            vq.write(x);
        }
        part[a % P] += x * x;
    }
    QRS_CYCLES("qrs_head", U, "receive", j, m, 1, CFG::MUL_LAT + CFG::ADD_LAT);
    // evaluate: fold, square root, v_0 beside alpha x_0, subtract, divide
    const T norm2 = fold_partials<T, P>(part);
    T alpha = T(0), v0 = T(0), tau = T(0);
    if (norm2 > T(0)) {
        const T norm = std::sqrt(norm2);
        alpha = x0 >= T(0) ? T(-norm) : norm;
        v0 = x0 - alpha;
        tau = T(1) / (norm2 - alpha * x0);
    }
    v[0] = v0;
    vq.write(v0);
    rq.write(alpha);
    FGC_CYCLES("qrs_head", U, "evaluate", 1, 1,
               CFG::ADD_LAT * ceil_log2(P) + CFG::SQRT_LAT +
                   (CFG::ADD_LAT > CFG::MUL_LAT ? CFG::ADD_LAT : CFG::MUL_LAT) + CFG::ADD_LAT +
                   CFG::DIV_LAT);
    // each later column: forwarded to the tail, v.x in P partials, folded and scaled by tau
    for (int c = j + 1; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
        for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
            part[t] = T(0);
        }
        // trip m, II 1, depth Lm + La
        QRS_WAIT("qrs_head", U, U == 0 ? "qrs_source" : "qrs_tail", U == 0 ? 0 : U - 1, "",
                 c);
        for (int a = 0; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=DIST
            const T x = in.read();
            xq.write(x);
            part[a % P] += v[a] * x;
        }
        QRS_CYCLES("qrs_head", U, "dot", c, m, 1, CFG::MUL_LAT + CFG::ADD_LAT);
        sq.write(tau * fold_partials<T, P>(part));
        QRS_CYCLES("qrs_head", U, "fold", c, 1, 1,
                   CFG::ADD_LAT * ceil_log2(P) + CFG::MUL_LAT);
    }
}

// The tail of stage U: reflection j applied to each later column; row j's entry to the
// collector, rows j + 1 ... to the next stage (or the sink).
template <class CFG, int U>
void qrs_tail(int j, int rows, int cols, hls::stream<typename CFG::T>& xq,
              hls::stream<typename CFG::T>& vq, hls::stream<typename CFG::T>& sq,
              hls::stream<typename CFG::T>& out, hls::stream<typename CFG::T>& rowq) {
    typedef typename CFG::T T;
    const int m = rows - j;
    T v[CFG::MAX_ROWS];
    // the vector: the words below the pivot, then v_0 (after the head's evaluate):
    // trip m, II 1, depth 1
    FGC_WAIT("qrs_tail", U, "qrs_head", U, "evaluate");
    for (int a = 0; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
        v[a + 1 < m ? a + 1 : 0] = vq.read();
    }
    FGC_CYCLES("qrs_tail", U, "vector", m, 1, 1);
    for (int c = j + 1; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
        const T s = sq.read();
        // x -= s v: trip m, II 1, depth Lm + La
        QRS_WAIT("qrs_tail", U, "qrs_head", U, "fold", c);
        for (int a = 0; a < m; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
            const T y = xq.read() - s * v[a];
            if (a == 0) {
                rowq.write(y);
            } else {
                out.write(y);
            }
        }
        QRS_CYCLES("qrs_tail", U, "axpy", c, m, 1, CFG::MUL_LAT + CFG::ADD_LAT);
    }
}

// What leaves the last stage into the next pass's banks: trip (cols - j1)(rows - j1), II 1,
// depth 2.
template <class CFG>
void qrs_sink(int j1, int rows, int cols, int k, hls::stream<typename CFG::T>& in,
              typename CFG::T next[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS]) {
    if (j1 >= k) return;
    QRS_WAIT("qrs_sink", 0, "qrs_tail", CFG::N_UNITS - 1, "", cols - 1);
    for (int c = j1, i = j1; c < cols;) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS * CFG::MAX_COLS
#pragma HLS PIPELINE II=1
        next[c % CFG::N_UNITS][i][c / CFG::N_UNITS] = in.read();
        if (i == rows - 1) {
            i = j1;
            ++c;
        } else {
            ++i;
        }
    }
    FGC_CYCLES("qrs_sink", 0, "sink", (cols - j1) * (rows - j1), 1, 2);
}

// Rows j0 ... j0 + n - 1 of R: R_jj from the head, the rest from the tail, into cond (j < f) or
// update (f <= j < f + nf), their largest magnitude into the running scale. Per row: trip
// w + 1 - first, II 1, depth 2 (read, compare).
template <class CFG>
void qrs_collect(int j0, int n, int rows, int f, int s,
                 hls::stream<typename CFG::T> rq[CFG::N_UNITS],
                 hls::stream<typename CFG::T> rowq[CFG::N_UNITS],
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
            if (u == t) diag = rq[u].read();
        }
        if (j + 1 < cols) {
            QRS_WAIT("qrs_collect", 0, "qrs_tail", t, "", cols - 1);
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
                    if (u == t) x = rowq[u].read();
                }
            }
            if (j < f) {
                cond[j * cols + c] = x;
            } else if (j - f < nf) {
                update[(j - f) * (s + 1) + (c - f)] = x;
            }
            const T mag = qrs_abs(x);
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
    static void run(int j0, int n, int rows, int cols, hls::stream<typename CFG::T> link[],
                    hls::stream<typename CFG::T> xq[], hls::stream<typename CFG::T> vq[],
                    hls::stream<typename CFG::T> sq[], hls::stream<typename CFG::T> rq[],
                    hls::stream<typename CFG::T> rowq[]) {
#pragma HLS INLINE
        if (U < n) {
            qrs_head<CFG, U>(j0 + U, rows, cols, link[U], xq[U], vq[U], sq[U], rq[U]);
            qrs_tail<CFG, U>(j0 + U, rows, cols, xq[U], vq[U], sq[U], link[U + 1], rowq[U]);
        }
        qrs_stages<CFG, U + 1>::run(j0, n, rows, cols, link, xq, vq, sq, rq, rowq);
    }
};

template <class CFG, int U>
struct qrs_stages<CFG, U, true> {
    static void run(int, int, int, int, hls::stream<typename CFG::T>*,
                    hls::stream<typename CFG::T>*, hls::stream<typename CFG::T>*,
                    hls::stream<typename CFG::T>*, hls::stream<typename CFG::T>*,
                    hls::stream<typename CFG::T>*) {
#pragma HLS INLINE
    }
};

// One pass: reflections j0 ... j0 + n - 1 (n <= N_UNITS), one DATAFLOW region.
template <class CFG>
void qrs_pass(int j0, int n, int rows, int f, int s, int k,
              const typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
              typename CFG::T next[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
              typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
              typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], typename CFG::T* scale) {
#pragma HLS DATAFLOW
    enum { COL_DEPTH = 2 * CFG::MAX_ROWS };  // a column and the fold behind it
    const int cols = f + s + 1;
    hls::stream<typename CFG::T> link[CFG::N_UNITS + 1];
#pragma HLS STREAM variable=link depth=COL_DEPTH
    hls::stream<typename CFG::T> xq[CFG::N_UNITS];
#pragma HLS STREAM variable=xq depth=COL_DEPTH
    hls::stream<typename CFG::T> vq[CFG::N_UNITS];
#pragma HLS STREAM variable=vq depth=CFG::MAX_ROWS
    hls::stream<typename CFG::T> sq[CFG::N_UNITS];
#pragma HLS STREAM variable=sq depth=2
    hls::stream<typename CFG::T> rq[CFG::N_UNITS];
#pragma HLS STREAM variable=rq depth=2
    hls::stream<typename CFG::T> rowq[CFG::N_UNITS];
#pragma HLS STREAM variable=rowq depth=CFG::MAX_COLS
    FGC_REGION("qrs_pass");
    qrs_source<CFG>(j0, rows, cols, work, link[0]);
    qrs_stages<CFG, 0>::run(j0, n, rows, cols, link, xq, vq, sq, rq, rowq);
    qrs_sink<CFG>(j0 + n, rows, cols, k, link[CFG::N_UNITS], next);
    qrs_collect<CFG>(j0, n, rows, f, s, rq, rowq, cond, update, scale);
    FGC_DRAINED(link, CFG::N_UNITS + 1);  // csim only (fgc_cycles.h)
    FGC_DRAINED(xq, CFG::N_UNITS);
    FGC_DRAINED(vq, CFG::N_UNITS);
    FGC_DRAINED(sq, CFG::N_UNITS);
    FGC_DRAINED(rq, CFG::N_UNITS);
    FGC_DRAINED(rowq, CFG::N_UNITS);
}

// ---- the step ---------------------------------------------------------------------------------

template <class CFG>
void qrs_step(typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS], int rows,
              int f, int s, typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
              typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], bool* singular) {
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
    // the pivots against the scale: trip f, II 1, depth 2 (read, compare)
    bool bad = k < f;
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        if (i >= k || !(qrs_abs(cond[i * cols + i]) > CFG::SINGULAR_EPS * scale)) bad = true;
    }
    FGC_CYCLES("qrs_step", 0, "pivot_check", f, 1, 2);
    *singular = bad;
}

}  // namespace fgc_units

#endif  // FGC_QR_STREAM_H
