"""storage: how many words a factor graph's linear system takes, step by step as in the papers.

**QR** (paper A) stores the whitened Jacobian A = W·J and right-hand side b = −W·r:

0. dense: the rows × columns matrix A plus b;
1. sparse per factor: each factor's dense Jacobian blocks (rows × dim for each variable it
   touches) and its residual, plus one index word per block naming its variable;
2. sequential: on a chain whose every factor type meets the clusters in one fixed pattern (offset
   and slot of each variable), the stream order says which factors and variables meet at each
   elimination step, so the index words are dropped (general graphs keep them);
3. skipping fixed entries: whitened entries that are structurally zero, entries equal to ±W[i, r]
   (a single ±1 Jacobian entry feeds them: kept only where skipping saves more words than storing
   the factor's whitening parameters), and entries derivable by a sign flip from the same entry of
   another variable's block of the same factor (the "symmetric pair").

A symmetric pair is only counted where it is *proven*: the two unwhitened entries must agree up to
sign at random probes and then be shown equal symbolically (inlining the kernel's assignments until
the difference expands to 0), and every row whitening mixes in must be related the same way. For
GTSAM's BetweenFactor<Pose3> (the LiDAR factor, ξ = Log(Z⁻¹Δ), Δ = x_i⁻¹x_j) J_j = Jr⁻¹(ξ) and
J_i = −J_j·Ad(Δ⁻¹): one block is derivable from the other only through a 6 × 6 product, and is its
negative only where x_i = x_j (not even at zero error, where J_i = −Ad(Z⁻¹) and J_j = I), so no
entry is shared. The IMU factor's velocity blocks are a true pair in the velocity rows
(J_vel_i = −J_vel_j = Jl⁻¹(φ)·R_jᵀ there).

**Cholesky** (paper B) stores H = AᵀA and g = Aᵀb (the LM damping μI only touches the diagonal):

0. dense: the N × N matrix H plus g;
1. neighbouring blocks: only cluster blocks (c, d) that share a factor — block-tridiagonal on a
   chain; on a general graph every variable is a cluster and each stored off-diagonal block needs
   an index word;
2. lower triangle: diagonal blocks' lower triangles and one block of each off-diagonal pair;
3. skipping fixed zeros: entries of H zero for every value, from the whitened Jacobians' structure
   (H_kl[a, b] ≠ 0 only if some factor has a row with A_k[·, a] ≠ 0 and A_l[·, b] ≠ 0).

Whitening mixes rows: isotropic and diagonal noise keep the Jacobian's zero pattern, a full
(upper-triangular) W makes whitened row i a combination of rows i…m−1.

Input: fused :class:`fgc.compiler.fuse.FactorBlock` s and a :class:`ChainLayout` (the keyframe
clusters in
chain order, e.g. from the schedule's classification) or ``None`` for a general graph.
"""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import sympy as sp

from fgc.compiler.cache import cached, source_digest
from fgc.compiler.derive import derive, random_measurement
from fgc.compiler.fuse import FactorBlock
from fgc.errors import StructureError
from fgc.frontend.dsl import Factor

SOLVERS = ("qr", "cholesky")
_PROOF_ROUNDS = 8
_PROOF_MAX_OPS = 4000


@dataclass(frozen=True)
class ChainLayout:
    """Variable keys per cluster (keyframe), in chain order: every factor must touch one cluster
    or two consecutive ones. Key order inside a cluster is the slot order (keep it the same in
    every cluster, e.g. (pose, velocity, bias))."""

    clusters: tuple[tuple, ...]


@dataclass(frozen=True)
class StorageStep:
    """Words stored after one step, and what the step's words are made of or skip."""

    name: str
    words: int
    index_words: int = 0
    noise_words: int = 0  # whitening parameters kept so that ±W[i, r] entries can be skipped
    skipped_zero: int = 0
    skipped_known: int = 0  # entries ±W[i, r]
    skipped_pair: int = 0  # entries derivable by sign from the other block of a pair


