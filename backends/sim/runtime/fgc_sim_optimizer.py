# fgc simulator run-time (fgc_sim_optimizer.py): copied verbatim into every emitted simulator
"""The fgc simulator's optimiser: Gauss-Newton or Levenberg-Marquardt as the accelerator runs it.

Levenberg-Marquardt follows paper B: linearise (error + Jacobian mode of the factor blocks), solve
(H + μI) δ = g by elimination along the schedule (QR or Cholesky), evaluate the cost at x ⊕ δ
(cost-only mode), accept the step and shrink μ if the cost decreased, otherwise grow μ and
re-solve. Stops: k_max iterations, ‖g‖∞ < ε1, ‖δ‖ ≤ ε2 (‖x‖ + ε2) with ε2 at least 10 ulp of the
working precision (‖x‖: the norm of all variables' storage), an accepted step whose relative cost
change and predicted decrease are both at most the relative tolerance (float32 cannot resolve the
cost change, the prediction it can), or a cost below the absolute tolerance. Gauss-Newton takes
every finite step (μ = 0); a singular elimination stops it (status "failed", reason "singular",
the pivot's variable in the result's "singular" record).

After a batch solve the float64 diagnosis of ``fgc_sim_diagnostics`` looks at the solution: a
variable the factors leave undetermined (which LM's damping hides) and the condition number κ
go into the result ("singular", "condition").
"""

import json
import time

import numpy

RESOLUTION_LIMIT = 1.0  # ρ (see resolution): rounding the state moves a residual by ≥ 1σ
# the result file's format (2: values keyed by variable, {str(key): {"key", "type", "value"}})
RESULT_FORMAT = "fgc-sim-result 2"


def _offsets(sizes):
    return numpy.concatenate([[0], numpy.cumsum(sizes)]).astype(numpy.intp)


class Problem:
    """A compiled structure with one data file's numbers, in one float dtype."""

    def __init__(self, spec, data, dtype, lib):
        self.spec, self.lib, self.dtype = spec, lib, numpy.dtype(dtype)
        self.les_dtype = les_dtype(self.dtype, spec["solver"]["linear_precision"])
        self.singular = None  # the last SingularError of an elimination
        self.on_iteration = None  # a batch solve's per-iteration callback (solve's progress)
        variables, factors = data
        dims, storage = spec["variable_dims"], spec["variable_storage"]
        _check_variables(variables, storage, lib.runtime.SimDataError)
        if len(factors) != spec["num_factors"]:
            raise lib.runtime.SimDataError(f"the data file has {len(factors)} factor rows, the "
                                           f"problem {spec['num_factors']}")
        _check_range(variables, factors, self.dtype, lib.runtime.SimDataError)
        x_off, self.t_off = _offsets(storage), _offsets(dims)
        self.x_off, self.n = x_off, int(self.t_off[-1])
        self.x0 = numpy.concatenate([v for v, _ in variables]).astype(self.dtype)
        self.blocks = [lib.runtime.Block(b, i, _rows(b, i, factors, lib), x_off, self.t_off,
                                         self.dtype) for i, b in enumerate(spec["blocks"])]
        self.base = _offsets([b.n * b.m * (b.d + 1) for b in self.blocks])
        self._plan = None  # the elimination's index tables: built by the first solve
        self._columns = {}  # block type → its variables' column offsets (_rows_of)
        # per variable type (index into spec["types"]): x ∘ Exp(δ) and Log(a⁻¹ b) over instances
        self.retractions = [lib.special.over_instances(r) for r, _ in spec["types"]]
        self.local_coordinates = [lib.special.over_instances(lc) for _, lc in spec["types"]]
        self.groups = [(self.retractions[kind],
                        numpy.array([x_off[v] + numpy.arange(storage[v]) for v in vs]),
                        numpy.array([self.t_off[v] + numpy.arange(dims[v]) for v in vs]))
                       for kind, vs in spec["retract_groups"]]

    @property
    def plan(self):
        """The elimination steps' index tables (``fgc_sim_linear.make_plan``), built when a
        solve first needs them: a Problem that only linearises or costs (verify's kernel
        check) never builds them."""
        if self._plan is None:
            spec = self.spec
            self._plan = self.lib.linear.make_plan(
                [s[:4] for s in spec["steps"]], self.t_off, spec["variable_dims"],
                self._rows_of, int(self.base[-1]),
                self.lib.linear.pivot_tolerances(spec["solver"]))
        return self._plan

    def _rows_of(self, entry):
        """Factor ``entry`` = (block, instance, member): its rows' starts in the flat [A | b]
        of all blocks, {variable: column offset} of the variables it touches, rhs offset."""
        b, i, member = entry
        blk = self.blocks[b]
        first, last, *_, touches = blk.spec["members"][member]
        col = self._columns.get(b)
        if col is None:  # each block type's column offsets, once (64k factors on w10000)
            col = self._columns[b] = _offsets(blk.spec["variable_dims"]).tolist()
        inst = blk.spec["instances"][i]
        starts = self.base[b] + (i * blk.m + numpy.arange(first, last)) * (blk.d + 1)
        return starts, {inst[k]: col[k] for k in touches}, blk.d

    def cost(self, x):
        """Total cost (GTSAM's graph error) at storage vector ``x``: the cost-only mode."""
        with numpy.errstate(all="ignore"):
            return sum((b.cost(x) for b in self.blocks), self.dtype.type(0))

    def linearize(self, x):
        """Every block's whitened [J | −r], the gradient g = Jᵀ(−r) (tangent vector) and the
        cost's rounding noise at x (see :func:`cost_noise`)."""
        with numpy.errstate(all="ignore"):
            abs_ = [b.linearize(x) for b in self.blocks]
        g = numpy.zeros(self.n)
        for b, ab in zip(self.blocks, abs_, strict=True):
            contrib = numpy.einsum("nmd,nm->nd", ab[..., :-1], ab[..., -1])
            g += numpy.bincount(b.columns.reshape(-1), contrib.reshape(-1), minlength=self.n)
        # bincount accumulates in float64; g only steers (stopping rule, predicted decrease)
        noise = cost_noise(self, x, [(ab, b.columns)
                                     for b, ab in zip(self.blocks, abs_, strict=True)])
        return abs_, g.astype(self.dtype), noise

    def solve(self, abs_, mu):
        """δ solving (H + μI) δ = g along the schedule, in the linear solver's precision (the
        factor rows widened to it, δ rounded back to the working precision)."""
        lin = self.lib.linear
        factors = numpy.concatenate([ab.reshape(-1) for ab in abs_]).astype(self.les_dtype,
                                                                             copy=False)
        conds = lin.eliminate(self.plan, factors, mu, self.spec["solver"]["linear"])
        delta = lin.back_substitute(self.plan, self.spec["back_substitution"], conds, self.n,
                                    self.les_dtype)
        return delta.astype(self.dtype, copy=False)

    def retract(self, x, delta):
        """x ⊕ δ: every variable retracted with its type's retraction."""
        return retract_groups(x, delta, self.groups)


