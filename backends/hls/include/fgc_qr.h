// fgc_qr.h: one QR unit set of the accelerator (paper A's linear solver): one elimination step's
// frontal matrix factored by Householder reflections, an Evaluate process building each column's
// Householder vector and N_UNITS Update processes applying it to their share of the columns.
//
// Fixed code, configured by a struct of constants (CFG, see qr_config_example below); the emitted
// design (the hls-accel part of the backend) assembles each step's rows and calls qr_step<CFG>.
//
// ---- interface ------------------------------------------------------------------------------
//
//   template <class CFG>
//   void qr_step(typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
//                int rows, int f, int s,
//                typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
//                typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS],
//                bool* singular);
//
// In: the step's stacked rows [A_f | A_s | b] (its factors' whitened rows, its children's update
// rows and, for Levenberg-Marquardt, the damping rows sqrt(mu) I under the frontal columns: the
// caller assembles them), `rows` rows of w + 1 = f + s + 1 columns: f frontal columns, s separator
// columns, the right-hand side last. The work memory is banked N_UNITS ways by column: column c of
// row i is work[c % N_UNITS][i][c / N_UNITS] (qr_put<CFG> / qr_get<CFG> write and read it, and
// qr_scatter<CFG> fills the banks from a dense row-major matrix). Every entry of rows 0 ... rows-1,
// columns 0 ... w must hold the step's value (zeros included); qr_step leaves every word of the
// memory it was given zero (the factor goes out through cond and update), so a caller whose banks
// start zero (the emitted design's: globals, zero in the bitstream) writes only a step's
// non-zero entries (fgc_eliminate.h's qr_stack with CFG::BANKS_ZERO).
// Declare it with `#pragma HLS ARRAY_PARTITION variable=work complete dim=1`: each bank is then
// its own memory, passed to one Update process (UG1399, partitioned arrays in dataflow), and
// `#pragma HLS ARRAY_PARTITION variable=work cyclic factor=2 dim=2`: each bank two memories by
// row parity, so the unit holding the next pivot column streams it two rows a cycle.
//
// Out (k = min(rows, w + 1) reflections, columns 0 ... k - 1):
// - cond: the conditional (R | S | d), rows 0 ... f - 1 of the triangular factor, row-major with
//   w + 1 columns: cond[i * (w + 1) + c]; zero left of the diagonal.
// - update: the new factor for the parent, nf = max(0, min(rows, w) - f) rows (fgc's
//   STEP_NF_ROWS) of the separator columns and the right-hand side, s + 1 columns:
//   update[r * (s + 1) + c] = R[f + r][f + c]; zero left of its diagonal (the kernel's parent
//   assembly copies whole rows).
// - *singular: true if k < f or a frontal pivot |R_ii| (i < f) is not above
//   CFG::SINGULAR_EPS * scale, scale = the largest |R_ic| over rows i < k, columns i ... w (the
//   kernel's rule); also true, with nothing computed, if rows > MAX_ROWS, w + 1 > MAX_COLS or
//   f > MAX_F. (k < f: the rows of cond from k on are not written.)
//
// ---- arithmetic (the kernel's householder(), kernel.cpp.jinja) --------------------------------
//
// For column j = 0 ... k - 1, over the rows i >= j whose entry in column j is non-zero plus the
// pivot row j (the active rows): norm2 = x.x summed as the column arrives (PARTIALS interleaved
// partial sums, folded in a binary tree; no scaling by the largest magnitude, so in float32 it
// overflows for entries beyond ~1e19, and a column of entries below ~1e-19, whose squares
// underflow to 0, is skipped as zero: a documented limit), alpha =
// -sign(x_0) sqrt(norm2), v_0 = x_0 - alpha, v_a = x_a below the pivot, tau = 1 / (norm2 - alpha
// x_0) (= 2 / v.v, without a second sum); every column c > j gets x -= (tau v.x) v over the active
// rows; R_jj = alpha and the active rows below it become 0. A column whose active entries are all
// 0 is skipped; with one active row (the pivot) the reflection is the pivot row's negation,
// exactly, and is taken as that. The sums are in a different order than the kernel's
// (interleaved partial sums instead of one chain per column), so the results equal the kernel's
// to rounding (~1e-15 relative in double), not bit for bit.
//
// ---- structure (UG1399 canonical dataflow) -------------------------------------------------
//
// A reflection's next pivot column depends on its Update, so the reflections are a sequential
// loop in qr_step, one DATAFLOW region (qr_reflection) each, j = -1 ... k - 1. What goes from
// one region to the next, column j's vector below the pivot (v) and its squared norm with its
// pivot (h), does so through two buffer pairs, va / ha and vb / hb, alternating with the parity
// of j: region j reads one pair (vin, hin) and writes the other (vout, hout), region j + 1 the
// other way round, so within a region each buffer is only read or only written. Region j:
//
//   qr_broadcast      streams the words of column j's vector below the pivot (vin) to each
//                     Update unit (vq[u]) and, if j + 1 < k, to the Evaluate (evq);
//   qr_finish         meanwhile turns hin ({norm2, n}, {x_0, j}) into v_0, tau and R_jj (the
//                     square root and the divide, the Evaluate's tail, overlapped with the
//                     broadcast) and streams v_0 and tau to each Update unit (tq[u]), all three
//                     to the Evaluate (etq), R_jj to the collector (rq);
//   qr_update<u>      u = 0 ... N_UNITS - 1 (one process each, through qr_update_units): applies
//                     reflection j to its own columns c > j, c % N_UNITS == u, in its own bank
//                     work[u] (read and written by that process only: its memory, no channel).
//                     The unit holding column j + 1 streams that column as it stands (rows
//                     max(j, 0) ... rows - 1) to the Evaluate (colq[u][i & 1], two rows a
//                     cycle from its bank's two row-parity memories when dot_axpy follows)
//                     while the vector arrives and zeroes it in its bank; its other columns
//                     go through one
//                     pipelined loop, column l's dot product beside column l - 1's update
//                     (dot_axpy), which pays its depth once per reflection and takes the
//                     vector, v_0 and tau as its first column needs them (the pivot's word
//                     last: the dot starts as the vector arrives, before the square root).
//                     Each column's entry in row j, final now, goes to the collector (rowq[u]);
//   qr_evaluate       applies reflection j to column j + 1 as it arrives (its dot product with
//                     the vector as both stream in, the scale once tau is there, then one pass
//                     that updates it): the entry in row j to the collector (exq), the words
//                     below the pivot into vout, the squared norm and pivot into hout (the next
//                     region's qr_finish does the rest);
//   qr_collect        writes row j of R (zeros, R_jj, the Evaluate's entry, then the units' in
//                     column order) into cond or update and keeps the running scale (its own
//                     memory).
//
// Each stream has one writer and one later reader, no process returns a value, no channel goes
// back; vin / hin are only read (by the broadcast / qr_finish), vout / hout only written (by the
// Evaluate); cond, update and the scale have one writer (the collector). Region -1 only streams
// column 0 to the Evaluate (an empty reflection); region k - 1 only applies the last
// reflection. After the loop qr_step checks the f pivots against the scale (sequential) and
// writes *singular: no pass over the factor after the reflections.
//
// ---- cycles -------------------------------------------------------------------------------
//
// Every pipelined loop states its trip count, II and depth and reports them to FGC_CYCLES
// (fgc_cycles.h; nothing unless FGC_COUNT_CYCLES is defined). n = active rows of the reflection,
// m = rows below the pivot, P = CFG::PARTIALS, La / Lm / Ld / Ls = CFG::ADD_LAT / MUL_LAT / DIV_LAT
// / SQRT_LAT, dot II = ceil(La / min(n, P)), dot depth = Lm + La (1 + ceil(log2 min(n, P))).
// plan.py's qr_unit_loops prices these loops from the step's structure (tests/test_hls_units.py
// checks that it equals the count).
#ifndef FGC_QR_H
#define FGC_QR_H

#include <cmath>
#include <limits>

#include "fgc_cycles.h"
#include "hls_stream.h"

