// fgc_backsub.h: back-substitution of one elimination step's conditional (R | S | d), the last
// stage of both linear solvers (QR: the qr<s>_backsub unit; Cholesky: the trisolve unit, R = L^T,
// since L z = g already ran in the cascade as the augmented column).
//
//   template <class CFG>
//   void cond_load(const typename CFG::T src[], int off, int f, int s, const typename CFG::T xs[MAX_COLS],
//                  const typename CFG::T xl[MAX_F], int xoff,
//                  typename CFG::T cond[MAX_F * MAX_COLS], typename CFG::T part[2][PARTIALS][MAX_F],
//                  int which, hls::stream<typename CFG::T>& xi);
//   template <class CFG>
//   void cond_backsub(const typename CFG::T cond[MAX_F * MAX_COLS], int f, int s,
//                     const typename CFG::T part[2][PARTIALS][MAX_F], typename CFG::T x[MAX_F],
//                     int split, hls::stream<typename CFG::T>& xo, int nx);
//
// The conditional as qr_step / cpe_step store it: f rows of w + 1 = f + s + 1 columns, row-major,
// cond[i * (w + 1) + c]; the separator's solution (solved by the parent steps first): xs[a],
// a < s, or, with xoff >= 0, xl[xoff + a] (a solved step's frontal solution where the separator's
// columns are that step's frontal columns xoff ... xoff + s - 1 in order: the driver's lane-local
// separator, read where the lane's solve left it). Out: x[i], i < f, with R x = d - S xs. CFG needs T, MAX_F, MAX_COLS (>= f + s + 1),
// PARTIALS (>= ADD_LAT), ADD_LAT, MUL_LAT, DIV_LAT; the QR and CPE configurations have them all.
//
// cond_load moves the words the solve reads (R's upper triangle, S and d of each row: f (w + 1)
// - f (f - 1) / 2 words, the structural zeros below R's diagonal left behind) from where the
// factorization stored them (src from word off on) into the unit's buffer, two a cycle (the source memory's two ports),
// and on the way adds each S_ia xs_a into a partial sum of row i: word lane h (the word's index
// parity: a lane per port) and bank (a >> 1) % PARTIALS, so a lane's sum comes back PARTIALS >=
// ADD_LAT iterations later (II 1) and the first S_ia of a sum sets it (no zeroing pass).
// `which` 1 moves R (from its diagonal) and d alone (no sum: they need no solution), 2 S alone
// (the sums): a step that waits for the step just solved takes in its R and d beside that
// solve and its S after it (the driver's BS_PART); cond_backsub's `split` then knows that S_i0
// is word i s of the S load (its lane's parity). `which` 3 (the driver's BS_PART 3, where the
// waiting step's separator is the solved step's frontal columns 0 ... s - 1 in order): R and d,
// then S column by column, a = s - 1 ... 0, two rows a cycle, x_a read from `xi` at a column's
// first iteration as the solving lane's triangle writes it (cond_backsub's `xo`, its x_r for
// r < nx as each is final); row i's terms into its own lane i & 1, bank a % PARTIALS (the
// first that column visited first), which cond_backsub's `split` 2 folds.
//
// cond_backsub then runs two pipelined loops and one move:
// - per row (trip f, II 1): its 2 PARTIALS sums folded and subtracted from d beside the
//   reciprocal of the diagonal 1 / R_ii (the divides independent of each other), the row then
//   scaled by it: y_i = (d_i - S_i xs) / R_ii, so that y_r is x_r once the columns right of r
//   are subtracted;
// - the triangle as one flattened loop over the columns r = f - 1 ... 1, last first: at a column's
//   first iteration x_r = y_r (final: its last update was the previous column's first
//   iteration), then y_i -= (R_ir / R_ii) x_r for the rows i = r - 1 ... 0 above the pivot, one a
//   cycle, R_ir / R_ii (R_ir times the row's reciprocal) off the chain. The recurrence per
//   unknown is CHAIN = MUL_LAT + ADD_LAT (the product with x_r, the subtraction; the scaling by
//   1 / R_rr no longer on it; an iteration is Lm + CHAIN deep), so a column takes max(r,
//   CHAIN + 1) iterations: columns shorter than the chain are padded, the long ones hide it (the
//   column updates run beside the chain). y_i is updated in place (one read, one write a cycle)
//   and each new value also written to z_i, from which a column's first iteration reads x_r (z:
//   one write, one read a cycle; inv: one read), so each array needs no more than its two ports. DEPENDENCE distance CHAIN is true for both: z_{r-1} is
//   read a column's length >= CHAIN + 1 iterations after it was written, y_i is updated again
//   a column's length - 1 >= CHAIN iterations later;
// - x_0 = y_0 (a move).
// No DATAFLOW inside: the driver below runs a lane's cond_backsub beside the other lane's
// cond_load (backsub_lane<p>). Cycles to FGC_CYCLES (fgc_cycles.h) as the loops state them.
//
// Two lanes wide (HlsConfig backsub_lanes = 2; the kernel defines FGC_BS_LANES, the driver
// partitions COND and the lanes' buffers cyclic over two banks): cond_load_wide<CFG, LANES>
// reads an aligned group of 2 LANES words of one row a cycle (static banks), its products summed
// by a tree before the row's partial sum; backsub_rows_wide<CFG, LANES> folds a row's PARTIALS
// sums into y, z, inv in the loading lane's process; cond_backsub_wide<CFG, LANES> is the
// triangle alone, LANES rows of a column an iteration (backsub_triangle<CFG, LANES>, which
// cond_backsub runs with LANES = 1). docs/hls.md, "Back-substitution two lanes wide".
#ifndef FGC_BACKSUB_H
#define FGC_BACKSUB_H

#include "fgc_cycles.h"
#include "hls_stream.h"

namespace fgc_units {

// the cycle count's key of the mark "the solving lane's x_0 is out" (FGC_WAVE_READY /
// FGC_WAVE_WAIT_AFTER: cond_load's part 3 waits for it); apart from the wave's row keys
#ifndef FGC_BS_X_KEY
#define FGC_BS_X_KEY (1L << 30)
#endif

// The triangle's recurrence per unknown (backsub.py's backsub_chain): the product
// (R_ir / R_ii) x_r and the subtraction (the rows are scaled by 1 / R_ii before it).
template <class CFG>
constexpr int backsub_chain() { return CFG::MUL_LAT + CFG::ADD_LAT; }

// Iterations of cond_backsub's triangle loop: the columns r = f - 1 ... 1, each
// max(ceil(r / LANES), CHAIN + 1) (LANES rows of a column an iteration).
// sum_{r=1}^{n} ceil(r / LANES): q whole runs of LANES columns (run k: LANES columns of k rows
// an iteration's k), then the m = n % LANES columns of q + 1
template <int LANES>
inline int backsub_ceil_sum(int n) {
    const int q = n / LANES, m = n % LANES;
    return LANES * q * (q + 1) / 2 + m * (q + 1);
}

template <class CFG, int LANES = 1>
inline int backsub_triangle_trip(int f) {
    const int pad = backsub_chain<CFG>() + 1;
    // columns r <= LANES pad take pad iterations, the longer ones ceil(r / LANES)
    const int n = f - 1, knee = LANES * pad;
    return n <= knee ? (n > 0 ? n * pad : 0)
                     : knee * pad + backsub_ceil_sum<LANES>(n) - backsub_ceil_sum<LANES>(knee);
}

// Words cond_load moves: each row i from its diagonal on (w + 1 - i words).
inline int backsub_words(int f, int s) { return f * (f + s + 1) - f * (f - 1) / 2; }

template <class CFG>
void cond_load(const typename CFG::T src[], int off, int f, int s,
               const typename CFG::T xs[CFG::MAX_COLS], const typename CFG::T xl[CFG::MAX_F],
               int xoff, typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
               typename CFG::T part[2][CFG::PARTIALS][CFG::MAX_F], int which,
               hls::stream<typename CFG::T>& xi) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    static_assert(CFG::PARTIALS >= CFG::ADD_LAT, "PARTIALS >= ADD_LAT: the load runs at II 1");
    const int cols = f + s + 1;
    // which 0: each row from its diagonal to d; 1 (and 3, first): R from its diagonal, then d;
    // 2: S; 3: then S column by column (scol), a = s - 1 ... 0, rows 2m, 2m + 1 an iteration
    const bool col = which == 3;
    const int words = which == 1 || col ? f * (f + 1) / 2 + f
                      : which == 2 ? f * s : backsub_words(f, s);
    const int rdit = (words + 1) / 2, len = (f + 1) / 2;  // len: a column's iterations
    const int trip = col ? rdit + s * len : rdit;
    const int last = which == 2 ? f + s - 1 : cols - 1;  // a row's last column
    int i = 0, c = which == 2 ? f : 0, base = 0;  // the next word: row i, column c, at base + c
    int a = s - 1, m = 0;  // part 3's S: column a, row pair m
    T xa = T(0);  // part 3: x_a, from the solving lane's triangle (xi) at a column's first
    // part 3: x_0 is read at the last column's first iteration, len - 1 before the last issues
    // (the load keeps pace with the triangle: units/backsub.py's streamed_s)
    if (col) FGC_WAVE_WAIT_AFTER(FGC_BS_X_KEY, len - 1);
    // trip ceil(words / 2) (part 3: + s len), II 1, depth 2 + Lm + La (read, multiply-add,
    // write)
    for (int e = 0; e < trip; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=(CFG::MAX_F*CFG::MAX_COLS+1)/2
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
        const bool scol = col && e >= rdit;
        if (scol && m == 0) xa = xi.read();
        for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
            // the word: row ri, column ci (S column sa, its partial sum b; a sum's first term
            // sets it), one read, one write and one multiply-add whichever walk it is on
            const int ri = scol ? 2 * m + h : i, ci = scol ? f + a : c;
            const int at = scol ? ri * cols : base;
            const bool live = scol ? ri < f : 2 * e + h < words;
            if (live) {
                const T v = src[off + at + ci];
                cond[at + ci] = v;
                const int sa = ci - f;
                if (sa >= 0 && sa < s) {
                    // part 3: bank a % P, the first the column visited first (a + P >= s),
                    // row 2m + h's own lane; else word lane h, bank (a >> 1) % P
                    const int b = scol ? sa % P : (sa >> 1) % P;
                    const bool first = scol ? sa + P >= s : sa < 2 * P;
                    const T xv = scol ? xa : xoff >= 0 ? xl[xoff + sa] : xs[sa];  // a mux
                    part[h][b][ri] = (first ? T(0) : part[h][b][ri]) + v * xv;
                }
                if (!scol) {
                    if (c == last) {
                        ++i;
                        base += cols;
                        c = which == 2 ? f : i;
                    } else if ((which == 1 || col) && c == f - 1) {
                        c = cols - 1;  // R's row done: its d
                    } else {
                        ++c;
                    }
                }
            }
        }
        if (scol) {
            if (m == len - 1) {
                m = 0;
                --a;
            } else {
                ++m;
            }
        }
    }
    FGC_CYCLES("backsub_copy", 0, "cond_load", trip, 1, 2 + CFG::MUL_LAT + CFG::ADD_LAT);
}

