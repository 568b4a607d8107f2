# fgc simulator run-time (fgc_sim_incremental.py): copied verbatim into every emitted simulator
"""Incremental smoothing over a chain (paper A, Algorithm 3.2), as the compiled plan schedules it.

Keyframe clusters arrive one by one. On arrival of cluster j the plan names a window of clusters
first … j (the newest k, or all of them on a batch step). The window's factors are relinearised
and optimised (GN/LM, clusters eliminated oldest to newest so the root is the newest cluster);
the older part of the Bayes net is kept: its conditionals and the factor τ it passes into the
window, linearised where they were last eliminated. τ enters the window as a linear factor in the
local coordinates Log(x̄⁻¹x) at its linearisation point x̄: rows [A·J | b − A·Log(x̄⁻¹x)], J the
Jacobian of that Log (GTSAM's LinearContainerFactor keeps A, a different cost away from x̄). After
the window converges it is eliminated once more without damping (QR) to store its conditionals and
new factors, and back-substitution walks the kept conditionals from the window down to cluster 0,
so every variable gets an estimate: x_c = x̄_c ⊕ R⁻¹ (d − S·Log(x̄_c+1⁻¹ x_c+1)). The newest kept
conditional (cluster first − 1) is not re-eliminated, but its parent x_first moved with the
window: it is re-expressed at the new x_first to first order (S ← S·J, d ← d − S·Log(x̄⁻¹x_first)),
as a Bayes net holds a conditional on its parent's tangent at the parent's linearisation point.
This is ISAM2 holding the kept variables (noRelinKeys) with the factors across the window's
edge kept linear where they were last linearised.

A fixed-lag window of W keyframes (``solve_fixed_lag``) is the same update with a window of the
newest W + 1 clusters and no batch steps: on arrival of keyframe j the window j − W … j is
optimised (the newest keyframes and the one about to leave), then eliminated once more; the
factor τ its oldest cluster passes up is the Schur complement of that cluster's conditional —
the dense Gaussian marginal prior on cluster j − W + 1, kept linear in the local coordinates at
the point where it was formed (A·Log(x̄⁻¹x), Jacobian A·J: its linearisation point never moves,
every other factor of the window is relinearised each iteration). The cluster leaving is
dropped: its estimate stays where the update left it, no kept conditional is walked back, so an
update costs the same however long the stream. This is GTSAM's fixed-lag smoothers' order
(optimise, then marginalise the keys older than the lag; lag W − 1 with timestamps = keyframe
index).
"""

import time

import numpy


