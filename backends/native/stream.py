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
from dataclasses import dataclass, field, replace

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
    ``iterations``, ``status``, ``reason``, ``cost``, ``seconds``, ``values``: per Program
    variable its storage, None where the update holds none; a list per variable in the
    fixed-lag stream, a tuple in the incremental one, :class:`IncrementalStream`) plus
    ``solve_seconds`` (the native call) and ``marginal_seconds`` (fixed-lag) or
    ``store_seconds`` (incremental)."""

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


class WindowTemplate:
    """A *template* window of ``size`` keyframes of the chain ``program`` (compiled from
    ``graph``): the graph's first ``size`` keyframes with their factors and a ``MarginalPrior…``
    factor on every keyframe, compiled as a batch Program (the stream's solver options without
    an incremental plan; ``self.template``); :meth:`assemble` fills it with the numbers of any
    window of at most ``size`` keyframes. No solver: :class:`WindowSolver` adds the native one,
    the HLS backend's on-chip window (:mod:`fgc_backends.hls.window`) its own."""

    def __init__(self, graph: Graph, program: Program, size: int, ordering: str | None = None):
        from fgc.compile import compile_graph

        if program.schedule.structure_class != "chain" or not program.schedule.clusters:
            raise NativeStreamError("native streaming needs a chain of keyframes")
        self.graph, self.program = graph, program
        clusters = program.schedule.clusters
        self.size = size = min(size, len(clusters))
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
        solver = replace(program.solver, incremental_k=None, batch_every=None)
        if ordering is not None:
            solver = replace(solver, ordering=ordering)
        kind = "window" if ordering is None else ordering
        self.template = compile_graph(template, solver, name=f"{program.name}_{kind}{size}",
                                      local_frame=False)  # window data are world coordinates
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
        self._check_prior_layout()

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

    def store(self, estimate: dict, x_out: np.ndarray, first: int, last: int) -> None:
        """Write the window's optimum ``x_out`` (template layout) into ``estimate`` for the
        keyframes first … last (slots past ``last`` are held: not written)."""
        clusters = self.program.schedule.clusters
        pos = 0
        for v in self.template.variables:
            slot = self.cluster_of[v.key]
            if first + slot <= last:
                key = clusters[first + slot][self.position[v.key]]
                estimate[key][:] = x_out[pos:pos + v.storage_dim]
            pos += v.storage_dim


