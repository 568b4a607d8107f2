// fgc_cpe.h: the Cholesky cascade of the accelerator (paper B's linear solver): N_CPE Cholesky
// process elements linked by FIFOs factor one elimination step's frontal matrix [H | g], N_CPE
// pivots a round; between rounds the trailing matrix goes back to memory.
//
// Fixed code, configured by a struct of constants (CFG, see cpe_config_example below); the emitted
// design (fgc_eliminate.h's cholesky_overlap) streams each step's [H | g] from its assembly into
// cpe_step<CFG>.
//
// ---- interface ------------------------------------------------------------------------------
//
//   template <class CFG>
//   void cpe_step(hls::stream<cpe_pair<typename CFG::T> >& src,
//                 typename CFG::T H[CFG::MAX_W][CFG::MAX_COLS], int f, int s, typename CFG::T mu,
//                 typename CFG::T cond[CFG::N_COND], int c0,
//                 typename CFG::T update[CFG::N_NF], int u0, bool* not_pd, bool* singular);
//
//   its two halves, cpe_rounds<CFG> (the rounds, each pivot row's pivot and largest |h| out)
//   and cpe_check<CFG> (the pivot check on them), for a driver that checks a step later
//   (fgc_cascades.h: beside the next region), and cond_backsub<CFG> (fgc_backsub.h, included)
//   for the step's back-substitution.
//
// In: src, the step's [H | g], w = f + s rows, each row from its diagonal to the gradient, two
// words a stream word (cpe_pair; cpe_pairs(w) of them, none if the step does not fit: cpe_fits):
// row i's columns i <= c < w are the upper triangle of the frontal-and-separator Hessian (the
// sum of its factors' Grams and its children's update matrices), column w the gradient. mu
// (Levenberg-Marquardt damping, 0 for Gauss-Newton) is added to the f frontal diagonal entries
// as the first round reads them. H: the buffer the trailing matrix goes through between rounds
// (with Tb inside cpe_step); a round reads only the words the copy back wrote into it. With
// CFG::STREAM_WORDS = 1 every word a later round reads it clears (H all zero on entry stays so); with
// STREAM_WORDS = 2 the feed reads two words a cycle and clears none (the array's two ports).
//
// Out:
// - cond[c0 + i * (w + 1) + c], i < f, c >= i: the conditional, row i of the factor as the pivot
//   left it: h_i = sqrt(d_i) U_i, U = L^T (R = U_ff, S, and d = L^-1 g in column w, the forward
//   solve riding in the cascade as the last column), each row scaled by the square root of its
//   pivot d_i = h_ii. The back-substitution R x = d - S xs solves the same system from these rows
//   (a row and its right-hand side scaled alike), so no square root is ever taken. Left of the
//   diagonal nothing is written (back-substitution never reads it).
// - update[u0 + a * (s + 1) + b]: the Schur complement for the parent, s rows of s + 1 columns,
//   (H_ss - S^T S)[a][b] for a <= b < s and the reduced gradient g_s - S^T d in column s; left of
//   the diagonal nothing is written (the parent reads an update matrix's upper triangle).
//   cond and update are the kernel's COND and NF: no copy after the cascade.
// - *not_pd: a pivot (after the updates of the earlier pivots) was not > 0: not positive definite;
//   *singular: not_pd, or a pivot |U_ii| (i < f) is not above CFG::SINGULAR_EPS * scale, scale =
//   the largest |U_ic|, i <= c < f (the kernel's rule, evaluated on h: U_ii^2 = d_i and
//   |U_ic| = |h_ic| / sqrt(d_i), so d_i > eps^2 max_j (max_c |h_jc|)^2 / d_j). Both true, with
//   nothing computed, if w > MAX_W or f > MAX_F.
//
// ---- arithmetic ---------------------------------------------------------------------------
//
// Pivot p: d = H[p][p] (must be > 0), r = 1 / d; row p leaves as it is (h = row p); every later
// row i > p: H[i][c] -= h[i] * (h[c] * r) (c >= i, the gradient column included), the
// right-looking update H - h h^T / d. The kernel's cholesky_frontal updates with U_pi U_pc, U = h
// / sqrt(d): equal to rounding (~1e-15 relative in double), not bit for bit.
//
// ---- structure (UG1399 canonical dataflow) -------------------------------------------------
//
// The stream between the processes carries CFG::STREAM_WORDS words of a row a cycle (cpe_vec: 1, or 2 -
// the pair of a row's words the assembly streams each cycle, so a step's words take half the
// cycles; each CPE then updates both words of a pair, 2 STREAM_WORDS multipliers and STREAM_WORDS adders).
//
// Round r (pivots p0 = r N_CPE ... min(f, p0 + N_CPE) - 1) is one DATAFLOW region, cpe_round; the
// rounds are a sequential loop in cpe_step around the region's one call site (two call sites
// would be two copies of the cascade in hardware). Round 0 reads src, every later round H; the
// drain writes the rows a round leaves for the next into cpe_step's Tb, and a copy loop puts
// them back into H before that round (multi-round steps only: f > N_CPE). In each region the
// feed is the only process that touches src and H and the drain the only one that touches Tb:
//
//   cpe_feed      streams rows p0 ... w - 1, row i from its diagonal to the gradient
//                 (w + 1 - i words; + mu on the frontal diagonal in round 0), round 0's from src,
//                 a later round's from Hin, clearing each word it reads, then a status word 0,
//                 into link[0];
//   cpe_tap<K>    K = 0 ... N_CPE - 1: passes link[K] on to tapped[K] and, when the word is its
//                 CPE's pivot d, sends r = 1 / d into recip[K]: the divide runs beside the stream,
//                 its latency hidden behind the pivot's row (the CPE needs r only after the row);
//   cpe<K>        reads tapped[K], writes link[K + 1], or, its pivot the round's last (p + 1 = f,
//                 or K = N_CPE - 1), tail[K]. Its pivot is p = p0 + K; with none (p >= f) the
//                 CPE and its tap do nothing: the round's stream left the cascade at the last
//                 pivot's CPE, so CPEs past a round's pivots add nothing to its depth. Rows
//                 p0 ... p - 1 (the rows of the CPEs before it) and its pivot row p pass
//                 unchanged, row p kept as h; every later word is Updated, x - h[i] (h[c] r), r
//                 read from recip[K] at the first of them. The status word passes ORed with its
//                 own not-positive-definite flag. One pipelined loop at II 1 over the round's
//                 words: two multipliers and an adder;
//   cpe_drain     reads tail[a] (a the round's last pivot's CPE: a multiplexer over the N_CPE
//                 tails) and writes the round's final rows out: its pivots' rows into cond (each
//                 row's pivot and its largest frontal |h| into dpiv / rmax for the singularity
//                 check), and the trailing rows into update (last round) or Hout (the next
//                 round's input); the status into its output argument.
//
// cpe_step runs the rounds (each but the last followed by its copy back) and checks the pivots
// last (sequential, 2 f iterations).
//
// Each stream has one writer and one later reader; no process waits for a later one (the drain
// never stalls, so a tail is 2 deep; the tap
// writes recip[K] Ld cycles after the pivot while it goes on streaming: tapped[K] is deep enough
// - MAX_COLS + DIV_LAT + 2 words - that the tap never stalls on it while its CPE waits for r).
//
// ---- cycles -------------------------------------------------------------------------------
//
// A round streams m (m + 1) / 2 + m words, m = w - p0 (STREAM_WORDS = 2: floor((m + 2)^2 / 4) - 1
// pairs, cpe_vecs), + the status word; every process is one pipelined loop of them at II 1, so
// the round takes its words plus the depth every process adds to the stream
// (units/cholesky.py's cpe_round_depth): the feed La + 2, a tap 2, a CPE with a pivot
// 2 Lm + La + 2 plus its wait for r, max(0, Ld - its row's stream words) (0 when its row is at
// least Ld stream words long), an idle tap or CPE nothing (the stream leaves at the last
// pivot's CPE), the drain 2 (La / Lm / Ld =
// CFG::ADD_LAT / MUL_LAT / DIV_LAT). Paper B's CPE (sqrt, then divide, then its row scaled, then the update: Ls + Ld +
// Lm + La a CPE) stalled the stream on every pivot; here a pivot costs the stream 2 Lm + La + 4.
// Each loop reports trip, II and depth to FGC_CYCLES (fgc_cycles.h); tests/hls/test_hls_units.py
// checks the plan's cpe_step_loops against the count.
#ifndef FGC_CPE_H
#define FGC_CPE_H

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
    static const int STREAM_WORDS = 1;       // words a cycle through the cascade (1 or 2)
    static const int N_COND = 512, N_NF = 512;  // the kernel's COND and NF
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