// cond_load with LANES > 1 (HlsConfig backsub_lanes; the kernel partitions src cyclic LANES,
// two ports a bank): one aligned group of W = 2 LANES words an iteration, word h of the group at
// src[W g + h], bank h % LANES (static: two reads a bank), into the lane's buffer at the same
// offset from the group boundary below off (cond[sh + i (w + 1) + c], sh = off % W: a word's
// bank in the buffer is its bank in src). An iteration reads the words of one row (row i, from
// its diagonal to d): the products S_ia xs_a of its W words (0 for R and d) summed by a tree of
// W - 1 adds, then added into partial sum j % PARTIALS of row i (j: the iteration within the
// row; the first PARTIALS set theirs), so a sum comes back PARTIALS >= ADD_LAT iterations later
// (II 1); cond_backsub folds row i's min(n_i, PARTIALS) sums (n_i its iterations). Depth read +
// multiply + tree + add + write: 2 + Lm + La (1 + log2 W).
template <class CFG, int LANES>
void cond_load_wide(const typename CFG::T src[], int off, int f, int s,
                    const typename CFG::T xs[CFG::MAX_COLS], const typename CFG::T xl[CFG::MAX_F],
                    int xoff, typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS + 2 * LANES],
                    typename CFG::T part[CFG::PARTIALS][CFG::MAX_F]) {
    typedef typename CFG::T T;
    enum { W = 2 * LANES };
    const int P = CFG::PARTIALS;
    static_assert(CFG::PARTIALS >= CFG::ADD_LAT, "PARTIALS >= ADD_LAT: the load runs at II 1");
    static_assert(LANES == 2, "two lanes: a group's four words two a bank of src");
    const int cols = f + s + 1, w = f + s;
    const int g0 = off / W;  // the group holding the conditional's first word
    int i = 0, base = off, g = off / W, j = 0;  // row i (at src[base]), group g, its j-th
    // trip: row by row, each row's words in the aligned groups of W words they touch (a group
    // holds the words of one row only: a group two rows share is read again for the second),
    // sum_i ((off + i cols + w) / W - (off + i cols + i) / W + 1) (units/backsub.py's
    // wide_trip); II 1 (the exit test on i, an integer recurrence of one cycle), depth
    // 2 + Lm + La (1 + log2 W)
    int trip = 0;
    for (; i < f; ++trip) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F*(CFG::MAX_COLS/4+2)
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
        T prod[W];
        for (int h = 0; h < 2 * LANES; ++h) {
#pragma HLS UNROLL
            const int c = W * g + h - base;  // the word's column in row i
            prod[h] = T(0);
            if (c >= i && c <= w) {
                const T v = src[W * g + h];
                cond[W * (g - g0) + h] = v;
                const int a = c - f;
                if (a >= 0 && a < s) {
                    const T xa = xoff >= 0 ? xl[xoff + a] : xs[a];  // a mux: no operator
                    prod[h] = v * xa;
                }
            }
        }
        const int b = j % P;
        const T sum = fold_partials<T, W>(prod);
        part[b][i] = (j < P ? T(0) : part[b][i]) + sum;
        if (W * g + W - 1 >= base + w) {  // the row's last group: the next row from its diagonal
            ++i;
            base += cols;
            g = (base + i) / W;
            j = 0;
        } else {
            ++g;
            ++j;
        }
    }
    FGC_CYCLES("backsub_copy", 0, "cond_load", trip, 1,
               2 + CFG::MUL_LAT + CFG::ADD_LAT * (1 + ceil_log2(W)));
}

// The triangle of cond_backsub (see the top of the file) on rows scaled by their reciprocal
// (y, z: y_i = (d_i - S_i xs) / R_ii; inv: 1 / R_ii), LANES rows of a column an iteration: a
// column r takes max(ceil(r / LANES), CHAIN + 1) iterations. Lane l updates the row of its
// residue l mod LANES (row LANES m + l: y, z and inv partitioned cyclic LANES, a lane's bank
// static), so each bank sees one read and one write of y and z an iteration (and z's read of
// x_r); R_ir comes from cond[sh + i (w + 1) + r], LANES reads an iteration (a buffer cyclic
// LANES: two ports a bank). LANES = 1 is the one-row loop. x_0 = y_0 after it (a move).
template <class CFG, int LANES>
void backsub_triangle(const typename CFG::T cond[], int sh, int f, int cols,
                      typename CFG::T y[CFG::MAX_F], typename CFG::T z[CFG::MAX_F],
                      const typename CFG::T inv[CFG::MAX_F], typename CFG::T x[CFG::MAX_F],
                      hls::stream<typename CFG::T>& xo, int nx) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    const int CHAIN = CFG::MUL_LAT + CFG::ADD_LAT;  // backsub_chain
    // the triangle, columns r = f - 1 ... 1 flattened (k: the iteration within column r)
    const int pad = CHAIN + 1;
    const int trip = backsub_triangle_trip<CFG, LANES>(f);
    T xr = T(0);
    for (int e = 0, r = f - 1, k = 0; e < trip; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F*CFG::MAX_F/2+CFG::MAX_F*(CFG::MUL_LAT+CFG::ADD_LAT+1)
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=y inter true distance=CHAIN
#pragma HLS DEPENDENCE variable=z inter true distance=CHAIN
        if (k == 0) {
            xr = z[r];
            x[r] = xr;
            if (r < nx) xo.write(xr);  // x_r final: to the other lane's load (cond_load part 3)
        }
        for (int l = 0; l < LANES; ++l) {
#pragma HLS UNROLL
            // column r's rows r - 1 - k LANES ... r - LANES - k LANES; lane l takes the one of
            // residue l: r - 1 - k LANES - t, t = (r - 1 - l) mod LANES
            const int t = (r - 1 - l) & (LANES - 1);
            if (k * LANES + t < r) {
                const int m = (r - 1 - k * LANES - t - l) / LANES;  // row LANES m + l
                const int i = LANES * m + l;
                const T yi = y[i] - (cond[sh + i * cols + r] * inv[i]) * xr;
                y[i] = yi;
                z[i] = yi;
            }
        }
        const int rows = (r + LANES - 1) / LANES;
        const int len = rows > pad ? rows : pad;
        if (k == len - 1) {
            k = 0;
            --r;
        } else {
            ++k;
        }
    }
    // depth Lm + CHAIN: R_ir / R_ii, then its product with x_r and the subtraction
    FGC_CYCLES("backsub", 0, "triangle", trip, 1, CFG::MUL_LAT + CHAIN);
    x[0] = z[0];  // a move, depth 1
    if (nx > 0) xo.write(z[0]);
    FGC_CYCLES("backsub", 0, "last", 1, 1, 1);
}

