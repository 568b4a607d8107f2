"""fuse: factors that constrain the same keyframe variables → factor blocks with one shared kernel.

**Grouping rule** (:func:`group_factors`; deterministic, independent of hash seeds):

1. Factors with the same *set* of (two or more) keys share a block.
2. A factor whose key set has at least two keys and is a strict subset of exactly one *maximal* key
   set (one not strictly inside another factor's) joins that set's block. On a LIO chain the LiDAR
   odometry factor on {x_j, x_j+1} joins the IMU factor on {x_j, v_j, x_j+1, v_j+1, b_j, b_j+1}.
3. Every *unary* factor (GPS, priors) is a block of its own, even beside another unary factor on
   the same variable. On a chain a unary factor's variable lies in two between-keyframe blocks (one
   at the ends), and only some keyframes carry a prior, so fusing it would make one-off block types
   at the chain's ends; and it has nothing to share: GPS is t − z (its Jacobian [0 R] is read from
   the inputs) and a prior's Log(z⁻¹x) has no common term with x_i⁻¹x_j (measured: fusing GPS into
   the IMU + LiDAR block removes no operation). A subset of two maximal sets (ambiguous) also stays
   a block of its own.

A block's variables are the keys of its *lead* member (a factor whose key set is the block's set,
first by type name, then graph order); the other members follow, ordered by (type name, variable
positions, graph order), so every instance of a repeating pattern gets the same :class:`BlockType`.

**Fused kernel.** Each member's residual is renamed onto the block's variable symbols (the LiDAR
factor's ``x1__R00`` becomes the IMU factor's ``pose_i__R00``), its measurement symbols get a member
prefix (``m1_measured__R00``), and the residuals are stacked. One
:func:`fgc.compiler.kernel.jacobian_kernel`
over the stack lets CSE share intermediates across residuals, Jacobians and members — the LIO
paper's General Calculation unit (:mod:`fgc.compiler.fuse_kernels`). Outputs: the stacked residual
(M rows),
then for each block variable k its unwhitened M × dim_k Jacobian, row-major (zero where a member
does not touch k). Fixed 0/±1 entries come from the members' derivations (``derive``'s
structure), so they are exact. A second *cost* kernel runs the same residual program and each
member's whitened cost ½‖W r‖² plus their sum, with W from
:func:`fgc.compiler.derive.whitening_matrix` (no
Jacobians). Fused kernels are cached on disk next to derivations, keyed by the members' derivation
fingerprints.

CSE only shares what is written alike: the built-in IMU factor forms R_jᵀ·(R_i·Exp θ) while the
LiDAR factor forms Z⁻¹·(R_iᵀR_j), so their residuals have no common subexpression and the saving of
the IMU + LiDAR block is small (``BlockOps.saving``); writing the IMU rotation error as
(R_iᵀR_j)ᵀ·Exp θ would let the two share R_iᵀR_j.
"""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from fgc.compiler.cache import Deferred, cached, source_digest
from fgc.compiler.derive import KernelInput, SymbolicFactor, derive
from fgc.compiler.fuse_kernels import (
    BlockOps,
    Member,
    OpCounts,
    build_kernels,
    noise_symbols,
    prefixed,
)
from fgc.compiler.kernel import Kernel, numeric_function
from fgc.errors import DslError
from fgc.frontend.dsl import Factor, FactorType, Graph
from fgc.frontend.geometry import LieGroup
from fgc.frontend.noise import NoiseModel

__all__ = ["BlockOps", "BlockType", "FactorBlock", "Member", "MemberSignature", "OpCounts",
           "block_type", "fuse", "group_factors"]

# (factor type, block-variable index of each of its variables, noise kind); lead first, at 0, 1, …
MemberSignature = tuple[FactorType, tuple[int, ...], str]


