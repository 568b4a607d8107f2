// fgc_lm.h: Levenberg-Marquardt / Gauss-Newton control, shared by the native solver and the HLS
// accelerator (one copy of the rules: a change to a stopping test lands here and in both).
//
//   template <class CFG> void optimize(typename CFG::T errors[2], int info[3]);
//
// GN/LM iterations from the kernel's estimate X: errors = {initial cost, final cost}, info =
// {iterations, status, reason}. Per iteration: linearise, stop on a small gradient, then
// try_steps: solve at mu, take x (+) delta in cost mode, accept (mu shrinks) or grow mu. A step
// whose predicted decrease 0.5 delta^T (g + mu delta) is within the cost's resolution `band`
// (16 eps of the cost, or its rounding noise at X if larger) is judged by that prediction (the
// simulator's rule); the band is worked out only for a step that does not lower the cost, once
// per linearisation.
//
// CFG (the kernel defines it; fgc_backends/cfamily/templates/common.jinja prints its constants)
// holds what is the problem's or the backend's:
//   T; MAX_ITERATIONS, MAX_TRIES; LM (false: Gauss-Newton, mu stays 0); the STATUS_* and
//   REASON_* codes; the scalar settings as functions returning T (lambda_initial(),
//   lambda_factor(), lambda_upper_bound(), mu_min(), eps_gradient(), eps_step(), rel_tol(),
//   resolution(), abs_tol()); root (sqrt), magnitude (abs), finite (isfinite) of T;
//   the kernel's hooks: cost_x() (the cost at X), linearize_x(mu) (false: not finite; mu the
//   damping of the solve that follows: the HLS Cholesky kernel factors at it beside the HGC),
//   gradient_max() (the gradient's largest |entry|), x_norm() (|X|), solve_at(mu) (false:
//   singular), step_test(solved, mu, out) (false: not solved or delta not finite; out = {|delta|^2,
//   predicted decrease}), retract_trial() (X_TRIAL = X (+) DELTA), cost_trial() (the cost at
//   X_TRIAL), noise_x() (the cost's rounding noise at X), accept_trial() (X = X_TRIAL),
//   with FGC_LM_TRIAL_IN_X restore_x() (X = its backup: the trial not taken),
//   accepted(it, cost, mu, change) (after each accepted step: the native host's progress);
//   with FGC_LM_COST_IN_LINEARIZE defined, linearized_cost() (the cost at the point
//   linearize_x last linearised at) instead of cost_x().
// FGC_LM_COST_IN_LINEARIZE (the HLS QR kernel without robust losses): the linearisation forms
// 1/2 |b|^2 of its whitened rows anyway (its gradient pass), so the first linearisation gives
// the cost at X and no cost pass runs before it; the same outcome (a non-finite cost at X
// fails the solve with REASON_NON_FINITE and no iteration) one pass sooner.
// FGC_LM_GRADIENT_IN_SOLVE (the HLS Cholesky kernel with back-substitution by columns): the
// solve's state update finds the gradient's largest |entry| as it reads g for the step test, so
// the small-gradient test runs after the first solve of a linearisation that succeeds
// (solved_gradient_max()), before its step test, and, where no solve of the linearisation
// succeeded, before try_steps returns a failure (gradient_max()): the same outcome as testing
// first (X unchanged, converged on the gradient; only mu, which is not returned, may have grown).
// FGC_LM_TRIAL_IN_X (the HLS Cholesky kernel with back-substitution by columns): the solve's
// state update writes X (+) delta into X itself and backs X up as it reads it, so after a solve
// that ran X holds the trial point: accept_trial() copies nothing, and every way out of a
// solve that ran other than an accepted step (a small gradient, a small step, a step not
// finite, a trial rejected) first calls restore_x() (X back from its backup), so the next
// solve, the rounding noise's band and the caller see X at the linearisation point as before.
// A solve that failed back-substitutes nothing and leaves X as it was.
// FGC_LM_NORM_IN_SOLVE (the HLS kernel under the one-step policy, with FGC_LM_GRADIENT_IN_SOLVE):
// x_norm() is read where the step size is tested, after the solve's step test, whose loop (the
// kernel's solved_gradient_max) finds |X| with the gradient's maximum: X is unchanged since the
// linearisation, so the same |X| as read before the solve.
// The reductions live in the hooks: the HLS kernel's run in interleaved partial sums at II 1
// (fgc_lm_units.h) and count cycles, the native solver's are plain loops.
//
// One cost pass in hardware: the HLS kernel computes the cost at X_TRIAL inside its linear
// solve (back-substitution's region) and cost_x() runs the same solve with no elimination,
// the cost pass at X (the native kernel's hooks run its total_cost on X, on X_TRIAL). In Vitis
// every call site of a function not inlined is its own RTL instance, so the two calls of the
// kernel's solve would build it, and every cost datapath, twice; try_steps and the HLS
// kernel's hooks are INLINE (their calls land in optimize's body) and optimize's ALLOCATION
// limits solve to one instance there: both calls share it (they never run at once). A caller
// of optimize_inline carries that ALLOCATION itself. The native compiler ignores the HLS
// pragmas.
#ifndef FGC_LM_H
#define FGC_LM_H

