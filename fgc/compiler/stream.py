"""The stream stage of the middle end: a chain's Program, the policy that feeds it keyframe by
keyframe and the slot layout of its template windows (:class:`fgc.ir.stream.StreamProgram`),
behind ``fgc stream`` and every backend's ``stream`` (``fgc_backends.CONTRACT``).

A compiled backend (native, HLS) runs a stream on *template* windows (:class:`WindowTemplate`,
of the sizes :attr:`fgc.ir.stream.SlotLayout.sizes` lists; the simulator needs none, so a
backend compiles them when it starts): a batch Program of S keyframes — the chain's first S
with the factors of every window of S keyframes (the union over the stream, so a factor every
few keyframes has its slot), plus on every keyframe a ``MarginalPrior…`` factor
(:func:`marginal_prior_type`: r = Log(x̄⁻¹x) − m per variable, whitened by a full square-root
information R, so its cost is ½‖R·Log(x̄⁻¹x) − R·m‖², exactly the simulator's ½‖A·s − b‖² with
R = A, m = A⁻¹b). Each update fills that one structure with numbers:

- window slot i holds keyframe first + i; a template factor takes the numbers of the graph factor
  on the same slots (same factor type, same variables by position in their keyframes); a template
  factor without one (the first keyframe's priors once the window has moved on, a factor the
  stream has only every few keyframes) and a graph factor that reaches past the newest keyframe
  (during the first W updates) get a zero square-root information: they contribute nothing,
  neither cost nor Jacobian;
- the slot-0 prior carries the marginal (zero before any keyframe left); slots past the newest
  keyframe are not in the problem: their variables are held by a unit prior at their current
  value (zero residual, zero gradient: their step is exactly zero), decoupled from the window by
  the zero-weighted factors between them.

What no template window can run — keyframes of different kinds, a factor between
non-consecutive keyframes — is found here, from the graph's structure
(:attr:`fgc.ir.stream.SlotLayout.refusal`), so a backend refuses before it starts.
"""

from __future__ import annotations

import dataclasses
import inspect
from dataclasses import replace

import numpy as np

from fgc.compile import compile_graph
from fgc.errors import FgcError
from fgc.frontend.dsl import FactorType, Graph, Matrix
from fgc.frontend.noise import NoiseModel
from fgc.ir.datafile import factor_words
from fgc.ir.program import Program, SolverConfig
from fgc.ir.stream import (
    FixedLag,
    Incremental,
    Policy,
    SlotLayout,
    StreamError,
    StreamProgram,
    Update,
)

_PRIOR_TYPES: dict[tuple[type, ...], FactorType] = {}


def check_mode(incremental: int | None, batch_every, window: int | None) -> None:
    """The command line's stream options (``--incremental``, ``--batch-every``, ``--window``)."""
    if window is not None and (incremental is not None or batch_every is not None):
        raise FgcError("--window (a fixed-lag window) excludes --incremental/--batch-every")
    if batch_every is not None and incremental is None:
        raise FgcError("--batch-every needs --incremental K: batch steps belong to an "
                       "incremental plan")
    if window is not None and window < 1:
        raise FgcError(f"--window {window}: the window must hold at least 1 keyframe")


def policy_of(incremental: int | None = None, batch_every=None,
              window: int | None = None) -> Policy | None:
    """The policy the options ask for (None: neither)."""
    check_mode(incremental, batch_every, window)
    if window is not None:
        return FixedLag(window)
    if incremental is not None:
        return Incremental(incremental, batch_every)
    return None


def compile_chain(graph: Graph, solver: SolverConfig | None = None,
                  policy: Policy | None = None, name: str = "stream") -> Program:
    """The chain Program of a stream: ``solver`` (default float64) with an :class:`Incremental`
    policy's plan. FgcError when the graph is not a chain."""
    solver = solver or SolverConfig(precision="float64")
    if isinstance(policy, Incremental):
        solver = replace(solver, incremental_k=policy.k, batch_every=policy.batch_every)
    try:
        # no local frame (fgc.ir.frame): the streaming paths assemble window data in world
        # coordinates from the estimates they keep
        program = compile_graph(graph, solver, name=name, local_frame=False)
    except ValueError as exc:  # the incremental plan's own checks (window, batch steps)
        raise FgcError(f"incremental plan: {exc}") from None
    if program.schedule.structure_class != "chain" or not program.schedule.clusters:
        raise FgcError(f"streaming needs a chain of keyframes; the graph is "
                       f"{program.schedule.structure_class}")
    return program