@dataclass(frozen=True)
class StoragePlan:
    """Dense word count and the words after each of the three steps (module docstring)."""

    solver: str
    structure: str  # "chain" or "general"
    rows: int  # QR: residual rows; Cholesky: N
    columns: int  # total tangent dimension N
    dense_words: int
    steps: tuple[StorageStep, ...]

    def ratio(self, step: int) -> float:
        """Dense words over the words after ``step`` (1, 2 or 3)."""
        return self.dense_words / self.steps[step - 1].words

    def table(self) -> str:
        """A plain-text table: step, words, dense/words."""
        lines = [f"{'dense':<28}{self.dense_words:>10}{1.0:>9.2f}x"]
        for i, s in enumerate(self.steps, 1):
            lines.append(f"{f'{i}. {s.name}':<28}{s.words:>10}{self.ratio(i):>9.2f}x")
        return "\n".join(lines)


@dataclass(frozen=True)
class FactorStructure:
    """Whitened structure of one factor type under one noise kind: per variable an m × dim mask
    of entries ``nonzero`` (not structurally zero), ``known`` (= ±W[i, r]: a single ±1 Jacobian
    entry feeds them) and ``shared`` (stored, but a sign flip of the same entry of an earlier
    variable's block); ``noise_params`` is the number of whitening parameters."""

    nonzero: tuple[np.ndarray, ...]
    known: tuple[np.ndarray, ...]
    shared: tuple[np.ndarray, ...]
    noise_params: int


def plan_storage(blocks: Sequence[FactorBlock], layout: ChainLayout | None = None,
                 solver: str = "qr") -> StoragePlan:
    """Word counts of the linear system of ``blocks``' factors for ``solver`` ("qr": A and b;
    "cholesky": H and g) on a chain ``layout`` (or a general graph when ``None``)."""
    if solver not in SOLVERS:
        raise ValueError(f"solver must be one of {SOLVERS}, got {solver!r}")
    factors = [f for b in blocks for f in b.factors]
    dims = {k: v.dim for b in blocks for k, v in zip(b.keys, b.type.variables, strict=True)}
    cluster_of, slot_of, order = _clusters(layout, factors, dims)
    structures = [factor_structure(f) for f in factors]
    if solver == "qr":
        return _plan_qr(factors, structures, dims, layout, cluster_of, slot_of)
    return _plan_cholesky(factors, structures, dims, layout, cluster_of, order)


def _clusters(layout: ChainLayout | None, factors: list[Factor], dims: dict
              ) -> tuple[dict, dict, list[list]]:
    """Cluster index and slot of every key, and the clusters' keys (one per key if general)."""
    if layout is None:
        order = [[k] for k in dims]
    else:
        order = [list(c) for c in layout.clusters]
        missing = sorted(map(str, set(dims) - {k for c in order for k in c}))
        if missing:
            raise StructureError(f"variables {missing} are in no cluster of the chain layout")
    cluster_of = {k: c for c, keys in enumerate(order) for k in keys}
    slot_of = {k: s for keys in order for s, k in enumerate(keys)}
    for f in factors if layout is not None else ():
        span = {cluster_of[k] for k in f.keys}
        if max(span) - min(span) > 1:
            raise StructureError(f"factor '{f.name}' on {list(f.keys)} spans clusters "
                                 f"{sorted(span)}: a chain factor touches at most two "
                                 "consecutive clusters")
    return cluster_of, slot_of, [[k for k in keys if k in dims] for keys in order]


# --------------------------------------------------------------------------------------------
# QR: A and b
# --------------------------------------------------------------------------------------------


def _plan_qr(factors, structures, dims, layout, cluster_of, slot_of) -> StoragePlan:
    rows = sum(f.type.residual_dim for f in factors)
    n = sum(dims.values())
    values = sum(f.type.residual_dim * (1 + sum(dims[k] for k in f.keys)) for f in factors)
    index = sum(len(f.keys) for f in factors)
    step1 = StorageStep("sparse per factor", values + index, index_words=index)
    index2 = index if layout is None else _chain_index_words(factors, cluster_of, slot_of)
    step2 = StorageStep("sequential (no index)", values + index2, index_words=index2)
    zero = known = pair = noise_words = 0
    for p in structures:
        n_known = sum(int(m.sum()) for m in p.known)
        if n_known > p.noise_params:  # skipping ±W[i, r] pays for storing W's parameters
            known, noise_words = known + n_known, noise_words + p.noise_params
        zero += sum(int((~m).sum()) for m in p.nonzero)
        pair += sum(int(m.sum()) for m in p.shared)
    words3 = values + index2 + noise_words - zero - known - pair
    step3 = StorageStep("skip fixed entries + pairs", words3, index2, noise_words, zero, known,
                        pair)
    structure = "general" if layout is None else "chain"
    return StoragePlan("qr", structure, rows, n, rows * n + rows, (step1, step2, step3))


