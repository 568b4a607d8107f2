// fgc_cpe.h: the Cholesky cascade of the accelerator (paper B's linear solver): N_CPE Cholesky
// process elements linked by FIFOs factor one elimination step's frontal matrix [H | g], N_CPE
// pivots a round; between rounds the trailing matrix goes back to memory.
//
// Fixed code, configured by a struct of constants (CFG, see cpe_config_example below); the emitted
// design (the hls-accel part of the backend) assembles each step's [H | g] and calls cpe_step<CFG>.
//
// ---- interface ------------------------------------------------------------------------------
//
//   template <class CFG>
//   void cpe_step(typename CFG::T H[CFG::MAX_W][CFG::MAX_COLS], int f, int s, typename CFG::T mu,
//                 typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
//                 typename CFG::T update[CFG::MAX_W * CFG::MAX_COLS],
//                 bool* not_pd, bool* singular);
//
//   and cond_backsub<CFG> (fgc_backsub.h, included) for the step's back-substitution.
//
// In: the step's [H | g], w = f + s rows, row-major with w + 1 used columns: H[i][c] for
// i <= c < w is the upper triangle of the frontal-and-separator Hessian (the sum of its factors'
// Grams and its children's update matrices), H[i][w] the gradient; entries left of the diagonal
// are not read. mu (Levenberg-Marquardt damping, 0 for Gauss-Newton) is added to the f frontal
// diagonal entries here. H is overwritten (it is one of the cascade's two trailing-matrix
// buffers; cpe_step holds the other).
//
// Out:
// - cond: the conditional (R | S | d): rows 0 ... f - 1 of U = L^T, row-major with w + 1 columns,
//   cond[i * (w + 1) + c], c >= i (R = U_ff upper triangular, S = L_ff^-1 H_fs, d = L_ff^-1 g_f,
//   the forward solve L z = g riding in the cascade as the last column); left of the diagonal
//   nothing is written (back-substitution never reads it).
// - update: the Schur complement for the parent, s rows of s + 1 columns:
//   update[a * (s + 1) + b] = (H_ss - S^T S)[a][b] for a <= b < s, the reduced gradient
//   g_s - S^T d in column s (b = s); left of the diagonal nothing is written (the parent reads
//   an update matrix's upper triangle).
// - *not_pd: a pivot (after the updates of the earlier pivots) was not > 0: not positive definite;
//   *singular: not_pd, or a pivot |U_ii| (i < f) is not above CFG::SINGULAR_EPS * scale, scale =
//   the largest |U_ic|, i <= c < f (the kernel's rule). Both true, with nothing computed, if
//   w > MAX_W or f > MAX_F. cond and update are written in any case.
// - the back-substitution R x = d - S xs is cond_backsub<CFG> (fgc_backsub.h): the trisolve
//   unit of plan.py, sequential; R^T is never needed since L z = g ran in the cascade.
//
// ---- arithmetic (the kernel's cholesky_frontal, kernel.cpp.jinja) -----------------------------
//
// Pivot p: d = H[p][p] (must be > 0), inv = 1 / sqrt(d), U[p][c] = H[p][c] * inv (c >= p); every
// later row i > p: H[i][c] -= U[p][i] * U[p][c] (c >= i). The kernel updates the entries of the
// pivot's tile as (H_pi / H_pp) * H_pc, here always U_pi * U_pc: equal to rounding (~1e-15
// relative in double), not bit for bit.
//
// ---- structure (UG1399 canonical dataflow) -------------------------------------------------
//
// Round r (pivots p0 = r N_CPE ... min(f, p0 + N_CPE) - 1) is one DATAFLOW region, cpe_round; the
// rounds are a sequential loop in cpe_step (round r + 1 reads what round r wrote back). The
// trailing matrix goes from round to round through two arrays, H and cpe_step's own Hb,
// alternating with the parity of r: round r reads one (Hin, only read in the region) and writes
// the other (Hout, only written), round r + 1 the other way round:
//
//   cpe_feed      streams rows p0 ... w - 1 of Hin, row i from its diagonal to the gradient
//                 (w + 1 - i words), then a status word 0, into link[0];
//   cpe<K>        K = 0 ... N_CPE - 1 (one process each, through cpe_cascade): reads link[K],
//                 writes link[K + 1]. Its pivot is p = p0 + K (none if p >= f: it passes every
//                 word). Rows p0 ... p - 1 (rows of U of the CPEs before it) pass; row p is the
//                 first row it changes: Evaluate (check, sqrt, 1 / pivot, the row of U, kept in
//                 the CPE and passed on); every later row is Updated entry by entry and passed on.
//                 The status word passes ORed with its own not-positive-definite flag;
//   cpe_drain     writes the words into Hout (rows of U and the trailing matrix); the round's
//                 final rows also straight out: its pivots' rows of U into cond (and their frontal
//                 entries' largest magnitude into its scale output) and, in the last round, the
//                 trailing rows into update; the status into its output argument. It is the only
//                 writer of Hout, cond, update, the scale and the status in the region; each
//                 stream and array of the region has one writer and one later reader.
//
// cpe_step adds mu first (sequential), runs the rounds, and checks the pivots against the largest
// scale of the rounds last (sequential, f compares): no copy of the factor after the cascade.
//
// ---- cycles -------------------------------------------------------------------------------
//
// Each pipelined loop states its trip count, II and depth and reports them to FGC_CYCLES
// (fgc_cycles.h). A round streams m (m + 1) / 2 + m words, m = w - p0 (plan.py's round words);
// a CPE counts as one stream of them, depth Ls + Ld + Lm + La (La / Lm / Ld / Ls = CFG::ADD_LAT /
// MUL_LAT / DIV_LAT / SQRT_LAT). plan.py's cpe_round_depth / cpe_step_loops price these loops
// (tests/test_hls_units.py checks that they equal the count).
#ifndef FGC_CPE_H
#define FGC_CPE_H