template <class CFG>
void cond_backsub(const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS], int f, int s,
                  const typename CFG::T part[2][CFG::PARTIALS][CFG::MAX_F],
                  typename CFG::T x[CFG::MAX_F], int split, hls::stream<typename CFG::T>& xo,
                  int nx) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    const int w = f + s, cols = w + 1;
    if (f <= 0) return;
    T y[CFG::MAX_F], z[CFG::MAX_F], inv[CFG::MAX_F];
    // per row: y_i = (d_i - (its 2 P partial sums folded)) / R_ii (1 / R_ii beside the fold, then
    // one multiply); trip f, II 1, depth max(La (1 + ceil(log2 2P)), Ld) + Lm. srow: the index of S_i0 among cond_load's words
    // (its parity: the lane of a = 0; split: its S load's, i s); a sum holds terms iff its first a is below s.
    for (int i = 0, srow = split == 1 ? 0 : f; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        T row[2 * CFG::PARTIALS];
        for (int h = 0; h < 2; ++h) {
            for (int b = 0; b < P; ++b) {
                // split 2 (S by columns, cond_load part 3): row i's own lane, bank a % P
                const bool used = split == 2 ? h == (i & 1) && b < s
                                             : 2 * b + ((h + srow) & 1) < s;
                row[h * P + b] = used ? part[h][b][i] : T(0);
            }
        }
        const T ri = T(1) / cond[i * cols + i];
        const T yi = (cond[i * cols + w] - fold_partials<T, 2 * CFG::PARTIALS>(row)) * ri;
        y[i] = yi;
        z[i] = yi;
        inv[i] = ri;
        srow += split == 1 ? s : cols - i - 1;
    }
    FGC_CYCLES("backsub", 0, "rows", f, 1,
               (CFG::ADD_LAT * (1 + ceil_log2(2 * CFG::PARTIALS)) > CFG::DIV_LAT
                    ? CFG::ADD_LAT * (1 + ceil_log2(2 * CFG::PARTIALS)) : CFG::DIV_LAT) +
                   CFG::MUL_LAT);
    backsub_triangle<CFG, 1>(cond, 0, f, cols, y, z, inv, x, xo, nx);
}

// The row loop after cond_load_wide<LANES> (HlsConfig backsub_lanes), in the loading lane's
// process: the conditional at cond[sh + i (w + 1) + c] (sh: its first word's offset from its
// group boundary), each row's min(n_i, PARTIALS) partial sums in part[b][i] (n_i: the row's
// groups), folded (PARTIALS sums, not 2 PARTIALS) and subtracted from d beside 1 / R_ii, the row
// scaled by it: y_i = z_i = (d_i - S_i xs) / R_ii, inv_i = 1 / R_ii, what the solving lane's
// triangle starts from (cond_backsub_wide) in the next slot. Trip f, II 1, depth
// max(La (1 + ceil(log2 P)), Ld) + Lm.
template <class CFG, int LANES>
void backsub_rows_wide(const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS + 2 * LANES],
                       int sh, int f, int s, const typename CFG::T part[CFG::PARTIALS][CFG::MAX_F],
                       typename CFG::T y[CFG::MAX_F], typename CFG::T z[CFG::MAX_F],
                       typename CFG::T inv[CFG::MAX_F]) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    const int w = f + s, cols = w + 1;
    for (int i = 0, base = sh; i < f; ++i, base += cols) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        const int n = (base + w) / (2 * LANES) - (base + i) / (2 * LANES) + 1;  // its groups
        T row[CFG::PARTIALS];
        for (int b = 0; b < P; ++b) row[b] = b < n ? part[b][i] : T(0);
        const T ri = T(1) / cond[base + i];
        const T yi = (cond[base + w] - fold_partials<T, CFG::PARTIALS>(row)) * ri;
        y[i] = yi;
        z[i] = yi;
        inv[i] = ri;
    }
    FGC_CYCLES("backsub", 0, "rows", f, 1,
               (CFG::ADD_LAT * (1 + ceil_log2(CFG::PARTIALS)) > CFG::DIV_LAT
                    ? CFG::ADD_LAT * (1 + ceil_log2(CFG::PARTIALS)) : CFG::DIV_LAT) +
                   CFG::MUL_LAT);
}

// cond_backsub of a step cond_load_wide and backsub_rows_wide loaded (HlsConfig
// backsub_lanes): the triangle alone, LANES rows of a column an iteration (backsub_triangle),
// from the scaled rows y, z and reciprocals inv the load left.
template <class CFG, int LANES>
void cond_backsub_wide(const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS + 2 * LANES],
                       int sh, int f, int s, typename CFG::T y[CFG::MAX_F],
                       typename CFG::T z[CFG::MAX_F], const typename CFG::T inv[CFG::MAX_F],
                       typename CFG::T x[CFG::MAX_F]) {
    if (f <= 0) return;
    hls::stream<typename CFG::T> none;  // (the wide lanes stream no x: cond_load's part 3 is one lane's)
    backsub_triangle<CFG, LANES>(cond, sh, f, f + s + 1, y, z, inv, x, none, 0);
}

}  // namespace fgc_units

#endif  // FGC_BACKSUB_H

// ---- The driver: back_substitute<CFG>(), one DATAFLOW region of two processes.
//
// backsub_slots: the conditionals on two lanes (units/backsub.py's backsub_slots). Slot k solves
// one step on lane BS_LANE[k] (its conditional loaded the slot before) while the next step's
// conditional loads into the other lane, S xs summed on the way (cond_load); a step whose
// separator needs the step just solved loads in a slot of its own (BS_SOLVE / BS_LOAD: the steps,
// -1 none). Per slot: the loaded step's separator solution in from DELTA (PORTS words a cycle),
// unless it is lane-local (BS_XOFF >= 0: the separator's columns are the frontal columns
// BS_XOFF ... of the step the loading lane solved last, whose solution that lane's BS_X still
// holds; cond_load reads it there: a two-ended chain's step after the root's children), then the
// slot's backsub_lane<p> region: lane p's backsub_set<p> (the solve, then the solved
// step's frontal solution out into DELTA and, a pair of words a cycle, into `dx` to the state
// update: backsub_out) beside the other lane's backsub_load (COND only).
//
// backsub_retire: the state update fed by back-substitution: X_TRIAL = X (+) delta variable by
// variable as their steps' words arrive (its own copy of delta, by tangent index), through the
// kernel's retraction datapaths (CFG::retract_variable, which also sends each variable's words
// on to the kernel's trial_cost, the region's third process: the cost at X_TRIAL), while the
// slot process solves the next steps. Every variable is a frontal variable of exactly one step, so X_TRIAL is whole when the
// region ends; LM control takes it from there (its retract_trial does nothing more here).
//
// Included a second time by the kernel with FGC_BACKSUB_DRIVER defined, inside its namespace
// (fgc::, or fgc::les for the mixed design), after its schedule tables and the BS_* slot tables,
// which these functions name: BS_SLOTS, BS_SOLVE, BS_LOAD, BS_LANE, BS_XOFF, RETIRE_VARS, RETIRE_STEP,
// STEP_F, STEP_W, STEP_COL_BEGIN, STEP_COL, STEP_COND_OFF (tables); COND, DELTA, L (the linear
// solver's scalar), MAX_F; TrialVar and trial_cost (the cost pass's stream word and process). CFG is the kernel's LesConfig (T, MAX_F, MAX_W, MAX_COLS, N_TANGENT,
// N_VARIABLES, PARTIALS, the latencies cond_load / cond_backsub read, MOVE_DEPTH: the copies'
// depth, the retire loop's RETIRE_II and RETIRE_DEPTH, and the hook retract_variable). The two
// lanes are written out (each its own memories and RTL instance: backsub_set0 / backsub_set1,
// ...), the number the plan prices (units/backsub.py's LANES).
#if defined(FGC_BACKSUB_DRIVER) && !defined(FGC_BACKSUB_DRIVER_H)
#define FGC_BACKSUB_DRIVER_H

#ifndef FGC_BS_COLUMNS  // the slot driver (backsub_lanes 1 or 2); the column driver below
#ifdef FGC_BS_LANES  // backsub_lanes > 1 (the kernel defines it only then)
// HlsConfig backsub_lanes (the kernel's FGC_BS_LANES): COND and the lanes' buffers cyclic
// FGC_BS_LANES (backsub_slots' pragmas), a buffer's words at their offset from the group
// boundary below the step's first word (cond_load_wide), hence 2 FGC_BS_LANES words more
L BS_COND0[MAX_F * (MAX_W + 1) + 2 * FGC_BS_LANES];  // lane 0's conditional (R | S | d)
#elif !defined(FGC_BS_ROOT_COMMIT)  // (else the kernel declared it for qr_commit)
L BS_COND0[MAX_F * (MAX_W + 1)];  // lane 0's conditional (R | S | d)
#endif
L BS_XS0[MAX_W + 1];  // its separator's solution
L BS_X0[MAX_F];  // its frontal solution (read by its next load when lane-local: BS_XOFF)
#ifdef FGC_BS_LANES  // backsub_lanes > 1 (the kernel defines it only then)
L BS_COND1[MAX_F * (MAX_W + 1) + 2 * FGC_BS_LANES];  // lane 1's
#else
L BS_COND1[MAX_F * (MAX_W + 1)];  // lane 1's
#endif
L BS_XS1[MAX_W + 1];
L BS_X1[MAX_F];
#endif