class WindowSolver(WindowTemplate):
    """The native solver compiled for a :class:`WindowTemplate` of ``size`` keyframes;
    :meth:`eliminate` eliminates the window from the solver's rows at a point (module
    docstring)."""

    def __init__(self, graph: Graph, program: Program, size: int, config=None):
        from fgc_backends import native

        super().__init__(graph, program, size)
        self.solver = native.load(self.template, config)
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
                    raise NativeStreamError(f"a factor on {list(keys)} spans keyframes {s} to "
                                            f"{hi} of the window: native streaming eliminates "
                                            "factors between consecutive keyframes only")
                if hi > s and n1 == 0:
                    continue
                block = rows[start:start + m * cols].reshape(m, cols)
                part = np.zeros((m, width + 1))
                part[:, targets] = block[:, :-1]
                part[:, -1] = block[:, -1]
                stacks.append(part)
            stacked = np.concatenate(stacks)
            if stacked.shape[0] < n0:
                raise NativeStreamError(f"window slot {s}: {stacked.shape[0]} rows cannot "
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
            from fgc_backends.cfamily.tables import factor_data_words
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
    unchanged) and mean = R⁻¹b; :class:`NativeStreamError` if it does not determine all n
    directions."""
    if rows is None or rows.shape[0] < n:
        have = 0 if rows is None else rows.shape[0]
        raise NativeStreamError(f"{what}: {have} rows cannot determine the {n} columns of the "
                                "factor it passes to the next keyframe")
    a, b = rows[:n, :-1], rows[:n, -1]
    signs = np.where(np.diag(a) < 0, -1.0, 1.0)
    a, b = a * signs[:, None], b * signs
    if np.min(np.diag(a)) <= 1e-12 * max(1.0, float(np.max(np.abs(a)))):
        raise NativeStreamError(f"{what}: the marginal prior it passes to the next keyframe is "
                                "singular")
    return a, b, np.linalg.solve(a, b)


class _ClusterGeometry:
    """Retraction x̄ ∘ Exp(δ) and local coordinates Log(x̄⁻¹x) of one keyframe's variables on
    their stacked storage, in NumPy: the sympy-derived kernels the simulator prints
    (:func:`fgc_backends.cfamily.retract.retract_kernel`, :func:`fgc_backends.sim.types.
    local_kernel`) compiled to Python, vector spaces as plain sums."""

    def __init__(self, types):
        from fgc.compiler.kernel import numeric_function
        from fgc.frontend.geometry.base import VectorSpace
        from fgc_backends.cfamily.retract import retract_kernel
        from fgc_backends.sim.types import local_kernel

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
        import ctypes

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
    def of(cls, window: WindowSolver, geometry: _ClusterGeometry) -> _CompiledGeometry | None:
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
            raise NativeStreamError("internal error: the library's keyframe layout is not the "
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
            raise NativeStreamError("internal error: the library's keyframe layout is not the "
                                    "stream's")


def _data(a: np.ndarray, at_least: int) -> int:
    """The address of float64 C-contiguous ``a`` holding at least ``at_least`` numbers."""
    if a.dtype != np.float64 or not a.flags.c_contiguous or a.size < at_least:
        raise NativeStreamError(f"internal error: an array of {a.size} {a.dtype} numbers where "
                                f"{at_least} contiguous float64 are read")
    return a.__array_interface__["data"][0]


class _Stream:
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
                raise NativeStreamError(f"keyframe {c}'s variables are not laid out as keyframe "
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
        from fgc_backends.cfamily.results import REASONS, STATUSES

        return int(info[0]), STATUSES[int(info[1])], REASONS[int(info[2])]

    def _result(self, estimate, records, initial_error, template) -> NativeStreamResult:
        from fgc.interop.estimates import values_from_storage

        status, reason = "converged", ""
        for r in records:
            if r["status"] != "converged":
                status, reason = r["status"], f"keyframe {r['keyframe']}: {r['reason']}"
                break
        storage = {k: v.copy() for k, v in estimate.items()}
        return NativeStreamResult(values_from_storage(self.program, storage), storage, status,
                                  reason, sum(r["iterations"] for r in records), records,
                                  initial_error, template)


class FixedLagStream(WindowSolver):
    """The native solver compiled for a fixed-lag window of ``window`` keyframes over the chain
    ``program`` (compiled from ``graph``): a template of W + 1 keyframes; :meth:`run` streams
    ``data``."""

    def __init__(self, graph: Graph, program: Program, window: int, config=None):
        if isinstance(window, bool) or not isinstance(window, int) or window < 1:
            raise NativeStreamError(f"the fixed-lag window must be a positive number of "
                                    f"keyframes, got {window!r}")
        super().__init__(graph, program, window + 1, config)
        self.window = window

    def run(self, data: ProblemData, progress=None) -> NativeStreamResult:
        window, stream = self.window, _Stream(self.program)
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
            self.store(estimate, x_out, first, j)
            t3 = time.perf_counter()
            if j >= window and j + 1 < len(clusters):  # keyframe j − W leaves: its marginal
                _, passed = self.eliminate(x_out, d, 1, pass_last=True)
                a, _, mean = as_prior(passed[0], self.slot_dims[1], f"keyframe {first}")
                # the prior on keyframe first + 1 at x̄ = its estimate now: R = A, mean A⁻¹b
                tau = (a, mean, [estimate[k].copy() for k in clusters[first + 1]])
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


class IncrementalStream:
    """The native solver running the simulator's incremental plan (``solve_incremental``:
    paper A's re-elimination of the newest K clusters on the kept Bayes net, batch steps
    re-eliminating every cluster). One :class:`WindowSolver` per template size: the largest
    incremental window (K, or more when a factor reaches further back) serves every
    incremental update, held slots padding the first ones; each batch step larger than that
    has its own template of its keyframes, compiled once per distinct size
    (``progress_build(size, index, count)`` before each). ``window_solver`` makes the window
    solvers (default :class:`WindowSolver`; the HLS C simulation passes its own).

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

    def __init__(self, graph: Graph, program: Program, config=None, progress_build=None,
                 window_solver=None, host: str = "native"):
        plan = program.schedule.incremental
        if plan is None:
            raise NativeStreamError("the Program has no incremental plan (--incremental K)")
        if program.schedule.structure_class != "chain" or not program.schedule.clusters:
            raise NativeStreamError("native streaming needs a chain of keyframes")
        self.graph, self.program, self.plan = graph, program, plan
        clusters = program.schedule.clusters
        cluster_of = {k: c for c, keys in enumerate(clusters) for k in keys}
        spans = [[cluster_of[str(k)] for k in f.keys] for f in graph.factors]
        self.updates = []  # (keyframe, batch, first)
        for u in plan.updates:
            early = [min(s) for s in spans if max(s) == u.keyframe]
            self.updates.append((u.keyframe, u.mode == "batch",
                                 min([u.clusters[0], *early])))
        steady = max([j - first + 1 for j, batch, first in self.updates if not batch],
                     default=1)
        sizes = sorted({steady} | {j - first + 1 for j, batch, first in self.updates
                                   if batch and j - first + 1 > steady})
        make = window_solver or (lambda size: WindowSolver(graph, program, size, config))
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
            raise NativeStreamError(f"host must be 'native' or 'python', got {host!r}")
        self.compiled = (None if host == "python"
                         else _CompiledGeometry.of(self.solvers[sizes[0]], self.geometry))

    def solver_for(self, size: int) -> WindowSolver:
        """The smallest compiled template that holds a window of ``size`` keyframes."""
        return self.solvers[next(s for s in self.sizes if s >= size)]

    def run(self, data: ProblemData, progress=None) -> NativeStreamResult:
        stream, geometry, compiled = _Stream(self.program), self.geometry, self.compiled
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
            win.store(estimate, x_out, first, j)
            if first > 0:  # the newest kept conditional, re-expressed at its parent's estimate
                c = first - 1
                if not complete[c]:
                    raise NativeStreamError(f"keyframe {c}: its kept conditional does not reach "
                                            f"keyframe {first}")
                shift, jac = local_jacobian(kept_next[c], x_all[first])
                kept_d[c] -= kept_s[c] @ shift
                kept_s[c] = kept_s[c] @ jac
                kept_next[c] = x_all[first]
            window_conds, passed = win.eliminate(x_out, d, j - first + 1)
            for i, (r, s, dv) in enumerate(window_conds):
                c = first + i
                kept_r[c], kept_d[c], kept_lin[c] = r, dv, x_all[c]
                complete[c] = c < j
                if c < j:
                    kept_s[c], kept_next[c] = s, x_all[c + 1]
                    taus[c + 1] = (passed[i], [estimate[k].copy() for k in stream.clusters[c + 1]])
            if first > 0 and not complete[:first].all():
                raise NativeStreamError(f"keyframes 0 … {first - 1}: a kept conditional does not "
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