#include <cmath>

#include "fgc_backsub.h"
#include "fgc_cycles.h"
#include "hls_stream.h"

namespace fgc_units {

// An example configuration (the emitted design defines its own).
struct cpe_config_example {
    typedef double T;
    static const int MAX_W = 12;             // frontal + separator columns of a step
    static const int MAX_COLS = MAX_W + 1;   // + the gradient
    static const int MAX_F = 6;              // frontal columns
    static const int N_CPE = 5;              // Cholesky process elements (--cpe)
    static const int PARTIALS = 12;          // partial sums of cond_backsub's dots (>= ADD_LAT)
    static const int ADD_LAT = 12, MUL_LAT = 9, DIV_LAT = 57, SQRT_LAT = 57;  // float64 (plan)
    static constexpr double SINGULAR_EPS = 1e-12;
};

template <class T>
inline T cpe_abs(T x) {
    return x < T(0) ? T(-x) : x;
}

// Words of rows first ... w - 1, row i from column i to w: sum (w + 1 - i).
inline int cpe_words(int first, int w) {
    const int m = w - first;
    return m > 0 ? m * (m + 1) / 2 + m : 0;
}

// Stream rows p0 ... w - 1 (upper triangle and gradient), then the status word.
template <class CFG>
void cpe_feed(const typename CFG::T Hin[CFG::MAX_W][CFG::MAX_COLS], int p0, int w,
              hls::stream<typename CFG::T>& out) {
    typedef typename CFG::T T;
    enum { MAX_WORDS = CFG::MAX_W * (CFG::MAX_W + 3) / 2 };
    const int words = cpe_words(p0, w);
    int i = p0, c = p0;
    // trip m (m + 1) / 2 + m, II 1, depth 2 (read, write)
    for (int t = 0; t < words; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
        out.write(Hin[i][c]);
        if (c == w) {
            ++i;
            c = i;
        } else {
            ++c;
        }
    }
    out.write(T(0));  // status: nothing wrong upstream
    FGC_CYCLES("cpe_feed", 0, "rows", words + 1, 1, 2);
}

// CPE K of the cascade for the round starting at pivot p0.
template <class CFG, int K>
void cpe(int p0, int w, int f, hls::stream<typename CFG::T>& in,
         hls::stream<typename CFG::T>& out) {
    typedef typename CFG::T T;
    enum { MAX_WORDS = CFG::MAX_W * (CFG::MAX_W + 3) / 2 };
    const int p = p0 + K;
    const int words = cpe_words(p0, w);
    if (p >= f) {  // no pivot in this round: pass every word and the status
        // trip words + 1, II 1, depth 1
        for (int t = 0; t <= words; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
            out.write(in.read());
        }
        FGC_CYCLES("cpe", K, "pass", words + 1, 1, 1);
        return;
    }
    const int before = words - cpe_words(p, w);  // rows p0 ... p - 1
    // rows of U from the CPEs before: trip before, II 1, depth 1 (this and the next two loops
    // are priced together as the CPE's one stream, see the count at the end)
    for (int t = 0; t < before; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
        out.write(in.read());
    }
    // Evaluate: the pivot, its square root and reciprocal (Ls + Ld, the stream stalls)
    T u[CFG::MAX_COLS];  // row p of U, u[c - p]
    const T d = in.read();
    const bool bad = !(d > T(0));
    const T inv = T(1) / std::sqrt(d);
    u[0] = d * inv;
    out.write(u[0]);
    // the rest of row p of U: trip w - p, II 1, depth Lm (after the Evaluate's Ls + Ld)
    for (int c = p + 1; c <= w; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_W
#pragma HLS PIPELINE II=1
        const T x = in.read() * inv;
        u[c - p] = x;
        out.write(x);
    }
    // Update the later rows entry by entry: trip (w-p-1)(w-p)/2 + w-p-1, II 1, depth Lm + La
    const int after = cpe_words(p + 1, w);
    int i = p + 1, c = p + 1;
    for (int t = 0; t < after; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
        const T x = in.read();
        out.write(x - u[i - p] * u[c - p]);
        if (c == w) {
            ++i;
            c = i;
        } else {
            ++c;
        }
    }
    const T status = in.read();
    out.write(bad || status != T(0) ? T(1) : T(0));
    // The four loops are one stream of words + 1 words at a word a cycle whose only stall is the
    // Evaluate: counted as one loop, trip words + 1, II 1, depth Ls + Ld + Lm + La (the CPE's
    // latency, what it adds to the cascade; plan.py's cpe_depth).
    FGC_CYCLES("cpe", K, "stream", words + 1, 1,
               CFG::SQRT_LAT + CFG::DIV_LAT + CFG::MUL_LAT + CFG::ADD_LAT);
}

// The N_CPE processes, K = 0 ... N_CPE - 1, as separate calls in the region.
template <class CFG, int K, bool END = (K == CFG::N_CPE)>
struct cpe_cascade {
    static void run(int p0, int w, int f, hls::stream<typename CFG::T> link[CFG::N_CPE + 1]) {
#pragma HLS INLINE
        cpe<CFG, K>(p0, w, f, link[K], link[K + 1]);
        cpe_cascade<CFG, K + 1>::run(p0, w, f, link);
    }
};

template <class CFG, int K>
struct cpe_cascade<CFG, K, true> {
    static void run(int, int, int, hls::stream<typename CFG::T>*) {
#pragma HLS INLINE
    }
};

// Write the round's words into Hout, the final ones also out: the rows of U of the round's
// pivots into cond (their frontal entries' largest magnitude into *scale) and, in the last round,
// the trailing rows into update; the status into *bad.
template <class CFG>
void cpe_drain(hls::stream<typename CFG::T>& in, int p0, int w, int f,
               typename CFG::T Hout[CFG::MAX_W][CFG::MAX_COLS],
               typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
               typename CFG::T update[CFG::MAX_W * CFG::MAX_COLS], typename CFG::T* scale,
               bool* bad) {
    typedef typename CFG::T T;
    enum { MAX_WORDS = CFG::MAX_W * (CFG::MAX_W + 3) / 2 };
    const int words = cpe_words(p0, w);
    const int cols = w + 1, s = w - f;
    const int done = p0 + CFG::N_CPE < f ? p0 + CFG::N_CPE : f;  // rows p0 ... done - 1 are final
    const bool last = done == f;
    T big = T(0);
    int i = p0, c = p0;
    // trip m (m + 1) / 2 + m (+ the status word), II 1, depth 2 (read, write)
    for (int t = 0; t < words; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
        const T x = in.read();
        Hout[i][c] = x;
        if (i < done) {
            cond[i * cols + c] = x;
            const T mag = c < f ? cpe_abs(x) : T(0);
            big = mag > big ? mag : big;
        } else if (last && i >= f) {
            update[(i - f) * (s + 1) + (c - f)] = x;
        }
        if (c == w) {
            ++i;
            c = i;
        } else {
            ++c;
        }
    }
    *scale = big;
    *bad = in.read() != T(0);
    FGC_CYCLES("cpe_drain", 0, "rows", words + 1, 1, 2);
}

// One round of N_CPE pivots from p0: the DATAFLOW region (see the top of the file).
template <class CFG>
void cpe_round(int p0, int w, int f, const typename CFG::T Hin[CFG::MAX_W][CFG::MAX_COLS],
               typename CFG::T Hout[CFG::MAX_W][CFG::MAX_COLS],
               typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
               typename CFG::T update[CFG::MAX_W * CFG::MAX_COLS], typename CFG::T* scale,
               bool* bad) {
#pragma HLS DATAFLOW
    enum { LINK_DEPTH = CFG::MAX_W };  // plan.py's cpe_fifo channels: depth n
    hls::stream<typename CFG::T> link[CFG::N_CPE + 1];
#pragma HLS STREAM variable=link depth=LINK_DEPTH
    FGC_REGION("cpe_round");
    cpe_feed<CFG>(Hin, p0, w, link[0]);
    cpe_cascade<CFG, 0>::run(p0, w, f, link);
    cpe_drain<CFG>(link[CFG::N_CPE], p0, w, f, Hout, cond, update, scale, bad);
    FGC_DRAINED(link, CFG::N_CPE + 1);  // csim only (fgc_cycles.h)
}

// ---- the step ---------------------------------------------------------------------------------

template <class CFG>
void cpe_step(typename CFG::T H[CFG::MAX_W][CFG::MAX_COLS], int f, int s, typename CFG::T mu,
              typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
              typename CFG::T update[CFG::MAX_W * CFG::MAX_COLS], bool* not_pd, bool* singular) {
    typedef typename CFG::T T;
    enum { MAX_ROUNDS = (CFG::MAX_F + CFG::N_CPE - 1) / CFG::N_CPE };
    const int w = f + s;
    if (f < 0 || s < 0 || w > CFG::MAX_W || f > CFG::MAX_F) {
        *not_pd = true;  // outside the configuration: nothing is computed
        *singular = true;
        return;
    }
    // mu on the frontal diagonal: trip f, II 1, depth La
    for (int j = 0; j < f; ++j) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        H[j][j] += mu;
    }
    FGC_CYCLES("cpe_step", 0, "damping", f, 1, CFG::ADD_LAT);
    bool npd = false;
    T scale = T(0);
    // the trailing matrix's second buffer: round r reads H and writes Hb for even r, the other
    // way round for odd r (a ping-pong between rounds, no array read and written in one)
    T Hb[CFG::MAX_W][CFG::MAX_COLS];
    for (int r = 0; r * CFG::N_CPE < f; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_ROUNDS
        const int p0 = r * CFG::N_CPE;
        bool round_bad = false;
        T round_scale = T(0);
        if ((r & 1) == 0) {
            cpe_round<CFG>(p0, w, f, H, Hb, cond, update, &round_scale, &round_bad);
        } else {
            cpe_round<CFG>(p0, w, f, Hb, H, cond, update, &round_scale, &round_bad);
        }
        FGC_SEQUENTIAL();
        npd = npd || round_bad;
        scale = round_scale > scale ? round_scale : scale;
    }
    // f == 0: no round; the update matrix is [H | g] as it came
    const int words = f == 0 ? cpe_words(0, w) : 0;
    for (int t = 0, i = 0, c = 0; t < words; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_W
#pragma HLS PIPELINE II=1
        update[i * (w + 1) + c] = H[i][c];
        if (c == w) {
            ++i;
            c = i;
        } else {
            ++c;
        }
    }
    FGC_CYCLES("cpe_step", 0, "no_pivots", words, 1, 1);
    // the pivots against the scale: trip f, II 1, depth 2 (read, compare)
    bool tiny = false;
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        if (!(cpe_abs(cond[i * (w + 1) + i]) > CFG::SINGULAR_EPS * scale)) tiny = true;
    }
    FGC_CYCLES("cpe_step", 0, "pivot_check", f, 1, 2);
    *not_pd = npd;
    *singular = npd || tiny;
}

}  // namespace fgc_units

#endif  // FGC_CPE_H