def retract_groups(x, delta, groups):
    """x ⊕ δ over ``groups``: (retraction over instances, storage indices, tangent indices) per
    variable type, the indices one row per variable."""
    out = x.copy()
    with numpy.errstate(all="ignore"):
        for fn, sidx, tidx in groups:
            out[sidx] = fn(x[sidx], delta[tidx])
    return out


def les_dtype(dtype, linear_precision):
    """The linear solver's dtype: ``linear_precision`` when it is wider than the working
    ``dtype``, else ``dtype`` (a run in float64 never solves narrower)."""
    if linear_precision is None:
        return numpy.dtype(dtype)
    return numpy.promote_types(dtype, numpy.dtype(linear_precision))


def cost_noise(problem, x, parts):
    """How much the cost changes when x is rounded to the working precision: each whitened
    residual row moves by up to eps·Σ|A_ij|·scale_j (scale_j: the largest storage entry of
    column j's variable, at least 1), changing the cost by |b|·that + ½·that². ``parts`` pairs
    rows [A | b] (instances × rows × (columns + 1)) with their global tangent columns."""
    scale = numpy.maximum(numpy.maximum.reduceat(numpy.abs(x), problem.x_off[:-1]), 1)
    columns = numpy.repeat(scale, problem.spec["variable_dims"]).astype(problem.dtype)
    eps, total = numpy.finfo(problem.dtype).eps, 0.0
    for ab, cols in parts:
        moved = eps * numpy.einsum("nmd,nd->nm", numpy.abs(ab[..., :-1]), columns[cols])
        total += float(numpy.sum(numpy.abs(ab[..., -1]) * moved + 0.5 * moved * moved))
    return total


