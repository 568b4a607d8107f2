"""Fixed-lag streaming on the native solver: per keyframe, the compiled C++ solves the window of
the newest keyframes with the marginal prior of the keyframes that left it (issue 19).

The semantics are the simulator's fixed-lag window (``solve_fixed_lag`` in the emitted
simulator's incremental module): on arrival of keyframe j the window j − W … j (the newest W
keyframes and the one about to leave) is optimised from the current estimates; then the oldest
keyframe is eliminated from the window's linearisation at the optimum, and the factor it passes
to the next keyframe — the Schur complement of its conditional, a dense Gaussian prior — enters
the next window, linear in the local coordinates at the point where it was formed (its
linearisation point never moves; every other factor is relinearised each iteration).

How the native solver runs it. A solver is compiled once, for a *template* window: the graph's
first W + 1 keyframes with their factors, plus on every keyframe a ``MarginalPrior…`` factor
(:func:`marginal_prior_type`: r = Log(x̄⁻¹x) − m per variable, whitened by a full square-root
information R, so its cost is ½‖R·Log(x̄⁻¹x) − R·m‖², exactly the simulator's ½‖A·s − b‖² with
R = A, m = A⁻¹b). Each update fills that one structure with numbers:

- window slot i holds keyframe first + i; a template factor takes the numbers of the graph factor
  on the same slots (same factor type, same variables by position in their keyframes); a template
  factor without one (the first keyframe's priors once the window has moved on) and a graph
  factor that reaches past j (during the first W updates) get a zero square-root information:
  they contribute nothing, neither cost nor Jacobian;
- the slot-0 prior carries the marginal (zero before any keyframe left); during the first W
  updates the slots past j are not in the problem: their variables are held by a unit prior at
  their current value (zero residual, zero gradient: their step is exactly zero), decoupled from
  the window by the zero-weighted factors between them;
- a graph factor inside the window that no template factor matches (the stream's pattern of
  factors is not the same for every window) is refused (:class:`NativeStreamError`).

The marginalisation: the native library linearises the window at its optimum
(``fgc_rows``: the whitened rows of every factor, as its LM does, marginal prior included, whose
Jacobian is the exact derivative of Log), and NumPy eliminates the leaving keyframe with one QR
of the (rows × two keyframes) matrix of the factors on it. Its time is reported beside the
native solve's (``marginal_seconds``; ``seconds`` is the whole update: data assembly, the native
solve and the marginalisation).
"""

from __future__ import annotations

import inspect
import time
from dataclasses import dataclass, field

import numpy as np

from fgc.errors import FgcError
from fgc.frontend.dsl import FactorType, Graph, Matrix
from fgc.frontend.noise import NoiseModel
from fgc.ir.datafile import ProblemData, factor_words
from fgc.ir.program import Program

_PRIOR_TYPES: dict[tuple[type, ...], FactorType] = {}


class NativeStreamError(FgcError):
    """The stream cannot run on the native solver (a window whose factors differ from the
    template's, a factor spanning more than two keyframes, a singular marginal)."""


def _marginal_prior(*variables, **measured):
    """Local coordinates Log(x̄⁻¹x) of each variable at its linearisation point ``at<i>``, stacked,
    minus ``mean``: whitened by R, R·Log(x̄⁻¹x) − R·mean."""
    local = []
    for i, value in enumerate(variables):
        local += list(measured[f"at{i}"].local(value))
    mean = measured["mean"]
    return [local[k] - mean[k, 0] for k in range(len(local))]