namespace fgc_lm {

template <class T>
struct Step {
    int kind;  // 0 accept, 1 converged, 2 failed
    int reason;
    T cost;
    T predicted;
};

#ifdef FGC_LM_GRADIENT_IN_SOLVE
// A failure of try_steps, unless the gradient (not yet tested: no solve succeeded) is small.
template <class CFG>
Step<typename CFG::T> failed_step(bool tested, int reason, typename CFG::T cost) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    if (!tested && CFG::gradient_max() < CFG::eps_gradient()) {
        return Step<T>{1, CFG::REASON_GRADIENT, cost, T(0)};
    }
    return Step<T>{2, reason, cost, T(0)};
}
#define FGC_LM_FAILED(reason) failed_step<CFG>(tested, reason, cost)
#else
#define FGC_LM_FAILED(reason) Step<T>{2, reason, cost, T(0)}
#endif
// A trial not taken: X back to the linearisation point where a solve ran (it wrote the trial
// into X: FGC_LM_TRIAL_IN_X); else nothing (X_TRIAL apart, X never written).
template <class CFG>
void undo_trial(bool ran) {
#pragma HLS INLINE
#ifdef FGC_LM_TRIAL_IN_X
    if (ran) CFG::restore_x();
#else
    (void)ran;
#endif
}

template <class CFG>
Step<typename CFG::T> try_steps(typename CFG::T cost, typename CFG::T mu[1]) {
#pragma HLS INLINE
    // (HLS: the scalar decision shares optimize's operators; g++ ignores the pragma)
    typedef typename CFG::T T;
    T band = T(-1);  // not yet known
#ifdef FGC_LM_NORM_IN_SOLVE  // |X| found after the solve (read where the step size is tested)
#define FGC_LM_X_NORM CFG::x_norm()
#else
    const T x_norm = CFG::x_norm();  // once per call (per linearisation), not per solve
#define FGC_LM_X_NORM x_norm
#endif
#ifdef FGC_LM_GRADIENT_IN_SOLVE
    bool tested = false;  // the small-gradient test ran (after the first solve that succeeded)
#endif
    for (int t = 0; t < CFG::MAX_TRIES; ++t) {
        const bool solved = CFG::solve_at(mu[0]);
#ifdef FGC_LM_GRADIENT_IN_SOLVE
        if (solved && !tested) {
            tested = true;
            if (CFG::solved_gradient_max() < CFG::eps_gradient()) {
                undo_trial<CFG>(solved);
                return Step<T>{1, CFG::REASON_GRADIENT, cost, T(0)};
            }
        }
#endif
        if (!solved && !(mu[0] > T(0))) return FGC_LM_FAILED(CFG::REASON_SINGULAR);
        T test[2];  // |delta|^2, the predicted decrease
        const bool ok = CFG::step_test(solved, mu[0], test);
        const T d2 = test[0], predicted = test[1];
        if (ok) {
            if (CFG::root(d2) <= CFG::eps_step() * (FGC_LM_X_NORM + CFG::eps_step())) {
                undo_trial<CFG>(solved);
                return Step<T>{1, CFG::REASON_STEP, cost, T(0)};
            }
            CFG::retract_trial();
            const T trial = CFG::cost_trial();
            bool accept = CFG::finite(trial) && (trial < cost || !(mu[0] > T(0)));
            if (!accept && CFG::finite(trial)) {
                if (band < T(0)) {
                    const T noise = CFG::noise_x();
                    band = CFG::resolution() * cost > noise ? T(CFG::resolution() * cost) : noise;
                }
                accept = predicted <= band && trial <= cost + band;
            }
            if (accept) {
                if (CFG::LM) {
                    mu[0] = mu[0] / CFG::lambda_factor() > CFG::mu_min()
                                ? T(mu[0] / CFG::lambda_factor()) : CFG::mu_min();
                }
                return Step<T>{0, 0, trial, predicted};
            }
        }
        undo_trial<CFG>(solved);  // not taken: X back before the next solve (or the way out)
        if (!(mu[0] > T(0))) return FGC_LM_FAILED(CFG::REASON_NON_FINITE);
        mu[0] = mu[0] * CFG::lambda_factor();
        if (mu[0] > CFG::lambda_upper_bound()) {
            return FGC_LM_FAILED(CFG::REASON_LAMBDA_LIMIT);
        }
    }
    return FGC_LM_FAILED(CFG::REASON_LAMBDA_LIMIT);
}
#undef FGC_LM_FAILED
#undef FGC_LM_X_NORM