// two solution words a stream word (the copies move two words a cycle)
struct BsPair { L word[2]; };

#ifdef FGC_BS_STEP_TEST
// LM's step test summed in the state update (the kernel's FGC_BS_STEP_TEST), one variable of
// the retire's loop: CFG::retract_variable retracts variable v (its words on to trial_cost, and
// tx2) and forms its terms, added here into the running sums: |delta|^2 (dd), delta^T g (dg),
// |x (+) delta|^2 (xx), the gradient's largest |entry| (gm), delta's finiteness (fin). Each
// sum's add (or compare) is the loop's carried dependence, its latency within RETIRE_II. Both
// drivers' retire loops call it (the slot design's backsub_retire, the column design's
// backsub_retire_cols): one body, inlined into the caller's pipeline.
template <class CFG>
inline void step_sums(int v, const L delta[CFG::N_TANGENT], bool at_x,
                      hls::stream<TrialVar>& tx, hls::stream<TrialVar>& tx2,
                      typename CFG::TestT& dd, typename CFG::TestT& dg,
                      typename CFG::TestT& gm, bool& fin, typename CFG::TestT& xx) {
#pragma HLS INLINE
    typename CFG::TestT vd = 0, vg = 0, vm = 0, vx = 0;
    bool vf = true;
    CFG::retract_variable(v, delta, at_x, tx, tx2, vd, vg, vm, vf, vx);
    dd += vd;
    dg += vg;
    xx += vx;
    gm = vm > gm ? vm : gm;
    fin = fin && vf;
}
#endif

#ifndef FGC_BS_COLUMNS

// The solved step's frontal solution out (cb: its STEP_COL_BEGIN) into DELTA and, a pair of
// words a cycle, into `dx` to the state update: the end of the solving lane's process, beside the
// other lane's load (which reads COND only; the separator came in from DELTA before the region).
template <class CFG>
void backsub_out(const L x[CFG::MAX_F], int f, int cb, hls::stream<BsPair>& dx) {
    for (int c = 0; c < f; c += 2) {
#pragma HLS LOOP_TRIPCOUNT max=(CFG::MAX_F+1)/2
#pragma HLS PIPELINE II=1
        BsPair out;
        for (int h = 0; h < 2; ++h) {
            const int j = c + h;  // an index: no floating-point operation here
            L v = L(0);
            if (j < f) {
                v = x[j];
                DELTA[STEP_COL[cb + j]] = v;
            }
            out.word[h] = v;
        }
        dx.write(out);
    }
    FGC_CYCLES("backsub_copy", 0, "solution_out", (f + 1) / 2, 1, CFG::MOVE_DEPTH);
}

#ifndef FGC_BS_LANES  // one lane wide (first: a reading that does not evaluate #if takes the
// first definition of a name, and these are the default design's)
// Lane u's solve: x = R^-1 (d - S xs) of one step, S xs in the partial sums its cond_load left
// (f = 0: none this time; split 1: its S loaded alone, BS_PART 2; split 2: by columns, BS_PART
// 3), then its solution out (backsub_out). nx > 0: its x_r, r < nx, also to the other lane's
// load as the triangle finds them (xo: that load's S by columns, BS_PART 3), marked for the
// cycle count once x_0 is out.
template <class CFG>
void backsub_set0(const L cond[CFG::MAX_F * CFG::MAX_COLS], int f, int s,
                  const L part[2][CFG::PARTIALS][CFG::MAX_F], L x[CFG::MAX_F], int cb,
                  hls::stream<BsPair>& dx, int split, hls::stream<L>& xo, int nx) {
    FGC_BRANCH();  // csim cycle counting only: a lane's solve and the other's load side by side
    fgc_units::cond_backsub<CFG>(cond, f, s, part, x, split, xo, nx);
    if (nx > 0) FGC_WAVE_READY(FGC_BS_X_KEY);  // csim cycle counting: x_0 is out
    backsub_out<CFG>(x, f, cb, dx);
}

template <class CFG>
void backsub_set1(const L cond[CFG::MAX_F * CFG::MAX_COLS], int f, int s,
                  const L part[2][CFG::PARTIALS][CFG::MAX_F], L x[CFG::MAX_F], int cb,
                  hls::stream<BsPair>& dx, int split, hls::stream<L>& xo, int nx) {
    FGC_BRANCH();
    fgc_units::cond_backsub<CFG>(cond, f, s, part, x, split, xo, nx);
    if (nx > 0) FGC_WAVE_READY(FGC_BS_X_KEY);  // csim cycle counting: x_0 is out
    backsub_out<CFG>(x, f, cb, dx);
}

// Lane u's load: a step's conditional from COND (at off) into the lane's buffer, S xs summed on
// the way (xs: the separator in from DELTA; xoff >= 0: from xl, the lane's last solution);
// which (BS_PART): 0 all of it, 1 R and d alone, 2 S alone, 3 R and d, then S by columns as
// the solving lane's x arrives on xi (cond_load).
template <class CFG>
void backsub_load0(int off, int f, int s, const L xs[CFG::MAX_COLS], const L xl[CFG::MAX_F],
                   int xoff, L cond[CFG::MAX_F * CFG::MAX_COLS],
                   L part[2][CFG::PARTIALS][CFG::MAX_F], int which, hls::stream<L>& xi) {
    FGC_BRANCH();
    fgc_units::cond_load<CFG>(COND, off, f, s, xs, xl, xoff, cond, part, which, xi);
}

template <class CFG>
void backsub_load1(int off, int f, int s, const L xs[CFG::MAX_COLS], const L xl[CFG::MAX_F],
                   int xoff, L cond[CFG::MAX_F * CFG::MAX_COLS],
                   L part[2][CFG::PARTIALS][CFG::MAX_F], int which, hls::stream<L>& xi) {
    FGC_BRANCH();
    fgc_units::cond_load<CFG>(COND, off, f, s, xs, xl, xoff, cond, part, which, xi);
}

// A slot whose solve is on lane 0: lane 0's cond_backsub beside lane 1's cond_load.
template <class CFG>
void backsub_lane0(const L cond0[CFG::MAX_F * CFG::MAX_COLS], int f0, int s0,
                   const L part0[2][CFG::PARTIALS][CFG::MAX_F], L x0[CFG::MAX_F], int cb0,
                   hls::stream<BsPair>& dx,
                   int off, int f1, int s1, const L xs1[CFG::MAX_COLS], const L x1[CFG::MAX_F],
                   int xoff, L cond1[CFG::MAX_F * CFG::MAX_COLS],
                   L part1[2][CFG::PARTIALS][CFG::MAX_F], int split, int which, int nx) {
#pragma HLS DATAFLOW
    hls::stream<L> xr;  // which 3: the solve's x_r, r < nx, to the load (all of them may wait)
#pragma HLS STREAM variable=xr depth=CFG::MAX_F
    backsub_set0<CFG>(cond0, f0, s0, part0, x0, cb0, dx, split, xr, nx);
    backsub_load1<CFG>(off, f1, s1, xs1, x1, xoff, cond1, part1, which, xr);
    FGC_DRAINED(&xr, 1);
}

// A slot whose solve is on lane 1: lane 1's cond_backsub beside lane 0's cond_load.
template <class CFG>
void backsub_lane1(const L cond1[CFG::MAX_F * CFG::MAX_COLS], int f1, int s1,
                   const L part1[2][CFG::PARTIALS][CFG::MAX_F], L x1[CFG::MAX_F], int cb1,
                   hls::stream<BsPair>& dx,
                   int off, int f0, int s0, const L xs0[CFG::MAX_COLS], const L x0[CFG::MAX_F],
                   int xoff, L cond0[CFG::MAX_F * CFG::MAX_COLS],
                   L part0[2][CFG::PARTIALS][CFG::MAX_F], int split, int which, int nx) {
#pragma HLS DATAFLOW
    hls::stream<L> xr;  // which 3: the solve's x_r, r < nx, to the load (all of them may wait)
#pragma HLS STREAM variable=xr depth=CFG::MAX_F
    backsub_set1<CFG>(cond1, f1, s1, part1, x1, cb1, dx, split, xr, nx);
    backsub_load0<CFG>(off, f0, s0, xs0, x0, xoff, cond0, part0, which, xr);
    FGC_DRAINED(&xr, 1);
}