def marginal_prior_type(types: tuple[type, ...]) -> FactorType:
    """The dense prior factor type on a keyframe whose variables have ``types`` (in order):
    variables ``x0 …``, measurements ``at0 …`` (the linearisation point, same types) and
    ``mean`` (a column of the keyframe's tangent dimension)."""
    if types not in _PRIOR_TYPES:
        dim = sum(t.dim for t in types)
        params = [inspect.Parameter(f"x{i}", inspect.Parameter.POSITIONAL_OR_KEYWORD,
                                    annotation=t) for i, t in enumerate(types)]
        params += [inspect.Parameter(f"at{i}", inspect.Parameter.KEYWORD_ONLY, annotation=t)
                   for i, t in enumerate(types)]
        params.append(inspect.Parameter("mean", inspect.Parameter.KEYWORD_ONLY,
                                        annotation=Matrix(dim, 1)))

        def marginal_prior(*variables, **measured):
            return _marginal_prior(*variables, **measured)

        marginal_prior.__signature__ = inspect.Signature(params)
        marginal_prior.__annotations__ = {p.name: p.annotation for p in params}
        name = "MarginalPrior" + "".join(t.__name__ for t in types)
        _PRIOR_TYPES[types] = FactorType(marginal_prior, name=name)
    return _PRIOR_TYPES[types]


@dataclass
class NativeStreamResult:
    """A native fixed-lag stream: the final estimate (every variable where the last update that
    held it left it), per-update records as the simulator's (``keyframe``, ``mode``, ``first``,
    ``iterations``, ``status``, ``reason``, ``cost``, ``seconds``, ``values``) plus
    ``solve_seconds`` (the native call) and ``marginal_seconds``."""

    values: dict
    storage: dict
    status: str
    reason: str
    iterations: int
    updates: list = field(default_factory=list)
    # the first window's cost at the initial values (finite: the solver could start); the whole
    # graph's error is not evaluated (the stream never holds the whole graph)
    initial_error: float | None = None
    template: Program | None = None