class Window:
    """One update's sub-problem, with the interface the optimiser expects of a problem."""

    def __init__(self, problem, chain, first, last, tau):
        self.problem, self.lib, self.dtype = problem, problem.lib, problem.dtype
        self.chain, self.first, self.last, self.tau = chain, first, last, tau
        self.x0 = chain.x
        variables = [v for c in range(first, last + 1) for v in chain.clusters[c]]
        dims = problem.spec["variable_dims"]
        self.offset = numpy.zeros(len(dims), dtype=numpy.intp)
        self.offset[variables] = numpy.concatenate([[0], numpy.cumsum([dims[v] for v in
                                                                      variables])[:-1]])
        self.n = sum(dims[v] for v in variables)
        self.sel = [numpy.flatnonzero((e >= first) & (m <= last))
                    for e, m in zip(chain.entry, chain.reach, strict=True)]
        sizes = [len(s) * b.m * (b.d + 1) for s, b in zip(self.sel, problem.blocks, strict=True)]
        self.base = numpy.concatenate([[0], numpy.cumsum(sizes)]).astype(numpy.intp)
        self.tmap = numpy.full(problem.n, -1, dtype=numpy.intp)  # global → window column
        for v in variables:
            start = problem.t_off[v]
            self.tmap[start:start + dims[v]] = self.offset[v] + numpy.arange(dims[v])
        self.columns = [self.tmap[b.columns[s]]
                        for b, s in zip(problem.blocks, self.sel, strict=True)]
        self.plan = self.lib.linear.make_plan(self._steps(), self.offset, dims, self._rows_of,
                                              int(self.base[-1]) + self._tau_size(),
                                              self.lib.linear.pivot_tolerances(
                                                  problem.spec["solver"]))
        self.groups = _groups(problem, variables, self.offset)

    def _tau_size(self):
        return 0 if self.tau is None else self.tau[0].size

    def _steps(self):
        steps = []
        for c in range(self.first, self.last + 1):
            entering = [(b, i, m) for b, sel in enumerate(self.sel)
                        for i in numpy.flatnonzero(self.chain.entry[b][sel] == c)
                        for m in range(len(self.problem.blocks[b].spec["members"]))]
            if c == self.first and self.tau is not None:
                entering.append(("tau",))
            sep = self.chain.clusters[c + 1] if c < self.last else ()
            steps.append((self.chain.clusters[c], sep, entering,
                          [c - self.first - 1] if c > self.first else []))
        return steps

    def _rows_of(self, entry):
        if entry[0] == "tau":
            rows, width = self.tau[0].shape
            starts = int(self.base[-1]) + numpy.arange(rows) * width
            return starts, self.chain.columns_in_row(self.first), width - 1
        b, i, member = entry
        blk = self.problem.blocks[b]
        first, last, *_, touches = blk.spec["members"][member]
        col = numpy.concatenate([[0], numpy.cumsum(blk.spec["variable_dims"])])
        inst = blk.spec["instances"][self.sel[b][i]]
        starts = self.base[b] + (i * blk.m + numpy.arange(first, last)) * (blk.d + 1)
        return starts, {inst[k]: int(col[k]) for k in touches}, blk.d

    # -- the optimiser's interface -------------------------------------------------------
    def linearize(self, x):
        with numpy.errstate(all="ignore"):
            parts = [b.linearize(x, s) for b, s in zip(self.problem.blocks, self.sel, strict=True)]
        if self.tau is not None:
            parts.append(self._tau_rows(x))
        g = numpy.zeros(self.n)
        blocks = parts[:len(self.columns)]  # τ's rows, last in parts, are added below
        for ab, cols in zip(blocks, self.columns, strict=True):
            contrib = numpy.einsum("nmd,nm->nd", ab[..., :-1], ab[..., -1])
            g += numpy.bincount(cols.reshape(-1), contrib.reshape(-1), minlength=self.n)
        pairs = [(ab, b.columns[s])
                 for ab, b, s in zip(blocks, self.problem.blocks, self.sel, strict=True)]
        if self.tau is not None:
            g[self._tau_columns()] += parts[-1][:, :-1].T @ parts[-1][:, -1]
            pairs.append((parts[-1][None], self.chain.tangent(self.first)[None]))
        noise = self.lib.optimizer.cost_noise(self.problem, x, pairs)
        return parts, g.astype(self.dtype), noise

    def cost(self, x):
        with numpy.errstate(all="ignore"):
            total = sum((b.cost(x, s) for b, s in zip(self.problem.blocks, self.sel, strict=True)),
                        self.dtype.type(0))
            if self.tau is not None:
                r = self._tau_rows(x)
                total += 0.5 * numpy.sum(r[:, -1] ** 2)
        return total

    def solve(self, parts, mu):
        lin, les = self.lib.linear, self.problem.les_dtype  # the linear solver's precision
        factors = numpy.concatenate([p.reshape(-1) for p in parts]).astype(les, copy=False)
        conds = lin.eliminate(self.plan, factors, mu, self.problem.spec["solver"]["linear"])
        order = [(i,) for i in reversed(range(len(self.plan.steps)))]
        delta = lin.back_substitute(self.plan, order, conds, self.n, les)
        return delta.astype(self.dtype, copy=False)

    def retract(self, x, delta):
        return self.lib.optimizer.retract_groups(x, delta, self.groups)

    # -- τ as a linear factor at its linearisation point ---------------------------------
    def _tau_rows(self, x):
        """τ at x: rows [A·J | b − A·s] with s = Log(x̄⁻¹x) and J = ∂s/∂δ at x ⊕ δ."""
        rows, lin = self.tau
        shift, jac = self.chain.local_jacobian(lin, x, self.first)
        a, b = rows[:, :-1], rows[:, -1]
        return numpy.concatenate([a @ jac, (b - a @ shift)[:, None]], 1)

    def _tau_columns(self):
        return self.tmap[self.chain.tangent(self.first)]