// The cascade's stream word: L consecutive words of one row, the vector j of row i holding
// columns i + L j ... i + L j + L - 1 (a row of w + 1 - i words in ceil((w + 1 - i) / L) vectors;
// a lane past column w carries a word nobody reads). L = CFG::STREAM_WORDS: 1, or 2 (a cpe_pair of the
// assembly's stream is then one vector, and every process of the round handles two words a
// cycle).
template <class T, int L>
struct cpe_vec;

template <class T>
struct cpe_vec<T, 1> {
    T lo;
};

template <class T>
struct cpe_vec<T, 2> {
    T lo, hi;
};

// Word l of a vector (l a constant once the lanes' loop is unrolled).
template <class T>
inline T cpe_get(const cpe_vec<T, 1>& x, int) {
    return x.lo;
}

template <class T>
inline T cpe_get(const cpe_vec<T, 2>& x, int l) {
    return l == 0 ? x.lo : x.hi;
}

template <class T>
inline void cpe_set(cpe_vec<T, 1>& x, int, T y) {
    x.lo = y;
}

template <class T>
inline void cpe_set(cpe_vec<T, 2>& x, int l, T y) {
    if (l == 0) {
        x.lo = y;
    } else {
        x.hi = y;
    }
}

// Vectors of rows first ... w - 1 at L words a vector: the words (L = 1), or the sum of
// ceil(k / 2) over k = 2 ... m + 1 (m = w - first), floor((m + 2)^2 / 4) - 1 (L = 2).
template <int L>
inline int cpe_vecs(int first, int w) {
    const int m = w - first;
    if (m <= 0) return 0;
    return L == 1 ? m * (m + 1) / 2 + m : (m + 2) * (m + 2) / 4 - 1;
}