namespace fgc_units {

// One word of a Householder vector on its way to the Update units: from the broadcast the header
// {0, n} (n active rows; n == 0: no reflection), then n - 1 words {v_a, row} below the pivot;
// from qr_finish {v_0, j}, {tau, n} (and {R_jj, j} to the Evaluate).
template <class T>
struct qr_word {
    T val;
    int idx;
};

// The root step in a wavefront: a stream word of the fed child's passed rows (qr_collect's
// writes, qr_feed_row's reads), S = 2 * N_UNITS slots of one row as the root's banks take
// them: slot 2u + h holds a word of bank u (h: its first or second in this stream word, two
// writes a bank memory a cycle, its two ports), at[] its local column in the bank
// (QR_PASS_NONE: the slot is empty).
enum { QR_PASS_NONE = 255 };
template <class T, int S>
struct qr_pass_word { T pw[S]; unsigned char at[S]; };
// lin_level's commit streams (qr_collect's COMMIT): two words of one row a stream word
template <class T>
struct qr_commit_pair { T pw[2]; };

// Two words of a Householder vector a cycle (FGC_QR_TWO_ROWS: the Update units take two rows a
// cycle): from the broadcast the header {0, 0, n, ne} (n active rows, ne of the words below the
// pivot on even rows), then the pairs {v_e, v_o, row_e, row_o}, the t-th even-row and the t-th
// odd-row word below the pivot (row -1: that lane has no t-th word).
template <class T>
struct qr_pair {
    T v0, v1;
    int r0, r1;
};

#ifdef FGC_QR_TWO_ROWS
// the broadcast's words to the Update units: pairs; the vector's buffers (vin / vout) hold the
// header, the pivot's slot and the words below the pivot by row parity, even rows at 2 + 2a and
// odd rows at 3 + 2a (a lane has at most ceil(MAX_ROWS / 2) words: MAX_ROWS + 3 slots)
template <class T>
using qr_vq_word = qr_pair<T>;
enum { QR_VEC_SLACK = 3 };
#else
// the broadcast's words to the Update units: one a cycle; the vector's buffers hold the header
// and the words in row order (MAX_ROWS + 1 slots)
template <class T>
using qr_vq_word = qr_word<T>;
enum { QR_VEC_SLACK = 1 };
#endif

// A row's structural pattern (the keep rule by structure, qr_step_structural): bit c set where
// the row can be non-zero in column c (columns 0 ... w, the right-hand side last). The
// Evaluate holds one a row of the step (its own memory beside evec) and runs the plan's fill
// rule on them (units/qr.py's reflection_lanes): reflection j's active rows (row j and the rows
// below it whose bit j is set) all take the union of their patterns.
template <class CFG>
struct qr_rowmask {
    enum { WORDS = (CFG::MAX_COLS + 63) / 64 };
    unsigned long long w[WORDS];
};
template <class CFG>
inline bool qr_mask_bit(const qr_rowmask<CFG>& m, int c) {
#pragma HLS INLINE
    return c >= 0 && ((m.w[c >> 6] >> (c & 63)) & 1ULL) != 0;
}
template <class CFG>
inline qr_rowmask<CFG> qr_mask_or(const qr_rowmask<CFG>& a, const qr_rowmask<CFG>& b, bool in) {
#pragma HLS INLINE
    qr_rowmask<CFG> r;
    for (int q = 0; q < (CFG::MAX_COLS + 63) / 64; ++q) {
#pragma HLS UNROLL
        r.w[q] = in ? (a.w[q] | b.w[q]) : a.w[q];
    }
    return r;
}
template <class CFG>
inline qr_rowmask<CFG> qr_mask_zero() {
#pragma HLS INLINE
    qr_rowmask<CFG> r;
    for (int q = 0; q < (CFG::MAX_COLS + 63) / 64; ++q) {
#pragma HLS UNROLL
        r.w[q] = 0ULL;
    }
    return r;
}

// An example configuration (the emitted design defines its own with the step tables' maxima and
// the operator table's latencies; plan.py prices the same constants).
struct qr_config_example {
    typedef double T;
    static const int MAX_ROWS = 24;  // stacked rows of a step, damping rows included
    static const int MAX_COLS = 13;  // w + 1: frontal + separator columns + right-hand side
    static const int MAX_F = 6;      // frontal columns
    static const int N_UNITS = 4;    // Update units (n_u, --units)
    static const int LOCAL_COLS = ceil_div(MAX_COLS, N_UNITS);  // columns in one bank
    static const int PARTIALS = 12;  // interleaved partial sums of a dot product (= ADD_LAT: II 1)
    static const int FOLD_LAT = 12 * 4 + 9;  // ADD_LAT ceil(log2 PARTIALS) + MUL_LAT: fold, scale
    static const int ADD_LAT = 12, MUL_LAT = 9, DIV_LAT = 57, SQRT_LAT = 57;  // float64 (plan)
    static constexpr double SINGULAR_EPS = 1e-12;
};

template <class T>
inline T qr_abs(T x) {
    return x < T(0) ? T(-x) : x;
}

// Fill the banks from a dense row-major [A | b] (rows x cols); the rest of the banks is zeroed.
template <class CFG>
void qr_scatter(const typename CFG::T dense[CFG::MAX_ROWS][CFG::MAX_COLS], int rows, int cols,
                typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS]) {
    typedef typename CFG::T T;
    for (int i = 0; i < CFG::MAX_ROWS; ++i) {
        for (int c = 0; c < CFG::N_UNITS * CFG::LOCAL_COLS; ++c) {
#pragma HLS PIPELINE II=1
            const bool in = i < rows && c < cols && c < CFG::MAX_COLS;
            work[c % CFG::N_UNITS][i][c / CFG::N_UNITS] = in ? dense[i][c] : T(0);
        }
    }
}

// Entry (i, c) of the banked matrix, read and written.
template <class CFG>
inline typename CFG::T qr_get(
    const typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS], int i, int c) {
#pragma HLS INLINE
    return work[c % CFG::N_UNITS][i][c / CFG::N_UNITS];
}
template <class CFG>
inline void qr_put(typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS], int i,
                   int c, typename CFG::T value) {
#pragma HLS INLINE
    work[c % CFG::N_UNITS][i][c / CFG::N_UNITS] = value;
}

// ---- the processes of one reflection ---------------------------------------------------------

// Stream the Householder vector in vin to every Update unit: the header {0, n}, then the n - 1
// words below the pivot (v_a = x_a, final as the Evaluate wrote them); the pivot's v_0 comes
// from qr_finish, which computes it meanwhile. The Evaluate, when there is a next column (j + 1
// < k), gets the header only (evq): it wrote the vector itself, and keeps its own copy by row.
// With FGC_QR_TWO_ROWS two words a cycle: the header {0, 0, n, ne}, then the pairs of words
// below the pivot by row parity (vin's slots 2 + 2a and 3 + 2a, the Evaluate's lanes):
// iteration a reads slots 2a and 2a + 1 (a = 0: the header and the pivot's slot, whose idx is
// ne); trip 1 + max(ne, no).
template <class CFG>
void qr_broadcast(const qr_word<typename CFG::T> vin[CFG::MAX_ROWS + QR_VEC_SLACK], int j, int k,
                  hls::stream<qr_vq_word<typename CFG::T> > vq[CFG::N_UNITS],
                  hls::stream<qr_word<typename CFG::T> >& evq) {
#ifdef FGC_QR_TWO_ROWS
    typedef typename CFG::T T;
    const bool to_eval = j + 1 < k;  // a next pivot column: the Evaluate runs
    const int n = vin[0].idx;
    const int below = n > 1 ? n - 1 : 0;
    const int ne = n > 1 ? vin[1].idx : 0, no = below - ne;
    const int words = 1 + (ne > no ? ne : no);  // the header, then max(ne, no) pairs
    // trip 1 + max(ne, no), II 1, depth 2 (read, write)
    for (int a = 0; a < words; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
        const qr_word<T> x0 = vin[2 * a], x1 = vin[2 * a + 1];
        qr_pair<T> x;
        x.v0 = a == 0 ? T(0) : x0.val;
        x.v1 = a == 0 ? T(0) : x1.val;
        x.r0 = a == 0 ? n : (a - 1 < ne ? x0.idx : -1);
        x.r1 = a == 0 ? ne : (a - 1 < no ? x1.idx : -1);
        for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
            vq[u].write(x);
        }
        if (to_eval && a == 0) evq.write(x0);  // the header only: the Evaluate keeps its own copy
    }
    FGC_CYCLES("qr_broadcast", 0, "vector", words, 1, 2);
#else
    const bool to_eval = j + 1 < k;  // a next pivot column: the Evaluate runs
    const int n = vin[0].idx;
    const int words = n > 0 ? n : 1;
    // trip max(n, 1), II 1, depth 2 (read, write)
    for (int a = 0; a < words; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
        const qr_word<typename CFG::T> x = vin[a == 0 ? 0 : a + 1];
        for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
            vq[u].write(x);
        }
        if (to_eval && a == 0) evq.write(x);  // the header only: the Evaluate keeps its own copy
    }
    FGC_CYCLES("qr_broadcast", 0, "vector", words, 1, 2);
#endif
}

// The Evaluate's tail, while the vector streams: from the column's squared norm and pivot (hin:
// {norm2, n}, {x_0, j}) alpha = -sign(x_0) sqrt(norm2), v_0 = x_0 - alpha and tau = 1 / (norm2 -
// alpha x_0) (2 / |v|^2, without a second sum; 0 for a column zero on every active row but for
// subnormal residue);
// {v_0, j}, {tau, n} to every Update unit and, with {R_jj = alpha, j}, to the Evaluate if
// j + 1 < k, R_jj to the collector. n = 0 (no reflection): zeros.
template <class CFG>
void qr_finish(const qr_word<typename CFG::T> hin[2], int k,
               hls::stream<qr_word<typename CFG::T> > tq[CFG::N_UNITS],
               hls::stream<qr_word<typename CFG::T> >& etq, hls::stream<typename CFG::T>& rq) {
    typedef typename CFG::T T;
    const T norm2 = hin[0].val, pivot = hin[1].val;
    const int n = hin[0].idx, j = hin[1].idx;  // (hin's j is the region's)
    const bool to_eval = j + 1 < k;  // a next pivot column: the Evaluate gets v_0, tau, R_jj
    FGC_CYCLES("qr_finish", 0, "read", 2, 1, 1);
    qr_word<T> w0, w1, w2;
    w0.idx = j;
    w1.idx = n;
    w2.idx = j;
    T alpha = T(0);
    if (n > 0) {
        const T norm = std::sqrt(norm2);
        alpha = pivot >= T(0) ? T(-norm) : norm;
        w0.val = pivot - alpha;
        // sqrt, subtract: depth Ls + La (v_0 out)
        FGC_CYCLES("qr_finish", 0, "v0", 1, 1, CFG::SQRT_LAT + CFG::ADD_LAT);
        // a column zero on every active row but for rounding residue (a separator column the
        // step's rows leave empty: norm2 subnormal, x_0 = 0; in float32 entries below ~1e-19)
        // is left as it is (tau = 0: no reflection) rather than scaled by 1 / den, which
        // overflows to inf and spoils every later column (den = norm2 + |x_0| sqrt(norm2) >= 0;
        // a compare and a select beside the divider: the same depth)
        const T den = norm2 - alpha * pivot;
        w1.val = den >= std::numeric_limits<T>::min() ? T(T(1) / den) : T(0);
        // alpha x_0 (beside the subtract), subtract, divide: depth Lm + Ld after v_0 (tau out)
        FGC_CYCLES("qr_finish", 0, "tau", 1, 1, CFG::MUL_LAT + CFG::DIV_LAT);
    } else {
        w0.val = T(0);
        w1.val = T(0);
        FGC_CYCLES("qr_finish", 0, "v0", 1, 1, 1);
        FGC_CYCLES("qr_finish", 0, "tau", 1, 1, 1);
    }
    for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
        tq[u].write(w0);
    }
    if (to_eval) etq.write(w0);
    w2.val = alpha;
    for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
        tq[u].write(w1);
    }
    if (to_eval) etq.write(w1);
    if (to_eval) etq.write(w2);  // R_jj: the Evaluate's (the Update units have no use for it)
    rq.write(alpha);
}