def resolution(problem, x, parts):
    """(ρ, variable) at x: ρ is the largest whitened-residual change, in σ, that rounding x to
    the working precision can cause (one row's eps·Σ|A_ij|·scale_j, as in :func:`cost_noise`);
    ``variable`` indexes the variable of that row's largest term. ρ ≥ 1 means the working
    precision cannot place the state within its noise: a coordinate's resolution (ulp) exceeds
    its σ, e.g. positions near 1e6 m with σ = 0.1 m, or σ = 1e-9 anywhere, in float32."""
    scale = numpy.maximum(numpy.maximum.reduceat(numpy.abs(x), problem.x_off[:-1]), 1)
    columns = numpy.repeat(scale, problem.spec["variable_dims"]).astype(numpy.float64)
    eps = float(numpy.finfo(problem.dtype).eps)
    best, column = 0.0, 0
    for ab, cols in parts:
        if ab.size == 0:
            continue
        terms = eps * numpy.abs(ab[..., :-1]).astype(numpy.float64) * columns[cols][:, None, :]
        rows = terms.sum(axis=-1)
        n, m = numpy.unravel_index(int(numpy.argmax(rows)), rows.shape)
        if rows[n, m] > best:
            best, column = float(rows[n, m]), int(cols[n, int(numpy.argmax(terms[n, m]))])
    variable = int(numpy.searchsorted(problem.t_off, column, side="right") - 1)
    return best, variable


def _check_variables(variables, storage, error):
    if len(variables) != len(storage):
        raise error(f"the data file has {len(variables)} variables, the problem {len(storage)}")
    for number, ((values, line), size) in enumerate(zip(variables, storage, strict=True)):
        if len(values) != size:
            raise error(f"line {line}: variable {number} needs {size} numbers, found "
                        f"{len(values)}", line, variable=number)


def _check_range(variables, factors, dtype, error):
    """Every number must fit the working precision: a float32 run would read |v| > 3.4e38 as
    ±inf. (Numbers that round to 0 are harmless data; a noise parameter that does leaves its
    rows empty, which elimination reports as singular.)"""
    top = numpy.finfo(dtype).max
    for what, rows in (("variable", variables), ("factor", factors)):
        for number, (values, line) in enumerate(rows):
            if numpy.any(numpy.abs(values) > top):
                raise error(f"line {line}: {what} {number} holds a number beyond the "
                            f"{dtype.name} range (|v| > {top:.3g})", line, **{what: number})


def _rows(spec, number, factors, lib):
    """The factor rows of block type ``number``'s instances as one (n × length) array."""
    length = sum(n_meas + n_params + 2 for _, _, _, n_params, n_meas, _ in spec["members"])
    rows = []
    for index in spec["factor_ids"]:
        values, line = factors[index]
        if len(values) != length:
            raise lib.runtime.SimDataError(
                f"line {line}: factor instance {index} (block type {number}) needs {length} "
                f"numbers, found {len(values)}", line, factor=index)
        rows.append(values)
    return numpy.array(rows).reshape(len(rows), length)


# --------------------------------------------------------------------------------------------
# Gauss-Newton / Levenberg-Marquardt
# --------------------------------------------------------------------------------------------


def optimize(problem, opts):
    """Run the solver; returns (x, final cost, iterations, μ, status, reason, cost log).
    ``problem.rejected`` counts the trial steps tried (retracted and costed) and not accepted,
    ``problem.noise_passes`` the iterations in which one was rejected with a finite cost: the
    accelerator works out the rounding-noise band then, once per iteration (the update model
    prices both)."""
    problem.rejected = problem.noise_passes = 0
    eps = float(numpy.finfo(problem.dtype).eps)
    # ‖δ‖ can only shrink to the storage's resolution: never ask for less than 10 ulp.
    limits = {"eps_step": max(opts["eps_step"], 10 * eps), "resolution": 16 * eps}
    x, cost = problem.x0, problem.cost(problem.x0)
    log, mu, it = [float(cost)], (opts["lambda_initial"] if opts["method"] == "lm" else 0.0), 0
    if not numpy.isfinite(cost):
        return x, cost, 0, mu, "failed", "non_finite", log
    while it < opts["max_iterations"]:
        abs_, g, noise = problem.linearize(x)
        if not all(numpy.all(numpy.isfinite(ab)) for ab in abs_):
            return x, cost, it, mu, "failed", "non_finite", log
        it += 1
        if numpy.max(numpy.abs(g), initial=0) < opts["eps_gradient"]:
            return x, cost, it, mu, "converged", "gradient", log
        band = max(limits["resolution"] * cost, noise)
        kind, x_new, new, mu, info = _step(problem, x, cost, (abs_, g, band), mu, opts, limits)
        if kind != "accept":
            return x, cost, it, mu, kind, info, log
        change = max(abs(cost - new), info) / cost if cost > 0 else 0.0
        x, cost = x_new, new
        log.append(float(cost))
        hook = getattr(problem, "on_iteration", None)  # a batch Problem's (not a Window's)
        if hook is not None:
            hook({"iteration": it, "error": float(cost), "lambda": float(mu),
                  "relative_decrease": float(change)})
        if cost <= opts["absolute_error_tol"]:
            return x, cost, it, mu, "converged", "absolute_error", log
        if change <= opts["relative_error_tol"]:
            return x, cost, it, mu, "converged", "relative_decrease", log
    return x, cost, it, mu, "max_iterations", "max_iterations", log