// Round 0's input: a step's words in the feed's order, two a word of the stream (the assembly
// reads two columns of a row a cycle): row i's words i, i + 1 | i + 2, i + 3 | ..., a row of an
// odd count ending in a pair whose hi the feed never reads.
template <class T>
struct cpe_pair {
    T lo, hi;
};

// Pairs of rows 0 ... w - 1 (row i: w + 1 - i words, ceil of half of them pairs): the sum of
// floor(k / 2) over k = 3 ... w + 2, floor((w + 2)^2 / 4) - 1.
inline int cpe_pairs(int w) { return (w + 2) * (w + 2) / 4 - 1; }

// The cycles CPE K waits for r = 1 / d: the tap sends r Ld + 2 cycles after the pivot passes
// it, and the CPE needs it after the pivot's row (row words w + 1 - p).
template <class CFG>
inline int cpe_wait(int p, int w) {
    const int row = (w + 1 - p + CFG::STREAM_WORDS - 1) / CFG::STREAM_WORDS;  // the row's vectors
    return CFG::DIV_LAT > row ? CFG::DIV_LAT - row : 0;
}

// Stream rows p0 ... w - 1 (upper triangle and gradient; dmu added on the diagonal of rows
// i < f), then the status word, L = CFG::STREAM_WORDS words a vector: round 0 (first, p0 = 0) reads
// them from src, the pairs the assembly streams in this order (fgc_eliminate.h's
// cholesky_assembler), a pair at a row's even offsets (L = 1: a word of it a cycle; L = 2: the
// pair is the vector); a later round reads them from Hin, the rows the round before left
// (L = 1: clearing each word read; L = 2: two words a cycle, not cleared - the array's two
// ports - which the round after reads only where the copy back wrote).
template <class CFG>
void cpe_feed(hls::stream<cpe_pair<typename CFG::T> >& src, bool first,
              typename CFG::T Hin[CFG::MAX_W][CFG::MAX_COLS], int p0, int w, int f,
              typename CFG::T dmu, hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> >& out) {
    typedef typename CFG::T T;
    enum { L = CFG::STREAM_WORDS, MAX_WORDS = CFG::MAX_W * (CFG::MAX_W + 3) / 2 };
    const int vecs = cpe_vecs<L>(p0, w);
    int i = p0, c = p0;  // the vector's first word
    cpe_pair<T> pair = {T(0), T(0)};
    // trip the round's vectors, II 1, depth La + 2 (read, add, write); L = 1: a word of Hin
    // read then cleared (one read and one write a cycle: the two ports), a word no other
    // iteration touches; L = 2: two words of Hin read
    for (int t = 0; t < vecs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=Hin inter false
        cpe_vec<T, L> x;
        if (CFG::STREAM_WORDS == 1) {
            if (first) {
                const bool even = ((c - i) & 1) == 0;
                if (even) pair = src.read();
                cpe_set(x, 0, even ? pair.lo : pair.hi);
            } else {
                cpe_set(x, 0, Hin[i][c]);
                Hin[i][c] = T(0);
            }
        } else {
            if (first) {
                pair = src.read();
                cpe_set(x, 0, pair.lo);
                cpe_set(x, L - 1, pair.hi);
            } else {
                cpe_set(x, 0, Hin[i][c]);
                cpe_set(x, L - 1, Hin[i][c + 1 <= w ? c + 1 : c]);
            }
        }
        cpe_set(x, 0, cpe_get(x, 0) + (c == i && i < f ? dmu : T(0)));  // a first word: a diagonal
        out.write(x);
        if (c + L > w) {
            ++i;
            c = i;
        } else {
            c += L;
        }
    }
    cpe_vec<T, L> status;
    for (int l = 0; l < CFG::STREAM_WORDS; ++l) cpe_set(status, l, T(0));
    out.write(status);  // status: nothing wrong upstream
    FGC_CYCLES("cpe_feed", 0, "rows", vecs + 1, 1, CFG::ADD_LAT + 2);
}

