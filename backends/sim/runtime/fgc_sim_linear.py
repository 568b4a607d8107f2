# fgc simulator run-time (fgc_sim_linear.py): copied verbatim into every emitted simulator
"""The linear solve of the fgc simulator: elimination along the compiled schedule.

Each elimination step stacks the whitened rows [A | b] of the factors entering it, the new factors
its children passed up and, for Levenberg-Marquardt, the damping rows √μ·I on its frontal
columns, over the columns (frontals, separator, right-hand side). Then

- ``qr`` (paper A): Householder QR; the top rows are the conditional (R_f, S, d), the next rows
  restricted to the separator are the new factor for the parent step;
- ``cholesky`` (paper B): the frontal matrix [AᵀA | Aᵀb] plus the children's update matrices and
  μ on the frontal diagonal, Cholesky of its frontal block (H_ff = L Lᵀ) and the update (Schur
  complement) for the parent, i.e. a multifrontal Cholesky of H + μI. Its conditional is
  (Lᵀ, L⁻¹H_fs, L⁻¹g_f): the same form as QR's, and equal to it up to row signs.

Back-substitution walks the Bayes net root first: δ_f = R_f⁻¹ (d − S δ_sep).

Rank deficiency is caught at each step: a frontal column whose pivot (|R_jj| in QR, L_jj in
Cholesky) is at most the pivot tolerance (:func:`pivot_tolerances`) times the norm of that column
in the step's stacked matrix (damping rows included) lies, to working precision, in the span of
the columns before it.
An exactly dependent column keeps only rounding error, about √rows·eps of its norm (≈1e-15 in
float64, ≈1e-6 in float32), so the tolerances sit well above that and well below the smallest
relative pivots of well-posed problems (≈1e-4 on the shipped IMU window).

Dense kernels: in float64 numpy's LAPACK routines (Householder QR, Cholesky, triangular solves by
LU, which does no pivoting on a triangular matrix) compute in the working precision. numpy's
LAPACK bindings promote float32 to float64, so float32 runs use the explicit column loops below
instead, which compute in float32 as the accelerator does.

Those matrices are small (one step's stacked rows: at most a few hundred columns on w10000), and
OpenBLAS splits them over threads that spin while they wait for each other: on a loaded 2-core
machine a 924 × 100 QR took 2.9 s with its threads and 6 ms on one. A solve therefore runs its
dense kernels with one BLAS thread (:func:`one_blas_thread`, OpenBLAS only: other BLAS libraries
are left as they are).
"""

import contextlib
import ctypes

import numpy


def pivot_tolerances(solver):
    """The relative pivot tolerance by working precision, from the problem's solver options
    (SimConfig.pivot_tolerance_float64 / _float32)."""
    return {numpy.dtype(numpy.float64): solver["pivot_tolerance_float64"],
            numpy.dtype(numpy.float32): solver["pivot_tolerance_float32"]}


# OpenBLAS' thread-count setters and getters, by the names its builds export (plain, 64-bit
# integer interface, SciPy's prefixed build for numpy's wheels)
_OPENBLAS_THREADS = (("openblas_set_num_threads", "openblas_get_num_threads"),
                     ("openblas_set_num_threads64_", "openblas_get_num_threads64_"),
                     ("scipy_openblas_set_num_threads64_", "scipy_openblas_get_num_threads64_"),
                     ("scipy_openblas_set_num_threads", "scipy_openblas_get_num_threads"))


def _openblas_controls():
    """(set, get) of every OpenBLAS loaded in this process (read from /proc/self/maps; none
    where there is no such file)."""
    try:
        with open("/proc/self/maps") as maps:
            paths = {line.split()[-1] for line in maps if "openblas" in line.lower()}
    except OSError:
        return []
    controls = []
    for path in sorted(paths):
        try:
            lib = ctypes.CDLL(path)  # already loaded: the same library, not a second copy
        except OSError:
            continue
        for set_name, get_name in _OPENBLAS_THREADS:
            setter, getter = getattr(lib, set_name, None), getattr(lib, get_name, None)
            if setter is not None and getter is not None:
                setter.argtypes, setter.restype, getter.restype = [ctypes.c_int], None, ctypes.c_int
                controls.append((setter, getter))
                break
    return controls