def compile_stream(graph: Graph, solver: SolverConfig | None = None,
                   policy: Policy | None = None, name: str = "stream") -> StreamProgram:
    """The stream stage: the chain Program (:func:`compile_chain`) with its policy and slot
    layout."""
    if policy is None:
        raise FgcError("streaming needs --incremental K or --window W")
    return stream_program(graph, compile_chain(graph, solver, policy, name), policy)


def stream_program(graph: Graph | None, program: Program, policy: Policy | int | None = None
                   ) -> StreamProgram:
    """The StreamProgram of an already compiled chain ``program`` (from ``graph``): ``policy``
    a policy, a fixed-lag window W, or None for the Program's own incremental plan. Without the
    ``graph`` only the simulator can run it (the template windows are filled from the graph's
    numbers)."""
    plan = program.schedule.incremental
    if policy is None or isinstance(policy, Incremental):
        if plan is None:
            raise FgcError("streaming needs --incremental K or --window W")
        policy = Incremental(program.solver.incremental_k, program.solver.batch_every)
    elif not isinstance(policy, FixedLag):
        policy = FixedLag(policy)
    if program.schedule.structure_class != "chain" or not program.schedule.clusters:
        raise FgcError(f"streaming needs a chain of keyframes; the graph is "
                       f"{program.schedule.structure_class}")
    return StreamProgram(program, policy, graph, slot_layout(graph, program, policy))


def slot_layout(graph: Graph | None, program: Program, policy: Policy) -> SlotLayout:
    """The backend-independent slot facts of ``program``'s stream (:class:`SlotLayout`)."""
    clusters = tuple(tuple(c) for c in program.schedule.clusters)
    cluster_of = {k: c for c, keys in enumerate(clusters) for k in keys}
    position = {k: p for keys in clusters for p, k in enumerate(keys)}
    factors = graph.factors if graph is not None else ()
    spans = tuple((min(s), max(s)) for s in ([cluster_of[str(k)] for k in f.keys]
                                             for f in factors))
    n = len(clusters)
    if isinstance(policy, FixedLag):
        w = policy.window
        updates = tuple(Update(j, False, max(0, j - w)) for j in range(n))
        sizes = (min(w + 1, n),)
    else:
        updates = []
        for u in program.schedule.incremental.updates:
            early = [lo for lo, hi in spans if hi == u.keyframe]
            updates.append(Update(u.keyframe, u.mode == "batch", min([u.clusters[0], *early])))
        updates = tuple(updates)
        steady = max([u.size for u in updates if not u.batch], default=1)
        sizes = tuple(sorted({steady} | {u.size for u in updates
                                         if u.batch and u.size > steady}))
    return SlotLayout(clusters, cluster_of, position, spans, updates, sizes,
                      _refusal(graph, clusters, spans))


def _refusal(graph: Graph | None, clusters, spans) -> str | None:
    """Why no template window can run this chain, or None."""
    if graph is None:
        return ("it needs the graph the Program was compiled from (each update's window is "
                "filled with the graph's numbers)")
    types = [tuple(graph.variables[k].type for k in _originals(graph, keys)) for keys in clusters]
    for c, kinds in enumerate(types):
        if kinds != types[0]:
            return (f"keyframe {c} has variables of types {[t.__name__ for t in kinds]}, "
                    f"keyframe 0 {[t.__name__ for t in types[0]]}: a window slides over "
                    "keyframes of one kind")
    for f, (lo, hi) in zip(graph.factors, spans, strict=True):
        if hi > lo + 1:
            return (f"the {f.type.name} factor on {[str(k) for k in f.keys]} joins keyframes "
                    f"{lo} and {hi}: a window eliminates factors between consecutive keyframes "
                    "only")
    return None


def _originals(graph: Graph, keys) -> list:
    """The graph's own keys (str or int) of Program keys (str)."""
    original = {str(k): k for k in graph.variables}
    return [original[k] for k in keys]


def prefix_program(graph: Graph, program: Program, size: int) -> Program:
    """The batch Program of the chain's first ``size`` keyframes: their variables and the
    factors among them, compiled with ``program``'s solver without its incremental plan (the
    ordering as asked: two-ended on a chain by default, the batch design)."""
    clusters = program.schedule.clusters[:size]
    keys = {k for c in clusters for k in c}
    sub = Graph()
    for k, var in graph.variables.items():
        if str(k) in keys:
            sub.add_variable(k, var.initial, var.type)
    for f in graph.factors:
        if all(str(k) in keys for k in f.keys):
            sub.add(f)
    solver = replace(program.solver, incremental_k=None, batch_every=None)
    return compile_graph(sub, solver, name=f"{program.name}_window{size}", local_frame=False)


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