// Tap K: the stream on to CPE K, and 1 / (its pivot) beside it. A tap whose CPE has no pivot in
// the round (p >= f) does nothing: the round's stream leaves the cascade at its last pivot's CPE
// (cpe's tail), so no word passes the idle taps and CPEs.
template <class CFG, int K>
void cpe_tap(int p0, int w, int f, hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> >& in,
             hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> >& out,
             hls::stream<typename CFG::T>& recip) {
    typedef typename CFG::T T;
    enum { L = CFG::STREAM_WORDS, MAX_WORDS = CFG::MAX_W * (CFG::MAX_W + 3) / 2 };
    const int p = p0 + K;
    const int vecs = p < f ? cpe_vecs<L>(p0, w) : -1;  // idle: no iteration
    const int at = vecs - cpe_vecs<L>(p, w);  // the pivot's vector
    // trip vecs + 1, II 1; the vectors pass in 2 cycles (read, write), r leaves Ld + 2 cycles
    // after the pivot (the divide's latency, beside the stream)
    for (int t = 0; t <= vecs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
        const cpe_vec<T, L> x = in.read();
        out.write(x);
        if (t == at) recip.write(T(1) / cpe_get(x, 0));
    }
    FGC_CYCLES("cpe_tap", K, p < f ? "stream" : "idle", vecs + 1, 1, 2);
}