@contextlib.contextmanager
def one_blas_thread():
    """Run the block with OpenBLAS on one thread, then restore its thread count."""
    controls = _openblas_controls()
    before = [getter() for _, getter in controls]
    for setter, _ in controls:
        setter(1)
    try:
        yield
    finally:
        for (setter, _), n in zip(controls, before, strict=True):
            setter(n)


class SingularError(Exception):
    """The stacked system of an elimination step is (numerically) rank deficient: the pivot of
    frontal column ``column`` of step ``step`` is ``ratio`` times that column's norm."""

    def __init__(self, step, column, ratio=0.0):
        super().__init__(f"elimination step {step}: the system is singular in frontal column "
                         f"{column} (pivot {ratio:.2e} × its column norm)")
        self.step, self.column, self.ratio = step, column, ratio


class NotPositiveDefinite(numpy.linalg.LinAlgError):
    """Cholesky broke down: the pivot of ``column`` is not positive."""

    def __init__(self, column):
        super().__init__(f"matrix is not positive definite (column {column})")
        self.column = column


class StepPlan:
    """Index tables of one elimination step (built once, used every iteration).

    ``gather`` picks the stacked matrix [A | b] of the step out of the work buffer: ``rows``
    factor rows, then each child's new-factor region, then the damping rows (√μ on the diagonal,
    read from the μ slot). ``region`` is where the step's own new factor goes (s × (s + 1)).
    """

    __slots__ = ("index", "f", "s", "front", "sep", "gather", "rows", "region", "children",
                 "child_flat", "diag")

    def __init__(self, index, f, s, front, sep, gather, rows, region, children, child_flat):
        self.index, self.f, self.s, self.front, self.sep = index, f, s, front, sep
        self.gather, self.rows, self.region = gather, rows, region
        self.children, self.child_flat = children, child_flat
        self.diag = numpy.arange(f)


class Plan:
    """All steps' tables and the layout of the work buffer: the factors' [A | b] entries (the
    first ``size`` words), a zero word, the √μ word, then every step's new-factor region;
    ``tolerance``: the relative pivot tolerance by dtype (:func:`pivot_tolerances`)."""

    def __init__(self, steps, size, tolerance):
        self.steps, self.size, self.tolerance = steps, size, tolerance
        self.zero, self.mu = size, size + 1
        self.length = max([st.region.stop for st in steps] + [size + 2])

    def buffer(self, factors):
        """A fresh work buffer holding ``factors`` (the flat [A | b] of all blocks)."""
        buf = numpy.zeros(self.length, dtype=factors.dtype)
        buf[:self.size] = factors
        return buf


def make_plan(steps, var_offset, var_dim, rows_of, size, tolerance):
    """Index tables of all steps (``tolerance``: see :class:`Plan`).

    ``steps``: (frontals, separator, entering, children) per step (variable indices; entering
    factors as keys of ``rows_of``); ``rows_of(entry)`` gives that factor's row starts in the
    [A | b] part of the buffer (an array), {variable: column offset in a row} and the rhs offset.
    """
    plan, next_region = [], size + 2
    for index, (frontals, separator, entering, children) in enumerate(steps):
        local, width = {}, 0
        for v in (*frontals, *separator):
            local[v] = width
            width += var_dim[v]
        f = sum(var_dim[v] for v in frontals)
        cols = numpy.concatenate([var_offset[v] + numpy.arange(var_dim[v])
                                  for v in (*frontals, *separator)]).astype(numpy.intp)
        parts = [_gather(index, entering, local, width, var_dim, rows_of, size)]
        kids, flats = [], []
        for c in children:
            cmap = _child_map(index, plan[c], cols, width)
            kids.append((c, cmap))
            flats.append((cmap[:, None] * (width + 1) + cmap[None, :]).reshape(-1))
            parts.append(_region_rows(plan[c], cmap, width, size))
        damping = numpy.full((f, width + 1), size, dtype=numpy.intp)
        damping[numpy.arange(f), numpy.arange(f)] = size + 1
        parts.append(damping)
        region = slice(next_region, next_region + (width - f) * (width - f + 1))
        next_region = region.stop
        plan.append(StepPlan(index, f, width - f, cols[:f], cols[f:], numpy.concatenate(parts),
                             len(parts[0]), region, kids, flats))
    return Plan(plan, size, tolerance)