def _step(problem, x, cost, lin, mu, opts, limits):
    """One accepted step (kind "accept", x, cost, μ, predicted decrease), or why there is none
    (kind "converged"/"failed", reason in the last field).

    LM accepts a step that lowers the cost and otherwise grows μ and re-solves; Gauss-Newton
    takes every finite step. Near the optimum the cost's rounding noise (~1e-7 relative in
    float32) hides real progress, so a step whose predicted decrease ½δᵀ(g + μδ) is below the
    cost's resolution ``band`` is judged by that prediction: accepted unless the cost rose
    beyond the band.
    """
    abs_, g, band = lin
    singular = problem.lib.linear.SingularError
    noise = False  # the band worked out in this iteration (the accelerator's rule)
    while True:
        try:
            delta = problem.solve(abs_, mu)
        except singular as exc:
            problem.singular = exc  # which pivot: named in the result
            if mu <= 0:
                return "failed", None, None, mu, "singular"
            delta = None
        if delta is not None and numpy.all(numpy.isfinite(delta)):
            if numpy.linalg.norm(delta) <= limits["eps_step"] * (numpy.linalg.norm(x)
                                                                 + limits["eps_step"]):
                return "converged", None, None, mu, "step"
            predicted = 0.5 * float(delta @ (g + mu * delta))
            x_new = problem.retract(x, delta)
            new = problem.cost(x_new)
            if numpy.isfinite(new) and (new < cost or mu <= 0
                                        or predicted <= band and new <= cost + band):
                mu_next = max(mu / opts["lambda_factor"], opts["mu_min"])  # damping stays on
                return "accept", x_new, new, mu_next, predicted
            problem.rejected += 1
            if numpy.isfinite(new) and not noise:
                noise = True
                problem.noise_passes += 1
        if mu <= 0:
            return "failed", None, None, mu, "non_finite"
        mu *= opts["lambda_factor"]
        if mu > opts["lambda_upper_bound"]:
            return "failed", None, None, mu, "lambda_limit"


# --------------------------------------------------------------------------------------------
# entry point
# --------------------------------------------------------------------------------------------


def solve(spec, data_path, result_path=None, precision=None, lib=None, policy=None,
          progress=None):
    """Read ``data_path``, optimise (in one batch, or keyframe by keyframe under the streaming
    ``policy``: a dict, see ``fgc_sim_incremental.solve_stream``), write the
    JSON result to ``result_path`` (if given) and return it as a dict (values: see
    ``keyed_values``). ``progress`` is called with each keyframe's update record as it
    completes (incremental and fixed-lag solves) or, in a batch solve, with each accepted
    iteration's record (iteration, error, lambda, relative_decrease)."""
    with lib.linear.one_blas_thread():  # small dense kernels: threads only wait (see there)
        return _solve(spec, data_path, result_path, precision, lib, policy, progress)