@dataclass(frozen=True)
class BlockType:
    """A fused kernel for one pattern of member factor types (shared by all its instances).

    ``kernel``: inputs are the variables' then the members' measurement symbols; outputs the stacked
    residual then each variable's M × dim_k Jacobian. ``cost_kernel``: inputs additionally each
    member's ``noise_symbols``; outputs the stacked residual, each member's ½‖W r‖², their sum.
    ``structure[k][i][j]`` is "0", "1", "-1" or "x" as in
    :class:`fgc.compiler.derive.SymbolicFactor`.
    """

    name: str
    key: str
    variables: tuple[KernelInput, ...]
    measurements: tuple[KernelInput, ...]
    members: tuple[Member, ...]
    kernels: Deferred = field(compare=False, repr=False)  # (kernel, cost_kernel), as cached
    structure: tuple[tuple[tuple[str, ...], ...], ...] = field(repr=False)
    ops: BlockOps

    @property
    def kernel(self) -> Kernel:
        return self.kernels.get()[0]

    @property
    def cost_kernel(self) -> Kernel:
        return self.kernels.get()[1]

    @property
    def residual_dim(self) -> int:
        return self.members[-1].rows[1]

    @cached_property
    def _numeric(self):
        return numeric_function(self.kernel)

    @cached_property
    def _numeric_cost(self):
        return numeric_function(self.cost_kernel)

    def _flat(self, values: Sequence, measured_per_member: Sequence[dict]) -> list:
        args: list = []
        for v in values:
            arr = v.storage_array() if isinstance(v, LieGroup) else np.asarray(v, float)
            args.extend(arr.reshape(-1))
        for m, measured in zip(self.members, measured_per_member, strict=True):
            for name in m.measurement_names:
                args.extend(np.asarray(measured[name], dtype=float).reshape(-1))
        return args

    def evaluate(self, values: Sequence, measured_per_member: Sequence[dict]
                 ) -> tuple[np.ndarray, list[np.ndarray]]:
        """Values (one per block variable) and each member's measurements → the unwhitened
        stacked residual (M,) and one M × dim_k Jacobian per block variable."""
        out = np.asarray(self._numeric(*self._flat(values, measured_per_member)), dtype=float)
        m = self.residual_dim
        jacs, pos = [], m
        for b in self.variables:
            jacs.append(out[pos:pos + m * b.dim].reshape(m, b.dim))
            pos += m * b.dim
        return out[:m], jacs

    def evaluate_cost(self, values: Sequence, measured_per_member: Sequence[dict],
                      noise_per_member: Sequence[NoiseModel]) -> tuple[np.ndarray, np.ndarray]:
        """The cost mode: stacked residual (M,) and each member's Gaussian cost ½‖W r‖²."""
        args = self._flat(values, measured_per_member)
        for nm in noise_per_member:
            args.extend(nm.params())
        out = np.asarray(self._numeric_cost(*args), dtype=float)
        m = self.residual_dim
        return out[:m], out[m:m + len(self.members)]


@dataclass(frozen=True)
class FactorBlock:
    """One instance of a block type in a graph: its variable keys and member factors (in the
    block type's member order; ``indices`` are their positions in ``graph.factors``)."""

    type: BlockType
    keys: tuple
    indices: tuple[int, ...]
    factors: tuple[Factor, ...] = field(compare=False, repr=False)

    @property
    def ops(self) -> BlockOps:
        return self.type.ops

    def _values(self, values) -> list:
        return [values[k] for k in self.keys] if isinstance(values, dict) else list(values)

    def evaluate(self, values, measured_per_member: Sequence[dict] | None = None
                 ) -> tuple[np.ndarray, list[np.ndarray]]:
        """Residual and Jacobians (see :meth:`BlockType.evaluate`); ``values`` is a sequence in
        block-variable order or a dict by key; measurements default to the member factors'."""
        measured = measured_per_member or [f.measured for f in self.factors]
        return self.type.evaluate(self._values(values), measured)

    def error(self, values) -> float:
        """GTSAM's error of the members at ``values``: Σ ½‖W r‖², or ρ(‖W r‖) if robust."""
        _, costs = self.type.evaluate_cost(self._values(values), [f.measured for f in self.factors],
                                           [f.noise for f in self.factors])
        total = 0.0
        for f, c in zip(self.factors, costs, strict=True):
            robust = f.noise.robust
            total += c if robust is None else robust.loss(float(np.sqrt(2.0 * c)))
        return float(total)




def fuse(graph: Graph) -> tuple[FactorBlock, ...]:
    """Group ``graph``'s factors into blocks (module docstring) and build each block's fused
    kernel. Blocks come in the order of their first factor in ``graph.factors``."""
    blocks = []
    # one block type per distinct signature: a 10,000-pose graph has a handful of signatures,
    # and building the type (derivation look-up, whitening symbols) 64,000 times took ~30 s.
    # Keyed by the factor type objects themselves, for this call only (one graph, one trace).
    types: dict[tuple, BlockType] = {}
    for group in group_factors(graph):
        lead_keys = graph.factors[group[0]].keys
        specs = tuple((graph.factors[i].type, _positions(lead_keys, graph.factors[i].keys),
                       graph.factors[i].noise.kind) for i in group)
        signature = tuple((id(t), pos, kind) for t, pos, kind in specs)
        if signature not in types:
            types[signature] = block_type(specs)
        blocks.append(FactorBlock(types[signature], tuple(lead_keys), tuple(group),
                                  tuple(graph.factors[i] for i in group)))
    return tuple(blocks)


