"""The host side of a stream on a compiled C-family template window, shared by the native solver
(:mod:`fgc_backends.native.streaming`) and the HLS design's host-kept C simulation
(:mod:`fgc_backends.hls.streaming`): the updates' loop, the marginalisation and the kept Bayes net
in NumPy (or in the compiled library's host kernels), the estimate and the records.

The semantics are the simulator's (``solve_fixed_lag`` / ``solve_incremental`` in the emitted
simulator's incremental module). The template window and how each update fills it are the
middle end's (:mod:`fgc.compiler.stream`); what runs the window's LM solve is a *compiled
solver* handed in by the backend (``load(template)``: an object with ``solve``, ``rows``,
``row_layout``, ``flatten``, ``project.config`` and, for the compiled host kernels,
``library`` — the native library's :class:`~fgc_backends.native.solver.NativeSolver`).

Fixed-lag (:class:`FixedLagDriver`): on arrival of keyframe j the window j − W … j is optimised
from the current estimates; then the oldest keyframe is eliminated from the window's
linearisation at the optimum (the solver's whitened rows, marginal prior included, one QR of
the rows × two keyframes matrix of the factors on it), and the factor it passes to the next
keyframe — the Schur complement of its conditional, a dense Gaussian prior — enters the next
window, linear in the local coordinates at the point where it was formed. Its time is reported
beside the solve's (``marginal_seconds``; ``seconds`` is the whole update: data assembly, the
solve and the marginalisation).

Incremental (:class:`IncrementalDriver`): the kept Bayes net, as its docstring says.
"""

from __future__ import annotations

import ctypes
import time
from dataclasses import dataclass, field

import numpy as np

from fgc.compiler.kernel import numeric_function
from fgc.compiler.stream import WindowTemplate, slot_layout
from fgc.frontend.dsl import Graph
from fgc.frontend.geometry.base import VectorSpace
from fgc.interop.estimates import values_from_storage
from fgc.ir.codes import REASONS, STATUSES
from fgc.ir.datafile import ProblemData
from fgc.ir.program import Program
from fgc.ir.stream import FixedLag, Incremental, StreamError
from fgc_backends.cfamily.retract import local_kernel, retract_kernel
from fgc_backends.cfamily.tables import factor_data_words


@dataclass
class StreamResult:
    """A stream on compiled template windows (native solver, HLS C simulation): the final
    estimate (every variable where the last update that held it left it), per-update records
    as the simulator's (``keyframe``, ``mode``, ``first``, ``iterations``, ``status``,
    ``reason``, ``cost``, ``seconds``, ``values``: per Program variable its storage, None where
    the update holds none; a list per variable in the fixed-lag stream, a tuple in the
    incremental one, :class:`IncrementalDriver`) plus ``solve_seconds`` (the compiled solve)
    and ``marginal_seconds`` (fixed-lag) or ``store_seconds`` (incremental)."""

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


@dataclass
class KeptNet:
    """The kept Bayes net of an incremental stream, keyframe-major: conditional c is
    R_c·δ_c + S_c·δ_c+1 = d_c (``r``, ``s``: n × n each; ``d``), linearised at ``lin`` [c] with
    its parent at ``lin_next`` [c]; ``x`` the estimate (one keyframe's storage a row);
    ``count``: how many conditionals the last back-substitution walked (its window's first)."""

    count: int
    r: np.ndarray
    s: np.ndarray
    d: np.ndarray
    lin: np.ndarray
    lin_next: np.ndarray
    x: np.ndarray