def _gather(index, entering, local, width, var_dim, rows_of, zero):
    blocks = []
    for entry in entering:
        starts, columns, rhs = rows_of(entry)
        rows = numpy.full((len(starts), width + 1), zero, dtype=numpy.intp)
        for v, first in columns.items():
            if v not in local:
                raise ValueError(f"elimination step {index}: a factor touches variable {v}, "
                                 "which is neither frontal nor separator here")
            rows[:, local[v]:local[v] + var_dim[v]] = starts[:, None] + first + numpy.arange(
                var_dim[v])
        rows[:, width] = starts + rhs
        blocks.append(rows)
    return numpy.concatenate(blocks) if blocks else numpy.zeros((0, width + 1), numpy.intp)


def _child_map(index, child, cols, width):
    """Columns of this step receiving the child's separator columns, then the rhs column."""
    where = {int(c): i for i, c in enumerate(cols)}
    missing = [int(c) for c in child.sep if int(c) not in where]
    if missing:
        raise ValueError(f"elimination step {index}: a child's separator column {missing[0]} "
                         "is not a column of its parent")
    return numpy.array([where[int(c)] for c in child.sep] + [width], dtype=numpy.intp)


def _region_rows(child, cmap, width, zero):
    """Gather rows reading a child's new-factor region into this step's columns."""
    rows = numpy.full((child.s, width + 1), zero, dtype=numpy.intp)
    region = numpy.arange(child.region.start, child.region.stop).reshape(child.s, child.s + 1)
    rows[:, cmap] = region
    return rows


# --------------------------------------------------------------------------------------------
# elimination
# --------------------------------------------------------------------------------------------


def eliminate(plan, factors, mu, method):
    """Conditionals (R_f, S, d) of every step for damping ``mu`` (0: Gauss-Newton), from the
    flat [A | b] of all factors."""
    buf = plan.buffer(factors)
    if method == "qr":
        return _eliminate_qr(plan, buf, mu)
    return _eliminate_cholesky(plan, buf, mu)


def eliminate_qr(plan, factors, mu):
    """QR elimination that also returns each step's new factor [A | b] (s × (s + 1)) for its
    parent: what incremental smoothing keeps of the older part of the Bayes net."""
    buf = plan.buffer(factors)
    conds = _eliminate_qr(plan, buf, mu)
    return conds, [buf[st.region].reshape(st.s, st.s + 1).copy() for st in plan.steps]


def _eliminate_qr(plan, buf, mu):
    buf[plan.mu] = numpy.sqrt(buf.dtype.type(mu))
    conds = [None] * len(plan.steps)
    tol = plan.tolerance[buf.dtype]
    for st in plan.steps:
        m = buf[st.gather]
        r = qr_r(m)
        f = st.f
        _check_pivots(st, r[:f, :f], numpy.sqrt(numpy.einsum("ij,ij->j", m[:, :f], m[:, :f])),
                      tol)
        conds[st.index] = (r[:f, :f], r[:f, f:-1], r[:f, -1])
        if st.s:
            region = buf[st.region].reshape(st.s, st.s + 1)
            k = max(min(len(r) - f, st.s), 0)
            region[:k] = r[f:f + k, f:]
            region[k:] = 0
    return conds


def _eliminate_cholesky(plan, buf, mu):
    dt = buf.dtype.type
    conds, update = [None] * len(plan.steps), [None] * len(plan.steps)
    tol = plan.tolerance[buf.dtype]
    for st in plan.steps:
        a = buf[st.gather[:st.rows]]
        h = a.T @ a
        flat = h.reshape(-1)
        for (c, _), idx in zip(st.children, st.child_flat, strict=True):
            flat[idx] += update[c]
            update[c] = None
        if mu > 0:
            h[st.diag, st.diag] += dt(mu)
        norms = numpy.sqrt(numpy.maximum(h[st.diag, st.diag], 0))  # stacked column norms
        try:
            low = cholesky(h[:st.f, :st.f])
        except NotPositiveDefinite as exc:
            raise SingularError(st.index, exc.column) from None
        _check_pivots(st, low, norms, tol)
        x = solve_lower(low, h[:st.f, st.f:])
        update[st.index] = (h[st.f:, st.f:] - x.T @ x).reshape(-1)
        conds[st.index] = (low.T, x[:, :-1], x[:, -1])
    return conds