class FixedLagStream:
    """The native solver compiled for a fixed-lag window of ``window`` keyframes over the chain
    ``program`` (compiled from ``graph``); :meth:`run` streams ``data``."""

    def __init__(self, graph: Graph, program: Program, window: int, config=None):
        from fgc.compile import compile_graph
        from fgc_backends import native

        if program.schedule.structure_class != "chain" or not program.schedule.clusters:
            raise NativeStreamError("native streaming needs a chain of keyframes")
        if isinstance(window, bool) or not isinstance(window, int) or window < 1:
            raise NativeStreamError(f"the fixed-lag window must be a positive number of "
                                    f"keyframes, got {window!r}")
        self.graph, self.program, self.window = graph, program, window
        clusters = program.schedule.clusters
        self.size = size = min(window + 1, len(clusters))
        original = {str(k): k for k in graph.variables}
        self.cluster_of = {k: c for c, keys in enumerate(clusters) for k in keys}
        self.position = {k: p for keys in clusters for p, k in enumerate(keys)}
        types = [tuple(graph.variables[original[k]].type for k in keys) for keys in clusters]
        for c, kinds in enumerate(types):
            if kinds != types[0]:
                raise NativeStreamError(f"keyframe {c} has variables of types "
                                        f"{[t.__name__ for t in kinds]}, keyframe 0 "
                                        f"{[t.__name__ for t in types[0]]}: a window slides "
                                        "over keyframes of one kind")
        self.types = types

        template = Graph()
        for c in range(size):
            for k in clusters[c]:
                var = graph.variables[original[k]]
                template.add_variable(var.key, var.initial, var.type)
        self.signatures, self.template_factors = [], []
        for f in graph.factors:
            spans = [self.cluster_of[str(k)] for k in f.keys]
            if max(spans) < size:
                template.add(f)
                self.template_factors.append(f)
                self.signatures.append(self._signature(f, 0))
        self.prior_types = []
        for c in range(size):
            keys = [original[k] for k in clusters[c]]
            ptype = marginal_prior_type(types[c])
            dim = sum(t.dim for t in types[c])
            lin = {f"at{i}": graph.variables[k].initial for i, k in enumerate(keys)}
            template.add(ptype(*keys, noise=NoiseModel("full", np.eye(dim)),
                               mean=np.zeros((dim, 1)), **lin))
            self.prior_types.append((ptype, dim))
        solver = program.solver
        self.template = compile_graph(template, solver, name=f"{program.name}_lag{window}")
        self.solver = native.load(self.template, config)
        self.config = self.solver.project.config
        # every graph factor by its signature (type, (keyframe, position) per variable)
        self.by_signature = {self._signature(f, 0): i for i, f in enumerate(graph.factors)}
        spans = [[self.cluster_of[str(k)] for k in f.keys] for f in graph.factors]
        self.span_lo = np.array([min(s) for s in spans])
        self.span_hi = np.array([max(s) for s in spans])
        # the words of a slot's prior after its linearisation point: unit (held) or zero
        self._held = [self._prior_tail(np.eye(dim), np.zeros(dim)) for _, dim in self.prior_types]
        self._unused = [self._prior_tail(np.zeros((dim, dim)), np.zeros(dim))
                        for _, dim in self.prior_types]
        self._words = {}
        self._zero = {}
        self._marginal_plan()
        self._check_prior_layout()

    def _marginal_plan(self) -> None:
        """Where the rows of the factors that eliminate slot 0 lie in the solver's
        linearisation (:meth:`NativeSolver.rows`) and which columns of the (slot 0, slot 1)
        matrix each of their variables' tangent columns is."""
        t = self.template
        dims = {v.key: v.dim for v in t.variables}
        column, width = {}, 0
        for slot in (0, 1):
            for v in t.variables:
                if self.cluster_of[v.key] == slot:
                    column[v.key] = width
                    width += dims[v.key]
        self.n0 = sum(dims[v.key] for v in t.variables if self.cluster_of[v.key] == 0)
        self.width = width
        layout = self.solver.row_layout()
        seen = [0] * len(t.blocks)
        self.slot0 = []  # (first word, m, columns, target columns)
        for spec in t.factors:
            k = seen[spec.block]
            seen[spec.block] += 1
            slots = [self.cluster_of[key] for key in spec.keys]
            if min(slots) != 0:
                continue
            if max(slots) > 1:
                raise NativeStreamError(f"a factor on {list(spec.keys)} spans keyframes 0 to "
                                        f"{max(slots)}: the native fixed-lag window marginalises "
                                        "factors between consecutive keyframes only")
            pos, _, m, cols = layout[spec.block]
            targets = np.concatenate([column[key] + np.arange(dims[key]) for key in spec.keys])
            self.slot0.append((pos + k * m * cols, m, cols, targets))

    def marginal(self, x: np.ndarray, d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Eliminate slot 0 from the window's linearisation at ``x`` (the solver's own rows: its
        factors and its marginal prior): the dense factor [A | b] it passes to slot 1, A upper
        triangular with a positive diagonal."""
        rows = self.solver.rows(x, d)
        stacks = []
        for start, m, cols, targets in self.slot0:
            block = rows[start:start + m * cols].reshape(m, cols)
            part = np.zeros((m, self.width + 1))
            part[:, targets] = block[:, :-1]
            part[:, -1] = block[:, -1]
            stacks.append(part)
        stacked = np.concatenate(stacks)
        n0, n1 = self.n0, self.width - self.n0
        if stacked.shape[0] < self.width:
            raise NativeStreamError(f"{stacked.shape[0]} rows cannot determine the "
                                    f"{self.width} columns of the leaving keyframe's "
                                    "conditional and marginal")
        r = np.linalg.qr(stacked, mode="r")
        a, b = r[n0:n0 + n1, n0:-1], r[n0:n0 + n1, -1]
        signs = np.where(np.diag(a) < 0, -1.0, 1.0)
        return a * signs[:, None], b * signs

    def _signature(self, f, shift: int) -> tuple:
        return (f.type.name, tuple((self.cluster_of[str(k)] + shift, self.position[str(k)])
                                   for k in f.keys))

    # -- the numbers of one update ----------------------------------------------------------
    def _factor(self, index: int, member) -> np.ndarray:
        if index not in self._words:
            f = self.graph.factors[index]
            self._words[index] = np.concatenate(factor_words(f.measured, f.noise, member))
        return self._words[index]

    def _zeroed(self, t: int, member) -> np.ndarray:
        if t not in self._zero:
            f = self.template_factors[t]
            noise = NoiseModel(f.noise.kind, np.zeros_like(f.noise.sqrt_information),
                               f.noise.robust)
            self._zero[t] = np.concatenate(factor_words(f.measured, noise, member))
        return self._zero[t]

    def _prior_tail(self, r: np.ndarray, mean: np.ndarray) -> np.ndarray:
        """A marginal prior's words after its linearisation point: the mean, the square-root
        information's upper triangle (a full noise model's parameters) and no robust loss
        (factor_words' layout, checked against it in :meth:`_check_prior_layout`)."""
        return np.concatenate([mean, r[np.triu_indices(r.shape[0])], [0.0, 0.0]])

    def _check_prior_layout(self) -> None:
        """The template's prior members take their words as :meth:`_prior_tail` lays them out."""
        n_template = len(self.template_factors)
        for spec in self.template.factors:
            block = self.template.blocks[spec.block]
            for member, t in zip(block.members, spec.factors, strict=True):
                if t < n_template:
                    continue
                ptype, dim = self.prior_types[t - n_template]
                names = [name for name, _ in member.measurements]
                lin = [np.arange(v.storage_dim, dtype=float) + 10 * i for i, v in enumerate(
                    v for v in self.template.variables
                    if self.cluster_of[v.key] == t - n_template)]
                r, mean = np.triu(np.arange(dim * dim, dtype=float).reshape(dim, dim)), \
                    np.arange(dim, dtype=float) - 7
                measured = {**{f"at{i}": v for i, v in enumerate(lin)}, "mean": mean}
                expected = np.concatenate(factor_words(measured, NoiseModel("full", r), member))
                if names != [*measured] or not np.array_equal(
                        expected, np.concatenate([*lin, self._prior_tail(r, mean)])):
                    raise NativeStreamError(f"internal error: {ptype.name}'s data layout is not "
                                            "the one the stream assembles")

    def assemble(self, estimate: dict, first: int, last: int, tau):
        """(x, d): the template's flat arrays (storage, factor data) for the window first …
        last, from the current ``estimate`` and the marginal ``tau`` (R, mean, x̄ per
        variable) on keyframe ``first``; :class:`NativeStreamError` if the window holds a graph
        factor the template does not match."""
        clusters = self.program.schedule.clusters
        slot_keys = [clusters[first + s] for s in range(self.size)]
        x = np.concatenate([estimate[slot_keys[self.cluster_of[v.key]][self.position[v.key]]]
                            for v in self.template.variables])
        words, matched = [], 0
        n_template = len(self.template_factors)
        tau_tail = None if tau is None else self._prior_tail(tau[0], tau[1])
        for spec in self.template.factors:
            block = self.template.blocks[spec.block]
            for member, t in zip(block.members, spec.factors, strict=True):
                if t < n_template:
                    kind, cells = self.signatures[t]
                    slots = [c for c, _ in cells]
                    index = self.by_signature.get((kind, tuple((c + first, p)
                                                               for c, p in cells)))
                    if index is not None and max(slots) + first <= last:
                        words.append(self._factor(index, member))
                        matched += 1
                    else:
                        words.append(self._zeroed(t, member))
                    continue
                slot = t - n_template
                if slot == 0 and tau is not None:  # the marginal of the keyframes that left
                    words += [*tau[2], tau_tail]
                elif first + slot > last:  # not arrived yet: held where it is
                    words += [*(estimate[k] for k in slot_keys[slot]), self._held[slot]]
                else:  # no prior: zero square-root information
                    words += [*(estimate[k] for k in slot_keys[slot]), self._unused[slot]]
        inside = int(np.count_nonzero((self.span_lo >= first) & (self.span_hi <= last)))
        if matched != inside:
            raise NativeStreamError(f"keyframes {first} … {last}: the window holds {inside} "
                                    f"factors but the compiled template matches {matched}: the "
                                    "stream's factors do not repeat keyframe by keyframe")
        return x, np.concatenate(words)

    def _check_once(self, x, d) -> None:
        """The first update's arrays against the template's layout (sizes, per-block words)."""
        t = self.template
        sizes, pos = [], 0
        for spec in t.factors:
            from fgc_backends.cfamily.tables import factor_data_words
            n = factor_data_words(t, spec.block)
            sizes.append(d[pos:pos + n])
            pos += n
        variables, pos = [], 0
        for v in t.variables:
            variables.append(x[pos:pos + v.storage_dim])
            pos += v.storage_dim
        self.solver.flatten(ProblemData(tuple(variables), tuple(sizes), t.structure_fingerprint))

    # -- the stream ---------------------------------------------------------------------------
    def run(self, data: ProblemData, progress=None) -> NativeStreamResult:
        from fgc.interop.estimates import values_from_storage
        from fgc_backends.cfamily.results import REASONS, STATUSES

        program, window = self.program, self.window
        clusters = program.schedule.clusters
        offsets = np.concatenate([[0], np.cumsum([v.storage_dim for v in program.variables])])
        index = {v.key: i for i, v in enumerate(program.variables)}
        full = np.concatenate([np.asarray(v, dtype=np.float64) for v in data.variables])
        estimate = {v.key: full[offsets[i]:offsets[i + 1]]
                    for i, v in enumerate(program.variables)}
        tau, records, status, reason, total_iterations = None, [], "converged", "", 0
        for j in range(len(clusters)):
            t0 = time.perf_counter()
            first = max(0, j - window)
            if j == 0:  # once, untimed: the arrays against the template's layout
                self._check_once(*self.assemble(estimate, 0, 0, None))
                t0 = time.perf_counter()
            x, d = self.assemble(estimate, first, j, tau)
            t1 = time.perf_counter()
            x_out, errors, info = self.solver.solve(x, d)
            t2 = time.perf_counter()
            if j == 0:
                initial_error = float(errors[0])
            pos = 0
            for v in self.template.variables:
                slot = self.cluster_of[v.key]
                if first + slot <= j:
                    key = clusters[first + slot][self.position[v.key]]
                    estimate[key][:] = x_out[pos:pos + v.storage_dim]
                pos += v.storage_dim
            t3 = time.perf_counter()
            if j >= window and j + 1 < len(clusters):  # keyframe j − W leaves: its marginal
                a, b = self.marginal(x_out, d)
                if np.min(np.diag(a)) <= 1e-12 * max(1.0, float(np.max(np.abs(a)))):
                    raise NativeStreamError(f"keyframe {first}: its marginal prior on keyframe "
                                            f"{first + 1} is singular")
                # the prior on keyframe first + 1 at x̄ = its estimate now: R = A, mean A⁻¹b
                tau = (a, np.linalg.solve(a, b), [estimate[k].copy()
                                                  for k in clusters[first + 1]])
            t4 = time.perf_counter()
            iterations, st, why = int(info[0]), STATUSES[int(info[1])], REASONS[int(info[2])]
            total_iterations += iterations
            oldest = max(0, j - window + 1)
            snapshot = [None] * len(program.variables)
            for c in range(oldest, j + 1):
                for k in clusters[c]:
                    snapshot[index[k]] = estimate[k].tolist()
            records.append({"keyframe": j, "mode": "fixed-lag", "first": first,
                            "iterations": iterations, "status": st, "reason": why,
                            "cost": float(errors[1]), "seconds": t4 - t0,
                            "solve_seconds": t2 - t1, "marginal_seconds": t4 - t3,
                            "values": snapshot})
            if progress is not None:
                progress(records[-1])
            if st != "converged" and status == "converged":
                status, reason = st, f"keyframe {j}: {why}"
        storage = {k: v.copy() for k, v in estimate.items()}
        return NativeStreamResult(values_from_storage(program, storage), storage, status,
                                  reason, total_iterations, records, initial_error,
                                  self.template)

