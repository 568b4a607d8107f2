// fgc_lm_units.h: LM control's reductions on the accelerator, the hooks the kernel's LmConfig
// gives fgc_lm.h (whose rules they serve): each a term a cycle (PIPELINE II=1) into as many
// interleaved partial sums (maxima) as the adder's (compare's) latency, the partial arrays
// completely partitioned, folded in a tree; cycles to FGC_CYCLES as the plan prices them
// (fgc_backends/hls/plan.py, lm_loops).
//
//   void lm_iterate<CFG>(g, x, out)                 out = {the gradient's largest |entry|, |x|}:
//                                                   once per linearisation (fgc_lm.h's
//                                                   gradient_max; |x| kept for its x_norm)
//   bool lm_step_test<CFG>(solved, mu, delta, g, out) out = {|delta|^2, 0.5 delta^T (g + mu delta)}
//   bool lm_solved_test<CFG>(g, x, delta, out)      out = {the gradient's largest |entry|, |x|^2,
//                                                   |delta|^2, delta^T g}: the one-step
//                                                   policy's, once after the solve (both above
//                                                   in one loop; lm_step_sums the scalars)
//   void lm_accept<CFG>(x, x_trial)                 x = x_trial
//   void lm_restore<CFG>(x, x_back)                 x = x_back (the column design's trial not taken)
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

// A reduction two words a cycle (a memory's two ports): lane h of a pair takes word e + h into
// its partial e / 2 % P (P >= the recurrence's latency: II 1 once a lane has P terms), the 2P
// partials then folded in a tree. II and depth as dot_ii / dot_depth (fgc_cycles.h) on a lane's
// trip, the fold over 2k sums (k = min(trip, P)); `lead`: what comes ahead of the recurrence.
inline int pair_ii(int words, int partials, int lat) {
    return dot_ii(ceil_div(words, 2), partials, lat);
}
inline int larger(int a, int b) { return a > b ? a : b; }
// A reduction's P interleaved partial sums (maxima) set to zero before its loop: registers
// (the callers partition them completely), all in one cycle.
template <class T, int P>
inline void zero_partials(T part[P]) {
#pragma HLS INLINE
    for (int p = 0; p < P; ++p) {
#pragma HLS UNROLL
        part[p] = T(0);
    }
}
inline int pair_depth(int words, int partials, int lat, int lead) {
    const int trip = ceil_div(words, 2);
    const int k = trip < partials ? (trip < 1 ? 1 : trip) : partials;
    return lead + lat * (1 + ceil_log2(2 * k));
}

template <class CFG>
void lm_iterate(const typename CFG::T g[CFG::N_TANGENT], const typename CFG::T x[CFG::N_X],
                typename CFG::T out[2]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    // the gradient's largest |entry| and |x|^2 in one loop, two words of each a cycle: entry i
    // into partial maximum (i / 2) % PARTIALS of lane i % 2 (as many as the sums: one distance
    // for both, PARTIALS >= MAXIMA), x_i^2 into partial sum (i / 2) % PARTIALS of lane i % 2;
    // folded in trees
    T gp[2 * CFG::PARTIALS], xp[2 * CFG::PARTIALS];  // (PARTIALS >= MAXIMA maxima: one distance)
#pragma HLS ARRAY_PARTITION variable=gp complete
#pragma HLS ARRAY_PARTITION variable=xp complete
    zero_partials<T, 2 * CFG::PARTIALS>(gp);
    zero_partials<T, 2 * CFG::PARTIALS>(xp);
    const int N_LONGER = CFG::N_X > CFG::N_TANGENT ? CFG::N_X : CFG::N_TANGENT;
    for (int e = 0; e < N_LONGER; e += 2) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=gp inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=xp inter true distance=CFG::PARTIALS
        for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
            const int i = e + h;
            const int k = h * CFG::PARTIALS + (e >> 1) % CFG::PARTIALS;  // gp's and xp's
            if (i < CFG::N_TANGENT) {
                const T a = CFG::magnitude(g[i]);
                gp[k] = a > gp[k] ? a : gp[k];
            }
            if (i < CFG::N_X) xp[k] += x[i] * x[i];
        }
    }
    out[0] = fold_maxima<T, 2 * CFG::PARTIALS>(gp);
    out[1] = CFG::root(fold_partials<T, 2 * CFG::PARTIALS>(xp));
    FGC_PHASE("lm_iteration");
    FGC_CYCLES("iterate", 0, "gradient_x_norm", ceil_div(N_LONGER, 2),
               larger(pair_ii(CFG::N_TANGENT, CFG::PARTIALS, CFG::CMP_LAT),
                      pair_ii(CFG::N_X, CFG::PARTIALS, CFG::ADD_LAT)),
               larger(pair_depth(CFG::N_TANGENT, CFG::PARTIALS, CFG::CMP_LAT, CFG::ABS_LAT),
                      pair_depth(CFG::N_X, CFG::PARTIALS, CFG::ADD_LAT, CFG::MUL_LAT)));
}