// Update unit U: reflection j on the columns of bank U right of j (cols = w + 1 columns in all);
// each column's entry in row j, final after reflection j, goes to the collector (rowout); the
// column j + 1, if it is here and j + 1 < k, goes to the Evaluate before reflection j (colout).
//
// The column j + 1 (the next pivot) is on the critical path: its owner streams it to the
// Evaluate as the vector arrives, and the Evaluate applies reflection j to it (the unit holding
// it does no more than the others). The unit's other
// columns go through one flattened pipelined loop that takes a column's dot product beside the
// update of a column before it (dot_axpy: its multiply-add pairs are both busy every cycle), so
// a unit pays the pipeline's depth once per reflection, not once per column.
// g++'s flow analysis cannot see that dot_axpy's fold writes a column's `scaled` (e = t +
// QR_DOT_LAT) before its axpy reads it (e = t + lag, lag >= QR_DOT_LAT + FOLD_LAT), and its
// -Wmaybe-uninitialized stops the C simulation's -Werror build on some shapes; the
// diagnostic is silenced for this function only (Vitis ignores GCC pragmas).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
// With FGC_QR_TWO_ROWS, two rows a cycle: the reflection's active rows in two lanes by row parity,
// lane 0 the even rows (the bank's even-row memory), lane 1 the odd rows (its odd-row memory):
// the broadcast's pairs give lane L's words below the pivot at positions 0 ... n_L - 1, and the
// pivot's word (row j, v_0 from qr_finish) is the last position, q - 1, of lane j & 1, q = the
// longer lane's words with the pivot. A column is q iterations of dot_axpy, each one read and
// one write of each memory; a position a lane has no word at is skipped (row -1).
template <class CFG, int U>
void qr_update(int j, int rows, int cols, int k, hls::stream<qr_vq_word<typename CFG::T> >& vin,
               hls::stream<qr_word<typename CFG::T> >& tin,
               typename CFG::T bank[CFG::MAX_ROWS][CFG::LOCAL_COLS],
               hls::stream<typename CFG::T> colout[2], hls::stream<typename CFG::T>& rowout) {
#ifdef FGC_QR_TWO_ROWS
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    static_assert(CFG::PARTIALS >= CFG::ADD_LAT, "PARTIALS >= ADD_LAT: the dot loops run at II 1");
    static_assert(CFG::FOLD_LAT == CFG::ADD_LAT * ceil_log2(CFG::PARTIALS) + CFG::MUL_LAT,
                  "FOLD_LAT = ADD_LAT ceil(log2 PARTIALS) + MUL_LAT: a column's fold and scale");
    // the dot_axpy loop's lags (iterations at II 1): a pair's dot product (two products, their
    // sum) lands in its partial sum QR_DOT_LAT after it is read; a column's fold and scale take
    // CFG::FOLD_LAT
    enum {
        QR_DOT_LAT = CFG::MUL_LAT + 2 * CFG::ADD_LAT,
        QR_LANE = CFG::MAX_ROWS / 2 + 1,  // positions of a lane
        QR_HELD = 1 << ceil_log2(QR_LANE + QR_DOT_LAT + CFG::FOLD_LAT)  // > lag
    };
    // the vector in two copies per lane, one for the dot's reads and one for the axpy's (each
    // copy one write and one read an iteration of dot_axpy: a dual-port memory), by position:
    // value and row (-1: no word at that position of the lane)
    T vd0[QR_LANE], vd1[QR_LANE], vx0[QR_LANE], vx1[QR_LANE];
    int rd0[QR_LANE], rd1[QR_LANE], rx0[QR_LANE], rx1[QR_LANE];
    const qr_pair<T> head = vin.read();  // {0, 0, n, ne}
    const int n = head.r0;
    FGC_CYCLES("qr_update", U, "header", 1, 1, 1);
    const int below = n > 1 ? n - 1 : 0;
    const int ne = n > 1 ? head.r1 : 0, no = below - ne;  // words below the pivot by parity
    const int bq = ne > no ? ne : no;  // the broadcast's pairs
    const int pj = j & 1;  // the pivot's lane (n > 1: j >= 0)
    const int n0 = ne + (pj == 0 ? 1 : 0), n1 = no + (pj == 1 ? 1 : 0);
    // a column's iterations: the longer lane, at least 2 (the first column's words, kept in
    // vd0 / vd1, are read again a column later: DEPENDENCE distance 2)
    const int q = n0 > n1 ? (n0 > 2 ? n0 : 2) : (n1 > 2 ? n1 : 2);
    // this unit's first column right of j; it is the next pivot column if it is j + 1 < k
    const int c0 = j + 1 + ((U - (j + 1)) % CFG::N_UNITS + CFG::N_UNITS) % CFG::N_UNITS;
    const bool next_here = c0 == j + 1 && c0 < k;
    const int l0 = c0 / CFG::N_UNITS;
    // the unit's other columns right of j: local columns lb ... lb + r - 1
    const int lb = next_here ? l0 + 1 : l0;
    const int r = c0 < cols ? (cols - 1 - U) / CFG::N_UNITS - lb + 1 : 0;
    // a reflection to apply to columns here: dot_axpy
    const bool fused = n > 1 && r > 0;
    // the broadcast's pairs read before dot_axpy (by the column loop below)
    int pre = 0;
    if (next_here) {
        // The next pivot column goes to the Evaluate as it is now (rows j0 ... rows - 1, j0 =
        // max(j, 0)), row i on colout[i & 1], and is zeroed here (as in the one-row unit).
        const int j0 = j > 0 ? j : 0;
        if (fused) {
            // the aligned pairs (2p, 2p + 1) while the broadcast's pairs arrive, one an
            // iteration (kept for dot_axpy): trip ceil(rows / 2) - floor(j0 / 2), II 1, depth 2
            enum { MAX_PAIRS = CFG::MAX_ROWS / 2 + 1 };  // pragma constants: enums
            const int p0 = j0 / 2, pairs = (rows + 1) / 2 - p0;
            for (int t = 0; t < pairs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_PAIRS
#pragma HLS PIPELINE II=1
                if (t < bq) {
                    const qr_pair<T> x = vin.read();
                    vd0[t] = x.v0;
                    vx0[t] = x.v0;
                    rd0[t] = x.r0;
                    rx0[t] = x.r0;
                    vd1[t] = x.v1;
                    vx1[t] = x.v1;
                    rd1[t] = x.r1;
                    rx1[t] = x.r1;
                }
                if (2 * (p0 + t) >= j0) {
                    colout[0].write(bank[2 * (p0 + t)][l0]);
                    bank[2 * (p0 + t)][l0] = T(0);
                }
                if (2 * (p0 + t) + 1 < rows) {
                    colout[1].write(bank[2 * (p0 + t) + 1][l0]);
                    bank[2 * (p0 + t) + 1][l0] = T(0);
                }
            }
            pre = bq < pairs ? bq : pairs;
            FGC_CYCLES("qr_update", U, "vector_column", pairs, 1, 2);
        } else {
            // no dot_axpy after it: one row a cycle while the pairs arrive (bq < rows - j0):
            // trip rows - j0, II 1, depth 2
            for (int t = 0; t < rows - j0; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
                if (t < bq) vin.read();
                const T x = bank[j0 + t][l0];
                if (((j0 + t) & 1) == 0) colout[0].write(x);
                if (((j0 + t) & 1) == 1) colout[1].write(x);
                bank[j0 + t][l0] = T(0);
            }
            FGC_CYCLES("qr_update", U, "vector_column", rows - j0, 1, 2);
        }
    } else if (!fused) {
        // the broadcast's pairs, not needed here: trip max(ne, no), II 1, depth 1
        for (int a = 0; a < bq; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
            vin.read();
        }
        FGC_CYCLES("qr_update", U, "vector", bq, 1, 1);
    }
    if (!fused) {
        // v_0 and tau from qr_finish (it waits for the square root, then the divide)
        FGC_WAIT("qr_update", U, "qr_finish", 0, "v0");
        tin.read();
        FGC_CYCLES("qr_update", U, "pivot_word", 1, 1, 1);
        FGC_WAIT("qr_update", U, "qr_finish", 0, "tau");
        tin.read();
        FGC_CYCLES("qr_update", U, "tail", 1, 1, 1);
        if (r <= 0 || j < 0) return;
        // no reflection (an all-zero column: row j as it is) or the pivot row's negation (one
        // active row), each entry to the collector (0 in the bank): trip r, II 1, depth 1
        for (int l = lb; l < lb + r; ++l) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::LOCAL_COLS
#pragma HLS PIPELINE II=1
            const T x = n == 1 ? T(-bank[j][l]) : bank[j][l];
            bank[j][l] = T(0);
            rowout.write(x);
        }
        FGC_CYCLES("qr_update", U, n == 1 ? "negate_rows" : "rows_out", r, 1, 1);
        return;
    }
    // dot_axpy two rows a cycle: the one-row unit's three streams (dot, fold, axpy; see its
    // comment), each a pair of words an iteration, position a of column l at rows rd0[a] (the
    // even-row memory) and rd1[a] (the odd-row memory); the pair's two products are added before
    // the partial of the iteration, so a partial is met again P >= La iterations later; the
    // axpy writes both rows (one write of each memory, beside the dot's one read of each).
    // trip q r + lag, lag = q - 1 + QR_DOT_LAT + FOLD_LAT, II 1, depth Lm + La; v_0 in iteration
    // q - 1, tau in iteration q - 1 + QR_DOT_LAT (FGC_WAIT_AFTER)
    enum { MAX_BATCH = QR_LANE * CFG::LOCAL_COLS + QR_HELD };  // pragma constants
    T part[CFG::LOCAL_COLS][P];