class TemplateSolver(WindowTemplate):
    """A :class:`~fgc.compiler.stream.WindowTemplate` of ``size`` keyframes with the solver
    ``load(template)`` compiles for it (module docstring); :meth:`eliminate` eliminates the
    window from the solver's rows at a point."""

    def __init__(self, graph: Graph, program: Program, size: int, load):
        super().__init__(graph, program, size)
        self.solver = load(self.template)
        self.config = self.solver.project.config
        self._row_plan()

    def _row_plan(self) -> None:
        """Where each template factor's rows lie in the solver's linearisation
        (:meth:`NativeSolver.rows`), by the oldest slot it touches, and which columns of the
        (that slot, the next) matrix its variables' tangent columns are."""
        t = self.template
        dims = {v.key: v.dim for v in t.variables}
        within, self.slot_dims = {}, [0] * self.size
        for v in t.variables:
            slot = self.cluster_of[v.key]
            within[v.key] = self.slot_dims[slot]
            self.slot_dims[slot] += dims[v.key]
        layout = self.solver.row_layout()
        seen = [0] * len(t.blocks)
        self.by_slot = [[] for _ in range(self.size)]  # (first word, m, columns, targets, keys)
        for spec in t.factors:
            k = seen[spec.block]
            seen[spec.block] += 1
            slots = [self.cluster_of[key] for key in spec.keys]
            lo = min(slots)
            pos, _, m, cols = layout[spec.block]
            targets = np.concatenate([within[key] + (self.slot_dims[lo] if slot > lo else 0)
                                      + np.arange(dims[key])
                                      for key, slot in zip(spec.keys, slots, strict=True)])
            self.by_slot[lo].append((pos + k * m * cols, m, cols, targets, max(slots),
                                     spec.keys))

    def eliminate(self, x: np.ndarray, d: np.ndarray, count: int,
                  pass_last: bool = False) -> tuple[list, list]:
        """Eliminate slots 0 … count − 1, oldest first, from the solver's rows at ``x`` (its
        factors and its marginal priors, undamped, one QR per slot): per slot its conditional
        (R, S, d) — R·δ_s + S·δ_s+1 = d, S empty for the last slot unless ``pass_last`` — and
        the dense factor [A | b] it passes to the next slot (None for the last slot unless
        ``pass_last``). Factors from the last slot into the next one are left out unless
        ``pass_last`` (past the window they carry zero square-root information)."""
        rows = self.solver.rows(x, d)
        conds, passed, carry = [], [], None
        for s in range(count):
            last = s == count - 1
            n0 = self.slot_dims[s]
            n1 = self.slot_dims[s + 1] if s + 1 < self.size and (pass_last or not last) else 0
            width = n0 + n1
            stacks = []
            if carry is not None:
                part = np.zeros((carry.shape[0], width + 1))
                part[:, :n0], part[:, -1] = carry[:, :-1], carry[:, -1]
                stacks.append(part)
            for start, m, cols, targets, hi, keys in self.by_slot[s]:
                if hi > s + 1:
                    raise StreamError(f"a factor on {list(keys)} spans keyframes {s} to "
                                      f"{hi} of the window: a template window "
                                      "eliminates factors between consecutive keyframes "
                                      "only")
                if hi > s and n1 == 0:
                    continue
                block = rows[start:start + m * cols].reshape(m, cols)
                part = np.zeros((m, width + 1))
                part[:, targets] = block[:, :-1]
                part[:, -1] = block[:, -1]
                stacks.append(part)
            stacked = np.concatenate(stacks)
            if stacked.shape[0] < n0:
                raise StreamError(f"window slot {s}: {stacked.shape[0]} rows cannot "
                                  f"determine its {n0} columns")
            r = np.linalg.qr(stacked, mode="r")
            conds.append((r[:n0, :n0], r[:n0, n0:width], r[:n0, -1]))
            carry = r[n0:width, n0:] if n1 else None
            passed.append(carry)
        return conds, passed

    def marginal(self, x: np.ndarray, d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Eliminate slot 0 from the window's linearisation at ``x`` (the solver's own rows: its
        factors and its marginal prior): the dense factor [A | b] it passes to slot 1, A upper
        triangular with a positive diagonal."""
        _, passed = self.eliminate(x, d, 1, pass_last=True)
        return as_prior(passed[0], self.slot_dims[1], "slot 0")[:2]

    def _check_once(self, x, d) -> None:
        """The first update's arrays against the template's layout (sizes, per-block words)."""
        t = self.template
        sizes, pos = [], 0
        for spec in t.factors:
            n = factor_data_words(t, spec.block)
            sizes.append(d[pos:pos + n])
            pos += n
        variables, pos = [], 0
        for v in t.variables:
            variables.append(x[pos:pos + v.storage_dim])
            pos += v.storage_dim
        self.solver.flatten(ProblemData(tuple(variables), tuple(sizes), t.structure_fingerprint))

    # -- one window solve ---------------------------------------------------------------------
    def solve(self, x: np.ndarray, d: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The window's LM solve on the template's flat arrays: (x, errors, info) as
        :meth:`NativeSolver.solve` returns them (the native library; a subclass may run
        another build of the same template)."""
        return self.solver.solve(x, d)