def _groups(problem, variables, offset):
    """Retraction groups restricted to the window's variables, with window tangent columns."""
    chosen, spec = set(variables), problem.spec
    groups = []
    for kind, vs in spec["retract_groups"]:
        vs = [v for v in vs if v in chosen]
        if vs:
            groups.append((problem.retractions[kind],
                           numpy.array([problem.x_off[v] + numpy.arange(
                               spec["variable_storage"][v]) for v in vs]),
                           numpy.array([offset[v] + numpy.arange(spec["variable_dims"][v])
                                        for v in vs])))
    return groups


class Chain:
    """The incremental state: the estimate, every cluster's latest conditional and the factor τ
    passed into each cluster, with the linearisation points they were computed at."""

    def __init__(self, problem):
        self.problem, self.clusters = problem, problem.spec["clusters"]
        self.x = problem.x0.copy()
        cluster_of = numpy.zeros(len(problem.spec["variable_dims"]), dtype=numpy.intp)
        for c, variables in enumerate(self.clusters):
            cluster_of[list(variables)] = c
        insts = [cluster_of[numpy.array(b.spec["instances"]).reshape(b.n, -1)]
                 for b in problem.blocks]
        self.entry, self.reach = [c.min(1) for c in insts], [c.max(1) for c in insts]
        self.kind = {v: kind for kind, vs in problem.spec["retract_groups"] for v in vs}
        self.conds, self.taus = {}, {}

    def storage(self, c):
        storage, off = self.problem.spec["variable_storage"], self.problem.x_off
        return numpy.concatenate([off[v] + numpy.arange(storage[v]) for v in self.clusters[c]])

    def tangent(self, c):
        dims, off = self.problem.spec["variable_dims"], self.problem.t_off
        return numpy.concatenate([off[v] + numpy.arange(dims[v]) for v in self.clusters[c]])

    def columns_in_row(self, c):
        """{variable: first column} of cluster c's variables in a row over the cluster."""
        dims, out, col = self.problem.spec["variable_dims"], {}, 0
        for v in self.clusters[c]:
            out[v], col = col, col + dims[v]
        return out

    def _parts(self, c):
        """Per variable of cluster c: its kind, its storage and tangent slices within the
        cluster, and its storage slice in x."""
        storage, off = self.problem.spec["variable_storage"], self.problem.x_off
        dims = self.problem.spec["variable_dims"]
        s = t = 0
        for v in self.clusters[c]:
            yield (self.kind[v], slice(s, s + storage[v]), slice(t, t + dims[v]),
                   slice(off[v], off[v] + storage[v]))
            s, t = s + storage[v], t + dims[v]

    def local(self, lin, x, c):
        """Log(x̄⁻¹ x) of cluster c's variables: ``lin`` is the cluster's storage x̄."""
        local = self.problem.local_coordinates
        return numpy.concatenate([local[kind](lin[None, sp], x[None, xs])[0]
                                  for kind, sp, _, xs in self._parts(c)])

    def local_jacobian(self, lin, x, c):
        """Log(x̄⁻¹ x) of cluster c and its derivative along x ⊕ δ (block diagonal), by central
        differences of the run-time's own Log and Exp: τ's rows must be the derivative of
        exactly the cost the window evaluates, or LM stalls on the mismatch."""
        problem, dims = self.problem, self.problem.spec["variable_dims"]
        h = numpy.sqrt(numpy.finfo(x.dtype).eps) * 10
        n = sum(dims[v] for v in self.clusters[c])
        jac = numpy.zeros((n, n), dtype=x.dtype)
        for kind, sp, tp, xs in self._parts(c):
            d = tp.stop - tp.start
            steps = numpy.concatenate([numpy.eye(d), -numpy.eye(d)]).astype(x.dtype) * h
            moved = problem.retractions[kind](numpy.repeat(x[None, xs], 2 * d, 0), steps)
            logs = problem.local_coordinates[kind](numpy.repeat(lin[None, sp], 2 * d, 0), moved)
            jac[tp, tp] = ((logs[:d] - logs[d:]) / (2 * h)).T
        return self.local(lin, x, c), jac

    def retract(self, lin, delta, c):
        """x̄ ⊕ δ for cluster c's variables (storage ``lin``, tangent ``delta``)."""
        retract = self.problem.retractions
        return numpy.concatenate([retract[kind](lin[None, sp], delta[None, tp])[0]
                                  for kind, sp, tp, _ in self._parts(c)])