#pragma HLS ARRAY_PARTITION variable=part complete dim=0
    T scaled[CFG::LOCAL_COLS];
    T held0[QR_HELD], held1[QR_HELD];  // the dot's words until their axpy
    const int words = q * r;
    const int lag = q - 1 + QR_DOT_LAT + CFG::FOLD_LAT;
    T tau = T(0);
    int ld = lb, ad = 0, lq = lb, aq = 0, lx = lb, ax = 0;
    FGC_WAIT_AFTER("qr_update", U, "qr_finish", 0, "v0", words + lag - q);
    FGC_WAIT_AFTER("qr_update", U, "qr_finish", 0, "tau", words + lag - q - QR_DOT_LAT);
    for (int e = 0; e < words + lag; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_BATCH
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=scaled inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=held0 inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=held1 inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=vd0 inter true distance=2
#pragma HLS DEPENDENCE variable=vd1 inter true distance=2
#pragma HLS DEPENDENCE variable=rd0 inter true distance=2
#pragma HLS DEPENDENCE variable=rd1 inter true distance=2
#pragma HLS DEPENDENCE variable=vx0 inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=vx1 inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=rx0 inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=rx1 inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=bank inter false
        if (e < words) {  // dot: position ad of column ld
            // the position's words: the first column's as they arrive, then kept
            T va0 = vd0[ad], va1 = vd1[ad];
            int row0 = rd0[ad], row1 = rd1[ad];
            if (e < q) {
                if (e >= pre && e < bq) {  // not read by the column loop: the dot takes it
                    const qr_pair<T> w = vin.read();
                    va0 = w.v0;
                    va1 = w.v1;
                    row0 = w.r0;
                    row1 = w.r1;
                } else if (e >= bq) {  // past the broadcast's pairs: no word in either lane
                    row0 = -1;
                    row1 = -1;
                }
                if (e == q - 1) {  // the pivot's word (row j, lane j & 1), last
                    const T v0 = tin.read().val;
                    if (pj == 0) {
                        va0 = v0;
                        row0 = j;
                    } else {
                        va1 = v0;
                        row1 = j;
                    }
                }
                vd0[e] = va0;
                rd0[e] = row0;
                vx0[e] = va0;
                rx0[e] = row0;
                vd1[e] = va1;
                rd1[e] = row1;
                vx1[e] = va1;
                rx1[e] = row1;
            }
            // the row pair's halves (a lane without a word reads its memory's row 0 or 1)
            const int h0 = row0 >= 0 ? row0 / 2 : 0, h1 = row1 >= 0 ? row1 / 2 : 0;
            const T x0 = bank[2 * h0][ld];
            const T x1 = bank[2 * h1 + 1][ld];
            held0[e & (QR_HELD - 1)] = x0;
            held1[e & (QR_HELD - 1)] = x1;
            const T term = T((row0 >= 0 ? T(va0 * x0) : T(0)) + (row1 >= 0 ? T(va1 * x1) : T(0)));
            part[ld][ad % P] = ad < P ? term : T(part[ld][ad % P] + term);
            if (ad == q - 1) {
                ad = 0;
                ++ld;
            } else {
                ++ad;
            }
        }
        if (e >= QR_DOT_LAT && e < words + QR_DOT_LAT) {  // fold: position e - QR_DOT_LAT
            if (aq == q - 1) {
                if (lq == lb) tau = tin.read().val;  // the first fold: tau
                T p[P];
#pragma HLS ARRAY_PARTITION variable=p complete
                for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
                    p[t] = t < q ? part[lq][t] : T(0);
                }
                scaled[lq] = tau * fold_partials<T, P>(p);
                aq = 0;
                ++lq;
            } else {
                ++aq;
            }
        }
        if (e >= lag) {  // axpy: position e - lag (each entry written once)
            const int w0 = rx0[ax], w1 = rx1[ax];
            const T y0 = held0[(e - lag) & (QR_HELD - 1)] - scaled[lx] * vx0[ax];
            const T y1 = held1[(e - lag) & (QR_HELD - 1)] - scaled[lx] * vx1[ax];
            // row j (the pivot's position, a = q - 1 of lane j & 1) to the collector, 0 in the bank
            const int g0 = w0 >= 0 ? w0 / 2 : 0, g1 = w1 >= 0 ? w1 / 2 : 0;
            if (w0 >= 0) bank[2 * g0][lx] = w0 == j ? T(0) : y0;
            if (w1 >= 0) bank[2 * g1 + 1][lx] = w1 == j ? T(0) : y1;
            if (ax == q - 1) rowout.write(pj == 0 ? y0 : y1);
            if (ax == q - 1) {
                ax = 0;
                ++lx;
            } else {
                ++ax;
            }
        }
    }
    FGC_CYCLES("qr_update", U, "dot_axpy", words + lag, 1, CFG::MUL_LAT + CFG::ADD_LAT);
#else
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    static_assert(CFG::PARTIALS >= CFG::ADD_LAT, "PARTIALS >= ADD_LAT: the dot loops run at II 1");
    static_assert(CFG::FOLD_LAT == CFG::ADD_LAT * ceil_log2(CFG::PARTIALS) + CFG::MUL_LAT,
                  "FOLD_LAT = ADD_LAT ceil(log2 PARTIALS) + MUL_LAT: a column's fold and scale");
    // the dot_axpy loop's lags (iterations at II 1): a word's dot product lands in its partial
    // sum QR_DOT_LAT after it is read; a column's fold and scale take CFG::FOLD_LAT
    enum {
        QR_DOT_LAT = CFG::MUL_LAT + CFG::ADD_LAT,
        QR_HELD = 1 << ceil_log2(CFG::MAX_ROWS + QR_DOT_LAT + CFG::FOLD_LAT)  // > lag
    };
    // the vector in two copies, one for the dot's reads and one for the axpy's (each copy one
    // write and one read an iteration of dot_axpy: a dual-port memory), in the dot's word order:
    // words 0 ... n - 2 below the pivot (rows rd / rx), word n - 1 the pivot's v_0 (row j)
    T vd[CFG::MAX_ROWS], vx[CFG::MAX_ROWS];
    int rd[CFG::MAX_ROWS], rx[CFG::MAX_ROWS];
    const int n = vin.read().idx;  // {0, n}
    FGC_CYCLES("qr_update", U, "header", 1, 1, 1);
    // this unit's first column right of j; it is the next pivot column if it is j + 1 < k
    const int c0 = j + 1 + ((U - (j + 1)) % CFG::N_UNITS + CFG::N_UNITS) % CFG::N_UNITS;
    const bool next_here = c0 == j + 1 && c0 < k;
    const int l0 = c0 / CFG::N_UNITS;
    const int below = n > 1 ? n - 1 : 0;
    // the unit's other columns right of j: local columns lb ... lb + r - 1
    const int lb = next_here ? l0 + 1 : l0;
    const int r = c0 < cols ? (cols - 1 - U) / CFG::N_UNITS - lb + 1 : 0;
    // a reflection to apply to columns here: dot_axpy, which takes the vector, v_0 and tau as
    // its first column's words need them
    const bool fused = n > 1 && r > 0;
    // the words of the vector below the pivot read before dot_axpy (by the column loop below)
    int pre = 0;
    if (next_here) {
        // The next pivot column goes to the Evaluate as it is now (rows j0 ... rows - 1, j0 =
        // max(j, 0)), row i on colout[i & 1]: the Evaluate applies reflection j to it, sends its
        // row j entry to the collector and builds reflection j + 1 from the rest, and nothing
        // reads the column in the bank again, so it is zeroed here (the banks are left zero).
        const int j0 = j > 0 ? j : 0;
        if (fused) {
            // Two rows a cycle: the bank is two memories by row parity (the caller's cyclic
            // factor=2 partition of its rows), so the aligned pair (2p, 2p + 1) is one read and
            // one write of each (row j0 - 1 of an odd j0 is row j - 1: zero since reflection
            // j - 1, not sent); the words below the pivot arrive meanwhile, one an iteration,
            // and dot_axpy takes the rest as they come: trip ceil(rows / 2) - floor(j0 / 2),
            // II 1, depth 2
            enum { MAX_PAIRS = CFG::MAX_ROWS / 2 + 1 };  // pragma constants: enums
            const int p0 = j0 / 2, pairs = (rows + 1) / 2 - p0;
            for (int t = 0; t < pairs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_PAIRS
#pragma HLS PIPELINE II=1
                if (t < below) {
                    const qr_word<T> x = vin.read();
                    vd[t] = x.val;
                    vx[t] = x.val;
                    rd[t] = x.idx;
                    rx[t] = x.idx;
                }
                // rows 2 (p0 + t) and 2 (p0 + t) + 1 (indices written out: they move with t)
                if (2 * (p0 + t) >= j0) {
                    colout[0].write(bank[2 * (p0 + t)][l0]);
                    bank[2 * (p0 + t)][l0] = T(0);
                }
                if (2 * (p0 + t) + 1 < rows) {
                    colout[1].write(bank[2 * (p0 + t) + 1][l0]);
                    bank[2 * (p0 + t) + 1][l0] = T(0);
                }
            }
            pre = below < pairs ? below : pairs;
            FGC_CYCLES("qr_update", U, "vector_column", pairs, 1, 2);
        } else {
            // no dot_axpy after it (no reflection, or no other column here): one row a
            // cycle while the n - 1 words below the pivot arrive (n - 1 < rows - j0): trip
            // rows - j0, II 1, depth 2
            for (int t = 0; t < rows - j0; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
                if (t < below) vin.read();
                const T x = bank[j0 + t][l0];
                if (((j0 + t) & 1) == 0) colout[0].write(x);
                if (((j0 + t) & 1) == 1) colout[1].write(x);
                bank[j0 + t][l0] = T(0);
            }
            FGC_CYCLES("qr_update", U, "vector_column", rows - j0, 1, 2);
        }
    } else if (!fused) {
        // the n - 1 words below the pivot, not needed here: trip n - 1, II 1, depth 1
        for (int a = 0; a < below; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
            vin.read();
        }
        FGC_CYCLES("qr_update", U, "vector", below, 1, 1);
    }
    // The banks are left zero (what qr_stack relies on: it writes only the next step's rows):
    // each pivot column was zeroed as it went to the Evaluate (above, one region before its
    // reflection), and every row's entries are zeroed as they go to the collector (row j is
    // no reflection's after j).
    if (!fused) {
        // v_0 and tau from qr_finish (it waits for the square root, then the divide)
        FGC_WAIT("qr_update", U, "qr_finish", 0, "v0");
        tin.read();
        FGC_CYCLES("qr_update", U, "pivot_word", 1, 1, 1);
        FGC_WAIT("qr_update", U, "qr_finish", 0, "tau");
        tin.read();
        FGC_CYCLES("qr_update", U, "tail", 1, 1, 1);
        if (r <= 0 || j < 0) return;
        // no reflection (an all-zero column: row j as it is) or the pivot row's negation (one
        // active row), each entry to the collector (0 in the bank): trip r, II 1, depth 1
        for (int l = lb; l < lb + r; ++l) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::LOCAL_COLS
#pragma HLS PIPELINE II=1
            const T x = n == 1 ? T(-bank[j][l]) : bank[j][l];
            bank[j][l] = T(0);
            rowout.write(x);
        }
        FGC_CYCLES("qr_update", U, n == 1 ? "negate_rows" : "rows_out", r, 1, 1);
        return;
    }
    // One flattened loop: column l's dot product v.x beside the update x -= (tau v.x) v of the
    // column before it (the same operators, both busy every cycle, where a dot pass and then an
    // update pass over all r columns would leave each idle half the time). Three streams of
    // column words run through it, each one word an iteration, column by column, word a of a
    // column at row rd[a] (the rows below the pivot, then the pivot's row j):
    //   dot   (iteration e = t for word t = (l - lb) n + a, e < n r): x = bank[rd[a]][l] into
    //         P interleaved partial sums of column l (a partial is met again P >= La
    //         iterations later; its first term overwrites it) and into the held ring. The
    //         first column's words take the vector as it comes: from the broadcast (e < n - 1,
    //         unless the column loop above read it) and v_0 from qr_finish (e = n - 1), each
    //         kept in vd / vx for the later columns: the pivot's word last, so the dot starts
    //         with the vector, not after the square root;
    //   fold  (e = t + QR_DOT_LAT, the word a column's last, a = n - 1: its partial sums
    //         have landed): scaled[l] = tau * fold(part[l]), tau from qr_finish at the first
    //         column's fold (after the divide);
    //   axpy  (e = t + lag, lag = n - 1 + QR_DOT_LAT + FOLD_LAT: the column's scaled is
    //         ready, FOLD_LAT after its fold): x from the held ring (the bank's two ports are
    //         the dot's read and this write), x - scaled[l] v_a into the bank, the entry in row
    //         j (a = n - 1) to the collector.
    // trip n r + lag, II 1, depth Lm + La (the axpy's multiply-add); it reads v_0 in iteration
    // n - 1 and tau in iteration n - 1 + QR_DOT_LAT (FGC_WAIT_AFTER: the loop ends no earlier
    // than its remaining iterations and depth after each arrives)
    enum { MAX_BATCH = CFG::MAX_ROWS * CFG::LOCAL_COLS + QR_HELD };  // pragma constants
    // the partial sums in registers: in one iteration the fold reads a column's P partials
    // while the dot adds into another column's
    T part[CFG::LOCAL_COLS][P];