// CPE K of the cascade for the round starting at pivot p0: its vectors on to the next tap
// (`next`), or, when its pivot is the round's last (p + 1 == f, or the cascade's last CPE), to
// the drain (`tail`, the drain reads the tail of the round's last pivot). A CPE with no pivot in
// the round (p >= f) does nothing.
template <class CFG, int K>
void cpe(int p0, int w, int f, hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> >& in,
         hls::stream<typename CFG::T>& recip,
         hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> >& next,
         hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> >& tail) {
    typedef typename CFG::T T;
    enum { L = CFG::STREAM_WORDS, MAX_WORDS = CFG::MAX_W * (CFG::MAX_W + 3) / 2 };
    const int p = p0 + K;
    if (p >= f) {  // no pivot in this round: the stream left the cascade before this CPE
        FGC_CYCLES("cpe", K, "idle", 0, 1, 1);
        return;
    }
    const int vecs = cpe_vecs<L>(p0, w);
    const bool last = K + 1 == CFG::N_CPE || p + 1 == f;  // the round's last pivot: to the drain
    const int before = vecs - cpe_vecs<L>(p, w);  // rows p0 ... p - 1 pass
    const int row = (w + 1 - p + L - 1) / L;       // then the pivot's row, kept as h
    const int trail = before + row;                // then the later rows, Updated
    T h[CFG::MAX_COLS + L];  // row p, h[c - p] (L = 2: one word past the row, never used)
#pragma HLS ARRAY_PARTITION variable=h complete
    if (CFG::STREAM_WORDS > 1) {
        for (int k = 0; k < CFG::MAX_COLS + L; ++k) {
#pragma HLS UNROLL
            h[k] = T(0);
        }
    }
    T r = T(0);
    bool bad = false;
    int i = p + 1, c = p + 1;  // the vector's first word once t >= trail
    // trip vecs + 1, II 1, depth 2 Lm + La + 2 (+ the wait for r: cpe_wait). h carries no
    // recurrence: what is written into it is the input word, never a function of h, and h[k]
    // (written at vector before + k / L, a register: h is partitioned) is first read a vector
    // of row p + 1 later (w - p >= 2 words, at least a vector), so no iteration reads what the
    // one before it writes. L lanes: h[c - p + l] times r, times h[i - p], subtracted from the
    // vector's word l (2 L multipliers and L adders)
    for (int t = 0; t <= vecs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=h inter false
        const cpe_vec<T, L> x = in.read();
        if (t >= before && t < trail) {
            for (int l = 0; l < CFG::STREAM_WORDS; ++l) h[(t - before) * L + l] = cpe_get(x, l);
        }
        if (t == before) bad = !(cpe_get(x, 0) > T(0));
        if (t == trail) r = recip.read();  // the status word when row p is the last
        const bool upd = t >= trail && t < vecs;
        const int hi = upd ? i - p : 0, hc = upd ? c - p : 0;
        cpe_vec<T, L> o;
        for (int l = 0; l < CFG::STREAM_WORDS; ++l) {
            const T y = h[hc + l] * r;
            const T z = upd ? h[hi] * y : T(0);
            cpe_set(o, l, cpe_get(x, l) - z);  // a word that passes: x - 0 = x
        }
        if (t == vecs) {  // the status
            cpe_set(o, 0, bad || cpe_get(x, 0) != T(0) ? T(1) : T(0));
        }
        if (last) {
            tail.write(o);
        } else {
            next.write(o);
        }
        if (upd) {
            if (c + L > w) {
                ++i;
                c = i;
            } else {
                c += L;
            }
        }
    }
    FGC_CYCLES("cpe", K, "stream", vecs + 1, 1,
               2 * CFG::MUL_LAT + CFG::ADD_LAT + 2 + cpe_wait<CFG>(p, w));
}

// The N_CPE taps and CPEs, K = 0 ... N_CPE - 1, as separate calls in the region: link[K] the
// stream into tap K (link[0] the feed's), tail[K] CPE K's to the drain; the last CPE has no next
// tap, its tail its one output (passed as both).
template <class CFG, int K, bool END = (K == CFG::N_CPE), bool LAST = (K + 1 == CFG::N_CPE)>
struct cpe_cascade {
    typedef cpe_vec<typename CFG::T, CFG::STREAM_WORDS> V;
    static void run(int p0, int w, int f, hls::stream<V> link[CFG::N_CPE],
                    hls::stream<V> tail[CFG::N_CPE], hls::stream<V> tapped[CFG::N_CPE],
                    hls::stream<typename CFG::T> recip[CFG::N_CPE]) {
#pragma HLS INLINE
        cpe_tap<CFG, K>(p0, w, f, link[K], tapped[K], recip[K]);
        cpe<CFG, K>(p0, w, f, tapped[K], recip[K], link[K + 1], tail[K]);
        cpe_cascade<CFG, K + 1>::run(p0, w, f, link, tail, tapped, recip);
    }
};

template <class CFG, int K>
struct cpe_cascade<CFG, K, false, true> {
    typedef cpe_vec<typename CFG::T, CFG::STREAM_WORDS> V;
    static void run(int p0, int w, int f, hls::stream<V> link[CFG::N_CPE],
                    hls::stream<V> tail[CFG::N_CPE], hls::stream<V> tapped[CFG::N_CPE],
                    hls::stream<typename CFG::T> recip[CFG::N_CPE]) {
#pragma HLS INLINE
        cpe_tap<CFG, K>(p0, w, f, link[K], tapped[K], recip[K]);
        cpe<CFG, K>(p0, w, f, tapped[K], recip[K], tail[K], tail[K]);
    }
};