#else  // backsub_lanes > 1 (the kernel defines FGC_BS_LANES only then)
// Lane u's solve (backsub_lanes > 1): the triangle of the step its load left scaled (ry, rz,
// rinv: the row loop ran in the load, beside the other lane's triangle), then its solution out.
// (The parameters keep the one-lane driver's order, the wide ones appended.)
template <class CFG>
void backsub_set0(const L cond[CFG::MAX_F * CFG::MAX_COLS + 2 * FGC_BS_LANES], int f, int s,
                  L ry[CFG::MAX_F], L x[CFG::MAX_F], int cb, hls::stream<BsPair>& dx,
                  L rz[CFG::MAX_F], const L rinv[CFG::MAX_F], int sh) {
    FGC_BRANCH();  // csim cycle counting only: a lane's solve and the other's load side by side
    fgc_units::cond_backsub_wide<CFG, FGC_BS_LANES>(cond, sh, f, s, ry, rz, rinv, x);
    backsub_out<CFG>(x, f, cb, dx);
}

template <class CFG>
void backsub_set1(const L cond[CFG::MAX_F * CFG::MAX_COLS + 2 * FGC_BS_LANES], int f, int s,
                  L ry[CFG::MAX_F], L x[CFG::MAX_F], int cb, hls::stream<BsPair>& dx,
                  L rz[CFG::MAX_F], const L rinv[CFG::MAX_F], int sh) {
    FGC_BRANCH();
    fgc_units::cond_backsub_wide<CFG, FGC_BS_LANES>(cond, sh, f, s, ry, rz, rinv, x);
    backsub_out<CFG>(x, f, cb, dx);
}

// Lane u's load (backsub_lanes > 1): a step's conditional from COND (at off) into the lane's
// buffer, 2 FGC_BS_LANES words a cycle, S xs summed on the way into the load's own partial
// sums, then the row loop: the rows scaled by their reciprocals into ry, rz, rinv (xs: the
// separator in from DELTA; xoff >= 0: from xl, the lane's last solution).
template <class CFG>
void backsub_load0(int off, int f, int s, const L xs[CFG::MAX_COLS], const L xl[CFG::MAX_F],
                   int xoff, L cond[CFG::MAX_F * CFG::MAX_COLS + 2 * FGC_BS_LANES],
                   L ry[CFG::MAX_F], L rz[CFG::MAX_F], L rinv[CFG::MAX_F]) {
    FGC_BRANCH();
    L part[CFG::PARTIALS][CFG::MAX_F];  // the partial sums of S xs (bank, row)
#pragma HLS ARRAY_PARTITION variable=part complete dim=1
    fgc_units::cond_load_wide<CFG, FGC_BS_LANES>(COND, off, f, s, xs, xl, xoff, cond, part);
    fgc_units::backsub_rows_wide<CFG, FGC_BS_LANES>(cond, off % (2 * FGC_BS_LANES), f, s, part,
                                                    ry, rz, rinv);
}

template <class CFG>
void backsub_load1(int off, int f, int s, const L xs[CFG::MAX_COLS], const L xl[CFG::MAX_F],
                   int xoff, L cond[CFG::MAX_F * CFG::MAX_COLS + 2 * FGC_BS_LANES],
                   L ry[CFG::MAX_F], L rz[CFG::MAX_F], L rinv[CFG::MAX_F]) {
    FGC_BRANCH();
    L part[CFG::PARTIALS][CFG::MAX_F];
#pragma HLS ARRAY_PARTITION variable=part complete dim=1
    fgc_units::cond_load_wide<CFG, FGC_BS_LANES>(COND, off, f, s, xs, xl, xoff, cond, part);
    fgc_units::backsub_rows_wide<CFG, FGC_BS_LANES>(cond, off % (2 * FGC_BS_LANES), f, s, part,
                                                    ry, rz, rinv);
}

// A slot whose solve is on lane 0: lane 0's triangle beside lane 1's load and row loop.
template <class CFG>
void backsub_lane0(const L cond0[CFG::MAX_F * CFG::MAX_COLS + 2 * FGC_BS_LANES], int f0, int s0,
                   L ry0[CFG::MAX_F], L x0[CFG::MAX_F], int cb0, hls::stream<BsPair>& dx,
                   int off, int f1, int s1, const L xs1[CFG::MAX_COLS], const L x1[CFG::MAX_F],
                   int xoff, L cond1[CFG::MAX_F * CFG::MAX_COLS + 2 * FGC_BS_LANES],
                   L ry1[CFG::MAX_F], L rz0[CFG::MAX_F], const L rinv0[CFG::MAX_F], int sh0,
                   L rz1[CFG::MAX_F], L rinv1[CFG::MAX_F]) {
#pragma HLS DATAFLOW
    backsub_set0<CFG>(cond0, f0, s0, ry0, x0, cb0, dx, rz0, rinv0, sh0);
    backsub_load1<CFG>(off, f1, s1, xs1, x1, xoff, cond1, ry1, rz1, rinv1);
}

// A slot whose solve is on lane 1: lane 1's triangle beside lane 0's load and row loop.
template <class CFG>
void backsub_lane1(const L cond1[CFG::MAX_F * CFG::MAX_COLS + 2 * FGC_BS_LANES], int f1, int s1,
                   L ry1[CFG::MAX_F], L x1[CFG::MAX_F], int cb1, hls::stream<BsPair>& dx,
                   int off, int f0, int s0, const L xs0[CFG::MAX_COLS], const L x0[CFG::MAX_F],
                   int xoff, L cond0[CFG::MAX_F * CFG::MAX_COLS + 2 * FGC_BS_LANES],
                   L ry0[CFG::MAX_F], L rz1[CFG::MAX_F], const L rinv1[CFG::MAX_F], int sh1,
                   L rz0[CFG::MAX_F], L rinv0[CFG::MAX_F]) {
#pragma HLS DATAFLOW
    backsub_set1<CFG>(cond1, f1, s1, ry1, x1, cb1, dx, rz1, rinv1, sh1);
    backsub_load0<CFG>(off, f0, s0, xs0, x0, xoff, cond0, ry0, rz0, rinv0);
}

#endif