#pragma HLS ARRAY_PARTITION variable=part complete dim=0
    T scaled[CFG::LOCAL_COLS];
    T held[QR_HELD];  // the dot's words until their axpy (lag < QR_HELD iterations later)
    const int words = n * r;
    const int lag = n - 1 + QR_DOT_LAT + CFG::FOLD_LAT;
    T tau = T(0);
    int ld = lb, ad = 0, lq = lb, aq = 0, lx = lb, ax = 0;
    FGC_WAIT_AFTER("qr_update", U, "qr_finish", 0, "v0", words + lag - n);
    FGC_WAIT_AFTER("qr_update", U, "qr_finish", 0, "tau", words + lag - n - QR_DOT_LAT);
    for (int e = 0; e < words + lag; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_BATCH
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=scaled inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=held inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=vd inter true distance=2
#pragma HLS DEPENDENCE variable=rd inter true distance=2
#pragma HLS DEPENDENCE variable=vx inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=rx inter true distance=CFG::FOLD_LAT
#pragma HLS DEPENDENCE variable=bank inter false
        if (e < words) {  // dot: word e
            // the word's vector entry and row: the first column's as they arrive, then kept
            T va = vd[ad];
            int row = rd[ad];
            if (e < below && e >= pre) {  // not read by the column loop: the dot takes it
                const qr_word<T> w = vin.read();
                va = w.val;
                row = w.idx;
            } else if (e == below) {
                va = tin.read().val;  // v_0 (the pivot's word, last)
                row = j;
            }
            if (e < n) {
                vd[e] = va;
                rd[e] = row;
                vx[e] = va;
                rx[e] = row;
            }
            const T x = bank[row][ld];
            held[e & (QR_HELD - 1)] = x;
            const T term = va * x;
            part[ld][ad % P] = ad < P ? term : T(part[ld][ad % P] + term);
            if (ad == n - 1) {
                ad = 0;
                ++ld;
            } else {
                ++ad;
            }
        }
        if (e >= QR_DOT_LAT && e < words + QR_DOT_LAT) {  // fold: word e - QR_DOT_LAT
            if (aq == n - 1) {
                if (lq == lb) tau = tin.read().val;  // the first fold: tau
                T p[P];
#pragma HLS ARRAY_PARTITION variable=p complete
                for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
                    p[t] = t < n ? part[lq][t] : T(0);
                }
                scaled[lq] = tau * fold_partials<T, P>(p);
                aq = 0;
                ++lq;
            } else {
                ++aq;
            }
        }
        if (e >= lag) {  // axpy: word e - lag (each entry (rx[a], l) written once)
            const T x = held[(e - lag) & (QR_HELD - 1)] - scaled[lx] * vx[ax];
            // row j (the pivot's word, a = n - 1) to the collector, 0 in the bank
            bank[rx[ax]][lx] = ax == n - 1 ? T(0) : x;
            if (ax == n - 1) rowout.write(x);
            if (ax == n - 1) {
                ax = 0;
                ++lx;
            } else {
                ++ax;
            }
        }
    }
    FGC_CYCLES("qr_update", U, "dot_axpy", words + lag, 1, CFG::MUL_LAT + CFG::ADD_LAT);
#endif
}
#pragma GCC diagnostic pop

// The N_UNITS Update processes, U = 0 ... N_UNITS - 1, as separate calls in the region.
template <class CFG, int U, bool END = (U == CFG::N_UNITS)>
struct qr_update_units {
    static void run(int j, int rows, int cols, int k,
                    hls::stream<qr_vq_word<typename CFG::T> > vq[CFG::N_UNITS],
                    hls::stream<qr_word<typename CFG::T> > tq[CFG::N_UNITS],
                    typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                    hls::stream<typename CFG::T> colq[CFG::N_UNITS][2],
                    hls::stream<typename CFG::T> rowq[CFG::N_UNITS]) {
#pragma HLS INLINE
        qr_update<CFG, U>(j, rows, cols, k, vq[U], tq[U], work[U], colq[U], rowq[U]);
        qr_update_units<CFG, U + 1>::run(j, rows, cols, k, vq, tq, work, colq, rowq);
    }
};

template <class CFG, int U>
struct qr_update_units<CFG, U, true> {
    static void run(int, int, int, int, hls::stream<qr_vq_word<typename CFG::T> >*,
                    hls::stream<qr_word<typename CFG::T> >*,
                    typename CFG::T (*)[CFG::MAX_ROWS][CFG::LOCAL_COLS],
                    hls::stream<typename CFG::T> (*)[2], hls::stream<typename CFG::T>*) {
#pragma HLS INLINE
    }
};

// One word (row i, the t-th of the pass) of column j + 1 after reflection j, in the Evaluate's
// one-row pass (receive_norm): row j's entry to the collector, the new pivot and the non-zero
// rows below it into vout (m words so far; nzb: row i non-zero in column j + 1, in value or, with
// the keep rule by structure, by its pattern), their squares into the partial sums (the partial of
// iteration t), and the Evaluate's own copy of the vector by row (evec: the word below the pivot,
// 0 elsewhere: the pass clears the rows it passes, j0 ... rows - 1).
template <class CFG>
inline void qr_next_word(int i, int j, int t, typename CFG::T e, bool nzb,
                         hls::stream<typename CFG::T>& exq,
                         qr_word<typename CFG::T> vout[CFG::MAX_ROWS + QR_VEC_SLACK], int& m,
                         int& me, int& mo,
                         typename CFG::T& pivot, typename CFG::T part[CFG::PARTIALS],
                         typename CFG::T evec[CFG::MAX_ROWS]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    const int col = j + 1;
    if (i == j) exq.write(e);  // row j's entry in column j + 1 to the collector
    if (i == col) pivot = e;
#ifdef FGC_QR_TWO_ROWS
    // by row parity (the broadcast's lanes): the pivot at 1, even rows at 2 + 2a, odd at 3 + 2a
    if (i == col || (i > col && nzb)) {
        const int slot = i == col ? 1 : ((i & 1) == 0 ? 2 + 2 * me : 3 + 2 * mo);
        vout[slot].val = e;
        vout[slot].idx = i;
        ++m;
        if (i > col && (i & 1) == 0) ++me;
        if (i > col && (i & 1) == 1) ++mo;
    }
#else
    (void)me;
    (void)mo;
    if (i == col || (i > col && nzb)) {
        vout[1 + m].val = e;
        vout[1 + m].idx = i;
        ++m;
    }
#endif
    evec[i] = i > col ? e : T(0);
    if (i >= col) part[t % CFG::PARTIALS] += e * e;
}

// Row i's word of column j + 1 from the Update unit that holds it (colq[owner][p], the stream of
// its row parity p = i & 1): one read of one of the 2 N_UNITS streams, in a pipelined loop of
// the Evaluate.
template <class CFG>
inline typename CFG::T qr_owner_word(hls::stream<typename CFG::T> colq[CFG::N_UNITS][2],
                                     int owner, int p) {
#pragma HLS INLINE
    typename CFG::T e = typename CFG::T(0);
    for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
        for (int q = 0; q < 2; ++q) {
#pragma HLS UNROLL
            if (u == owner && q == p) e = colq[u][q].read();
        }
    }
    return e;
}

