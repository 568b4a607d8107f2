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
// Same order as the kernel's back-substitution (kernel.cpp.jinja): the separator's share of every
// row first (independent rows, rhs_i = d_i - S_i xs, a dot product with PARTIALS interleaved
// partial sums), the reciprocals of the diagonal (independent), then the frontal triangle column
// by column, last first: x_r = rhs_r / R_rr, rhs_i -= R_ir x_r for the rows i < r above it, so a
// column's dependency chain is one multiply and one multiply-add. Sequential code, no DATAFLOW.
// Cycles to FGC_CYCLES (fgc_cycles.h) as the loops state them.
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
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
        T part[P];
#pragma HLS ARRAY_PARTITION variable=part complete
        for (int t = 0; t < P; ++t) {
#pragma HLS UNROLL
            part[t] = T(0);
        }
        // S_i xs: trip s, II ceil(La / min(s, P)), depth Lm + La (1 + ceil(log2 min(s, P)))
        for (int a = 0; a < s; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_COLS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=part inter false
            part[a % P] += cond[i * cols + f + a] * xs[a];
        }
        const T acc = fold_partials<T, P>(part);
        rhs[i] = cond[i * cols + w] - acc;  // + La
        FGC_CYCLES("backsub", 0, "separator", s, dot_ii(s, P, CFG::ADD_LAT),
                   dot_depth(s, P, CFG::ADD_LAT, CFG::MUL_LAT) + CFG::ADD_LAT);
    }
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