// The slots, root first, into DELTA; each solved step's words to the state update too.
template <class CFG>
void backsub_slots(hls::stream<BsPair>& dx, bool at_x) {
    FGC_OUTER_BRANCH();  // csim cycle counting only: this process beside backsub_retire
#ifdef FGC_BS_LANES  // backsub_lanes > 1 (the kernel defines it only then)
    // four ports of COND (two a bank), the lanes' buffers alike, the separators' words registers
    // (cond_load_wide reads 2 FGC_BS_LANES of them an iteration)
#pragma HLS ARRAY_PARTITION variable=COND cyclic factor=FGC_BS_LANES
#pragma HLS ARRAY_PARTITION variable=BS_COND0 cyclic factor=FGC_BS_LANES
#pragma HLS ARRAY_PARTITION variable=BS_COND1 cyclic factor=FGC_BS_LANES
#pragma HLS ARRAY_PARTITION variable=BS_XS0 complete
#pragma HLS ARRAY_PARTITION variable=BS_XS1 complete
#pragma HLS ARRAY_PARTITION variable=BS_X0 complete
#pragma HLS ARRAY_PARTITION variable=BS_X1 complete
    // per lane: its loaded step's rows scaled by 1 / R_ii (y, and z the copy the triangle reads
    // x_r from) and the reciprocals, cyclic over the lanes of the triangle (a lane's bank static)
    L bs_y0[CFG::MAX_F], bs_z0[CFG::MAX_F], bs_inv0[CFG::MAX_F];
#pragma HLS ARRAY_PARTITION variable=bs_y0 cyclic factor=FGC_BS_LANES
#pragma HLS ARRAY_PARTITION variable=bs_z0 cyclic factor=FGC_BS_LANES
#pragma HLS ARRAY_PARTITION variable=bs_inv0 cyclic factor=FGC_BS_LANES
    L bs_y1[CFG::MAX_F], bs_z1[CFG::MAX_F], bs_inv1[CFG::MAX_F];
#pragma HLS ARRAY_PARTITION variable=bs_y1 cyclic factor=FGC_BS_LANES
#pragma HLS ARRAY_PARTITION variable=bs_z1 cyclic factor=FGC_BS_LANES
#pragma HLS ARRAY_PARTITION variable=bs_inv1 cyclic factor=FGC_BS_LANES
#else
    L bs_part0[2][CFG::PARTIALS][CFG::MAX_F];  // lane 0's partial sums of S xs (word lane, bank, row)
#pragma HLS ARRAY_PARTITION variable=bs_part0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=bs_part0 complete dim=2
    L bs_part1[2][CFG::PARTIALS][CFG::MAX_F];  // lane 1's
#pragma HLS ARRAY_PARTITION variable=bs_part1 complete dim=1
#pragma HLS ARRAY_PARTITION variable=bs_part1 complete dim=2
#endif
    const int slots = at_x ? 0 : BS_SLOTS;  // at_x: no solve (the cost at X)
#ifdef FGC_BS_ROOT_COMMIT
    const int first = 1;  // slot 0, the root's load: qr_commit wrote it into BS_COND0
#else
    const int first = 0;
#endif
    for (int k = first; k < slots; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=BS_SLOTS
#ifdef FGC_BS_LANES
        const int p = BS_LANE[k], sv = BS_SOLVE[k], ld = BS_LOAD[k];
        const bool rd = false;
        const int which = 0;  // (the wide lanes load whole conditionals)
#else
        // BS_PART: a slot that solves alone takes in R and d of the next slot's step (which
        // waits for this solve), the next slot that step's S (which the solving lane's rows
        // loop then reads split)
        // (3: R, d and then S of this slot's own step, S as this solve's x arrives: the
        // solving lane streams x_r, r < its separator's s, to the load; the next slot's rows
        // loop reads S's sums by columns)
        const int which = BS_PART[k];
        const bool rd = which == 1;
        const int split = k == 0 ? 0 : BS_PART[k - 1] == 2 ? 1 : BS_PART[k - 1] == 3 ? 2 : 0;
        const int p = BS_LANE[k], sv = BS_SOLVE[k], ld = rd ? BS_LOAD[k + 1] : BS_LOAD[k];
#endif
        const int sf = sv >= 0 ? STEP_F[sv] : 0, ssep = sv >= 0 ? STEP_W[sv] - STEP_F[sv] : 0;
        const int scb = sv >= 0 ? STEP_COL_BEGIN[sv] : 0;
        const int lf = ld >= 0 ? STEP_F[ld] : 0, lsep = ld >= 0 ? STEP_W[ld] - STEP_F[ld] : 0;
        const int lcb = ld >= 0 ? STEP_COL_BEGIN[ld] : 0, off = ld >= 0 ? STEP_COND_OFF[ld] : 0;
        // lane-local, or R and d alone: no separator_in
        const int xo = BS_XOFF[k], nin = xo >= 0 || rd || which == 3 ? 0 : lsep;
        for (int a = 0; a < nin; a += 2) {
#pragma HLS LOOP_TRIPCOUNT max=(CFG::MAX_W+1)/2
#pragma HLS PIPELINE II=1
            for (int h = 0; h < 2; ++h) {
                if (a + h < nin) {
                    const L v = DELTA[STEP_COL[lcb + lf + a + h]];
                    if (p == 0) BS_XS1[a + h] = v;
                    else BS_XS0[a + h] = v;
                }
            }
        }
        FGC_CYCLES("backsub_copy", 0, "separator_in", (nin + 1) / 2, 1, CFG::MOVE_DEPTH);
#ifdef FGC_BS_LANES  // backsub_lanes > 1 (the kernel defines it only then)
        // the solved step's first word's offset from its group boundary (cond_load_wide's layout)
        const int ssh = sv >= 0 ? STEP_COND_OFF[sv] % (2 * FGC_BS_LANES) : 0;
        if (p == 0)
            backsub_lane0<CFG>(BS_COND0, sf, ssep, bs_y0, BS_X0, scb, dx, off, lf, lsep, BS_XS1,
                               BS_X1, xo, BS_COND1, bs_y1, bs_z0, bs_inv0, ssh, bs_z1, bs_inv1);
        else
            backsub_lane1<CFG>(BS_COND1, sf, ssep, bs_y1, BS_X1, scb, dx, off, lf, lsep, BS_XS0,
                               BS_X0, xo, BS_COND0, bs_y0, bs_z1, bs_inv1, ssh, bs_z0, bs_inv0);
#else
        const int nx = which == 3 ? lsep : 0;  // the solve's x_r the load takes (r < nx)
        if (p == 0)
            backsub_lane0<CFG>(BS_COND0, sf, ssep, bs_part0, BS_X0, scb, dx, off, lf, lsep, BS_XS1,
                               BS_X1, xo, BS_COND1, bs_part1, split, which, nx);
        else
            backsub_lane1<CFG>(BS_COND1, sf, ssep, bs_part1, BS_X1, scb, dx, off, lf, lsep, BS_XS0,
                               BS_X0, xo, BS_COND0, bs_part0, split, which, nx);
#endif
        FGC_JOIN();
        if (sv >= 0) FGC_OUTER_SEND();
    }
}

// The state update as the solutions arrive: one pipelined loop over the variables in the order
// they are solved (RETIRE_VARS), a variable every CFG::RETIRE_II cycles; the first variable of
// a step (RETIRE_STEP: its step, else -1) first takes the step's words from `dx` (stalling until
// they come), then each variable is retracted by CFG::retract_variable (its type's datapath).
template <class CFG>
void backsub_retire(hls::stream<BsPair>& dx, hls::stream<TrialVar>& tx,
                    hls::stream<TrialVar>& tx2, bool at_x) {
    FGC_OUTER_BRANCH();
    L delta[CFG::N_TANGENT];  // the solved entries by tangent index
#ifdef FGC_BS_STEP_TEST
    // the one-step policy's sums (the kernel's FGC_BS_STEP_TEST): |delta|^2, delta^T g, delta's
    // finiteness, the gradient's largest |entry| and |X|^2 summed a variable an iteration (the
    // variable's terms from retract_variable; a sum's add is its carried dependence, its
    // latency within RETIRE_II), to CFG::retire_test after the solve (not at_x)
    typename CFG::TestT dd = 0, dg = 0, gm = 0, xx = 0;
    bool fin = true;
#endif
    for (int i = 0; i < CFG::N_VARIABLES; ++i) {
#pragma HLS PIPELINE II=CFG::RETIRE_II
        const int s = RETIRE_STEP[i];
        if (s >= 0 && !at_x) {
            FGC_OUTER_RECEIVE();  // csim cycle counting: no earlier than the step was sent
            const int f = STEP_F[s], cb = STEP_COL_BEGIN[s];
            for (int c = 0; c < CFG::MAX_F; c += 2) {
#pragma HLS UNROLL
                if (c < f) {
                    const BsPair in = dx.read();
                    for (int h = 0; h < 2; ++h) {
                        if (c + h < f) delta[STEP_COL[cb + c + h]] = in.word[h];
                    }
                }
            }
        }
        // its words on to trial_cost (and tx2: the kernel's second cost process, if any)
#ifdef FGC_BS_STEP_TEST
        step_sums<CFG>(RETIRE_VARS[i], delta, at_x, tx, tx2, dd, dg, gm, fin, xx);
#else
        CFG::retract_variable(RETIRE_VARS[i], delta, at_x, tx, tx2);
#endif
        FGC_CYCLES("retire", 0, "variable", 1, CFG::RETIRE_II, CFG::RETIRE_DEPTH);
    }
#ifdef FGC_BS_STEP_TEST
    if (!at_x) CFG::retire_test(dd, dg, gm, fin, xx);
#endif
}

// Back-substitution root first into DELTA, the state update X_TRIAL = X (+) DELTA beside it,
// and beside that the cost at X_TRIAL (the kernel's trial_cost, fed the retired variables). at_x:
// no solve, the cost at X (backsub_retire sends X's variables).
template <class CFG>
void back_substitute(bool at_x) {
#pragma HLS DATAFLOW
    hls::stream<BsPair> dx;  // the solved steps' frontal solutions, a pair of words a word
#pragma HLS STREAM variable=dx depth=CFG::MAX_F
    hls::stream<TrialVar> tx;  // the retired variables' storage words, a variable a word
#pragma HLS STREAM variable=tx depth=CFG::N_VARIABLES
    hls::stream<TrialVar> tx2;  // those the kernel's second cost process takes, if any (TRIAL_SEND;
#pragma HLS STREAM variable=tx2 depth=CFG::TRIAL_TX2_DEPTH
    // else never written nor read: one word deep)
    FGC_PHASE(at_x ? "factor_cost" : "backsub");
    backsub_slots<CFG>(dx, at_x);
    backsub_retire<CFG>(dx, tx, tx2, at_x);
    trial_cost(tx, tx2);  // (the kernel's: with a second cost process, a DATAFLOW region of two)
    FGC_OUTER_JOIN();
    FGC_DRAINED(&dx, 1);
    FGC_DRAINED(&tx, 1);
    FGC_DRAINED(&tx2, 1);
}

