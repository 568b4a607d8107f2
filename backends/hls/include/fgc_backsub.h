// fgc_backsub.h: back-substitution of one elimination step's conditional (R | S | d), the last
// stage of both linear solvers (QR: the qr<s>_backsub unit; Cholesky: the trisolve unit, R = L^T,
// since L z = g already ran in the cascade as the augmented column).
//
//   template <class CFG>
//   void cond_backsub(const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS], int f, int s,
//                     const typename CFG::T xs[CFG::MAX_COLS], typename CFG::T x[CFG::MAX_F]);
//
// In: cond as qr_step / cpe_step write it (f rows of w + 1 = f + s + 1 columns, row-major,
// cond[i * (w + 1) + c]); xs[a], a < s: the separator's solution (solved by the parent steps
// first). Out: x[i], i < f, with R x = d - S xs. CFG needs T, MAX_F, MAX_COLS (>= f + s + 1),
// PARTIALS (>= ADD_LAT), ADD_LAT, MUL_LAT, DIV_LAT; the QR and CPE configurations have them all.
//
// The separator's share of every row first (rhs_i = d_i - S_i xs: the rows' dot products in one
// pipelined loop at II 1, each row's terms in PARTIALS interleaved partial sums, the same sums
// and fold as a dot product per row would add), the reciprocals of the diagonal (independent),
// then the frontal triangle column by column, last first: x_r = rhs_r / R_rr, rhs_i -= R_ir x_r
// for the rows i < r above it, so a column's dependency chain is one multiply and one
// multiply-add. No DATAFLOW inside: the kernel runs one cond_backsub per unit set side by side
// (back_substitute's backsub_level region). Cycles to FGC_CYCLES (fgc_cycles.h) as the loops
// state them.
#ifndef FGC_BACKSUB_H
#define FGC_BACKSUB_H

#include "fgc_cycles.h"

namespace fgc_units {

template <class CFG>
void cond_backsub(const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS], int f, int s,
                  const typename CFG::T xs[CFG::MAX_COLS], typename CFG::T x[CFG::MAX_F]) {
    typedef typename CFG::T T;
    const int P = CFG::PARTIALS;
    static_assert(CFG::PARTIALS >= CFG::ADD_LAT, "PARTIALS >= ADD_LAT: the dot loops run at II 1");
    const int w = f + s, cols = w + 1;
    T rhs[CFG::MAX_F], inv[CFG::MAX_F];
    // S xs, every row at once: PARTIALS interleaved partial sums per row (bank a % P of part),
    // the entries S_ia in column order, a's rows one after another. Consecutive iterations hit
    // different rows and a partial sum comes back every P f >= P >= ADD_LAT iterations (the
    // DEPENDENCE's distance, at least P): II 1.
    T part[CFG::PARTIALS][CFG::MAX_F];
#pragma HLS ARRAY_PARTITION variable=part complete dim=1
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        for (int t = 0; t < P; ++t) part[t][i] = T(0);
    }
    FGC_CYCLES("backsub", 0, "zero", f, 1, 1);
    // trip f s, II 1, depth Lm + La
    for (int e = 0, a = 0, i = 0; e < f * s; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F*CFG::MAX_COLS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter true distance=CFG::PARTIALS
        part[a % P][i] += cond[i * cols + f + a] * xs[a];
        if (i == f - 1) {
            i = 0;
            ++a;
        } else {
            ++i;
        }
    }
    FGC_CYCLES("backsub", 0, "separator", f * s, 1, CFG::MUL_LAT + CFG::ADD_LAT);
    // rhs_i = d_i - (the row's partial sums folded): trip f, II 1, depth La (1 + ceil(log2 P))
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        T row[P];
        for (int t = 0; t < P; ++t) row[t] = part[t][i];
        rhs[i] = cond[i * cols + w] - fold_partials<T, P>(row);
    }
    FGC_CYCLES("backsub", 0, "fold", f, 1, CFG::ADD_LAT * (1 + ceil_log2(CFG::PARTIALS)));
    // trip f, II 1, depth Ld
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
        inv[i] = T(1) / cond[i * cols + i];
    }
    FGC_CYCLES("backsub", 0, "reciprocals", f, 1, CFG::DIV_LAT);
    for (int r = f - 1; r >= 0; --r) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
        const T xr = rhs[r] * inv[r];  // depth Lm
        x[r] = xr;
        FGC_CYCLES("backsub", 0, "solve", 1, 1, CFG::MUL_LAT);
        // the column above the pivot: trip r, II 1, depth Lm + La
        for (int i = 0; i < r; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
            rhs[i] -= cond[i * cols + r] * xr;
        }
        FGC_CYCLES("backsub", 0, "column", r, 1, CFG::MUL_LAT + CFG::ADD_LAT);
    }
}

}  // namespace fgc_units

#endif  // FGC_BACKSUB_H
