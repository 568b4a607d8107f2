# fgc simulator run-time (fgc_sim_diagnostics.py): copied verbatim into every emitted simulator
"""Diagnosis of the linear system at a solution, in float64: rank and condition number.

After a batch solve the simulator linearises at the solution and eliminates the whitened rows
[J | −r] once more without damping, with QR along the schedule:

- ``rank``: the rows as they are. A pivot at most the float64 pivot tolerance times its column's
  norm names a variable the factors do not determine (a gauge left free by a prior without
  information, an unexcited bias); LM's damping keeps such a step well posed, so this is where
  LM's rank deficiency is found.
- ``condition``: every row scaled to unit norm (float rounding in a row is relative to that
  row's own size) and every column of R scaled to unit norm (a change of units rounds the
  same), κ = σ_max/σ_min of that R by power iteration on RᵀR and on (RᵀR)⁻¹, with products and
  triangular solves along the Bayes net. Power iteration approaches each extreme from inside,
  so κ is an estimate from below (within a small factor after a dozen iterations).
"""

import numpy


def diagnose(problem, x, iterations):
    """{"singular": None or a record of :func:`singular_info`, "condition": κ or None} for a
    float64 ``problem`` at storage ``x``; None where the linearisation is not finite."""
    lin = problem.lib.linear
    with numpy.errstate(all="ignore"):
        abs_, _, _ = problem.linearize(x)
    if not all(numpy.all(numpy.isfinite(ab)) for ab in abs_):
        return None
    try:
        lin.eliminate(problem.plan, _flat(abs_), 0.0, "qr")
        conds = lin.eliminate(problem.plan, _flat([_equilibrate(ab) for ab in abs_]), 0.0, "qr")
    except lin.SingularError as exc:
        return {"singular": singular_info(problem.spec, exc), "condition": None}
    kappa = condition(problem.plan, conds, problem.n, iterations)
    return {"singular": None, "condition": kappa}


def singular_info(spec, exc):
    """The variable (index) and tangent component of the singular pivot of ``exc``, its step
    and its pivot-to-column-norm ratio."""
    column, frontals = exc.column, spec["steps"][exc.step][0]
    for v in frontals:
        dim = spec["variable_dims"][v]
        if column < dim:
            break
        column -= dim
    return {"variable": int(v), "component": int(column), "step": int(exc.step),
            "ratio": float(exc.ratio)}


def _flat(parts):
    return numpy.concatenate([p.reshape(-1) for p in parts])


def _equilibrate(ab):
    """Rows [J | −r] scaled to ‖J row‖ = 1 (all-zero rows stay zero)."""
    norm = numpy.sqrt(numpy.sum(ab[..., :-1] ** 2, -1, keepdims=True))
    return ab / numpy.where(norm > 0, norm, 1.0)


# --------------------------------------------------------------------------------------------
# κ of R·D⁻¹ (D: column norms of R) by power iteration
# --------------------------------------------------------------------------------------------


def condition(plan, conds, n, iterations):
    """σ_max/σ_min of R·D⁻¹ (None if a column of R is zero)."""
    scale = numpy.zeros(n)
    for st, (r, s, _) in zip(plan.steps, conds, strict=True):
        scale[st.front] += numpy.sum(r * r, 0)
        scale[st.sep] += numpy.sum(s * s, 0)
    scale = numpy.sqrt(scale)
    if not numpy.all(scale > 0):
        return None
    start = numpy.random.default_rng(0).standard_normal(n)  # fixed: the estimate is repeatable
    big = _power(lambda u: _rt_mul(plan, conds, _r_mul(plan, conds, u / scale, n), n) / scale,
                 start, iterations)
    small = _power(lambda u: _r_solve(plan, conds, _rt_solve(plan, conds, u * scale, n), n)
                   * scale, start, iterations)
    return float(numpy.sqrt(big * small))


def _power(op, v, iterations):
    """Largest eigenvalue of the symmetric positive operator ``op`` (power iteration)."""
    v = v / numpy.linalg.norm(v)
    lam = 0.0
    for _ in range(iterations):
        w = op(v)
        lam = float(numpy.linalg.norm(w))
        if not (numpy.isfinite(lam) and lam > 0):
            break
        v = w / lam
    return lam


def _r_mul(plan, conds, u, n):
    out = numpy.zeros(n)
    for st, (r, s, _) in zip(plan.steps, conds, strict=True):
        out[st.front] = r @ u[st.front] + s @ u[st.sep]
    return out


def _rt_mul(plan, conds, w, n):
    out = numpy.zeros(n)
    for st, (r, s, _) in zip(plan.steps, conds, strict=True):
        out[st.front] += r.T @ w[st.front]
        out[st.sep] += s.T @ w[st.front]
    return out


def _r_solve(plan, conds, b, n):
    """R⁻¹b: the root step first (steps are numbered children before parents)."""
    out = numpy.zeros(n)
    for st in reversed(plan.steps):
        r, s, _ = conds[st.index]
        out[st.front] = numpy.linalg.solve(r, b[st.front] - s @ out[st.sep])
    return out


def _rt_solve(plan, conds, c, n):
    """R⁻ᵀc: the leaves first, each step passing Sᵀy on to its separator."""
    work, out = c.copy(), numpy.zeros(n)
    for st in plan.steps:
        r, s, _ = conds[st.index]
        out[st.front] = numpy.linalg.solve(r.T, work[st.front])
        work[st.sep] -= s.T @ out[st.front]
    return out
