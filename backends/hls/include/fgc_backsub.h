// fgc_backsub.h: back-substitution of one elimination step's conditional (R | S | d), the last
// stage of both linear solvers (QR: the qr<s>_backsub unit; Cholesky: the trisolve unit, R = L^T,
// since L z = g already ran in the cascade as the augmented column).
//
//   template <class CFG>
//   void cond_load(const typename CFG::T src[], int off, int f, int s, const typename CFG::T xs[MAX_COLS],
//                  typename CFG::T cond[MAX_F * MAX_COLS], typename CFG::T part[2][PARTIALS][MAX_F]);
//   template <class CFG>
//   void cond_backsub(const typename CFG::T cond[MAX_F * MAX_COLS], int f, int s,
//                     const typename CFG::T part[2][PARTIALS][MAX_F], typename CFG::T x[MAX_F]);
//
// The conditional as qr_step / cpe_step store it: f rows of w + 1 = f + s + 1 columns, row-major,
// cond[i * (w + 1) + c]; xs[a], a < s: the separator's solution (solved by the parent steps
// first). Out: x[i], i < f, with R x = d - S xs. CFG needs T, MAX_F, MAX_COLS (>= f + s + 1),
// PARTIALS (>= ADD_LAT), ADD_LAT, MUL_LAT, DIV_LAT; the QR and CPE configurations have them all.
//
// cond_load moves the words the solve reads (R's upper triangle, S and d of each row: f (w + 1)
// - f (f - 1) / 2 words, the structural zeros below R's diagonal left behind) from where the
// factorization stored them (src from word off on) into the unit's buffer, two a cycle (the source memory's two ports),
// and on the way adds each S_ia xs_a into a partial sum of row i: word lane h (the word's index
// parity: a lane per port) and bank (a >> 1) % PARTIALS, so a lane's sum comes back PARTIALS >=
// ADD_LAT iterations later (II 1) and the first S_ia of a sum sets it (no zeroing pass).
//
// cond_backsub then runs two pipelined loops and one multiply:
// - per row (trip f, II 1): its 2 PARTIALS sums folded and subtracted from d (y_i = d_i - S_i xs)
//   beside the reciprocal of the diagonal 1 / R_ii (the divides independent of each other);
// - the triangle as one flattened loop over the columns r = f - 1 ... 1, last first: at a column's
//   first iteration x_r = y_r / R_rr (y_r final: its last update was the previous column's first
//   iteration), then y_i -= R_ir x_r for the rows i = r - 1 ... 0 above the pivot, one a cycle.
//   The recurrence per unknown is CHAIN = 2 MUL_LAT + ADD_LAT (x_r, its product, the
//   subtraction), so a column takes max(r, CHAIN + 1) iterations: columns shorter than the chain
//   are padded, the long ones hide it (the column updates run beside the chain). y_i is updated
//   in place (one read, one write a cycle) and each new value also written to z_i, from which
//   a column's first iteration reads x_r's y_r (z: one write, one read a cycle), so each array
//   needs no more than its two ports. DEPENDENCE distance CHAIN is true for both: z_{r-1} is
//   read a column's length >= CHAIN + 1 iterations after it was written, y_i is updated again
//   a column's length - 1 >= CHAIN iterations later;
// - x_0 = y_0 / R_00.
// No DATAFLOW inside: the kernel runs one cond_backsub per unit set side by side (back_substitute's
// backsub_level region). Cycles to FGC_CYCLES (fgc_cycles.h) as the loops state them.
#ifndef FGC_BACKSUB_H
#define FGC_BACKSUB_H

#include "fgc_cycles.h"

