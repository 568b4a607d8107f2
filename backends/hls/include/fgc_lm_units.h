// fgc_lm_units.h: LM control's reductions on the accelerator, the hooks the kernel's LmConfig
// gives fgc_lm.h (whose rules they serve): each a term a cycle (PIPELINE II=1) into as many
// interleaved partial sums (maxima) as the adder's (compare's) latency, the partial arrays
// completely partitioned, folded in a tree; cycles to FGC_CYCLES as the plan prices them
// (fgc_backends/hls/plan.py, lm_loops).
//
//   T    lm_x_norm<CFG>(x)                          |x|, at the top of try_steps
//   bool lm_step_test<CFG>(solved, mu, delta, g, out) out = {|delta|^2, 0.5 delta^T (g + mu delta)}
//   T    lm_gradient_max<CFG>(g)                    the gradient's largest |entry|
//   void lm_accept<CFG>(x, x_trial)                 x = x_trial
//   void lm_top<CFG>(x_in, data, x_out, x, data_buf, errors, info)
//                                                   the batch top's body: x and the data in,
//                                                   fgc_lm::optimize<CFG>, x out
//
// CFG needs T, N_X, N_TANGENT, PARTIALS (>= ADD_LAT), ADD_LAT, MUL_LAT, MAXIMA (>= CMP_LAT),
// CMP_LAT, ABS_LAT, and the (II, depth) of a move and of the decision: MOVE_II, MOVE_DEPTH,
// DECISION_II, DECISION_DEPTH; for the top N_DATA and fgc_lm.h's CFG (its rules and hooks); the
// kernel's LmConfig has them all.
#ifndef FGC_LM_UNITS_H
#define FGC_LM_UNITS_H

#include "fgc_cycles.h"
#include "fgc_lm.h"