# --------------------------------------------------------------------------------------------
# the update loop
# --------------------------------------------------------------------------------------------


def solve_stream(problem, opts, optimize, policy, progress=None):
    """Run the streaming ``policy`` (a dict: ``{"mode": "incremental"}``, the compiled plan, or
    ``{"mode": "fixed-lag", "window": W}``) keyframe by keyframe; returns (x, status, reason,
    per-update records). A new policy is one more mode here."""
    mode = policy.get("mode")
    if mode == "incremental":
        if problem.spec["incremental"] is None:
            raise ValueError("this problem was compiled without an incremental plan")
        return solve_incremental(problem, opts, optimize, progress)
    if mode == "fixed-lag":
        if problem.spec["clusters"] is None:
            raise ValueError("a fixed-lag window needs a chain of keyframes")
        return solve_fixed_lag(problem, opts, optimize, policy["window"], progress)
    raise ValueError(f"unknown streaming policy {policy!r}")


def solve_incremental(problem, opts, optimize, progress=None):
    """Run every update of the plan; returns (x, status, reason, per-update records).
    ``progress`` (if given) is called with each update's record as soon as it is done."""
    chain, history, status, reason = Chain(problem), [], "converged", ""
    for keyframe, batch, clusters, _ in problem.spec["incremental"]:
        t0 = time.perf_counter()
        new = [e[r == keyframe] for e, r in zip(chain.entry, chain.reach, strict=True)]
        first = min([clusters[0]] + [int(n.min()) for n in new if len(n)])
        tau = chain.taus.get(first) if first > 0 else None
        window = Window(problem, chain, first, keyframe, tau)
        x, cost, it, _, st, why, _ = optimize(window, opts)
        if first > 0:
            _relinearize_parent(chain, x, first - 1)
        _store(chain, window, window.x0 if one_step(opts) else x)
        _back_substitute(chain, x, first)
        chain.x = x
        seconds = time.perf_counter() - t0
        history.append({"keyframe": keyframe, "mode": "batch" if batch else "incremental",
                        "first": first, "iterations": it, "status": st, "reason": why,
                        "rejected": window.rejected, "noise_passes": window.noise_passes,
                        "cost": float(cost), "seconds": seconds,
                        "values": _snapshot(chain, keyframe)})
        if progress is not None:
            progress(history[-1])
        if st != "converged" and status == "converged":
            status, reason = st, f"keyframe {keyframe}: {why}"
    return chain.x, status, reason, history