template <class CFG, int K, bool LAST>
struct cpe_cascade<CFG, K, true, LAST> {
    typedef cpe_vec<typename CFG::T, CFG::STREAM_WORDS> V;
    static void run(int, int, int, hls::stream<V>*, hls::stream<V>*, hls::stream<V>*,
                    hls::stream<typename CFG::T>*) {
#pragma HLS INLINE
    }
};

// The next vector of the round's stream from the tail of its last pivot's CPE, tail[a] (the
// CPEs after it are idle): a read of one of N_CPE streams, each index a constant once the loop is
// unrolled (a multiplexer on the drain's input).
template <class CFG>
inline cpe_vec<typename CFG::T, CFG::STREAM_WORDS> cpe_tail_read(
    hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> > tail[CFG::N_CPE], int a) {
#pragma HLS INLINE
    cpe_vec<typename CFG::T, CFG::STREAM_WORDS> x;
    for (int l = 0; l < CFG::STREAM_WORDS; ++l) cpe_set(x, l, typename CFG::T(0));
    for (int k = 0; k < CFG::N_CPE; ++k) {
#pragma HLS UNROLL
        if (k == a) x = tail[k].read();
    }
    return x;
}

// Write the round's words out, read from the tail of its last pivot's CPE: the rows of its
// pivots into cond (each row's pivot into dpiv and its largest frontal |h| into rmax), the
// trailing rows into update (last round) or Hout; the status into *bad. L words a cycle (the
// arrays' two ports at L = 2).
template <class CFG>
void cpe_drain(hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> > tail[CFG::N_CPE], int p0,
               int w, int f, typename CFG::T Hout[CFG::MAX_W][CFG::MAX_COLS],
               typename CFG::T cond[CFG::N_COND], int c0,
               typename CFG::T update[CFG::N_NF], int u0,
               typename CFG::T dpiv[CFG::MAX_F], typename CFG::T rmax[CFG::MAX_F], bool* bad) {
    typedef typename CFG::T T;
    enum { L = CFG::STREAM_WORDS, MAX_WORDS = CFG::MAX_W * (CFG::MAX_W + 3) / 2 };
    const int vecs = cpe_vecs<L>(p0, w);
    const int cols = w + 1, s = w - f;
    const int done = p0 + CFG::N_CPE < f ? p0 + CFG::N_CPE : f;  // rows p0 ... done - 1 are final
    const bool last = done == f;
    const int a = done - 1 - p0;  // the round's last pivot's CPE
    T big = T(0);
    int i = p0, c = p0;
    // trip the round's vectors (+ the status), II 1, depth 2 (read, write)
    for (int t = 0; t < vecs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS
#pragma HLS PIPELINE II=1
        const cpe_vec<T, L> x = cpe_tail_read<CFG>(tail, a);
        T b = c == i ? T(0) : big;  // the row's largest so far
        for (int l = 0; l < CFG::STREAM_WORDS; ++l) {
            const int cc = c + l;
            if (cc <= w) {
                if (i < done) {
                    cond[c0 + i * cols + cc] = cpe_get(x, l);
                    const T mag = cc < f ? cpe_abs(cpe_get(x, l)) : T(0);
                    b = (l == 0 && c == i) || mag > b ? mag : b;
                } else if (last) {
                    update[u0 + (i - f) * (s + 1) + (cc - f)] = cpe_get(x, l);
                } else {
                    Hout[i][cc] = cpe_get(x, l);
                }
            }
        }
        big = b;
        if (i < done && c == i) dpiv[i] = cpe_get(x, 0);
        if (c + L > w) {
            if (i < done) rmax[i] = b;
            ++i;
            c = i;
        } else {
            c += L;
        }
    }
    *bad = cpe_get(cpe_tail_read<CFG>(tail, a), 0) != T(0);
    FGC_CYCLES("cpe_drain", 0, "rows", vecs + 1, 1, 2);
}