template <class CFG>
bool lm_step_test(bool solved, typename CFG::T mu, const typename CFG::T delta[CFG::N_TANGENT],
                  const typename CFG::T g[CFG::N_TANGENT], typename CFG::T out[2]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    bool ok = solved;
    // |delta|^2 and delta^T g, two entries a cycle: entry i into partial sums
    // (i / 2) % PARTIALS of lane i % 2 of each (II 1), folded in trees; then delta^T (g + mu
    // delta) = delta^T g + mu |delta|^2 (two products a word, not three: mu delta, g + mu delta
    // and their product with delta)
    T dp[2 * CFG::PARTIALS], pp[2 * CFG::PARTIALS];
#pragma HLS ARRAY_PARTITION variable=dp complete
#pragma HLS ARRAY_PARTITION variable=pp complete
    zero_partials<T, 2 * CFG::PARTIALS>(dp);
    zero_partials<T, 2 * CFG::PARTIALS>(pp);
    for (int e = 0; e < CFG::N_TANGENT; e += 2) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=dp inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=pp inter true distance=CFG::PARTIALS
        for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
            const int i = e + h;
            const int k = h * CFG::PARTIALS + (e >> 1) % CFG::PARTIALS;
            if (i < CFG::N_TANGENT) {
                const T d = delta[i];
                ok = ok && CFG::finite(d);
                dp[k] += d * d;
                pp[k] += d * g[i];
            }
        }
    }
    const T d2 = fold_partials<T, 2 * CFG::PARTIALS>(dp);
    out[0] = d2;
    out[1] = T(0.5) * (fold_partials<T, 2 * CFG::PARTIALS>(pp) + mu * d2);
    FGC_PHASE("lm_control");
    FGC_CYCLES("decide", 0, "step_test", ceil_div(CFG::N_TANGENT, 2),
               pair_ii(CFG::N_TANGENT, CFG::PARTIALS, CFG::ADD_LAT),
               pair_depth(CFG::N_TANGENT, CFG::PARTIALS, CFG::ADD_LAT, CFG::MUL_LAT)
                   + CFG::MUL_LAT + CFG::ADD_LAT);  // the fold, then + mu |delta|^2
    FGC_CYCLES("decide", 0, "decision", 1, CFG::DECISION_II, CFG::DECISION_DEPTH);
    return ok;
}