def solve_fixed_lag(problem, opts, optimize, window, progress=None):
    """Keyframe by keyframe with a fixed-lag window of ``window`` keyframes (module docstring);
    returns (x, status, reason, per-update records). Each record's ``values`` holds the window
    after the update (None elsewhere); x holds every variable, a marginalised one where the
    last update that held it left it."""
    if window < 1:
        raise ValueError(f"the fixed-lag window must be >= 1 keyframe, got {window}")
    chain, history, status, reason = Chain(problem), [], "converged", ""
    for keyframe in range(len(chain.clusters)):
        t0 = time.perf_counter()
        first = max(0, keyframe - window)
        for entry, reach in zip(chain.entry, chain.reach, strict=True):
            early = entry[reach == keyframe]
            if len(early) and int(early.min()) < first:
                raise ValueError(f"keyframe {keyframe}: a factor reaches back to keyframe "
                                 f"{int(early.min())}, already marginalised by the "
                                 f"{window}-keyframe window")
        tau = chain.taus.get(first) if first > 0 else None
        win = Window(problem, chain, first, keyframe, tau)
        x, cost, it, _, st, why, _ = optimize(win, opts)
        _store(chain, win, win.x0 if one_step(opts) else x)
        for c in range(first):  # marginalised: nothing of theirs is needed again
            chain.conds.pop(c, None)
            chain.taus.pop(c, None)
        chain.x = x
        seconds = time.perf_counter() - t0
        history.append({"keyframe": keyframe, "mode": "fixed-lag", "first": first,
                        "iterations": it, "status": st, "reason": why,
                        "rejected": win.rejected, "noise_passes": win.noise_passes,
                        "cost": float(cost),
                        "seconds": seconds,
                        "values": _snapshot(chain, keyframe, max(0, keyframe - window + 1))})
        if progress is not None:
            progress(history[-1])
        if st != "converged" and status == "converged":
            status, reason = st, f"keyframe {keyframe}: {why}"
    return chain.x, status, reason, history


def _snapshot(chain, keyframe, oldest=0):
    """The estimate after an update: each variable's storage, in the problem's variable order,
    None for the variables of clusters that have not arrived yet (or are older than cluster
    ``oldest``)."""
    storage, off = chain.problem.spec["variable_storage"], chain.problem.x_off
    out = [None] * len(storage)
    for c in range(oldest, keyframe + 1):
        for v in chain.clusters[c]:
            out[v] = chain.x[off[v]:off[v] + storage[v]].astype(float).tolist()
    return out


def one_step(opts):
    """ISAM2's update policy (one Gauss-Newton step an update: method "gn", max_iterations 1).
    Its store is the update's own factorisation: the window eliminated without damping at the
    point the update linearised it (its start), as ISAM2 keeps its Bayes tree at the
    linearisation point θ with the estimate θ ⊕ Δ; the kept conditionals and τ hold that
    point. (Where the step was not taken the start is the estimate, as in every other
    policy.)"""
    return opts.get("method") == "gn" and int(opts.get("max_iterations", 0)) == 1


def _store(chain, window, x):
    """Eliminate the window once more without damping at ``x`` (the converged estimate, or
    the update's start under :func:`one_step`): its conditionals and the factors passed
    between its clusters, linearised at ``x``, are what later updates keep."""
    parts, _, _ = window.linearize(x)
    conds, news = window.lib.linear.eliminate_qr(
        window.plan, numpy.concatenate([p.reshape(-1) for p in parts]).astype(
            chain.problem.les_dtype, copy=False), 0.0)
    for k, c in enumerate(range(window.first, window.last + 1)):
        lin_next = x[chain.storage(c + 1)] if c < window.last else None
        chain.conds[c] = (conds[k], x[chain.storage(c)], lin_next)
        if c < window.last:
            chain.taus[c + 1] = (news[k], lin_next)


def _relinearize_parent(chain, x, c):
    """Re-express kept cluster c's conditional R·δ_c + S·Log(x̄⁻¹x_c+1) = d at the new
    estimate of its parent x_c+1: S ← S·J, d ← d − S·Log(x̄⁻¹x_c+1), x̄ ← x_c+1 (first order,
    as a Bayes net stores a conditional on the parent's tangent at its linearisation point)."""
    (r, s, d), lin, lin_next = chain.conds[c]
    shift, jac = chain.local_jacobian(lin_next, x, c + 1)
    chain.conds[c] = ((r, s @ jac, d - s @ shift), lin, x[chain.storage(c + 1)])


def _back_substitute(chain, x, first):
    """Kept clusters first − 1 … 0 from their conditionals, given the newer estimate."""
    solve_upper = chain.problem.lib.linear.solve_upper
    for c in range(first - 1, -1, -1):
        (r, s, d), lin, lin_next = chain.conds[c]
        delta = solve_upper(r, d - s @ chain.local(lin_next, x, c + 1)).astype(x.dtype,
                                                                                copy=False)
        x[chain.storage(c)] = chain.retract(lin, delta, c)