// optimize's body, INLINE: a kernel that runs its linearisation or elimination again after LM
// (the on-chip stream's window and batch kernel: fgc_stream.h) calls it directly, so LM's call
// sites and its own land in one module, whose ALLOCATION makes each one RTL instance.
template <class CFG>
void optimize_inline(typename CFG::T errors[2], int info[3]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    T mu[1] = {CFG::lambda_initial()};
    int it = 0, status = CFG::STATUS_MAX_ITERATIONS, reason = CFG::REASON_MAX_ITERATIONS;
#ifdef FGC_LM_COST_IN_LINEARIZE
    T cost = T(0);  // the first linearisation's
    errors[0] = cost;
#else
    T cost = CFG::cost_x();
    errors[0] = cost;
    if (!CFG::finite(cost)) {
        status = CFG::STATUS_FAILED;
        reason = CFG::REASON_NON_FINITE;
    }
#endif
    for (int k = 0; k < CFG::MAX_ITERATIONS; ++k) {
        if (status != CFG::STATUS_MAX_ITERATIONS) break;
        const bool linearized = CFG::linearize_x(mu[0]);
#ifdef FGC_LM_COST_IN_LINEARIZE
        if (k == 0) {  // the cost at X, from the linearisation at X
            cost = CFG::linearized_cost();
            errors[0] = cost;
            if (!CFG::finite(cost)) {
                status = CFG::STATUS_FAILED;
                reason = CFG::REASON_NON_FINITE;
                break;
            }
        }
#endif
        if (!linearized) {
            status = CFG::STATUS_FAILED;
            reason = CFG::REASON_NON_FINITE;
            break;
        }
        ++it;
#ifndef FGC_LM_GRADIENT_IN_SOLVE  // (else tested in try_steps, after the solve)
        if (CFG::gradient_max() < CFG::eps_gradient()) {
            status = CFG::STATUS_CONVERGED;
            reason = CFG::REASON_GRADIENT;
            break;
        }
#endif
        const Step<T> step = try_steps<CFG>(cost, mu);
        if (step.kind != 0) {
            if (step.kind == 1) {  // (not ?: over the codes: C++14 would odr-use them)
                status = CFG::STATUS_CONVERGED;
            } else {
                status = CFG::STATUS_FAILED;
            }
            reason = step.reason;
            break;
        }
        const T moved = CFG::magnitude(cost - step.cost) > step.predicted ? CFG::magnitude(cost - step.cost)
                                                                    : step.predicted;
        const T change = cost > T(0) ? T(moved / cost) : T(0);
        CFG::accept_trial();
        cost = step.cost;
        CFG::accepted(it, cost, mu[0], change);
        if (cost <= CFG::abs_tol()) {
            status = CFG::STATUS_CONVERGED;
            reason = CFG::REASON_ABSOLUTE_ERROR;
        } else if (change <= CFG::rel_tol()) {
            status = CFG::STATUS_CONVERGED;
            reason = CFG::REASON_RELATIVE_DECREASE;
        }
    }
    errors[1] = cost;
    info[0] = it;
    info[1] = status;
    info[2] = reason;
}

template <class CFG>
void optimize(typename CFG::T errors[2], int info[3]) {
#pragma HLS ALLOCATION function instances=solve limit=1
#pragma HLS ALLOCATION function instances=back_substitute_at limit=1
#pragma HLS ALLOCATION function instances=eliminate_all limit=1
#ifdef FGC_LM_LINEARIZE_SOLVE  // the HLS Cholesky kernel's linearize_x(mu) and solve_at(mu) share it
#pragma HLS ALLOCATION function instances=linearize_solve limit=1
#endif
    optimize_inline<CFG>(errors, info);
}

}  // namespace fgc_lm

#endif  // FGC_LM_H