#else  // FGC_BS_COLUMNS: back-substitution by columns (HlsConfig backsub_lanes = 4)
// One process per end of a two-ended chain (units/backsub.py's column_*; docs/hls.md,
// "Back-substitution by columns"). Each end solves its steps (BSC_SEQ: end 0 the root first)
// as one long triangle, a pass per step: the columns r = f - 1 ... 0 of its conditional, x_r
// read at a column's first iteration, then y_i -= c_ir x_r for its own rows above r and, where
// column r is one of the child's separator columns (BSC_COLA), for all the child's rows
// (c = S'_ia / R'_ii), four rows an iteration (lane l the row of residue l mod 4); beside the
// columns the pass takes in the conditional of the step two ahead, a group of four COND words
// an iteration from the loader's stream: 1 / R_ii (the diagonal: its row's first group) and
// the group's words scaled by it (c_ic = R_ic / R_ii, y_i = d_i / R_ii) into the free slot of
// the end's three (BSC_SLOT / BSC_CSLOT / BSC_ISLOT). End 1 first runs a pass over the root's
// columns (BSC_FEED: x_r from end 0's stream `xroot`), updating its first step's rows. The
// solutions go to the state update as pairs (x_{f-1}, x_{f-2}), ... on the end's own stream.
const int BSC_U = 4;  // update lanes per end (units/backsub.py's COLUMN_LANES)
const int BSC_W = 4;  // words of an aligned COND group (COLUMN_WIDTH)
const int BSC_NSLOT = 3;  // an end's conditional buffers (COLUMN_SLOTS)
const int BSC_RB = (MAX_F + BSC_U - 1) / BSC_U;  // a bank's rows of a slot
const int BSC_GB = (MAX_W + 1) / BSC_W + 2;  // a row's groups at most

struct BsGroup { L w[BSC_W]; };  // an aligned group of COND words (the loader's stream word)

// A walk over one step's conditional in COND, row by row (from its diagonal to d), each row's
// aligned groups of BSC_W words (units/backsub.py's column_groups; cond_load_wide's walk)
struct BscCursor {
    int f, w, cols, i, base, g;
};

inline void bsc_start(BscCursor& c, int step) {
#pragma HLS INLINE
    c.f = STEP_F[step];
    c.w = STEP_W[step];
    c.cols = c.w + 1;
    c.i = 0;
    c.base = STEP_COND_OFF[step];
    c.g = c.base / BSC_W;
}

inline void bsc_next(BscCursor& c) {
#pragma HLS INLINE
    if (BSC_W * c.g + BSC_W - 1 >= c.base + c.w) {  // the row's last group
        ++c.i;
        c.base += c.cols;
        c.g = (c.base + c.i) / BSC_W;
    } else {
        ++c.g;
    }
}

// End E's walk over its steps (BSC_SEQ[BSC_SEQ_BEGIN[E]] ...): its cursor on step BSC_SEQ[k],
// or a false when k is past the end's last step
template <int E>
inline void bsc_seq_start(BscCursor& c, int k, bool& a) {
#pragma HLS INLINE
    a = k < BSC_SEQ_BEGIN[E + 1];
    if (a) bsc_start(c, BSC_SEQ[k]);
}

// End E's share of a loader iteration: the cursor's aligned group of COND to the end's stream,
// then the next group (after a step's last row, the end's next step)
template <int E>
inline void bsc_feed(hls::stream<BsGroup>& g, BscCursor& c, int& k, bool& a) {
#pragma HLS INLINE
    BsGroup x;
    for (int h = 0; h < BSC_W; ++h) x.w[h] = COND[BSC_W * c.g + h];
    g.write(x);
    bsc_next(c);
    if (c.i == c.f) {
        ++k;
        bsc_seq_start<E>(c, k, a);
    }
}

// The loader: COND cyclic BSC_W (word h of a group in bank h: two reads a bank an iteration),
// an aligned group to each end an iteration, each end's steps in BSC_SEQ order. II 1, depth 2
// (read, write).
template <class CFG>
void backsub_loader(hls::stream<BsGroup>& g0, hls::stream<BsGroup>& g1, bool at_x) {
#pragma HLS ARRAY_PARTITION variable=COND cyclic factor=4
    FGC_OUTER_BRANCH();  // csim cycle counting only: the column region beside the state update
    FGC_REGION("backsub_columns");
    if (at_x) return;
    int k0 = BSC_SEQ_BEGIN[0], k1 = BSC_SEQ_BEGIN[1];
    bool a0 = false, a1 = false;
    BscCursor c0 = {0, 0, 0, 0, 0, 0}, c1 = {0, 0, 0, 0, 0, 0};
    bsc_seq_start<0>(c0, k0, a0);
    bsc_seq_start<1>(c1, k1, a1);
    int trip = 0;
    for (; a0 || a1; ++trip) {
#pragma HLS LOOP_TRIPCOUNT max=N_COND/2
#pragma HLS PIPELINE II=1
        if (a0) bsc_feed<0>(g0, c0, k0, a0);
        if (a1) bsc_feed<1>(g1, c1, k1, a1);
    }
    FGC_CYCLES("backsub_loader", 0, "groups", trip, 1, 2);
}

// Where word (i, c) of a step (COND offset off, cols words a row) sits in an end's buffer:
// bank [i % U][its COND bank], at (slot, i / U, its group within the row)
inline int bsc_addr(int slot, int off, int cols, int i, int c) {
#pragma HLS INLINE
    const int p = off + i * cols + c, first = (off + i * cols + i) / BSC_W;
    return (slot * BSC_RB + i / BSC_U) * BSC_GB + (p / BSC_W - first);
}

// An end's passes (BSC_PASS_BEGIN[E] ...): one pipelined loop a pass (II 1), its columns and
// its ingestion side by side, until both are done (trip: units/backsub.py's column_pass_trip).
// E = 0 sends the root's x_r to end 1 (BSC_ROOT), E = 1 reads them (BSC_FEED).
template <class CFG, int E, class XIN, class XOUT>
void backsub_end(hls::stream<BsGroup>& gin, hls::stream<BsPair>& dx, XIN&& xin, XOUT&& xout,
                 bool at_x) {
#pragma HLS INLINE
    typedef L T;
    const int CHAIN = CFG::MUL_LAT + CFG::ADD_LAT;
    const int PAD = CHAIN + 1;
    // the coefficients: [row residue][COND bank][slot, row / U, group]: lane l reads bank
    // [l][*] (one word), the ingestion writes [*][h] (word h of its group): a read and a
    // write a bank an iteration
    T cbuf[BSC_U][BSC_W][BSC_NSLOT * BSC_RB * BSC_GB];
#pragma HLS ARRAY_PARTITION variable=cbuf complete dim=1
#pragma HLS ARRAY_PARTITION variable=cbuf complete dim=2
    T y[BSC_NSLOT][MAX_F];  // the rows of the three slots, registers
#pragma HLS ARRAY_PARTITION variable=y complete dim=0
    if (at_x) return;
    for (int q = BSC_PASS_BEGIN[E]; q < BSC_PASS_BEGIN[E + 1]; ++q) {
#pragma HLS LOOP_TRIPCOUNT max=N_STEPS+3
        const int st = BSC_STEP[q], ch = BSC_CHILD[q], in = BSC_INGEST[q];
        const int sl = BSC_SLOT[q], cs = BSC_CSLOT[q], is = BSC_ISLOT[q];
        const bool feed = BSC_FEED[q] != 0, root = BSC_ROOT[q] != 0;
        const int f = st >= 0 ? STEP_F[st] : 0, soff = st >= 0 ? STEP_COND_OFF[st] : 0;
        const int scols = st >= 0 ? STEP_W[st] + 1 : 0;
        const int fc = ch >= 0 ? STEP_F[ch] : 0, coff = ch >= 0 ? STEP_COND_OFF[ch] : 0;
        const int ccols = ch >= 0 ? STEP_W[ch] + 1 : 0, cblocks = (fc + BSC_U - 1) / BSC_U;
        const int ca = BSC_COLA_BEGIN[q];
        BscCursor ci = {0, 0, 0, 0, 0, 0};
        bool ing = in >= 0;
        if (ing) bsc_start(ci, in);
        T xr = T(0), xprev = T(0), diag = T(1);
        int r = f - 1, k = 0, trip = 0;
        if (feed) FGC_WAIT("backsub_end", 1, "backsub_end", 0, "root");
        for (; r >= 0 || ing; ++trip) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_F*(MAX_F/4+MAX_F/4+2)
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=y inter true distance=CHAIN
            // cbuf: the pass writes slot BSC_ISLOT and reads BSC_SLOT / BSC_CSLOT, three
            // different slots (units/backsub.py's column_passes): no iteration reads a word
            // another iteration of the pass writes
#pragma HLS DEPENDENCE variable=cbuf inter false
            if (r >= 0) {
                const int a = BSC_COLA[ca + r];
                const int own = feed ? 0 : (r + BSC_U - 1) / BSC_U;
                const int n = own + (a >= 0 ? cblocks : 0);
                const int len = n == 0 ? 1 : (n > PAD ? n : PAD);
                if (k == 0) {
                    xr = feed ? xin.read() : y[sl][r];  // final: its last update a column ago
                    if (root) xout.write(xr);
                    if (!feed) {  // pairs (x_{f-1}, x_{f-2}), ...: an index test, no operator
                        if (((f - 1 - r) & 1) == 0) {
                            xprev = xr;
                            if (r == 0) {
                                BsPair out;
                                out.word[0] = xr;
                                out.word[1] = T(0);
                                dx.write(out);
                            }
                        } else {
                            BsPair out;
                            out.word[0] = xprev;
                            out.word[1] = xr;
                            dx.write(out);
                        }
                    }
                }
                for (int l = 0; l < BSC_U; ++l) {
#pragma HLS UNROLL
                    // lane l's row: an own row r - 1 - U k ... (the one of residue l), or the
                    // child's row U (k - own) + l; the same multiply-subtract either way (the
                    // row, its slot and the coefficient's place are muxes: no operator)
                    const int t = (r - 1 - l) & (BSC_U - 1);
                    const bool mine = k < own;
                    const int i = mine ? r - 1 - k * BSC_U - t : BSC_U * (k - own) + l;
                    const bool act = mine ? k * BSC_U + t < r : (a >= 0 && i < fc);
                    const int ys = mine ? sl : cs, off = mine ? soff : coff;
                    const int cols = mine ? scols : ccols, c = mine ? r : fc + a;
                    if (act) {
                        const int p = off + i * cols + c;
                        const T coef = cbuf[l][p % BSC_W][bsc_addr(ys, off, cols, i, c)];
                        y[ys][i] = y[ys][i] - coef * xr;
                    }
                }
                if (k == len - 1) {
                    k = 0;
                    --r;
                } else {
                    ++k;
                }
            }
            if (ing) {  // a group of row ci.i of the step taken in
                const BsGroup grp = gin.read();
                const int hd = ci.base + ci.i - BSC_W * ci.g;  // the diagonal's word, if here
                for (int h = 0; h < BSC_W; ++h)
                    if (h == hd) diag = grp.w[h];  // a mux: the row's first group
                const T inv = T(1) / diag;
                const int first = (ci.base + ci.i) / BSC_W;
                const int addr = (is * BSC_RB + ci.i / BSC_U) * BSC_GB + (ci.g - first);
                for (int h = 0; h < BSC_W; ++h) {
#pragma HLS UNROLL
                    const int c = BSC_W * ci.g + h - ci.base;
                    if (c >= ci.i && c <= ci.w) {
                        const T v = grp.w[h] * inv;
                        cbuf[ci.i % BSC_U][h][addr] = v;
                        if (c == ci.w) y[is][ci.i] = v;  // y_i = d_i / R_ii
                    }
                }
                bsc_next(ci);
                if (ci.i == ci.f) ing = false;
            }
        }
        // depth: the column's read, product, subtraction, write beside the ingestion's read,
        // divide, scaling, write: the deeper (units/backsub.py's column_pass_depth)
        FGC_CYCLES("backsub_end", E, root ? "root" : "pass", trip, 1,
                   2 + CHAIN > 2 + CFG::DIV_LAT + CFG::MUL_LAT ? 2 + CHAIN
                                                              : 2 + CFG::DIV_LAT + CFG::MUL_LAT);
        if (st >= 0 && !feed) FGC_OUTER_SEND_STEP(st);
    }
}