def group_factors(graph: Graph) -> tuple[tuple[int, ...], ...]:
    """Factor indices per block, lead member first (grouping rule in the module docstring)."""
    by_set: dict[frozenset, list[int]] = {}
    for i, f in enumerate(graph.factors):
        by_set.setdefault(frozenset(f.keys), []).append(i)
    sets_with: dict = {}
    for s in by_set:
        for k in s:
            sets_with.setdefault(k, []).append(s)

    def supersets(s: frozenset) -> list[frozenset]:
        return [t for t in sets_with[next(iter(s))] if s < t]

    maximal = {s for s in by_set if not supersets(s)}
    groups: dict[frozenset, list[int]] = {}
    unary: list[list[int]] = []
    for s, indices in by_set.items():
        if len(s) < 2:
            unary += [[i] for i in indices]
            continue
        owners = [t for t in supersets(s) if t in maximal]
        groups.setdefault(owners[0] if len(owners) == 1 else s, []).extend(indices)
    ordered = sorted([*groups.values(), *unary], key=min)
    return tuple(_member_order(graph, g) for g in ordered)


def _member_order(graph: Graph, group: list[int]) -> tuple[int, ...]:
    full = frozenset().union(*(graph.factors[i].keys for i in group))
    lead = min((i for i in group if frozenset(graph.factors[i].keys) == full),
               key=lambda i: (graph.factors[i].type.name, i))
    lead_keys = graph.factors[lead].keys
    rest = sorted((i for i in group if i != lead), key=lambda i: (
        graph.factors[i].type.name, _positions(lead_keys, graph.factors[i].keys), i))
    return (lead, *rest)


def _positions(lead_keys: Sequence, keys: Sequence) -> tuple[int, ...]:
    return tuple(list(lead_keys).index(k) for k in keys)


_MEMO: dict[str, BlockType] = {}


def block_type(specs: Sequence[MemberSignature]) -> BlockType:
    """The fused block type of ``specs`` (lead first): memoised, and cached on disk."""
    derived = [derive(t) for t, _, _ in specs]
    variables = derived[0].variables
    members, meas_blocks, row = [], [], 0
    for i, ((ftype, pos, kind), sf) in enumerate(zip(specs, derived, strict=True)):
        _check_member(ftype, sf, tuple(pos), variables)
        prefix, m = f"m{i}_", sf.residual_dim
        members.append(Member(ftype.name, sf.fingerprint, tuple(pos), (row, row + m), kind, prefix,
                              tuple(b.name for b in sf.measurements),
                              noise_symbols(kind, m, prefix)))
        meas_blocks += [KernelInput(prefix + b.name, b.type_name, b.dim,
                              tuple(prefixed(s, prefix) for s in b.symbols))
                        for b in sf.measurements]
        row += m
    name = "+".join(m.name for m in members)
    key = _block_key(members, variables)
    if key not in _MEMO:  # one object per pattern: its numeric kernels compile once
        built = cached(("fuse", name), key, lambda: _deferred_kernels(build_kernels(
            specs[0][0], derived, members, variables, tuple(meas_blocks))), tuple)
        _MEMO[key] = BlockType(name, key, variables, tuple(meas_blocks), tuple(members), *built)
    return _MEMO[key]


def _deferred_kernels(built: tuple) -> tuple:
    """(kernel, cost kernel, structure, ops) → (Deferred((kernel, cost kernel)), structure, ops):
    a warm compile reads the structure and op counts, the kernels only on a lowering miss."""
    kernel, cost, structure, ops = built
    return Deferred((kernel, cost)), structure, ops


def _check_member(ftype: FactorType, sf: SymbolicFactor, pos: tuple, variables) -> None:
    if len(pos) != len(sf.variables) or len(set(pos)) != len(pos):
        raise DslError(f"factor '{ftype.name}': bad block positions {pos}")
    for p, b in zip(pos, sf.variables, strict=True):
        if not 0 <= p < len(variables) or variables[p].type_name != b.type_name:
            raise DslError(f"factor '{ftype.name}': variable '{b.name}' ({b.type_name}) cannot "
                           f"share block variable {p}")


def _block_key(members: list[Member], variables: tuple[KernelInput, ...]) -> str:
    h = hashlib.sha256()
    for m in members:
        h.update(f"{m.fingerprint}|{m.positions}|{m.noise_kind};".encode())
    h.update(",".join(b.type_name for b in variables).encode())
    h.update(source_digest("compiler/fuse.py", "compiler/fuse_kernels.py",
                           "compiler/kernel.py"))
    return h.hexdigest()