def _check_pivots(st, r, norms, tol):
    """Raise SingularError at the first frontal column whose pivot is at most ``tol`` times its
    stacked column norm (or that has no row left to hold a pivot)."""
    if r.shape[0] < st.f:
        raise SingularError(st.index, r.shape[0])
    with numpy.errstate(divide="ignore", invalid="ignore"):
        ratio = numpy.abs(numpy.diagonal(r)) / norms
    bad = numpy.flatnonzero(~(ratio > tol))
    if len(bad):
        j = int(bad[0])
        raise SingularError(st.index, j, float(numpy.nan_to_num(ratio[j])))


def back_substitute(plan, order, conds, n, dtype):
    """δ from the Bayes net, levels in ``order`` (root first)."""
    delta = numpy.zeros(n, dtype=dtype)
    for level in order:
        for i in level:
            st = plan.steps[i]
            r, s, d = conds[i]
            rhs = d - s @ delta[st.sep] if st.s else d
            delta[st.front] = solve_upper(r, rhs)
    return delta


# --------------------------------------------------------------------------------------------
# dense kernels (working precision = the arrays' dtype)
# --------------------------------------------------------------------------------------------


_UPPER = {}  # shape → upper-triangular 0/1 mask


def qr_r(m):
    """R of a Householder QR of m: min(rows, cols) × cols, upper triangular."""
    if m.dtype != numpy.float64:
        return _householder_r(m)
    h, _ = numpy.linalg.qr(m, mode="raw")  # R is the upper triangle of hᵀ (LAPACK layout)
    r = h.T[:min(m.shape)]
    mask = _UPPER.get(r.shape)
    if mask is None:
        mask = _UPPER[r.shape] = numpy.triu(numpy.ones(r.shape))
    return r * mask


def cholesky(a):
    """Lower-triangular L with a = L Lᵀ; NotPositiveDefinite (naming the column) if a is not
    positive definite."""
    if a.dtype == numpy.float64:
        try:
            return numpy.linalg.cholesky(a)
        except numpy.linalg.LinAlgError:
            pass  # the column loop below finds the failing column
    return _cholesky(a)


def solve_upper(r, b):
    if r.dtype == numpy.float64:
        return numpy.linalg.solve(r, b)
    return _substitute(r, b, reversed(range(len(r))), lambda i: slice(i + 1, None))


def solve_lower(low, b):
    if low.dtype == numpy.float64:
        return numpy.linalg.solve(low, b)
    return _substitute(low, b, range(len(low)), lambda i: slice(0, i))


def _householder_r(m):
    """Paper A's Algorithm 3.1 column by column: Evaluate builds the Householder vector v of
    column j, Update applies I − 2vvᵀ/vᵀv to the remaining columns. The column is scaled by its
    largest magnitude first (the reflection does not depend on v's scale): on a tiny non-zero
    column vᵀv would underflow in float32 (1e-20² = 0) and 2/vᵀv overflow to inf."""
    a = m.copy()
    rows, cols = a.shape
    k = min(rows, cols)
    for j in range(k):
        big = numpy.max(numpy.abs(a[j:, j]))
        if big == 0:
            continue
        v = a[j:, j] / big
        norm = numpy.sqrt(v @ v)
        alpha = -norm if v[0] >= 0 else norm
        v[0] -= alpha
        a[j:, j:] -= (2 / (v @ v)) * numpy.outer(v, v @ a[j:, j:])
        a[j + 1:, j] = 0
        a[j, j] = alpha * big
    return numpy.triu(a[:k])


def _cholesky(a):
    """Right-looking Cholesky (one CPE round per column: Evaluate, then Update)."""
    a = a.copy()
    low = numpy.zeros_like(a)
    for j in range(len(a)):
        if not a[j, j] > 0:
            raise NotPositiveDefinite(j)
        d = numpy.sqrt(a[j, j])
        col = a[j + 1:, j] / d
        low[j, j], low[j + 1:, j] = d, col
        a[j + 1:, j + 1:] -= numpy.outer(col, col)
    return low


def _substitute(t, b, rows, done):
    x = numpy.zeros_like(b)
    for i in rows:
        x[i] = (b[i] - t[i, done(i)] @ x[done(i)]) / t[i, i]
    return x