namespace fgc_units {

// The triangle's recurrence per unknown (backsub.py's backsub_chain): the multiply by 1 / R_rr,
// the product R_ir x_r and the subtraction.
template <class CFG>
constexpr int backsub_chain() { return 2 * CFG::MUL_LAT + CFG::ADD_LAT; }

// Iterations of cond_backsub's triangle loop: the columns r = f - 1 ... 1, each max(r, CHAIN + 1).
template <class CFG>
inline int backsub_triangle_trip(int f) {
    const int pad = backsub_chain<CFG>() + 1;
    // columns r <= pad take pad iterations, the longer ones r
    return f - 1 <= pad ? (f > 1 ? (f - 1) * pad : 0)
                        : pad * pad + (f - 1) * f / 2 - pad * (pad + 1) / 2;
}

// Words cond_load moves: each row i from its diagonal on (w + 1 - i words).
inline int backsub_words(int f, int s) { return f * (f + s + 1) - f * (f - 1) / 2; }

template <class CFG>
void cond_load(const typename CFG::T src[], int off, int f, int s,
               const typename CFG::T xs[CFG::MAX_COLS],
               typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
               typename CFG::T part[2][CFG::PARTIALS][CFG::MAX_F]) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    static_assert(CFG::PARTIALS >= CFG::ADD_LAT, "PARTIALS >= ADD_LAT: the load runs at II 1");
    const int cols = f + s + 1;
    const int words = backsub_words(f, s);
    int i = 0, c = 0, base = 0;  // the next word: row i, column c, at base + c (base = i cols)
    // trip ceil(words / 2), II 1, depth 2 + Lm + La (read, multiply-add, write)
    for (int e = 0; e < words; e += 2) {
#pragma HLS LOOP_TRIPCOUNT max=(CFG::MAX_F*CFG::MAX_COLS+1)/2
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
        for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
            if (e + h < words) {
                const T v = src[off + base + c];
                cond[base + c] = v;
                const int a = c - f;
                if (a >= 0 && a < s) {
                    const int b = (a >> 1) % P;
                    const bool first = a < 2 * P;
                    part[h][b][i] = (first ? T(0) : part[h][b][i]) + v * xs[a];
                }
                if (c == cols - 1) {
                    ++i;
                    base += cols;
                    c = i;
                } else {
                    ++c;
                }
            }
        }
    }
    FGC_CYCLES("backsub_copy", 0, "cond_load", ceil_div(words, 2), 1,
               2 + CFG::MUL_LAT + CFG::ADD_LAT);
}

template <class CFG>
void cond_backsub(const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS], int f, int s,
                  const typename CFG::T part[2][CFG::PARTIALS][CFG::MAX_F],
                  typename CFG::T x[CFG::MAX_F]) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    const int CHAIN = 2 * CFG::MUL_LAT + CFG::ADD_LAT;  // backsub_chain
    const int w = f + s, cols = w + 1;
    if (f <= 0) return;
    T y[CFG::MAX_F], z[CFG::MAX_F], inv[CFG::MAX_F];
    // per row: y_i = d_i - (its 2 P partial sums folded), 1 / R_ii beside it; trip f, II 1,
    // depth max(La (1 + ceil(log2 2P)), Ld). srow: the index of S_i0 among cond_load's words
    // (its parity: the lane of a = 0); a sum holds terms iff its first a is below s.
    for (int i = 0, srow = f; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        T row[2 * CFG::PARTIALS];
        for (int h = 0; h < 2; ++h) {
            for (int b = 0; b < P; ++b) {
                const bool used = 2 * b + ((h + srow) & 1) < s;
                row[h * P + b] = used ? part[h][b][i] : T(0);
            }
        }
        const T yi = cond[i * cols + w] - fold_partials<T, 2 * CFG::PARTIALS>(row);
        y[i] = yi;
        z[i] = yi;
        inv[i] = T(1) / cond[i * cols + i];
        srow += cols - i - 1;
    }
    FGC_CYCLES("backsub", 0, "rows", f, 1,
               CFG::ADD_LAT * (1 + ceil_log2(2 * CFG::PARTIALS)) > CFG::DIV_LAT
                   ? CFG::ADD_LAT * (1 + ceil_log2(2 * CFG::PARTIALS)) : CFG::DIV_LAT);
    // the triangle, columns r = f - 1 ... 1 flattened (k: the iteration within column r)
    const int pad = CHAIN + 1;
    const int trip = backsub_triangle_trip<CFG>(f);
    T xr = T(0);
    for (int e = 0, r = f - 1, k = 0; e < trip; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F*CFG::MAX_F/2+CFG::MAX_F*(2*CFG::MUL_LAT+CFG::ADD_LAT+1)
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=y inter true distance=CHAIN
#pragma HLS DEPENDENCE variable=z inter true distance=CHAIN
        if (k == 0) {
            xr = z[r] * inv[r];
            x[r] = xr;
        }
        if (k < r) {
            const int i = r - 1 - k;
            const T yi = y[i] - cond[i * cols + r] * xr;
            y[i] = yi;
            z[i] = yi;
        }
        const int len = r > pad ? r : pad;
        if (k == len - 1) {
            k = 0;
            --r;
        } else {
            ++k;
        }
    }
    FGC_CYCLES("backsub", 0, "triangle", trip, 1, CHAIN);
    x[0] = z[0] * inv[0];  // depth Lm
    FGC_CYCLES("backsub", 0, "last", 1, 1, CFG::MUL_LAT);
}

}  // namespace fgc_units

#endif  // FGC_BACKSUB_H