// The one-step policy's (units/lm_control.py's fused_step_test): one solve a linearisation, so
// what lm_iterate forms before it (the gradient's largest |entry|, |x|) and lm_step_test after it
// (|delta|^2, delta^T g, delta finite) come from one loop after the solve (fgc_lm.h's
// FGC_LM_GRADIENT_IN_SOLVE and FGC_LM_NORM_IN_SOLVE: neither g nor x is written by the solve), two
// words of each a cycle: out = {the gradient's largest |entry|, |x|^2, |delta|^2, delta^T g};
// returns delta's finiteness. The step test's scalars: lm_step_sums.
template <class CFG>
bool lm_solved_test(const typename CFG::T g[CFG::N_TANGENT], const typename CFG::T x[CFG::N_X],
                    const typename CFG::T delta[CFG::N_TANGENT], typename CFG::T out[4]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    // entry i of each into partial (i / 2) % PARTIALS of lane i % 2 (one distance for all four,
    // PARTIALS >= MAXIMA), folded in trees
    T gp[2 * CFG::PARTIALS], xp[2 * CFG::PARTIALS], dp[2 * CFG::PARTIALS], pp[2 * CFG::PARTIALS];
#pragma HLS ARRAY_PARTITION variable=gp complete
#pragma HLS ARRAY_PARTITION variable=xp complete
#pragma HLS ARRAY_PARTITION variable=dp complete
#pragma HLS ARRAY_PARTITION variable=pp complete
    zero_partials<T, 2 * CFG::PARTIALS>(gp);
    zero_partials<T, 2 * CFG::PARTIALS>(xp);
    zero_partials<T, 2 * CFG::PARTIALS>(dp);
    zero_partials<T, 2 * CFG::PARTIALS>(pp);
    bool ok = true;
    const int N_LONGER = CFG::N_X > CFG::N_TANGENT ? CFG::N_X : CFG::N_TANGENT;
    for (int e = 0; e < N_LONGER; e += 2) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=gp inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=xp inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=dp inter true distance=CFG::PARTIALS
#pragma HLS DEPENDENCE variable=pp inter true distance=CFG::PARTIALS
        for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
            const int i = e + h;
            const int k = h * CFG::PARTIALS + (e >> 1) % CFG::PARTIALS;
            if (i < CFG::N_TANGENT) {
                const T gi = g[i];  // (one read of G a lane: its two ports)
                const T a = CFG::magnitude(gi);
                gp[k] = a > gp[k] ? a : gp[k];
                const T d = delta[i];
                ok = ok && CFG::finite(d);
                dp[k] += d * d;
                pp[k] += d * gi;
            }
            if (i < CFG::N_X) xp[k] += x[i] * x[i];
        }
    }
    out[0] = fold_maxima<T, 2 * CFG::PARTIALS>(gp);
    out[1] = fold_partials<T, 2 * CFG::PARTIALS>(xp);
    out[2] = fold_partials<T, 2 * CFG::PARTIALS>(dp);
    out[3] = fold_partials<T, 2 * CFG::PARTIALS>(pp);
    FGC_PHASE("lm_control");
    FGC_CYCLES("decide", 0, "solved_test", ceil_div(N_LONGER, 2),
               larger(larger(pair_ii(CFG::N_TANGENT, CFG::PARTIALS, CFG::CMP_LAT),
                             pair_ii(CFG::N_X, CFG::PARTIALS, CFG::ADD_LAT)),
                      pair_ii(CFG::N_TANGENT, CFG::PARTIALS, CFG::ADD_LAT)),
               larger(larger(pair_depth(CFG::N_TANGENT, CFG::PARTIALS, CFG::CMP_LAT, CFG::ABS_LAT),
                             pair_depth(CFG::N_X, CFG::PARTIALS, CFG::ADD_LAT, CFG::MUL_LAT)),
                      pair_depth(CFG::N_TANGENT, CFG::PARTIALS, CFG::ADD_LAT, CFG::MUL_LAT)));
    return ok;
}

template <class CFG>
void lm_accept(typename CFG::T x[CFG::N_X], const typename CFG::T x_trial[CFG::N_X]) {
    // two words a cycle (the memories' two ports)
    for (int e = 0; e < CFG::N_X; e += 2) {
#pragma HLS PIPELINE II=1
        for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
            if (e + h < CFG::N_X) x[e + h] = x_trial[e + h];
        }
    }
    FGC_EVENT("accept");
    FGC_PHASE("lm_accept");
    FGC_CYCLES("accept", 0, "accept", ceil_div(CFG::N_X, 2), CFG::MOVE_II, CFG::MOVE_DEPTH);
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

// The column design's LM control (accel.cpp.jinja's retire_test: Cholesky with back-substitution
// by columns, not on-chip streams): the step test's sums |delta|^2 and delta^T g and delta's
// finiteness are formed by back_substitute's state update as each variable's delta arrives
// (fgc_backsub.h's backsub_retire_cols, at its II), which also writes x (+) delta into X in
// place (X backed up as it is read), sums its |x (+) delta|^2 (the next |X| if the step is
// taken; the top's x_in the first) and moves G out of the next linearisation's way (the
// kernel's retract_variable); the top's data copy zeroes G once a call (linearize_all has no
// zeroing pass). What is left per linearisation is the gradient's largest |entry| (only where
// no solve ran), per solve the scalars of the step test, per accepted step nothing, per trial
// not taken the restore.

// the gradient's largest |entry|, two words a cycle into 2 PARTIALS partial maxima (lm_iterate
// without |x|)
template <class CFG>
typename CFG::T lm_gradient_max(const typename CFG::T g[CFG::N_TANGENT]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    T gp[2 * CFG::PARTIALS];  // (PARTIALS >= MAXIMA maxima)
#pragma HLS ARRAY_PARTITION variable=gp complete
    zero_partials<T, 2 * CFG::PARTIALS>(gp);
    for (int e = 0; e < CFG::N_TANGENT; e += 2) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=gp inter true distance=CFG::PARTIALS
        for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
            const int i = e + h;
            const int k = h * CFG::PARTIALS + (e >> 1) % CFG::PARTIALS;
            if (i < CFG::N_TANGENT) {
                const T a = CFG::magnitude(g[i]);
                gp[k] = a > gp[k] ? a : gp[k];
            }
        }
    }
    FGC_PHASE("lm_iteration");
    FGC_CYCLES("iterate", 0, "gradient_max", ceil_div(CFG::N_TANGENT, 2),
               pair_ii(CFG::N_TANGENT, CFG::PARTIALS, CFG::CMP_LAT),
               pair_depth(CFG::N_TANGENT, CFG::PARTIALS, CFG::CMP_LAT, CFG::ABS_LAT));
    return fold_maxima<T, 2 * CFG::PARTIALS>(gp);
}