// Evaluate: reflection j applied to column j + 1 and that column's Householder vector (if j + 1
// < k). The column arrives from the unit that holds it as it stood before reflection j (rows j0
// ... rows - 1, j0 = max(j, 0); two streams by row parity), reflection j's vector below the pivot
// from the Evaluate's own copy (evec, by row, written by its last pass in region j - 1; two
// memories by row parity: the caller's cyclic factor=2 partition), its header from the broadcast
// (evq: {0, n}) and v_0, tau, R_jj from qr_finish (etq). Two rows a cycle (the aligned pair 2p,
// 2p + 1): the column's dot product with the vector as the column arrives (the pair's two terms
// added, then into the partial of the iteration), folded with the pivot's term once v_0 is there,
// scaled once tau is; then one pass, two of its kept rows a cycle (row j, the next pivot's, the
// rows active in reflection j and the column's non-zero entries, kept as it arrives), that
// updates them (x -= tau (v.x) v on the active rows), sends row j's entry to the collector
// (exq), keeps the next pivot and non-zero rows below it in vout ({0, n'}, then n' words {x_a,
// row}, rows ascending) and in evec while summing their squares (the pair's two squares added,
// then into the partial of the iteration; folded) for hout ({norm2, n'}, {x_0, j + 1}), which
// the next region's qr_finish turns into v_0, tau and R_jj while its broadcast streams the rest.
// With no reflection to apply (n = 0; n = 1: the pivot row's negation, exact) the column is
// received and passed on in one pass, a row a cycle. evec is left 0 on every row it read and
// holds the next vector below its pivot (region -1 clears rows 0 ... rows - 1 of the step).
// The rows it keeps and the rows of the next vector: STRUCT false, the rows non-zero in value
// (a column zero in value on every row: no reflection); STRUCT true (qr_step_structural), the
// rows non-zero by structure, the plan's rule (units/qr.py's reflection_lanes): msk holds each
// row's pattern (region -1 loads it from mask0 as its one pass reads the rows), a row is active
// in reflection j if it is row j or its bit j is set, the kept rows are row j, row j + 1, the
// active rows and the rows whose bit j + 1 is set, the active rows take the union of their
// patterns (written back in the update pass), and the next vector is row j + 1 and the rows below
// it whose bit j + 1 is set, none if no row from j + 1 on has it (a column zero by structure);
// a column non-zero by structure but zero in value is reflected with tau = 0 (qr_finish), in the
// cycles the plan prices. The counted cycles then follow the structure, whatever the data.
template <class CFG>
void qr_evaluate(int j, int rows, int k, hls::stream<typename CFG::T> colq[CFG::N_UNITS][2],
                 hls::stream<qr_word<typename CFG::T> >& evq,
                 hls::stream<qr_word<typename CFG::T> >& etq, hls::stream<typename CFG::T>& exq,
                 qr_word<typename CFG::T> vout[CFG::MAX_ROWS + QR_VEC_SLACK],
                 qr_word<typename CFG::T> hout[2], typename CFG::T evec[CFG::MAX_ROWS],
                 const qr_rowmask<CFG>* mask0, qr_rowmask<CFG> msk[CFG::MAX_ROWS]) {
    typedef typename CFG::T T;
    typedef qr_rowmask<CFG> M;
    const bool STRUCT = mask0 != 0;  // the step's patterns given: the keep rule by structure
    const int P = CFG::PARTIALS;
    const int col = j + 1;
    if (col >= k) return;
    const int owner = col % CFG::N_UNITS;
    const int j0 = j > 0 ? j : 0;
    // the column's kept rows (rows xr, their vector words xv: 0 off reflection j's active rows
    // below the pivot) of rows j0 ... rows - 1, two written and two read a cycle (dual port)
    T x[CFG::MAX_ROWS];
    T xv[CFG::MAX_ROWS];
    int xr[CFG::MAX_ROWS];
    // (STRUCT) the kept rows' patterns and whether each is active in reflection j
    M xm[CFG::MAX_ROWS];
    bool xa[CFG::MAX_ROWS];
    M uni = qr_mask_zero<CFG>();  // (STRUCT) the union of the active rows' patterns
    bool anyc = false;  // (STRUCT) a row from j + 1 on non-zero by structure in column j + 1
    const int n = evq.read().idx;  // {0, n}
    FGC_CYCLES("qr_evaluate", 0, "header", 1, 1, 1);
    T part[P];
#pragma HLS ARRAY_PARTITION variable=part complete
    for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
        part[t] = T(0);
    }
    int m = 0;
    int me = 0, mo = 0;  // (two rows a cycle) the words below the pivot on even / odd rows
    T pivot = T(0);
    if (n <= 1) {
        // nothing to apply but, with one active row, the pivot row's negation (exact): the
        // column received, row j's entry sent, the vector kept and its squares summed in one
        // pass: trip rows - j0, II 1, depth Lm + La
        FGC_WAIT("qr_evaluate", 0, "qr_update", owner, "vector_column");
        for (int t = 0; t < rows - j0; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_ROWS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
            // (msk: iteration t reads and writes row j0 + t's pattern only)
#pragma HLS DEPENDENCE variable=msk inter false
            const int i = j0 + t;
            const T e = qr_owner_word<CFG>(colq, owner, i & 1);
            bool nzb = e != T(0);
            if (STRUCT) {  // (no reflection, or the pivot row's alone: no fill)
                M mi = j < 0 ? mask0[i] : msk[i];
                // (a value off the pattern - the pattern a model error - is kept all the same,
                // its bit set: the factor stays exact, the count above the plan's)
                if (e != T(0) && col < CFG::MAX_COLS) mi.w[col >> 6] |= 1ULL << (col & 63);
                msk[i] = mi;
                nzb = qr_mask_bit<CFG>(mi, col);
                anyc = anyc || (i >= col && nzb);
            }
            qr_next_word<CFG>(i, j, t, i == j && n == 1 ? T(-e) : e, nzb, exq, vout, m, me, mo,
                              pivot, part, evec);
        }
        FGC_CYCLES("qr_evaluate", 0, "receive_norm", rows - j0, 1, CFG::MUL_LAT + CFG::ADD_LAT);
    } else {
        // receive the column two rows a cycle (the aligned pairs 2p, 2p + 1 from p = j0 / 2;
        // row j0 - 1 of an odd j0 is not sent) and read (and clear) the vector's words of those
        // rows, v.x over them: trip ceil(rows / 2) - floor(j0 / 2), II 1, depth Lm + 2 La (the
        // two products, their sum, the partial of the iteration, met again P >= La iterations
        // later). It reads the column as its unit streams it (the counters' critical path).
        FGC_WAIT("qr_evaluate", 0, "qr_update", owner, "vector_column");
        // The rows the update pass needs are kept (x, rows xr, words xv; c of them, ascending):
        // row j, the next pivot's row, the rows active in reflection j and the column's
        // non-zero entries; the others are zero before the update and after it, no word of the
        // next vector and no term of its norm, so that pass skips them
        enum { MAX_PAIRS = CFG::MAX_ROWS / 2 + 1 };  // pragma constants: enums
        const int p0 = j0 / 2, pairs = (rows + 1) / 2 - p0;
        int c = 0;
        for (int t = 0; t < pairs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_PAIRS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=evec inter false
            const int i0 = 2 * (p0 + t), i1 = i0 + 1;
            const bool h0 = i0 >= j0, h1 = i1 < rows;  // the pair's rows in j0 ... rows - 1
            const T e0 = h0 ? qr_owner_word<CFG>(colq, owner, 0) : T(0);
            const T e1 = h1 ? qr_owner_word<CFG>(colq, owner, 1) : T(0);
            // the vector's words of the two rows (0 off reflection j's active rows below the
            // pivot; row j's v_0 comes from qr_finish), cleared as they are read
            T v0 = T(0), v1 = T(0);
            if (h0) {
                v0 = i0 > j ? evec[i0] : T(0);
                evec[i0] = T(0);
            }
            if (h1) {
                v1 = i1 > j ? evec[i1] : T(0);
                evec[i1] = T(0);
            }
            const bool a0 = v0 != T(0), a1 = v1 != T(0);
            part[t % P] += T((a0 ? T(v0 * e0) : T(0)) + (a1 ? T(v1 * e1) : T(0)));
            // (STRUCT) the two rows' patterns: active in reflection j, non-zero in column j + 1
            M m0 = STRUCT && h0 ? msk[i0] : qr_mask_zero<CFG>();
            M m1 = STRUCT && h1 ? msk[i1] : qr_mask_zero<CFG>();
            // (a value off the pattern kept all the same, its bit set: see the one-row pass)
            if (e0 != T(0)) m0.w[col >> 6] |= 1ULL << (col & 63);
            if (e1 != T(0)) m1.w[col >> 6] |= 1ULL << (col & 63);
            const bool s0 = h0 && (i0 == j || (i0 > j && qr_mask_bit<CFG>(m0, j)));
            const bool s1 = h1 && (i1 == j || (i1 > j && qr_mask_bit<CFG>(m1, j)));
            if (STRUCT) uni = qr_mask_or<CFG>(qr_mask_or<CFG>(uni, m0, s0), m1, s1);
            const bool n0 = STRUCT ? s0 || qr_mask_bit<CFG>(m0, col) : a0 || e0 != T(0);
            const bool n1 = STRUCT ? s1 || qr_mask_bit<CFG>(m1, col) : a1 || e1 != T(0);
            const bool k0 = h0 && (i0 == j || i0 == col || n0);
            const bool k1 = h1 && (i1 == j || i1 == col || n1);
            if (k0) {
                x[c] = e0;
                xv[c] = v0;
                xr[c] = i0;
                xm[c] = m0;
                xa[c] = s0;
            }
            const int c1 = k0 ? c + 1 : c;
            if (k1) {
                x[c1] = e1;
                xv[c1] = v1;
                xr[c1] = i1;
                xm[c1] = m1;
                xa[c1] = s1;
            }
            c = k1 ? c1 + 1 : c1;
        }
        FGC_CYCLES("qr_evaluate", 0, "receive_dot", pairs, 1, CFG::MUL_LAT + 2 * CFG::ADD_LAT);
        // v_0 (qr_finish waits for the square root): its term is one more leaf of the fold's tree
        FGC_WAIT("qr_evaluate", 0, "qr_finish", 0, "v0");
        const T vp = etq.read().val;
        T leaves[P + 1];
#pragma HLS ARRAY_PARTITION variable=leaves complete
        for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
            leaves[t] = part[t];
            part[t] = T(0);
        }
        leaves[P] = vp * x[0];  // row j, the first kept row; depth Lm
        FGC_CYCLES("qr_evaluate", 0, "pivot_term", 1, 1, CFG::MUL_LAT);
        const T dot = fold_partials<T, P + 1>(leaves);  // depth La ceil(log2 (P + 1))
        FGC_CYCLES("qr_evaluate", 0, "fold_dot", 1, 1, CFG::ADD_LAT * ceil_log2(P + 1));
        // tau and R_jj (the collector has R_jj from qr_finish)
        FGC_WAIT("qr_evaluate", 0, "qr_finish", 0, "tau");
        const T tau = etq.read().val;
        etq.read();
        FGC_CYCLES("qr_evaluate", 0, "tail", 2, 1, 1);
        const T scaled = tau * dot;  // depth Lm
        FGC_CYCLES("qr_evaluate", 0, "scale", 1, 1, CFG::MUL_LAT);
        // the update of the kept rows two a cycle (kept words 2t, 2t + 1), row j's entry (kept
        // word 0) to the collector, the vector kept (vout, evec) and its squares summed: trip
        // ceil(c / 2), II 1, depth 2 Lm + 3 La (the multiply-add, the squares, their sum, the
        // partial of the iteration)
        const int kpairs = (c + 1) / 2;
        for (int t = 0; t < kpairs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_PAIRS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
            const bool g1 = 2 * t + 1 < c;
            const int i0 = xr[2 * t], i1 = g1 ? xr[2 * t + 1] : -1;
            // the active rows' vector words (the pivot's v_0, the others' kept): one multiply-add
            // for each of the two
            const T w0 = i0 == j ? vp : xv[2 * t];
            const T w1 = g1 ? xv[2 * t + 1] : T(0);
            const T x0 = x[2 * t], x1 = g1 ? x[2 * t + 1] : T(0);
            const T e0 = i0 == j || w0 != T(0) ? T(x0 - scaled * w0) : x0;
            const T e1 = w1 != T(0) ? T(x1 - scaled * w1) : x1;
            if (i0 == j) exq.write(e0);  // row j's entry in column j + 1 to the collector
            if (i0 == col) pivot = e0;
            if (i1 == col) pivot = e1;
            // (STRUCT) the rows' patterns after reflection j: the active rows' the union
            const M p0 = xa[2 * t] ? uni : xm[2 * t];
            const M p1 = !g1 ? qr_mask_zero<CFG>() : xa[2 * t + 1] ? uni : xm[2 * t + 1];
            if (STRUCT) {
                msk[i0] = p0;
                if (g1) msk[i1] = p1;
            }
            const bool z0 = STRUCT ? qr_mask_bit<CFG>(p0, col) : e0 != T(0);
            const bool z1 = STRUCT ? g1 && qr_mask_bit<CFG>(p1, col) : e1 != T(0);
            anyc = anyc || (i0 >= col && z0) || (i1 >= col && z1);
            const bool o0 = i0 == col || (i0 > col && z0);
            const bool o1 = i1 == col || (i1 > col && z1);
#ifdef FGC_QR_TWO_ROWS
            // by row parity (the broadcast's lanes): the pivot at 1, even rows at 2 + 2a, odd
            // rows at 3 + 2a
            const bool b0 = o0 && i0 > col, b1 = o1 && i1 > col;
            const int s0 = i0 == col ? 1 : ((i0 & 1) == 0 ? 2 + 2 * me : 3 + 2 * mo);
            const int me1 = b0 && (i0 & 1) == 0 ? me + 1 : me;
            const int mo1 = b0 && (i0 & 1) == 1 ? mo + 1 : mo;
            const int s1 = i1 == col ? 1 : ((i1 & 1) == 0 ? 2 + 2 * me1 : 3 + 2 * mo1);
            if (o0) {
                vout[s0].val = e0;
                vout[s0].idx = i0;
            }
            if (o1) {
                vout[s1].val = e1;
                vout[s1].idx = i1;
            }
            me = b1 && (i1 & 1) == 0 ? me1 + 1 : me1;
            mo = b1 && (i1 & 1) == 1 ? mo1 + 1 : mo1;
            m += (o0 ? 1 : 0) + (o1 ? 1 : 0);
#else
            if (o0) {
                vout[1 + m].val = e0;
                vout[1 + m].idx = i0;
            }
            const int m1 = o0 ? m + 1 : m;
            if (o1) {
                vout[1 + m1].val = e1;
                vout[1 + m1].idx = i1;
            }
            m = o1 ? m1 + 1 : m1;
#endif
            if (i0 > col) evec[i0] = e0;
            if (i1 > col) evec[i1] = e1;
            part[t % P] += T((i0 >= col ? T(e0 * e0) : T(0)) + (i1 >= col ? T(e1 * e1) : T(0)));
        }
        FGC_CYCLES("qr_evaluate", 0, "axpy_norm", kpairs, 1,
                   2 * CFG::MUL_LAT + 3 * CFG::ADD_LAT);
    }
    const T norm2 = fold_partials<T, P>(part);  // depth La ceil(log2 P)
    FGC_CYCLES("qr_evaluate", 0, "fold", 1, 1, CFG::ADD_LAT * ceil_log2(P));
    if (n <= 1) {  // qr_finish's words, not needed here (v_0, tau, R_jj)
        FGC_WAIT("qr_evaluate", 0, "qr_finish", 0, "v0");
        etq.read();
        FGC_CYCLES("qr_evaluate", 0, "pivot_word", 1, 1, 1);
        FGC_WAIT("qr_evaluate", 0, "qr_finish", 0, "tau");
        etq.read();
        etq.read();
        FGC_CYCLES("qr_evaluate", 0, "tail", 2, 1, 1);
    }
    // nothing to reflect: n' = 0 (STRUCT: no row from j + 1 on non-zero by structure in column
    // j + 1; else every entry 0, or too small to square)
    if (STRUCT ? !anyc : !(norm2 > T(0))) m = 0;
    vout[0].val = T(0);
    vout[0].idx = m;