// The x side an end never takes (end 0 reads no root x, end 1 sends none: BSC_FEED only on
// end 1, BSC_ROOT only on end 0): a value with no storage, not a stream, so each end's process
// touches xroot in its one direction and holds no FIFO of its own
struct BscNoX {
    L read() { return L(0); }
    void write(L) {}
};

// End 0 sends the root's x_r (xroot: written only), end 1 reads them (xroot: read only)
template <class CFG>
void backsub_end0(hls::stream<BsGroup>& gin, hls::stream<BsPair>& dx, hls::stream<L>& xroot,
                  bool at_x) {
    backsub_end<CFG, 0>(gin, dx, BscNoX(), xroot, at_x);
}

template <class CFG>
void backsub_end1(hls::stream<BsGroup>& gin, hls::stream<BsPair>& dx, hls::stream<L>& xroot,
                  bool at_x) {
    backsub_end<CFG, 1>(gin, dx, xroot, BscNoX(), at_x);
}

// The state update as the two ends' solutions arrive (backsub_retire's loop, RETIRE_VARS
// order): a step's first variable takes the step's pairs from its end's stream (BSC_END_OF),
// x_{f-1} first, into its copy of delta and DELTA (LM control's step test reads it).
template <class CFG>
void backsub_retire_cols(hls::stream<BsPair>& dx0, hls::stream<BsPair>& dx1,
                         hls::stream<TrialVar>& tx, hls::stream<TrialVar>& tx2, bool at_x) {
    FGC_SEQUENTIAL();  // csim cycle counting only: the column region's records end here
    FGC_OUTER_BRANCH();
    L delta[CFG::N_TANGENT];  // the solved entries by tangent index
#ifdef FGC_BS_STEP_TEST
    // LM's step test (the kernel's FGC_BS_STEP_TEST): |delta|^2, delta^T g, delta's finiteness
    // and the gradient's largest |entry| summed a variable an iteration (the variable's terms from retract_variable; a
    // sum's add is its carried dependence, its latency within RETIRE_II), to CFG::retire_test
    typename CFG::TestT dd = 0, dg = 0, gm = 0;  // (and the gradient's largest |entry|)
    typename CFG::TestT xx = 0;  // |x (+) delta|^2: X's words as the state update writes them
    bool fin = true;
#endif
    for (int i = 0; i < CFG::N_VARIABLES; ++i) {
#pragma HLS PIPELINE II=CFG::RETIRE_II
        const int s = RETIRE_STEP[i];
        if (s >= 0 && !at_x) {
            FGC_OUTER_RECEIVE_STEP(s);  // csim cycle counting: no earlier than its pass ended
            const int f = STEP_F[s], cb = STEP_COL_BEGIN[s], e = BSC_END_OF[s];
            for (int c = 0; c < CFG::MAX_F; c += 2) {
#pragma HLS UNROLL
                if (c < f) {
                    const BsPair in = e ? dx1.read() : dx0.read();
                    for (int h = 0; h < 2; ++h) {
                        if (c + h < f) {
                            const int col = STEP_COL[cb + f - 1 - c - h];
                            delta[col] = in.word[h];
                            DELTA[col] = in.word[h];
                        }
                    }
                }
            }
        }
#ifdef FGC_BS_STEP_TEST
        // its words on to trial_cost, its terms into the sums
        step_sums<CFG>(RETIRE_VARS[i], delta, at_x, tx, tx2, dd, dg, gm, fin, xx);
#else
        CFG::retract_variable(RETIRE_VARS[i], delta, at_x, tx);  // its words on to trial_cost
#endif
        FGC_CYCLES("retire", 0, "variable", 1, CFG::RETIRE_II, CFG::RETIRE_DEPTH);
    }
#ifdef FGC_BS_STEP_TEST
    CFG::retire_test(dd, dg, gm, fin, xx);
#else
    (void)tx2;  // (written only with the kernel's second cost process)
#endif
}

// Back-substitution by columns: the loader, the two ends, the state update beside them and
// the cost at X_TRIAL beside that. at_x: no solve, the cost at X.
template <class CFG>
void back_substitute(bool at_x) {
#pragma HLS DATAFLOW
    hls::stream<BsGroup> g0;  // the loader's groups to each end
    hls::stream<BsGroup> g1;
#pragma HLS STREAM variable=g0 depth=BSC_FIFO0
#pragma HLS STREAM variable=g1 depth=BSC_FIFO1
    hls::stream<L> xroot;  // the root's x_r, end 0 to end 1
#pragma HLS STREAM variable=xroot depth=CFG::MAX_F
    hls::stream<BsPair> dx0;  // each end's solutions to the state update
    hls::stream<BsPair> dx1;
#pragma HLS STREAM variable=dx0 depth=BSC_DX0
#pragma HLS STREAM variable=dx1 depth=BSC_DX1
    hls::stream<TrialVar> tx;  // the retired variables' storage words, a variable a word
#pragma HLS STREAM variable=tx depth=CFG::N_VARIABLES
    hls::stream<TrialVar> tx2;  // those the kernel's second cost process takes, if any
#pragma HLS STREAM variable=tx2 depth=CFG::N_VARIABLES
    FGC_PHASE(at_x ? "factor_cost" : "backsub");
    backsub_loader<CFG>(g0, g1, at_x);
    backsub_end0<CFG>(g0, dx0, xroot, at_x);
    backsub_end1<CFG>(g1, dx1, xroot, at_x);
    backsub_retire_cols<CFG>(dx0, dx1, tx, tx2, at_x);
    trial_cost(tx, tx2);  // (the kernel's: with a second cost process, a DATAFLOW region of two)
    FGC_OUTER_JOIN();
    FGC_DRAINED(&g0, 1);
    FGC_DRAINED(&g1, 1);
    FGC_DRAINED(&xroot, 1);
    FGC_DRAINED(&dx0, 1);
    FGC_DRAINED(&dx1, 1);
    FGC_DRAINED(&tx, 1);
    FGC_DRAINED(&tx2, 1);
}
#endif  // FGC_BS_COLUMNS

#endif  // FGC_BACKSUB_DRIVER