// One round of N_CPE pivots from p0: the DATAFLOW region (see the top of the file).
template <class CFG>
void cpe_round(hls::stream<cpe_pair<typename CFG::T> >& src, bool first, int p0, int w, int f,
               typename CFG::T dmu, typename CFG::T Hin[CFG::MAX_W][CFG::MAX_COLS],
               typename CFG::T Hout[CFG::MAX_W][CFG::MAX_COLS],
               typename CFG::T cond[CFG::N_COND], int c0, typename CFG::T update[CFG::N_NF],
               int u0, typename CFG::T dpiv[CFG::MAX_F], typename CFG::T rmax[CFG::MAX_F],
               bool* bad) {
#pragma HLS DATAFLOW
    enum { LINK_DEPTH = CFG::MAX_W, TAP_DEPTH = CFG::MAX_COLS + CFG::DIV_LAT + 2 };
    hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> > link[CFG::N_CPE];
    hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> > tail[CFG::N_CPE];
    hls::stream<cpe_vec<typename CFG::T, CFG::STREAM_WORDS> > tapped[CFG::N_CPE];
    hls::stream<typename CFG::T> recip[CFG::N_CPE];
#pragma HLS STREAM variable=link depth=LINK_DEPTH
#pragma HLS STREAM variable=tail depth=2
#pragma HLS STREAM variable=tapped depth=TAP_DEPTH
#pragma HLS STREAM variable=recip depth=2
    FGC_REGION("cpe_round");
    cpe_feed<CFG>(src, first, Hin, p0, w, f, dmu, link[0]);
    cpe_cascade<CFG, 0>::run(p0, w, f, link, tail, tapped, recip);
    cpe_drain<CFG>(tail, p0, w, f, Hout, cond, c0, update, u0, dpiv, rmax, bad);
    FGC_DRAINED(link, CFG::N_CPE);  // csim only (fgc_cycles.h)
    FGC_DRAINED(tail, CFG::N_CPE);
    FGC_DRAINED(tapped, CFG::N_CPE);
    FGC_DRAINED(recip, CFG::N_CPE);
}

// ---- the step ---------------------------------------------------------------------------------

// Whether a step of f frontal and s separator columns fits the configuration (cpe_step computes
// nothing and its source streams nothing otherwise).
template <class CFG>
inline bool cpe_fits(int f, int s) {
    return f >= 0 && s >= 0 && f + s <= CFG::MAX_W && f <= CFG::MAX_F;
}

// cpe_step's rounds (and the copy of [H | g] when f = 0) without its pivot check: each pivot
// row's pivot into dpiv and its largest frontal |h| into rmax (cpe_check's input), *not_pd as
// cpe_step's; false, with nothing computed, if the step does not fit (cpe_fits).
template <class CFG>
bool cpe_rounds(hls::stream<cpe_pair<typename CFG::T> >& src,
                typename CFG::T H[CFG::MAX_W][CFG::MAX_COLS], int f, int s, typename CFG::T mu,
                typename CFG::T cond[CFG::N_COND], int c0, typename CFG::T update[CFG::N_NF],
                int u0, typename CFG::T dpiv[CFG::MAX_F], typename CFG::T rmax[CFG::MAX_F],
                bool* not_pd) {
    typedef typename CFG::T T;
    enum { MAX_ROUNDS = (CFG::MAX_F + CFG::N_CPE - 1) / CFG::N_CPE };
    enum { MAX_WORDS = CFG::MAX_W * (CFG::MAX_W + 3) / 2 };
    const int w = f + s;
    if (!cpe_fits<CFG>(f, s)) {
        *not_pd = true;  // outside the configuration: nothing is computed
        return false;
    }
    bool npd = false;
    // the trailing matrix between rounds: round 0 reads src, a later round H (clearing it);
    // each writes the rows it leaves for the next round into Tb, which go back into H before
    // that round. One call site of the region (two would be two copies of the cascade in
    // hardware)
    T Tb[CFG::MAX_W][CFG::MAX_COLS];
    for (int r = 0; r * CFG::N_CPE < f; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_ROUNDS
        const int p0 = r * CFG::N_CPE;
        bool round_bad = false;
        cpe_round<CFG>(src, r == 0, p0, w, f, r == 0 ? mu : T(0), H, Tb, cond, c0, update, u0,
                       dpiv, rmax, &round_bad);
        FGC_SEQUENTIAL();
        npd = npd || round_bad;
        // rows done ... w - 1 back into H for the next round, two words a cycle (the arrays'
        // two ports): trip half their words, II 1, depth 2
        const int done = p0 + CFG::N_CPE;
        const int back = done < f ? cpe_words(done, w) : 0;
        for (int t = 0, i = done, c = done; t < back; t += 2) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_WORDS/2
#pragma HLS PIPELINE II=1
            for (int h = 0; h < 2; ++h) {
                if (t + h < back) {
                    H[i][c] = Tb[i][c];
                    if (c == w) {
                        ++i;
                        c = i;
                    } else {
                        ++c;
                    }
                }
            }
        }
        FGC_CYCLES("cpe_step", 0, "back", (back + 1) / 2, 1, 2);
    }
    // f == 0: no round; the update matrix is [H | g] as it came from src, a word a cycle
    const int words = f == 0 ? cpe_words(0, w) : 0;
    cpe_pair<T> pair = {T(0), T(0)};
    for (int t = 0, i = 0, c = 0; t < words; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_W
#pragma HLS PIPELINE II=1
        const bool even = ((c - i) & 1) == 0;
        if (even) pair = src.read();
        update[u0 + i * (w + 1) + c] = even ? pair.lo : pair.hi;
        if (c == w) {
            ++i;
            c = i;
        } else {
            ++c;
        }
    }
    FGC_CYCLES("cpe_step", 0, "no_pivots", words, 1, 2);
    *not_pd = npd;
    return true;
}