#ifdef FGC_QR_TWO_ROWS
    vout[1].idx = me;  // the pivot's slot: how many of the words below it are on even rows
#endif
    hout[0].val = norm2;
    hout[0].idx = m;
    hout[1].val = pivot;
    hout[1].idx = col;
}

// A passed-row sink and source that pass nothing (qr_step: every step but the wave's two).
template <class T, int S>
struct qr_no_pass {
    void write(const qr_pass_word<T, S>&) {}
    qr_pass_word<T, S> read() {
        qr_pass_word<T, S> w;
        for (int v = 0; v < S; ++v) {
            w.pw[v] = T(0);
            w.at[v] = QR_PASS_NONE;
        }
        return w;
    }
};
// A sink for the words a collector writes that takes none (qr_step: every step but lin_level's
// wave's two sets', whose collectors stream them to its commit process).
template <class T>
struct qr_no_commit {
    void write(const qr_commit_pair<T>&) {}
};
// A commit stream's pair out at a row's word i (its odd word, with the even one `held` before
// it; or the row's last word alone, its pair's second word 0).
template <class T, class COMMIT>
inline void qr_commit_word(COMMIT& commitq, T held, T x, int i, bool last) {
#pragma HLS INLINE
    if ((i & 1) == 1 || last) {
        qr_commit_pair<T> two;
        two.pw[0] = (i & 1) == 1 ? held : x;
        two.pw[1] = (i & 1) == 1 ? x : T(0);
        commitq.write(two);
    }
}
template <class PASS>
struct qr_passes {
    enum { value = 1 };
};
template <class T, int S>
struct qr_passes<qr_no_pass<T, S> > {
    enum { value = 0 };
};

// The collector: row j of R, final after reflection j (R_jj from qr_finish, the next pivot
// column's entry from the Evaluate, the rest from the Update units in column order), into cond
// (j < f) or update (f <= j < f + nf), and its largest magnitude into the running scale (a
// function argument read before it is written).
// PASS: qr_no_pass (nothing more), or the wave's stream (hls::stream<qr_pass_word<T, S> >)
// that also takes each passed row's words (f <= j < f + nf) as they are written into update,
// where `pass`: word q into the slot pack[q] names (its bank's, with its local column in the
// root's banks), the stream word out after the last word it holds (pack[q]'s bit 16), so that
// the root's set writes a stream word into its banks in one cycle (qr_feed_row). COMMIT:
// qr_no_commit, or (lin_level's wave) a stream (hls::stream<qr_commit_pair<T> >) that takes, where
// `pass`, the words written into cond and then, where `commit_nf` (set 0: its passed rows are
// the other set's and NF's), into update, in that order, a pair of one row's words a stream
// word (the conditional's f rows of w + 1 words, then the new factor's nf rows of s + 1:
// qr_commit's order and places), which lin_level's commit process writes into COND and NF as
// they come (fgc_eliminate.h's qr_commit_pairs), so that no commit loop follows the step (set
// 1's step c1 and the root: their conditionals; c1's passed rows went into the root by its own
// stream). coff: the conditional's first word in cond (the wave's root: after its set's own
// step's).
template <class CFG, class PASS, class COMMIT>
void qr_collect(int j, int rows, int f, int s, int k, hls::stream<typename CFG::T>& rq,
                hls::stream<typename CFG::T>& exq, hls::stream<typename CFG::T> rowq[CFG::N_UNITS],
                typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
                typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], typename CFG::T* scale,
                PASS& passq, bool pass, COMMIT& commitq, int coff, const int pack[CFG::MAX_COLS],
                bool commit_nf) {
    typedef typename CFG::T T;
    enum { S = 2 * CFG::N_UNITS };
    const int w = f + s, cols = w + 1;
    const int last = rows < w ? rows : w;
    const int nf = last - f > 0 ? last - f : 0;
    const T diag = rq.read();
    FGC_CYCLES("qr_collect", 0, "header", 1, 1, 1);
    if (j < 0 || j >= k) return;
    T big = *scale;
    qr_pass_word<T, S> word;  // a passed row's words as the root's banks take them (pack)
    for (int v = 0; v < S; ++v) {
#pragma HLS UNROLL
        word.pw[v] = T(0);
        word.at[v] = QR_PASS_NONE;
    }
    T held = T(0);  // a row's even word, out with the odd one after it (a commit pair)
    // from the row's first column out (0 in cond, f in update: zeros left of the diagonal, as
    // the parent's assembly copies whole rows) to the right-hand side:
    // trip w + 1 - first, II 1, depth 2 (read, compare)
    const int first = j < f ? 0 : f;
    for (int c = first; c < cols; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
#pragma HLS PIPELINE II=1
        T x = T(0);
        if (c == j) {
            x = diag;
        } else if (c == j + 1 && j + 1 < k) {
            x = exq.read();  // the next pivot column's: the Evaluate updated it
        } else if (c > j) {
            for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
                if (u == c % CFG::N_UNITS) x = rowq[u].read();
            }
        }
        if (j < f) {
            cond[coff + j * cols + c] = x;
            if (pass) qr_commit_word<T>(commitq, held, x, c, c == cols - 1);
            held = x;
        } else if (j - f < nf) {
            const int q = c - f;
            update[(j - f) * (s + 1) + q] = x;
            if (pass) {
                if (commit_nf) qr_commit_word<T>(commitq, held, x, q, c == cols - 1);
                held = x;
                // word q into its slot (pack[q]: slot | local column << 8 | out << 16), the
                // stream word out after its last word (the emitter's table: units/qr.py's
                // pass_pack)
                const int pk = pack[q], slot = pk & 255;
                for (int v = 0; v < S; ++v) {
#pragma HLS UNROLL
                    if (v == slot) {
                        word.pw[v] = x;
                        word.at[v] = (unsigned char)((pk >> 8) & 255);
                    }
                }
                if ((pk >> 16) & 1) {
                    passq.write(word);
                    for (int v = 0; v < S; ++v) {
#pragma HLS UNROLL
                        word.at[v] = QR_PASS_NONE;
                    }
                }
            }
        }
        const T mag = qr_abs(x);
        big = mag > big ? mag : big;
    }
    *scale = big;
    FGC_CYCLES("qr_collect", 0, "row", cols - first, 1, 2);
}

// One reflection: the DATAFLOW region (see the top of the file).
template <class CFG, class PASS, class COMMIT>
void qr_reflection(int j, int rows, int f, int s, int cols, int k,
                   const qr_word<typename CFG::T> vin[CFG::MAX_ROWS + QR_VEC_SLACK],
                   const qr_word<typename CFG::T> hin[2],
                   qr_word<typename CFG::T> vout[CFG::MAX_ROWS + QR_VEC_SLACK],
                   qr_word<typename CFG::T> hout[2],
                   typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                   typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
                   typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS],
                   typename CFG::T* scale, typename CFG::T evec[CFG::MAX_ROWS], PASS& passq,
                   bool pass, COMMIT& commitq, int coff, const int pack[CFG::MAX_COLS],
                   bool commit_nf, const qr_rowmask<CFG>* mask0,
                   qr_rowmask<CFG> msk[CFG::MAX_ROWS]) {
#pragma HLS DATAFLOW
    enum { V_DEPTH = 2 * CFG::ADD_LAT };  // plan.py's qr<s>_v channel (pragma constants: enums)
    hls::stream<qr_vq_word<typename CFG::T> > vq[CFG::N_UNITS];
#pragma HLS STREAM variable=vq depth=V_DEPTH
    hls::stream<qr_word<typename CFG::T> > tq[CFG::N_UNITS];
#pragma HLS STREAM variable=tq depth=2
    hls::stream<typename CFG::T> rq;
    // the next pivot column, a stream per row parity (its unit sends two rows a cycle)
    enum { COL_DEPTH = (CFG::MAX_ROWS + 1) / 2 };
    hls::stream<typename CFG::T> colq[CFG::N_UNITS][2];
#pragma HLS STREAM variable=colq depth=COL_DEPTH
    hls::stream<typename CFG::T> rowq[CFG::N_UNITS];
#pragma HLS STREAM variable=rowq depth=CFG::LOCAL_COLS
    // the vector's header for the Evaluate (its words it keeps itself, in evec)
    hls::stream<qr_word<typename CFG::T> > evq;
#pragma HLS STREAM variable=evq depth=2
    hls::stream<qr_word<typename CFG::T> > etq;
#pragma HLS STREAM variable=etq depth=3
    hls::stream<typename CFG::T> exq;
#pragma HLS STREAM variable=exq depth=2
    FGC_REGION("qr_reflection");
    qr_broadcast<CFG>(vin, j, k, vq, evq);
    qr_finish<CFG>(hin, k, tq, etq, rq);
    qr_update_units<CFG, 0>::run(j, rows, cols, k, vq, tq, work, colq, rowq);
    qr_evaluate<CFG>(j, rows, k, colq, evq, etq, exq, vout, hout, evec, mask0, msk);
    qr_collect<CFG, PASS, COMMIT>(j, rows, f, s, k, rq, exq, rowq, cond, update, scale, passq,
                                  pass, commitq, coff, pack, commit_nf);
    FGC_DRAINED(vq, CFG::N_UNITS);  // csim only (fgc_cycles.h)
    FGC_DRAINED(tq, CFG::N_UNITS);
    FGC_DRAINED(&colq[0][0], 2 * CFG::N_UNITS);
    FGC_DRAINED(rowq, CFG::N_UNITS);
    FGC_DRAINED(&rq, 1);
    FGC_DRAINED(&evq, 1);
    FGC_DRAINED(&etq, 1);
    FGC_DRAINED(&exq, 1);
}