namespace fgc_units {

template <class CFG>
typename CFG::T lm_x_norm(const typename CFG::T x[CFG::N_X]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    // |x|^2: word i into partial sum i % PARTIALS (a word a cycle: II 1), folded in a tree
    T xp[CFG::PARTIALS];
#pragma HLS ARRAY_PARTITION variable=xp complete
    for (int p = 0; p < CFG::PARTIALS; ++p) {
#pragma HLS UNROLL
        xp[p] = T(0);
    }
    for (int i = 0; i < CFG::N_X; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=xp inter true distance=CFG::PARTIALS
        xp[i % CFG::PARTIALS] += x[i] * x[i];
    }
    const T x_norm = CFG::root(fold_partials<T, CFG::PARTIALS>(xp));
    FGC_PHASE("lm_iteration");
    FGC_CYCLES("iterate", 0, "x_norm", CFG::N_X, dot_ii(CFG::N_X, CFG::PARTIALS, CFG::ADD_LAT),
               dot_depth(CFG::N_X, CFG::PARTIALS, CFG::ADD_LAT, CFG::MUL_LAT));
    return x_norm;
}

template <class CFG>
bool lm_step_test(bool solved, typename CFG::T mu, const typename CFG::T delta[CFG::N_TANGENT],
                  const typename CFG::T g[CFG::N_TANGENT], typename CFG::T out[2]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    bool ok = solved;
    // |delta|^2 and delta^T (g + mu delta), entry i into partial sums i % PARTIALS of each
    // (II 1), folded in a tree
    T dp[CFG::PARTIALS], pp[CFG::PARTIALS];
#pragma HLS ARRAY_PARTITION variable=dp complete
#pragma HLS ARRAY_PARTITION variable=pp complete
    for (int p = 0; p < CFG::PARTIALS; ++p) {
#pragma HLS UNROLL
        dp[p] = T(0);
        pp[p] = T(0);
    }
    for (int i = 0; i < CFG::N_TANGENT; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=dp inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=pp inter true distance=CFG::PARTIALS
        const T d = delta[i];
        ok = ok && CFG::finite(d);
        dp[i % CFG::PARTIALS] += d * d;
        pp[i % CFG::PARTIALS] += d * (g[i] + mu * d);
    }
    out[0] = fold_partials<T, CFG::PARTIALS>(dp);
    out[1] = T(0.5) * fold_partials<T, CFG::PARTIALS>(pp);
    FGC_PHASE("lm_control");
    FGC_CYCLES("decide", 0, "step_test", CFG::N_TANGENT,
               dot_ii(CFG::N_TANGENT, CFG::PARTIALS, CFG::ADD_LAT),
               CFG::MUL_LAT + CFG::ADD_LAT
                   + dot_depth(CFG::N_TANGENT, CFG::PARTIALS, CFG::ADD_LAT, CFG::MUL_LAT));
    FGC_CYCLES("decide", 0, "decision", 1, CFG::DECISION_II, CFG::DECISION_DEPTH);
    return ok;
}

template <class CFG>
typename CFG::T lm_gradient_max(const typename CFG::T g[CFG::N_TANGENT]) {
    typedef typename CFG::T T;
    // entry i into partial maximum i % MAXIMA (II 1), folded in a tree of compares
    T gp[CFG::MAXIMA];
#pragma HLS ARRAY_PARTITION variable=gp complete
    for (int p = 0; p < CFG::MAXIMA; ++p) {
#pragma HLS UNROLL
        gp[p] = T(0);
    }
    for (int i = 0; i < CFG::N_TANGENT; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=gp inter true distance=CFG::MAXIMA
        const T a = CFG::magnitude(g[i]);
        gp[i % CFG::MAXIMA] = a > gp[i % CFG::MAXIMA] ? a : gp[i % CFG::MAXIMA];
    }
    const T g_max = fold_maxima<T, CFG::MAXIMA>(gp);
    FGC_PHASE("lm_iteration");
    FGC_CYCLES("iterate", 0, "gradient_max", CFG::N_TANGENT,
               dot_ii(CFG::N_TANGENT, CFG::MAXIMA, CFG::CMP_LAT),
               dot_depth(CFG::N_TANGENT, CFG::MAXIMA, CFG::CMP_LAT, CFG::ABS_LAT));
    return g_max;
}

template <class CFG>
void lm_accept(typename CFG::T x[CFG::N_X], const typename CFG::T x_trial[CFG::N_X]) {
    for (int i = 0; i < CFG::N_X; ++i) x[i] = x_trial[i];
    FGC_EVENT("accept");
    FGC_PHASE("lm_accept");
    FGC_CYCLES("accept", 0, "accept", CFG::N_X, CFG::MOVE_II, CFG::MOVE_DEPTH);
}

template <class CFG>
void lm_top(const typename CFG::T x_in[CFG::N_X], const typename CFG::T data[CFG::N_DATA],
            typename CFG::T x_out[CFG::N_X], typename CFG::T x[CFG::N_X],
            typename CFG::T data_buf[CFG::N_DATA], typename CFG::T errors[2], int info[3]) {
    FGC_EVENT("call");
    FGC_PHASE("setup");
    for (int i = 0; i < CFG::N_X; ++i) {
#pragma HLS PIPELINE II=1
        x[i] = x_in[i];
    }
    for (int i = 0; i < CFG::N_DATA; ++i) {
#pragma HLS PIPELINE II=1
        data_buf[i] = data[i];
    }
    FGC_CYCLES("top", 0, "x_in", CFG::N_X, CFG::MOVE_II, CFG::MOVE_DEPTH);
    FGC_CYCLES("top", 0, "data_in", CFG::N_DATA, CFG::MOVE_II, CFG::MOVE_DEPTH);
    fgc_lm::optimize<CFG>(errors, info);
    FGC_PHASE("setup");
    for (int i = 0; i < CFG::N_X; ++i) {
#pragma HLS PIPELINE II=1
        x_out[i] = x[i];
    }
    FGC_CYCLES("top", 0, "x_out", CFG::N_X, CFG::MOVE_II, CFG::MOVE_DEPTH);
}

}  // namespace fgc_units

#endif  // FGC_LM_UNITS_H