// cpe_step's pivot check on the f pivots dpiv and rows' largest frontal |h| rmax (cpe_rounds'):
// whether a pivot is too small.
template <class CFG>
bool cpe_check(const typename CFG::T dpiv[CFG::MAX_F], const typename CFG::T rmax[CFG::MAX_F],
               int f) {
    typedef typename CFG::T T;
    // the scale: max_i rmax_i^2 / d_i (= the largest |U_ic|, squared) and the smallest pivot
    // beside it: trip f, II 1, depth Lm + Ld + 2 (read, multiply, divide, compare)
    T scale2 = T(0), dmin = T(0);
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        const T q = rmax[i] * rmax[i] / dpiv[i];
        scale2 = q > scale2 ? q : scale2;
        dmin = i == 0 || dpiv[i] < dmin ? dpiv[i] : dmin;
    }
    FGC_CYCLES("cpe_step", 0, "scale", f, 1, CFG::MUL_LAT + CFG::DIV_LAT + 2);
    // every pivot against it, d_i > eps^2 scale^2 (U_ii > eps scale), is the smallest one's
    // d_min / scale^2 > eps^2 (a NaN pivot is not_pd already): one divide and a compare, depth
    // Ld + 2 (a divider: no DSP)
    const T eps2 = T(CFG::SINGULAR_EPS * CFG::SINGULAR_EPS);
    const bool tiny = f > 0 && !(dmin / scale2 > eps2);
    FGC_CYCLES("cpe_step", 0, "pivot_check", f > 0 ? 1 : 0, 1, CFG::DIV_LAT + 2);
    return tiny;
}

template <class CFG>
void cpe_step(hls::stream<cpe_pair<typename CFG::T> >& src, typename CFG::T H[CFG::MAX_W][CFG::MAX_COLS],
              int f, int s, typename CFG::T mu, typename CFG::T cond[CFG::N_COND], int c0,
              typename CFG::T update[CFG::N_NF], int u0, bool* not_pd, bool* singular) {
    typedef typename CFG::T T;
    T dpiv[CFG::MAX_F], rmax[CFG::MAX_F];  // each pivot row's pivot and largest frontal |h|
    bool npd = false;
    if (!cpe_rounds<CFG>(src, H, f, s, mu, cond, c0, update, u0, dpiv, rmax, &npd)) {
        *not_pd = true;  // outside the configuration: nothing is computed
        *singular = true;
        return;
    }
    const bool tiny = cpe_check<CFG>(dpiv, rmax, f);
    *not_pd = npd;
    *singular = npd || tiny;
}

}  // namespace fgc_units

#endif  // FGC_CPE_H