def _solve(spec, data_path, result_path, precision, lib, policy, progress):
    opts = dict(spec["solver"])
    precision = precision or opts["precision"]
    t0 = time.perf_counter()
    data = lib.runtime.read_data(data_path, spec["structure"])
    problem = Problem(spec, data, precision, lib)
    if policy is None:
        problem.on_iteration = progress
    t1 = time.perf_counter()
    x, status, reason, it, mu, log, updates = _optimize_all(problem, opts, policy, progress)
    t2 = time.perf_counter()
    diagnosis = None  # rank and condition at the solution (batch solves)
    if updates is None and opts["diagnose"] and reason not in ("singular", "non_finite"):
        diagnosis = _diagnose(problem, data, x, opts)
    resolved = None  # float32 (any precision below float64): can it place the state at all?
    if problem.dtype != numpy.float64 and reason not in ("singular", "non_finite"):
        abs_, _, _ = problem.linearize(x)
        parts = [(ab, b.columns) for b, ab in zip(problem.blocks, abs_, strict=True)]
        rho, variable = resolution(problem, x, parts)
        resolved = {"rho": rho, "variable": variable}
        if rho >= RESOLUTION_LIMIT and status == "converged":
            status, reason = "failed", "precision_limit"
    singular = _singular(problem, reason, diagnosis, lib)
    if singular is not None and diagnosis is not None and (
            opts["method"] == "gn" or opts["singular_lm_fails"]):
        status, reason = "failed", "singular"
    offsets = _offsets(spec["variable_storage"])
    keys = variable_keys(spec)
    if updates is not None:
        updates = [{**u, "values": keyed_values(keys, u["values"])} for u in updates]
    result = {
        "format": RESULT_FORMAT, "status": status, "reason": reason,
        "converged": status == "converged", "iterations": it,
        "initial_error": _number(log[0]), "final_error": _number(log[-1]), "cost_log": log,
        "lambda": float(mu), "precision": precision,
        "linear_precision": problem.les_dtype.name, "method": opts["method"],
        "linear": opts["linear"], "setup_seconds": t1 - t0, "solve_seconds": t2 - t1,
        "diagnose_seconds": time.perf_counter() - t2, "incremental": updates,
        "singular": singular, "condition": (diagnosis or {}).get("condition"),
        "resolution": resolved,
        "values": keyed_values(keys, [x[a:b].astype(float).tolist()
                                      for a, b in zip(offsets[:-1], offsets[1:], strict=True)]),
    }
    if result_path is not None:
        with open(result_path, "w") as handle:
            json.dump(result, handle, indent=1)
            handle.write("\n")
    return result


def _optimize_all(problem, opts, policy=None, progress=None):
    """(x, status, reason, iterations, μ, cost log, incremental updates or None)."""
    if policy is None:
        x, _, it, mu, status, reason, log = optimize(problem, opts)
        return x, status, reason, it, mu, log, None
    x, status, reason, updates = problem.lib.incremental.solve_stream(problem, opts, optimize,
                                                                      policy, progress)
    log = [float(problem.cost(problem.x0)), float(problem.cost(x))]
    return x, status, reason, sum(u["iterations"] for u in updates), 0.0, log, updates


def _diagnose(problem, data, x, opts):
    """The diagnosis of :mod:`fgc_sim_diagnostics` at x, always in float64."""
    check = problem
    if problem.dtype != numpy.float64:
        check = Problem(problem.spec, data, "float64", problem.lib)
    return problem.lib.diagnostics.diagnose(check, x.astype(numpy.float64),
                                            opts["condition_iterations"])


def _singular(problem, reason, diagnosis, lib):
    """Where the system is singular: from the failed elimination of a batch solve, or from the
    diagnosis at the solution; None if it is not (or, incremental, cannot be placed)."""
    if reason == "singular" and getattr(problem, "singular", None) is not None:
        return lib.diagnostics.singular_info(problem.spec, problem.singular)
    return None if diagnosis is None else diagnosis["singular"]


def variable_keys(spec):
    """(key, value type) per variable, in the problem's order: the user's keys (an int stays an
    int), decoded from the text the problem module holds them as."""
    return [(json_value(key), type_name) for key, type_name in spec["variables"]]


def json_value(text):
    """A key of the problem module's table: JSON text, or "hex:" and its UTF-8 in hex."""
    if text.startswith("hex:"):
        text = bytes.fromhex(text[4:]).decode("utf-8")
    return json.loads(text)


def keyed_values(keys, storages):
    """The values as the result holds them: {str(key): {"key": key, "type": value type,
    "value": storage numbers}} in the problem's variable order, for each variable with a value
    (an incremental update's estimate has none for the variables yet to arrive)."""
    return {str(key): {"key": key, "type": type_name, "value": value}
            for (key, type_name), value in zip(keys, storages, strict=True)
            if value is not None}


def write_error(result_path, exc):
    """Record a data error in the result file, so that a caller can name what is wrong."""
    with open(result_path, "w") as handle:
        json.dump({"format": RESULT_FORMAT, "status": "data_error", "message": str(exc),
                   "line": exc.line, "factor": exc.factor, "variable": exc.variable}, handle)
        handle.write("\n")


def _number(value):
    value = float(value)
    return value if numpy.isfinite(value) else None