class WindowTemplate:
    """A *template* window of ``size`` keyframes of the chain ``program`` (compiled from
    ``graph``): the graph's first ``size`` keyframes with their factors and a ``MarginalPrior…``
    factor on every keyframe, compiled as a batch Program (the stream's solver options without
    an incremental plan; ``self.template``); :meth:`assemble` fills it with the numbers of any
    window of at most ``size`` keyframes (module docstring). No solver: the C-family layer's
    :class:`fgc_backends.cfamily.stream.TemplateSolver` adds a compiled one, the HLS backend's
    on-chip window (:mod:`fgc_backends.hls.window`) its own layout."""

    def __init__(self, graph: Graph, program: Program, size: int, ordering: str | None = None):
        if program.schedule.structure_class != "chain" or not program.schedule.clusters:
            raise StreamError("streaming on a template window needs a chain of keyframes")
        self.graph, self.program = graph, program
        clusters = program.schedule.clusters
        self.size = size = min(size, len(clusters))
        original = {str(k): k for k in graph.variables}
        self.cluster_of = {k: c for c, keys in enumerate(clusters) for k in keys}
        self.position = {k: p for keys in clusters for p, k in enumerate(keys)}
        types = [tuple(graph.variables[original[k]].type for k in keys) for keys in clusters]
        for c, kinds in enumerate(types):
            if kinds != types[0]:
                raise StreamError(f"keyframe {c} has variables of types "
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
        for f in graph.factors:  # the first window's factors, in graph order
            spans = [self.cluster_of[str(k)] for k in f.keys]
            if max(spans) < size:
                template.add(f)
                self.template_factors.append(f)
                self.signatures.append(self._signature(f, 0))
        for sig, f in self._later_signatures(set(self.signatures)):
            # a factor some later window holds on slots the first window's factors do not:
            # the template gets it too (on the first window's keys), so every window's factors
            # have their slots (a prior every few keyframes)
            f = dataclasses.replace(f, keys=tuple(original[clusters[c][p]] for c, p in sig[1]))
            template.add(f)
            self.template_factors.append(f)
            self.signatures.append(sig)
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
        # world-coordinate window data; a member of a type some chain factor makes robust
        # gets the robust-loss datapath, though the template's own factors may have none
        robust = frozenset(f.type.name for f in graph.factors if f.noise.robust is not None)
        self.template = compile_graph(template, solver, name=f"{program.name}_{kind}{size}",
                                      local_frame=False, robust_types=robust)
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

    def _later_signatures(self, seen: set) -> list:
        """The (signature on slots, graph factor) of every factor a window of ``size``
        keyframes holds at some place in the stream that ``seen`` lacks: per shape (factor
        type, keyframe offsets and positions of its variables) the slots it can take, in graph
        order then slot order."""
        shapes: dict[tuple, list] = {}
        for f in self.graph.factors:
            cells = [(self.cluster_of[str(k)], self.position[str(k)]) for k in f.keys]
            lo = min(c for c, _ in cells)
            width = max(c for c, _ in cells) - lo
            if width >= self.size:
                continue
            shape = (f.type.name, tuple((c - lo, p) for c, p in cells))
            reach = min(lo, self.size - 1 - width)  # the highest slot its oldest keyframe takes
            if shape not in shapes:
                shapes[shape] = [f, reach]
            shapes[shape][1] = max(shapes[shape][1], reach)
        out = []
        for (kind, rel), (f, reach) in shapes.items():
            for offset in range(reach + 1):
                sig = (kind, tuple((c + offset, p) for c, p in rel))
                if sig not in seen:
                    seen.add(sig)
                    out.append((sig, f))
        return out

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
                    raise StreamError(f"internal error: {ptype.name}'s data layout is not "
                                      "the one the stream assembles")

    def assemble(self, estimate: dict, first: int, last: int, tau):
        """(x, d): the template's flat arrays (storage, factor data) for the window first …
        last, from the current ``estimate`` and the marginal ``tau`` (R, mean, x̄ per
        variable) on keyframe ``first``; :class:`StreamError` if the window holds a graph
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
            raise StreamError(f"keyframes {first} … {last}: the window holds {inside} "
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