def _chain_index_words(factors: list[Factor], cluster_of: dict, slot_of: dict) -> int:
    """Index words still needed on a chain: those of factor types met in more than one pattern
    of (cluster offset, slot) per variable."""
    patterns: dict[str, set] = {}
    for f in factors:
        first = min(cluster_of[k] for k in f.keys)
        patterns.setdefault(f.type.name, set()).add(
            tuple((cluster_of[k] - first, slot_of[k]) for k in f.keys))
    return sum(len(f.keys) for f in factors if len(patterns[f.type.name]) > 1)


# --------------------------------------------------------------------------------------------
# Cholesky: H and g
# --------------------------------------------------------------------------------------------


def _plan_cholesky(factors, structures, dims, layout, cluster_of, order) -> StoragePlan:
    n = sum(dims.values())
    hnz, gnz = _hessian_pattern(factors, structures)
    pairs = sorted({(max(cluster_of[a], cluster_of[b]), min(cluster_of[a], cluster_of[b]))
                    for f in factors for a in f.keys for b in f.keys
                    if cluster_of[a] != cluster_of[b]})
    size = [sum(dims[k] for k in keys) for keys in order]
    diag_full = sum(d * d for d in size)
    off = sum(size[c] * size[d] for c, d in pairs)
    idx1, idx2 = (0, 0) if layout is not None else (2 * len(pairs), len(pairs))
    step1 = StorageStep("neighbouring blocks", diag_full + 2 * off + n + idx1, index_words=idx1)
    words2 = sum(d * (d + 1) // 2 for d in size) + off + n + idx2
    step2 = StorageStep("lower triangle", words2, index_words=idx2)
    kept = sum(int(np.tril(_cluster_block(hnz, order[c], order[c], dims)).sum())
               for c in range(len(order)))
    kept += sum(int(_cluster_block(hnz, order[c], order[d], dims).sum()) for c, d in pairs)
    kept += sum(int(g.sum()) for g in gnz.values())
    step3 = StorageStep("skip fixed zeros", kept + idx2, index_words=idx2,
                        skipped_zero=words2 - idx2 - kept)
    structure = "general" if layout is None else "chain"
    return StoragePlan("cholesky", structure, n, n, n * n + n, (step1, step2, step3))


def _hessian_pattern(factors, structures) -> tuple[dict, dict]:
    """Structural nonzeros of H's variable blocks {(k, l): bool d_k × d_l} and of g {k: bool}."""
    hnz: dict = {}
    gnz: dict = {}
    for f, p in zip(factors, structures, strict=True):
        for a, na in zip(f.keys, p.nonzero, strict=True):
            gnz[a] = gnz.get(a, False) | na.any(axis=0)
            for b, nb in zip(f.keys, p.nonzero, strict=True):
                hnz[a, b] = hnz.get((a, b), False) | ((na.T.astype(int) @ nb) > 0)
    return hnz, gnz


def _cluster_block(hnz: dict, rows: list, cols: list, dims: dict) -> np.ndarray:
    """The bool nonzero pattern of H's cluster block (rows, cols) assembled from variables."""
    return np.block([[np.broadcast_to(hnz.get((a, b), False), (dims[a], dims[b]))
                      for b in cols] for a in rows])


# --------------------------------------------------------------------------------------------
# per-factor whitened structure
# --------------------------------------------------------------------------------------------

_STRUCTURES: dict[tuple[str, str], FactorStructure] = {}


def factor_structure(f: Factor) -> FactorStructure:
    """Whitened structure of factor ``f`` (memoised per factor type and noise kind)."""
    sf = derive(f.type)
    key = (sf.fingerprint, f.noise.kind)
    if key not in _STRUCTURES:
        h = hashlib.sha256(f"{sf.fingerprint}|{f.noise.kind}|".encode())  # chains from derive
        h.update(source_digest("compiler/storage.py"))
        _STRUCTURES[key] = cached(("structure", f"{f.type.name}-{f.noise.kind}"), h.hexdigest(),
                                  lambda: _factor_structure(f, sf), FactorStructure)
    return _STRUCTURES[key]


def _factor_structure(f: Factor, sf) -> FactorStructure:
    """Uncached analysis behind :func:`factor_structure`."""
    m = sf.residual_dim
    w = np.eye(m, dtype=int) if f.noise.kind != "full" else np.triu(np.ones((m, m), int))
    codes = [np.array(s) for s in sf.structure]
    nonzero, known = [], []
    for c in codes:
        nz, unit = c != "0", (c == "1") | (c == "-1")
        count, general = w @ nz, w @ (nz & ~unit)
        nonzero.append(count > 0)
        known.append((count == 1) & (general == 0))
    shared = _shared(f, sf, w, codes, nonzero, known)
    return FactorStructure(tuple(nonzero), tuple(known), tuple(shared),
                           len(f.noise.params()))


def _shared(f: Factor, sf, w: np.ndarray, codes, nonzero, known) -> list[np.ndarray]:
    """Stored whitened entries of each block derivable by sign from an earlier block."""
    stored = [nz & ~kn for nz, kn in zip(nonzero, known, strict=True)]
    shared = [np.zeros_like(s) for s in stored]
    probes = _probe(f, sf)
    for k in range(len(codes)):
        for q in range(k + 1, len(codes)):
            if sf.variables[k].type_name != sf.variables[q].type_name:
                continue
            for sign in (1, -1):
                related = _related(sf, k, q, sign, codes, probes)
                whitened = (w @ ~related) == 0  # every mixed-in row related the same way
                shared[q] |= whitened & stored[k] & stored[q]
    return shared


def _related(sf, k: int, q: int, sign: int, codes, probes) -> np.ndarray:
    """Unwhitened entries with J_k = sign · J_q, proven (fixed codes, or symbolic proof)."""
    ck, cq = codes[k], codes[q]
    out = np.zeros(ck.shape, dtype=bool)
    defs = dict(sf.kernel.assignments)
    jk, jq = sf.jacobians[k], sf.jacobians[q]
    for i, j in np.ndindex(*ck.shape):
        if ck[i, j] != "x" or cq[i, j] != "x":
            out[i, j] = ck[i, j] != "x" and cq[i, j] != "x" and \
                int(ck[i, j]) == sign * int(cq[i, j])
        elif all(abs(p[k][i, j] - sign * p[q][i, j]) < 1e-9 * (1 + abs(p[k][i, j]))
                 for p in probes):
            out[i, j] = _proven_equal(jk[i, j] - sign * jq[i, j], defs)
    return out


def _proven_equal(diff, defs: dict) -> bool:
    """True if ``diff`` (over kernel assignments) expands to 0 after inlining assignments."""
    d = sp.expand(diff)
    for _ in range(_PROOF_ROUNDS):
        if d == 0:
            return True
        inner = d.free_symbols & defs.keys()
        if not inner or sp.count_ops(d) > _PROOF_MAX_OPS:
            return False
        d = sp.expand(d.xreplace({x: defs[x] for x in inner}))
    return d == 0


def _probe(f: Factor, sf, n: int = 3) -> list[list[np.ndarray]]:
    """Unwhitened Jacobians of ``f``'s type at ``n`` random points (fixed seed)."""
    rng = np.random.default_rng(20240612)
    out = []
    for _ in range(n):
        values = [a.type.random(rng) for a in f.type.variables]
        measured = {a.name: random_measurement(a.type, rng) for a in f.type.measurements}
        with np.errstate(all="ignore"):
            out.append(sf.evaluate(values, measured)[1])
    return out