// ---- the step ---------------------------------------------------------------------------------

// After the reflections (qr_step, fgc_qr_stream.h's qrs_step): true if k < f or a frontal pivot
// |R_ii| of cond (w + 1 = cols columns) is not above CFG::SINGULAR_EPS * scale (that product
// once, before the loop: one multiplier in sequential code). Trip f, II 1, depth 2 (read,
// compare).
template <class CFG>
bool qr_pivot_check(const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS], int f, int cols,
                    int k, typename CFG::T scale, int coff = 0) {
    bool bad = k < f;
    const typename CFG::T least = CFG::SINGULAR_EPS * scale;
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        if (i >= k || !(qr_abs(cond[coff + i * cols + i]) > least)) bad = true;
    }
    FGC_CYCLES("qr_pivot_check", 0, "pivot_check", f, 1, 2);
    return bad;
}


// The words qr_collect writes into cond (nc) and then update (nu) for a step of `rows` rows, f
// frontal and s separator columns (none outside the configuration: qr_step_io computes nothing).
template <class CFG>
void qr_collected_words(int rows, int f, int s, int* nc, int* nu) {
    const int cols = f + s + 1;
    const bool ok = rows >= 0 && f >= 0 && s >= 0 && rows <= CFG::MAX_ROWS &&
                    cols <= CFG::MAX_COLS && f <= CFG::MAX_F;
    const int k = rows < cols ? rows : cols;
    const int last = rows < f + s ? rows : f + s;
    const int nf = last - f > 0 ? last - f : 0;
    *nc = ok ? (k < f ? k : f) * cols : 0;
    *nu = ok ? nf * (s + 1) : 0;
}

// The root step in a wavefront (fgc_eliminate.h's qr_eliminate_all with CFG::WAVE): before its
// region j the root's unit set reads the fed child's passed rows whose entry[i] <= j (the
// region that first needs row i: units/qr.py's wave_entries), row i into the root's row
// row0 + i, `words` stream words (units/qr.py's pass_words), each of 2 * N_UNITS slots as the
// banks take them: slot 2u + h into bank u at its local column at[2u + h] (two writes into
// any bank memory a cycle, its two ports; the bank of each write fixed). A row's read waits
// for the child's region that wrote it (fgc_cycles.h's FGC_WAVE_WAIT): trip `words`, II 1,
// depth 2.
template <class CFG, class FEED>
void qr_feed_row(FEED& feedq, typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                 int row, int words, int i) {
    (void)i;  // (the count's key only)
    FGC_WAVE_WAIT(i);
    for (int p = 0; p < words; ++p) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
#pragma HLS PIPELINE II=1
        const qr_pass_word<typename CFG::T, 2 * CFG::N_UNITS> x = feedq.read();
        for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
            for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
                const int a = x.at[2 * u + h];
                if (a != QR_PASS_NONE) work[u][row][a] = x.pw[2 * u + h];
            }
        }
    }
    FGC_CYCLES("qr_feed", 0, "wave_row", words, 1, 2);
}

// qr_step with the wave's ends: PASS (the fed child's set: where `pass`, its passed rows out as
// its collector writes them, word q into the stream word's slot pack[q] says) and FEED (the
// root's set: nfed rows of `words` stream words read before the regions that need them);
// qr_no_pass for neither. FGC_WAVE_READY after the region that finished each passed row. A unit
// set calls it from one site, so its units are one RTL copy whatever it runs.
// coff: the conditional's first word in cond (lin_level's wave: the root's after step c1's).
// COMMIT (qr_collect's commitq, where `pass`): lin_level's wave's sets stream their steps'
// words to its commit process as their collectors write them. ready false: no FGC_WAVE_READY
// marks and the passed rows not into COMMIT (lin_level's wave's set 1, whose collector packs
// its own step's passed rows for itself: qr_collect's commit_nf is `ready`).
// mask0 (qr_step_structural; 0: none): the step's rows' patterns, the Evaluate keeping rows by
// structure (qr_evaluate).
template <class CFG, class PASS, class FEED, class COMMIT>
void qr_step_io(typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS], int rows,
                int f, int s, typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
                typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], bool* singular,
                PASS& passq, bool pass, COMMIT& commitq, FEED& feedq, const int entry[CFG::MAX_COLS],
                const int pack[CFG::MAX_COLS], int row0, int nfed, int words,
                int coff = 0, bool ready = true, const qr_rowmask<CFG>* mask0 = 0) {
    typedef typename CFG::T T;
    const int cols = f + s + 1;
    if (rows < 0 || f < 0 || s < 0 || rows > CFG::MAX_ROWS || cols > CFG::MAX_COLS ||
        f > CFG::MAX_F) {
        *singular = true;  // outside the configuration: nothing is computed
        return;
    }
    const int k = rows < cols ? rows : cols;
    const int last = rows < f + s ? rows : f + s;
    const int nf = last - f > 0 ? last - f : 0;
    enum { MAX_REGIONS = CFG::MAX_COLS + 1 };
    // the reflector's two buffers (vector va / vb, norm and pivot ha / hb): region j reads va, ha
    // and writes vb, hb for even j + 1, the other way round for odd j + 1 (a ping-pong between
    // regions, no buffer read and written in one)
    qr_word<T> va[CFG::MAX_ROWS + QR_VEC_SLACK], vb[CFG::MAX_ROWS + QR_VEC_SLACK], ha[2], hb[2];
    va[0].val = T(0);  // region -1 reads va, ha: an empty reflection
    va[0].idx = 0;
    ha[0].val = T(0);
    ha[0].idx = 0;
    ha[1].val = T(0);
    ha[1].idx = -1;
    T scale = T(0);
    // the Evaluate's own copy of the vector below the pivot, by row (qr_evaluate): read two rows
    // a cycle (two memories by row parity), its rows cleared by region -1 before any is read
    T evec[CFG::MAX_ROWS];
#pragma HLS ARRAY_PARTITION variable=evec cyclic factor=2
    // (STRUCT) the rows' patterns, the Evaluate's too (two a cycle, as evec; unused otherwise)
    qr_rowmask<CFG> msk[CFG::MAX_ROWS];
#pragma HLS ARRAY_PARTITION variable=msk cyclic factor=2
    // the two parity call sites below are exclusive and sequential: one RTL copy of the region
    // serves both (UG1399, ALLOCATION of a function: one instance for its call sites)
#pragma HLS ALLOCATION function instances=qr_reflection<CFG,PASS,COMMIT> limit=1
    int fed = 0;
    for (int j = -1; j < k; ++j) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_REGIONS
        for (; fed < nfed && entry[fed] <= j; ++fed) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
            qr_feed_row<CFG, FEED>(feedq, work, row0 + fed, words, fed);
        }
        if (((j + 1) & 1) == 0) {
            qr_reflection<CFG, PASS, COMMIT>(j, rows, f, s, cols, k, va, ha, vb, hb, work, cond,
                                             update, &scale, evec, passq, pass, commitq, coff,
                                             pack, ready, mask0, msk);
        } else {
            qr_reflection<CFG, PASS, COMMIT>(j, rows, f, s, cols, k, vb, hb, va, ha, work, cond,
                                             update, &scale, evec, passq, pass, commitq, coff,
                                             pack, ready, mask0, msk);
        }
        FGC_SEQUENTIAL();
        if (qr_passes<PASS>::value && pass && ready && j >= f && j - f < nf)
            FGC_WAVE_READY(j - f);
    }
    *singular = qr_pivot_check<CFG>(cond, f, cols, k, scale, coff);
}

template <class CFG>
void qr_step(typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS], int rows, int f,
             int s, typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
             typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], bool* singular) {
    qr_no_pass<typename CFG::T, 2 * CFG::N_UNITS> none;
    qr_no_commit<typename CFG::T> kept;
    const int nothing[CFG::MAX_COLS] = {0};
    qr_step_io<CFG, qr_no_pass<typename CFG::T, 2 * CFG::N_UNITS>,
               qr_no_pass<typename CFG::T, 2 * CFG::N_UNITS>,
               qr_no_commit<typename CFG::T> >(work, rows, f, s, cond, update, singular, none,
                                                false, kept, none, nothing, nothing, 0, 0, 0);
}

// qr_step with the keep rule by structure (qr_evaluate's STRUCT): mask0[i], row i's pattern
// over columns 0 ... w (the right-hand side last; every value non-zero in the stack must be on
// it, a pattern's non-zero may be zero in value). The reflections then count the cycles the
// plan prices on that pattern (units/qr.py's qr_unit_loops with it and its right-hand side),
// whatever the values: a kept row zero in value adds zeros, a column zero in value on a
// structurally non-empty column is reflected with tau = 0.
template <class CFG>
void qr_step_structural(typename CFG::T work[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                        int rows, int f, int s, typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
                        typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], bool* singular,
                        const qr_rowmask<CFG> mask0[CFG::MAX_ROWS]) {
    qr_no_pass<typename CFG::T, 2 * CFG::N_UNITS> none;
    qr_no_commit<typename CFG::T> kept;
    const int nothing[CFG::MAX_COLS] = {0};
    qr_step_io<CFG, qr_no_pass<typename CFG::T, 2 * CFG::N_UNITS>,
               qr_no_pass<typename CFG::T, 2 * CFG::N_UNITS>,
               qr_no_commit<typename CFG::T> >(work, rows, f, s, cond, update, singular,
                                                none, false, kept, none, nothing, nothing, 0, 0,
                                                0, 0, true, mask0);
}

}  // namespace fgc_units

#endif  // FGC_QR_H