def as_prior(rows: np.ndarray, n: int, what: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A passed factor [A | b] on a keyframe of tangent dimension ``n`` as a marginal prior:
    (R, b, mean) with R = A row-signed to a positive diagonal (the cost ½‖A·s − b‖² is
    unchanged) and mean = R⁻¹b; :class:`StreamError` if it does not determine all n
    directions."""
    if rows is None or rows.shape[0] < n:
        have = 0 if rows is None else rows.shape[0]
        raise StreamError(f"{what}: {have} rows cannot determine the {n} columns of the "
                          "factor it passes to the next keyframe")
    a, b = rows[:n, :-1], rows[:n, -1]
    signs = np.where(np.diag(a) < 0, -1.0, 1.0)
    a, b = a * signs[:, None], b * signs
    if np.min(np.diag(a)) <= 1e-12 * max(1.0, float(np.max(np.abs(a)))):
        raise StreamError(f"{what}: the marginal prior it passes to the next keyframe is "
                          "singular")
    return a, b, np.linalg.solve(a, b)


class _ClusterGeometry:
    """Retraction x̄ ∘ Exp(δ) and local coordinates Log(x̄⁻¹x) of one keyframe's variables on
    their stacked storage, in NumPy: the sympy-derived kernels the simulator prints
    (:func:`fgc_backends.cfamily.retract.retract_kernel` and ``local_kernel``) compiled to
    Python, vector spaces as plain sums."""

    def __init__(self, types):
        self.parts, s, t = [], 0, 0
        for cls in types:
            flat = issubclass(cls, VectorSpace) and cls.storage_dim == cls.dim
            fns = None if flat else (numeric_function(retract_kernel(cls)),
                                     numeric_function(local_kernel(cls)))
            self.parts.append((fns, slice(s, s + cls.storage_dim), slice(t, t + cls.dim)))
            s, t = s + cls.storage_dim, t + cls.dim
        self.dim = t

    def local(self, lin: np.ndarray, x: np.ndarray) -> np.ndarray:
        out = np.empty(self.dim)
        for fns, sp, tp in self.parts:
            out[tp] = x[sp] - lin[sp] if fns is None else fns[1](*lin[sp], *x[sp])
        return out

    def retract(self, lin: np.ndarray, delta: np.ndarray) -> np.ndarray:
        out = np.empty(lin.size)
        for fns, sp, tp in self.parts:
            out[sp] = lin[sp] + delta[tp] if fns is None else fns[0](*lin[sp], *delta[tp])
        return out

    def local_jacobian(self, lin: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Log(x̄⁻¹x) and its derivative along x ∘ Exp(δ) (block diagonal), by central
        differences as the simulator forms it (``Chain.local_jacobian``)."""
        h = np.sqrt(np.finfo(np.float64).eps) * 10
        jac = np.zeros((self.dim, self.dim))
        for fns, sp, tp in self.parts:
            if fns is None:
                jac[tp, tp] = np.eye(tp.stop - tp.start)
                continue
            for i in range(tp.stop - tp.start):
                step = np.zeros(tp.stop - tp.start)
                step[i] = h
                plus = fns[1](*lin[sp], *fns[0](*x[sp], *step))
                minus = fns[1](*lin[sp], *fns[0](*x[sp], *(-step)))
                jac[tp, tp.start + i] = (np.asarray(plus) - np.asarray(minus)) / (2 * h)
        return self.local(lin, x), jac


class _CompiledGeometry:
    """The incremental stream's per-update host arithmetic in a native library (a double build:
    ``fgc_kept_walk`` and ``fgc_local_jacobian``, emitted beside the solver from the same
    retraction and Log kernels its factors use): the back-substitution through every kept
    conditional in one call on contiguous arrays, and the re-expression's Log and its
    central-difference Jacobian. :meth:`of` is None for a library without them (a float or
    fixed-point build): the stream then runs :class:`_ClusterGeometry` in Python."""

    def __init__(self, library, kinds: np.ndarray, n: int, m: int):
        self.kinds, self.n, self.m = kinds, n, m
        self._kinds = kinds.__array_interface__["data"][0]
        self._walk, self._jacobian = library.fgc_kept_walk, library.fgc_local_jacobian
        self._walk.argtypes = [ctypes.c_int] * 2 + [ctypes.c_void_p] + [ctypes.c_int] * 2 + [
            ctypes.c_void_p] * 6
        self._walk.restype = ctypes.c_int
        self._jacobian.argtypes = [ctypes.c_int, ctypes.c_void_p, ctypes.c_int, ctypes.c_int] + [
            ctypes.c_void_p] * 4
        self._jacobian.restype = ctypes.c_int
        self._local, self._jac = np.empty(n), np.empty((n, n))

    @classmethod
    def of(cls, window: TemplateSolver, geometry: _ClusterGeometry) -> _CompiledGeometry | None:
        """The compiled host kernels of ``window``'s native library for its keyframes (kinds by
        the library's retraction order: first appearance of each type in the template)."""
        library = getattr(getattr(window, "solver", None), "library", None)
        if not (hasattr(library, "fgc_kept_walk") and hasattr(library, "fgc_local_jacobian")):
            return None
        order: dict[str, int] = {}
        for v in window.template.variables:
            order.setdefault(v.type_name, len(order))
        by_key = {v.key: v for v in window.template.variables}
        keys = window.program.schedule.clusters[0]
        kinds = np.array([order[by_key[k].type_name] for k in keys], dtype=np.int32)
        m = sum(by_key[k].storage_dim for k in keys)
        return cls(library, kinds, geometry.dim, m)

    def local_jacobian(self, lin: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """As :meth:`_ClusterGeometry.local_jacobian` (the same central differences), compiled."""
        lin, x = np.ascontiguousarray(lin), np.ascontiguousarray(x)
        if self._jacobian(len(self.kinds), self._kinds, self.n, self.m, _data(lin, self.m),
                          _data(x, self.m), _data(self._local, self.n),
                          _data(self._jac, self.n * self.n)):
            raise StreamError("internal error: the library's keyframe layout is not the "
                              "stream's")
        return self._local.copy(), self._jac.copy()

    def walk(self, count: int, r, s, d, lin, lin_next, x) -> None:
        """x_c = lin_c ⊕ R_c⁻¹(d_c − S_c·Log(lin_next_c⁻¹ x_c+1)) for c = count − 1 … 0, in place
        on ``x`` (keyframe-major storage; x_count is read): the arrays keyframe-major, C order."""
        n, m = self.n, self.m
        if count == 0:
            return
        if self._walk(count, len(self.kinds), self._kinds, n, m, _data(r, count * n * n),
                      _data(s, count * n * n), _data(d, count * n), _data(lin, count * m),
                      _data(lin_next, count * m), _data(x, (count + 1) * m)):
            raise StreamError("internal error: the library's keyframe layout is not the "
                              "stream's")


def _data(a: np.ndarray, at_least: int) -> int:
    """The address of float64 C-contiguous ``a`` holding at least ``at_least`` numbers."""
    if a.dtype != np.float64 or not a.flags.c_contiguous or a.size < at_least:
        raise StreamError(f"internal error: an array of {a.size} {a.dtype} numbers where "
                          f"{at_least} contiguous float64 are read")
    return a.__array_interface__["data"][0]


class StreamState:
    """What the two stream kinds share: the estimate, the records, the result."""

    def __init__(self, program: Program):
        self.program = program
        self.clusters = program.schedule.clusters
        self.index = {v.key: i for i, v in enumerate(program.variables)}

    def _start(self, data: ProblemData) -> dict:
        program = self.program
        offsets = np.concatenate([[0], np.cumsum([v.storage_dim for v in program.variables])])
        full = np.concatenate([np.asarray(v, dtype=np.float64) for v in data.variables])
        self._full = full
        return {v.key: full[offsets[i]:offsets[i + 1]] for i, v in enumerate(program.variables)}

    def _start_keyframes(self, data: ProblemData) -> tuple[dict, np.ndarray]:
        """As :meth:`_start`, the keyframes' variables held keyframe-major in one array (each
        keyframe's storage a row, its variables in cluster order; every keyframe of one
        layout): (estimate by key, views into that array; the array)."""
        estimate = self._start(data)
        first = self.clusters[0]
        sizes = [estimate[k].size for k in first]
        x_all = np.empty((len(self.clusters), sum(sizes)))
        offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(int)
        self._layout = [(int(offsets[p]), int(offsets[p + 1])) for p in range(len(first))]
        self._keyframe_index = []
        for c, keys in enumerate(self.clusters):
            if [estimate[k].size for k in keys] != sizes:
                raise StreamError(f"keyframe {c}'s variables are not laid out as keyframe "
                                  "0's")
            for p, k in enumerate(keys):
                x_all[c, offsets[p]:offsets[p + 1]] = estimate[k]
                estimate[k] = x_all[c, offsets[p]:offsets[p + 1]]
            self._keyframe_index.append([self.index[k] for k in keys])
        # per position in a keyframe: its variables' indices over the keyframes, as a slice
        # (start, step) when they are evenly spaced in the Program's order (the usual
        # keyframe-major order), else None
        self._spaced = []
        for p in range(len(first)):
            column = [row[p] for row in self._keyframe_index]
            step = column[1] - column[0] if len(column) > 1 else 1
            even = step > 0 and column == list(range(column[0], column[0] + step * len(column),
                                                     step))
            self._spaced.append((column[0], step) if even else None)
        return estimate, x_all

    def split_keyframe(self, row: np.ndarray, c: int) -> list:
        """Keyframe ``c``'s variables (cluster order) from its row of the keyframe-major array
        (:meth:`_start_keyframes`), copies."""
        return [row[a:b].copy() for a, b in self._layout[:len(self.clusters[c])]]

    def _snapshot_keyframes(self, x_all: np.ndarray, newest: int) -> list:
        """:meth:`_snapshot` of keyframes 0 … newest from the keyframe-major array, each
        variable's storage a tuple: per position in a keyframe, its column block converted at
        once and placed by a slice assignment (a loop where the Program's order is not evenly
        spaced). Tuples, not lists: tuples of floats leave the garbage collector's lists after
        its first pass, while the lists of every record kept (O(j²) of them over a stream) made
        its collections cost as much as the rest of the stream's host work."""
        snapshot = [None] * len(self.program.variables)
        count = newest + 1
        for p, ((a, b), spaced) in enumerate(zip(self._layout, self._spaced, strict=True)):
            values = list(zip(*x_all[:count, a:b].T.tolist(), strict=True))
            if spaced is not None:
                start, step = spaced
                snapshot[start:start + step * count:step] = values
            else:
                for row, value in zip(self._keyframe_index[:count], values, strict=True):
                    snapshot[row[p]] = value
        return snapshot

    def _snapshot(self, estimate: dict, oldest: int, newest: int) -> list:
        snapshot = [None] * len(self.program.variables)
        for c in range(oldest, newest + 1):
            for k in self.clusters[c]:
                snapshot[self.index[k]] = estimate[k].tolist()
        return snapshot

    @staticmethod
    def _info(info) -> tuple[int, str, str]:
        return int(info[0]), STATUSES[int(info[1])], REASONS[int(info[2])]

    def _result(self, estimate, records, initial_error, template) -> StreamResult:
        status, reason = "converged", ""
        for r in records:
            if r["status"] != "converged":
                status, reason = r["status"], f"keyframe {r['keyframe']}: {r['reason']}"
                break
        storage = {k: v.copy() for k, v in estimate.items()}
        return StreamResult(values_from_storage(self.program, storage), storage, status,
                                  reason, sum(r["iterations"] for r in records), records,
                                  initial_error, template)


class FixedLagDriver(TemplateSolver):
    """A solver compiled (``load``) for a fixed-lag window of ``window`` keyframes over the chain
    ``program`` (compiled from ``graph``): a template of W + 1 keyframes; :meth:`run` streams
    ``data``."""

    def __init__(self, graph: Graph, program: Program, window: int, load):
        if isinstance(window, bool) or not isinstance(window, int) or window < 1:
            raise StreamError(f"the fixed-lag window must be a positive number of "
                              f"keyframes, got {window!r}")
        slot_layout(graph, program, FixedLag(window)).check("a template window", StreamError)
        super().__init__(graph, program, window + 1, load)
        self.window = window

    def run(self, data: ProblemData, progress=None) -> StreamResult:
        window, stream = self.window, StreamState(self.program)
        clusters = stream.clusters
        estimate = stream._start(data)
        tau, records, initial_error = None, [], None
        for j in range(len(clusters)):
            t0 = time.perf_counter()
            first = max(0, j - window)
            if j == 0:  # once, untimed: the arrays against the template's layout
                self._check_once(*self.assemble(estimate, 0, 0, None))
                t0 = time.perf_counter()
            x, d = self.assemble(estimate, first, j, tau)
            t1 = time.perf_counter()
            x_out, errors, info = self.solve(x, d)
            t2 = time.perf_counter()
            if j == 0:
                initial_error = float(errors[0])
            # one-step policy: the marginal from the update's own linearisation point
            at, lin_point = x_out, None
            if self.program.solver.one_step and j >= window and j + 1 < len(clusters):
                at = x
                lin_point = [estimate[k].copy() for k in clusters[first + 1]]
            self.store(estimate, x_out, first, j)
            t3 = time.perf_counter()
            if j >= window and j + 1 < len(clusters):  # keyframe j − W leaves: its marginal
                _, passed = self.eliminate(at, d, 1, pass_last=True)
                a, _, mean = as_prior(passed[0], self.slot_dims[1], f"keyframe {first}")
                # the prior on keyframe first + 1 at x̄ = its estimate now (one-step: where
                # the update linearised it): R = A, mean A⁻¹b
                tau = (a, mean, lin_point if lin_point is not None
                       else [estimate[k].copy() for k in clusters[first + 1]])
            t4 = time.perf_counter()
            iterations, st, why = stream._info(info)
            records.append({"keyframe": j, "mode": "fixed-lag", "first": first,
                            "iterations": iterations, "status": st, "reason": why,
                            "cost": float(errors[1]), "seconds": t4 - t0,
                            "solve_seconds": t2 - t1, "marginal_seconds": t4 - t3,
                            "values": stream._snapshot(estimate, max(0, j - window + 1), j)})
            if progress is not None:
                progress(records[-1])
        return stream._result(estimate, records, initial_error, self.template)


class IncrementalDriver:
    """Compiled template windows running the simulator's incremental plan (``solve_incremental``:
    paper A's re-elimination of the newest K clusters on the kept Bayes net, batch steps
    re-eliminating every cluster). One :class:`TemplateSolver` per template size: the largest
    incremental window (K, or more when a factor reaches further back) serves every
    incremental update, held slots padding the first ones; each batch step larger than that
    has its own template of its keyframes, compiled once per distinct size
    (``progress_build(size, index, count)`` before each). ``window_solver(size)`` makes the
    window solvers (:class:`TemplateSolver`: the native solver's, or the HLS C simulation's).

    Per update, after the window's solve: the newest kept conditional is re-expressed at its
    parent's new estimate (Log and its central-difference Jacobian), the window is eliminated
    at its optimum (NumPy QR on the library's rows, O(window)), and every kept conditional is
    back-substituted, c = first − 1 … 0. The kept Bayes net and the estimate live in
    keyframe-major arrays (:class:`KeptNet`, ``self.kept`` after :meth:`run`), so the
    re-expression and the whole back-substitution are one library call each
    (:class:`_CompiledGeometry`: a double build's ``fgc_local_jacobian`` and ``fgc_kept_walk``).
    ``host="python"`` runs the same formulas in NumPy (:class:`_ClusterGeometry`, the path
    before they were compiled), as does a library without them (a float or fixed-point
    build)."""

    def __init__(self, graph: Graph, program: Program, window_solver, progress_build=None,
                 host: str = "native"):
        plan = program.schedule.incremental
        if plan is None:
            raise StreamError("the Program has no incremental plan (--incremental K)")
        if program.schedule.structure_class != "chain" or not program.schedule.clusters:
            raise StreamError("streaming on a template window needs a chain of keyframes")
        self.graph, self.program, self.plan = graph, program, plan
        slots = slot_layout(graph, program, Incremental(program.solver.incremental_k,
                                                        program.solver.batch_every))
        slots.check("a template window", StreamError)
        self.updates = [(u.keyframe, u.batch, u.first) for u in slots.updates]
        sizes = list(slots.sizes)
        make = window_solver
        self.solvers = {}
        for i, size in enumerate(sizes):
            if progress_build is not None:
                progress_build(size, i, len(sizes))
            self.solvers[size] = make(size)
        self.sizes = sizes
        types = self.solvers[sizes[0]].types
        self.geometry = _ClusterGeometry(types[0])
        # the kept back-substitution and the re-expression's Jacobian: compiled (a double
        # library) unless host="python" (the reference formulas in NumPy, as before)
        if host not in ("native", "python"):
            raise StreamError(f"host must be 'native' or 'python', got {host!r}")
        self.compiled = (None if host == "python"
                         else _CompiledGeometry.of(self.solvers[sizes[0]], self.geometry))

    def solver_for(self, size: int) -> TemplateSolver:
        """The smallest compiled template that holds a window of ``size`` keyframes."""
        return self.solvers[next(s for s in self.sizes if s >= size)]

    def run(self, data: ProblemData, progress=None) -> StreamResult:
        stream, geometry, compiled = StreamState(self.program), self.geometry, self.compiled
        estimate, x_all = stream._start_keyframes(data)
        count, n = len(stream.clusters), geometry.dim
        # the kept Bayes net, keyframe-major: conditional c is R_c·δ_c + S_c·δ_c+1 = d_c,
        # linearised at lin_c with its parent at lin_next_c (complete: S_c spans the parent)
        kept_r, kept_s = np.zeros((count, n, n)), np.zeros((count, n, n))
        kept_d = np.zeros((count, n))
        kept_lin, kept_next = np.zeros_like(x_all), np.zeros_like(x_all)
        complete = np.zeros(count, dtype=bool)
        local_jacobian = (geometry if compiled is None else compiled).local_jacobian
        taus, records, initial_error = {}, [], None
        for n_update, (j, batch, first) in enumerate(self.updates):
            win = self.solver_for(j - first + 1)
            if n_update == 0:  # once, untimed: the arrays against each template's layout
                for w in self.solvers.values():
                    w._check_once(*w.assemble(estimate, 0, 0, None))
            t0 = time.perf_counter()
            prior = None
            if first > 0:
                rows, lin = taus[first]
                a, _, mean = as_prior(rows, win.slot_dims[0], f"keyframe {first - 1}")
                prior = (a, mean, lin)
            x, d = win.assemble(estimate, first, j, prior)
            t1 = time.perf_counter()
            x_out, errors, info = win.solve(x, d)
            t2 = time.perf_counter()
            if n_update == 0:
                initial_error = float(errors[0])
            # one-step policy: the store at the update's own linearisation point (its start)
            at, lin_all = x_out, x_all
            if self.program.solver.one_step:
                at, lin_all = x, x_all.copy()
            win.store(estimate, x_out, first, j)
            if first > 0:  # the newest kept conditional, re-expressed at its parent's estimate
                c = first - 1
                if not complete[c]:
                    raise StreamError(f"keyframe {c}: its kept conditional does not reach "
                                      f"keyframe {first}")
                shift, jac = local_jacobian(kept_next[c], x_all[first])
                kept_d[c] -= kept_s[c] @ shift
                kept_s[c] = kept_s[c] @ jac
                kept_next[c] = x_all[first]
            window_conds, passed = win.eliminate(at, d, j - first + 1)
            for i, (r, s, dv) in enumerate(window_conds):
                c = first + i
                kept_r[c], kept_d[c], kept_lin[c] = r, dv, lin_all[c]
                complete[c] = c < j
                if c < j:
                    kept_s[c], kept_next[c] = s, lin_all[c + 1]
                    taus[c + 1] = (passed[i], stream.split_keyframe(lin_all[c + 1], c + 1))
            if first > 0 and not complete[:first].all():
                raise StreamError(f"keyframes 0 … {first - 1}: a kept conditional does not "
                                  "reach its parent")
            if compiled is not None:  # back-substitution through the kept part: one call
                compiled.walk(first, kept_r, kept_s, kept_d, kept_lin, kept_next, x_all)
            else:
                for c in range(first - 1, -1, -1):
                    rhs = kept_d[c] - kept_s[c] @ geometry.local(kept_next[c], x_all[c + 1])
                    x_all[c] = geometry.retract(kept_lin[c], np.linalg.solve(kept_r[c], rhs))
            t3 = time.perf_counter()
            iterations, st, why = stream._info(info)
            records.append({"keyframe": j, "mode": "batch" if batch else "incremental",
                            "first": first, "iterations": iterations, "status": st,
                            "reason": why, "cost": float(errors[1]), "seconds": t3 - t0,
                            "solve_seconds": t2 - t1, "store_seconds": t3 - t2,
                            "window_keyframes": win.size,
                            "values": stream._snapshot_keyframes(x_all, j)})
            if progress is not None:
                progress(records[-1])
        # the kept Bayes net as the last update left it (keyframes 0 … its first − 1 walked)
        self.kept = KeptNet(first, kept_r, kept_s, kept_d, kept_lin, kept_next, x_all)
        return stream._result(estimate, records, initial_error,
                              self.solvers[self.sizes[0]].template)