// lm_step_test on the state update's sums: out = {dd, 0.5 (dg + mu dd)}
template <class CFG>
bool lm_step_sums(bool solved, typename CFG::T mu, typename CFG::T dd, typename CFG::T dg,
                  bool finite, typename CFG::T out[2]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    out[0] = dd;
    out[1] = T(0.5) * (dg + mu * dd);
    FGC_EVENT("step_test");  // (a solve whose step is tested: not one stopped on its gradient)
    FGC_PHASE("lm_control");
    FGC_CYCLES("decide", 0, "step_scalars", 1, 1, CFG::MUL_LAT + CFG::ADD_LAT);  // + mu |delta|^2
    FGC_CYCLES("decide", 0, "decision", 1, CFG::DECISION_II, CFG::DECISION_DEPTH);
    return solved && finite;
}

// The column design keeps the trial in X (fgc_lm.h's FGC_LM_TRIAL_IN_X: the state update writes
// x (+) delta into X and X's words into x_back as it reads them): a trial not taken puts X back,
// two words a cycle (the memories' two ports). Once per solve that ran and was not taken.
template <class CFG>
void lm_restore(typename CFG::T x[CFG::N_X], const typename CFG::T x_back[CFG::N_X]) {
    for (int e = 0; e < CFG::N_X; e += 2) {
#pragma HLS PIPELINE II=1
        for (int h = 0; h < 2; ++h) {
#pragma HLS UNROLL
            if (e + h < CFG::N_X) x[e + h] = x_back[e + h];
        }
    }
    FGC_EVENT("restore");
    FGC_PHASE("lm_restore");
    FGC_CYCLES("restore", 0, "restore", ceil_div(CFG::N_X, 2), CFG::MOVE_II, CFG::MOVE_DEPTH);
}

// lm_top for the column design: |x|^2 of the words coming in (PARTIALS interleaved partial
// sums, a word a cycle) into xx, and G zeroed beside the data's copy (each data word also to
// CFG::data_word: a kernel's second copy of some), before optimize
template <class CFG>
void lm_top_norm(const typename CFG::T x_in[CFG::N_X], const typename CFG::T data[CFG::N_DATA],
                 typename CFG::T x_out[CFG::N_X], typename CFG::T x[CFG::N_X],
                 typename CFG::T data_buf[CFG::N_DATA], typename CFG::T g[CFG::N_TANGENT],
                 typename CFG::T& xx, typename CFG::T errors[2], int info[3]) {
    typedef typename CFG::T T;
    FGC_EVENT("call");
    FGC_PHASE("setup");
    T xp[CFG::PARTIALS];
#pragma HLS ARRAY_PARTITION variable=xp complete
    zero_partials<T, CFG::PARTIALS>(xp);
    for (int i = 0; i < CFG::N_X; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=xp inter true distance=CFG::PARTIALS
        const T v = x_in[i];
        x[i] = v;
        xp[i % CFG::PARTIALS] += v * v;
    }
    xx = fold_partials<T, CFG::PARTIALS>(xp);
    const int N_ZERO = CFG::N_DATA > CFG::N_TANGENT ? CFG::N_DATA : CFG::N_TANGENT;
    for (int i = 0; i < N_ZERO; ++i) {
#pragma HLS PIPELINE II=1
        if (i < CFG::N_DATA) {
            data_buf[i] = data[i];
            CFG::data_word(i, data[i]);  // (a second copy of some words: the kernel's)
        }
        if (i < CFG::N_TANGENT) g[i] = T(0);
    }
    FGC_CYCLES("top", 0, "x_in", CFG::N_X, dot_ii(CFG::N_X, CFG::PARTIALS, CFG::ADD_LAT),
               dot_depth(CFG::N_X, CFG::PARTIALS, CFG::ADD_LAT, CFG::MUL_LAT));
    FGC_CYCLES("top", 0, "data_in", N_ZERO, CFG::MOVE_II, CFG::MOVE_DEPTH);
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
