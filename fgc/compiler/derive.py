"""derive: a factor type → its symbolic residual, tangent-space Jacobians and their structure.

Jacobians are taken with respect to each variable's tangent space under right perturbation,
``∂ r(x ⊕ δ) / ∂δ`` at δ = 0 with ``x ⊕ δ = x.retract(δ)``, by the chain rule
``∂r/∂storage · ∂storage/∂δ`` (the second factor is derived once per type from ``retract``).
Entries that are identically 0 or ±1 are found and made exact: symbolically where sympy sees it,
otherwise by evaluating at random points on the manifold (e.g. ``RᵀR = I``).

Derivations are cached on disk (``$FGC_CACHE_DIR``, default ``~/.cache/fgc``) under a hash of the
factor's traced residual (what it computes, whatever it reads) and of fgc's own derivation code
and sympy's version, so compiling a known factor again is cheap and a changed one is re-derived.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field
from functools import cache, cached_property
from pathlib import Path

import numpy as np
import sympy as sp

from fgc.compiler.cache import Deferred, entry, load, source_digest, store
from fgc.compiler.kernel import Kernel, drop_dead, jacobian_kernel, numeric_function
from fgc.errors import DerivationError
from fgc.frontend.dsl import FactorType, MatrixType, storage_dim, type_name
from fgc.frontend.geometry import LieGroup, special
from fgc.ir.codes import NOISE_KINDS as KINDS

GENERAL, ZERO, ONE, MINUS_ONE = "x", "0", "1", "-1"
_PROBES = 3
_PROBE_TOL = 1e-11


@dataclass(frozen=True)
class KernelInput:
    """One input of a factor kernel: a variable or a measurement, and its storage symbols."""

    name: str
    type_name: str
    dim: int  # tangent dimension (variables) or storage size (measurements)
    symbols: tuple[sp.Symbol, ...]


@dataclass(frozen=True)
class SymbolicFactor:
    """The derivation of one factor type.

    ``expression`` is the unwhitened residual (m × 1) over the input symbols. ``kernel`` computes
    it and all Jacobians as a straight-line program: outputs are the m residual entries, then for
    each variable k its m × dim_k Jacobian (row-major). ``residual`` and ``jacobians[k]`` are those
    outputs as matrices over the kernel's intermediate symbols. ``structure[k][i][j]`` is "0", "1",
    "-1" (fixed entries, exact in the kernel) or "x" (computed).
    """

    name: str
    fingerprint: str
    variables: tuple[KernelInput, ...]
    measurements: tuple[KernelInput, ...]
    expression: sp.Matrix = field(compare=False)
    kernel: Kernel = field(compare=False)
    structure: tuple[tuple[tuple[str, ...], ...], ...]

    def __reduce__(self):
        # the expressions are unpickled only when used (see fgc.compiler.cache.Deferred)
        return (_restore, (self.name, self.fingerprint, self.variables, self.measurements,
                           self.structure, self.residual_dim,
                           Deferred((self.expression, self.kernel))))

    def __getattr__(self, name: str):
        # only called for attributes not set: a restored factor's expression and kernel
        deferred = self.__dict__.get("_deferred")
        if name in ("expression", "kernel") and deferred is not None:
            expression, kernel = deferred.get()
            object.__setattr__(self, "expression", expression)
            object.__setattr__(self, "kernel", kernel)
            del self.__dict__["_deferred"]
            return self.__dict__[name]
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    @property
    def residual_dim(self) -> int:
        rows = self.__dict__.get("_rows")
        return rows if rows is not None else self.expression.rows

    @property
    def residual(self) -> sp.Matrix:
        return sp.Matrix(self.kernel.outputs[: self.residual_dim])

    @property
    def jacobians(self) -> tuple[sp.Matrix, ...]:
        m, pos, out = self.residual_dim, self.residual_dim, []
        for b in self.variables:
            out.append(sp.Matrix(m, b.dim, self.kernel.outputs[pos:pos + m * b.dim]))
            pos += m * b.dim
        return tuple(out)

    @property
    def inputs(self) -> tuple[sp.Symbol, ...]:
        return tuple(s for b in self.variables + self.measurements for s in b.symbols)

    @cached_property
    def _numeric(self):
        return numeric_function(self.kernel)

    @cached_property
    def _numeric_residual(self):
        return sp.lambdify(self.inputs, list(self.expression),
                           modules=[special.numeric_namespace(), "numpy"], cse=True)

    def _flat_inputs(self, values, measured: dict) -> list:
        args: list = []
        for v in values:
            arr = v.storage_array() if isinstance(v, LieGroup) else np.asarray(v, float)
            args.extend(arr.reshape(-1))
        for block in self.measurements:
            args.extend(np.asarray(measured[block.name], dtype=float).reshape(-1))
        return args

    def evaluate(self, values, measured: dict) -> tuple[np.ndarray, list[np.ndarray]]:
        """Numeric (unwhitened) residual and Jacobians at variable values and measurements."""
        flat = np.asarray(self._numeric(*self._flat_inputs(values, measured)), dtype=float)
        m = self.residual_dim
        r, rest = flat[:m], flat[m:]
        jacs, pos = [], 0
        for b in self.variables:
            jacs.append(rest[pos:pos + m * b.dim].reshape(m, b.dim))
            pos += m * b.dim
        return r, jacs

    @cached_property
    def _guard_margins(self):
        """``g - t`` of every :class:`special.GuardedQuotient` of the kernel, compiled (None if
        it has none)."""
        guards = set()
        for e in [e for _, e in self.kernel.assignments] + list(self.kernel.outputs):
            guards |= sp.sympify(e).atoms(special.GuardedQuotient)
        if not guards:
            return None
        margins = tuple(q.args[2] - q.args[3] for q in sorted(guards, key=sp.default_sort_key))
        return numeric_function(Kernel(self.kernel.inputs,
                                       drop_dead(self.kernel.assignments, margins), margins))

    def singular_at(self, values, measured: dict) -> bool:
        """Whether a singular-point convention is in force at these values (a guard at or
        below its threshold: a norm of a zero vector, a bearing to a coincident point), where
        the residual is not differentiable and the Jacobian is GTSAM's convention."""
        fn = self._guard_margins
        if fn is None:
            return False
        margins = np.asarray(fn(*self._flat_inputs(values, measured)), dtype=float)
        return bool(np.any(margins <= 0))

    def evaluate_residual(self, values, measured: dict) -> np.ndarray:
        out = self._numeric_residual(*self._flat_inputs(values, measured))
        return np.asarray(out, dtype=float).reshape(-1)

    @cached_property
    def _residual_kernel(self):
        """The kernel's residual rows alone (dead Jacobian assignments dropped), compiled:
        seconds cheaper to build than lambdify's CSE of the residual expression."""
        outs = tuple(self.kernel.outputs[:self.residual_dim])
        return numeric_function(Kernel(self.kernel.inputs,
                                       drop_dead(self.kernel.assignments, outs), outs))

    def evaluate_residuals(self, inputs: np.ndarray) -> np.ndarray:
        """Unwhitened residuals of many instances: ``inputs`` is (n, len(self.inputs)) float64,
        the flat variable storages then measurements of each instance; returns
        (n, residual_dim). One vectorised call over the columns, or one call per row when a
        special function of the residual takes scalars only (the SO(3) log)."""
        inputs = np.asarray(inputs, dtype=np.float64)
        n, fn = inputs.shape[0], self._residual_kernel
        try:
            out = fn(*inputs.T)
            return np.stack([np.broadcast_to(np.asarray(x, dtype=np.float64), (n,))
                             for x in out], axis=1)
        except (ValueError, TypeError, IndexError):
            return np.array([np.asarray(fn(*row), dtype=np.float64) for row in inputs],
                            dtype=np.float64).reshape(n, self.residual_dim)


def _restore(name, fingerprint, variables, measurements, structure, rows, deferred
             ) -> SymbolicFactor:
    sf = object.__new__(SymbolicFactor)
    for field_name, value in (("name", name), ("fingerprint", fingerprint),
                              ("variables", variables), ("measurements", measurements),
                              ("structure", structure), ("_rows", rows),
                              ("_deferred", deferred)):
        object.__setattr__(sf, field_name, value)
    return sf


def whitening_matrix(kind: str, dim: int, prefix: str = "noise") -> sp.Matrix:
    """Symbolic square-root information matrix of a noise kind; symbols follow
    :meth:`fgc.frontend.noise.NoiseModel.params` order."""
    if kind not in KINDS:
        raise DerivationError(f"unknown noise kind {kind!r}")
    if kind == "isotropic":
        return sp.eye(dim) * sp.Symbol(f"{prefix}__s", positive=True)
    if kind == "diagonal":
        return sp.diag(*[sp.Symbol(f"{prefix}__{i}", positive=True) for i in range(dim)])
    out = sp.zeros(dim, dim)
    for i, j in zip(*np.triu_indices(dim), strict=True):
        out[i, j] = sp.Symbol(f"{prefix}__{i}_{j}", real=True)
    return out


# --------------------------------------------------------------------------------------------
# derivation
# --------------------------------------------------------------------------------------------


def derive(ftype: FactorType, use_cache: bool = True) -> SymbolicFactor:
    """Derive residual, Jacobians and structure of ``ftype`` (memoised, and cached on disk).

    The key is :func:`content_key`: a digest of what the residual function computes (its traced
    expression), so a value it reads from anywhere (a dict, a class attribute, another module)
    is part of the key, as are fgc's derivation code and sympy's version."""
    key, traced = content_key(ftype)
    if key in _MEMO:
        return _MEMO[key]
    result, path = None, None
    if use_cache:
        path = entry("derive", ftype.name, key)
        result = load(path, key, SymbolicFactor)
        if result is not None and result.fingerprint != key:
            result = None
    if result is None:
        result = _derive_uncached(ftype, key, traced)
        if use_cache:
            store(path, key, result)
    _MEMO[key] = result
    return result


_MEMO: dict[str, SymbolicFactor] = {}


def memo_key(ftype: FactorType) -> str:
    """The key :func:`derive` files ``ftype``'s derivation under (memo and disk)."""
    return content_key(ftype)[0]


def is_cached(ftype: FactorType) -> bool:
    """Whether :func:`derive` would find ``ftype`` without symbolic work (memo or a disk entry;
    the entry is validated only when read)."""
    key = memo_key(ftype)
    if key in _MEMO:
        return True
    path = entry("derive", ftype.name, key)
    return path is not None and path.is_file()


def content_key(ftype: FactorType) -> tuple[str, tuple]:
    """(key, trace) of ``ftype``: the key digests the traced residual, the argument names and
    types, the factor's name, fgc's derivation code and sympy's version. The trace is memoised
    per factor type and graph generation (:meth:`FactorType.traced`), the key per trace."""
    traced = ftype.traced()
    memo = _KEYS.get(id(ftype))
    if memo is not None and memo[0] is ftype and memo[1] is traced:
        return memo[2], traced
    h = hashlib.sha256(b"fgc-derive-key-1\n")
    h.update(f"{ftype.name}\n{_code_version()}\n".encode())
    for arg in ftype.variables + ftype.measurements:
        h.update(f"{arg.name}:{type_name(arg.type)};".encode())
    var_values, meas_values, residual = traced
    h.update(b"\ninputs:")
    for values in (var_values, meas_values):
        for name, value in values.items():
            h.update(f"{name}=".encode())
            h.update(expression_digest(sp.Matrix(_symbols_of(value))))
    h.update(b"\nresidual:")
    h.update(expression_digest(residual))
    key = h.hexdigest()
    _KEYS[id(ftype)] = (ftype, traced, key)  # holds ftype, so its id() is not reused meanwhile
    return key, traced


_KEYS: dict[int, tuple] = {}  # id(factor type) → (factor type, its current trace, its key)


def expression_digest(matrix: sp.MatrixBase) -> bytes:
    """SHA-256 of a canonical serialisation of a sympy matrix, deterministic across processes.

    The expression is walked as a DAG (each distinct subexpression written once, referred to by
    its post-order number), so a large residual with shared subterms (the IMU factor's) costs
    its number of distinct nodes, not its tree size (``srepr`` of it takes minutes). Node order
    is sympy's canonical ``args`` order; symbols carry their assumptions, numbers their exact
    value (a ``Float`` by its mpf tuple and precision)."""
    h = hashlib.sha256(f"{matrix.rows}x{matrix.cols}\n".encode())
    ids: dict = {}
    for root in matrix:
        root = sp.sympify(root)
        stack = [(root, False)]
        while stack:
            node, expanded = stack.pop()
            if node in ids:
                continue
            if not expanded and node.args:
                stack.append((node, True))
                stack.extend((a, False) for a in reversed(node.args) if a not in ids)
                continue
            h.update(_node_text(node, ids).encode())
            ids[node] = len(ids)
        h.update(f"out {ids[root]}\n".encode())
    return h.digest()


def _node_text(node, ids: dict) -> str:
    cls = type(node).__name__
    if node.args:
        return f"{cls}({','.join(str(ids[a]) for a in node.args)})\n"
    if isinstance(node, sp.Symbol):
        return f"{cls}:{node.name}:{sorted(node.assumptions0.items())}\n"
    if isinstance(node, sp.Float):
        return f"Float:{node._mpf_}:{node._prec}\n"
    return f"{cls}:{sp.srepr(node)}\n"


def _derive_uncached(ftype: FactorType, fingerprint: str, traced=None) -> SymbolicFactor:
    var_values, meas_values, residual = traced if traced is not None else ftype.trace()
    var_blocks = tuple(
        KernelInput(a.name, a.type.__name__, a.type.dim, tuple(_symbols_of(var_values[a.name])))
        for a in ftype.variables)
    meas_blocks = tuple(
        KernelInput(a.name, _type_label(a.type), storage_dim(a.type),
              tuple(_symbols_of(meas_values[a.name])))
        for a in ftype.measurements)
    _check_free_symbols(ftype, residual, var_blocks + meas_blocks)
    kernel, _ = jacobian_kernel(residual, tangent_seeds(ftype, var_blocks, meas_blocks),
                                sum(b.dim for b in var_blocks))
    kernel = _reorder_jacobian(kernel, residual.rows, [b.dim for b in var_blocks])
    sf = SymbolicFactor(ftype.name, fingerprint, var_blocks, meas_blocks, residual, kernel, ())
    return _with_structure(sf, ftype)


def tangent_seeds(ftype: FactorType, var_blocks, meas_blocks) -> list:
    """(input symbol, {tangent column: ∂symbol/∂δ}) for every kernel input, in input order."""
    seeds, offset = [], 0
    for arg, block in zip(ftype.variables, var_blocks, strict=True):
        d_storage = storage_tangent_jacobian(arg.type, arg.name)
        for i, sym in enumerate(block.symbols):
            seeds.append((sym, {offset + c: d_storage[i, c] for c in range(block.dim)
                                if d_storage[i, c] != 0}))
        offset += block.dim
    seeds += [(sym, {}) for b in meas_blocks for sym in b.symbols]
    return seeds


def _reorder_jacobian(kernel: Kernel, m: int, dims: list[int]) -> Kernel:
    """Outputs [r; J (m × n) row-major] → [r; J_1 row-major; J_2 row-major; ...]."""
    n = sum(dims)
    jac = kernel.outputs[m:]
    outs, start = list(kernel.outputs[:m]), 0
    for d in dims:
        outs += [jac[i * n + start + j] for i in range(m) for j in range(d)]
        start += d
    return Kernel(kernel.inputs, kernel.assignments, tuple(outs))


def _type_label(t) -> str:
    return t.__name__ if not isinstance(t, MatrixType) else f"Matrix{t.rows}x{t.cols}"


def _symbols_of(value) -> list[sp.Symbol]:
    if isinstance(value, LieGroup):
        return list(value.to_storage())
    if isinstance(value, sp.MatrixBase):
        return list(value)
    return [value]


def _check_free_symbols(ftype: FactorType, residual: sp.Matrix, blocks) -> None:
    known = {s for b in blocks for s in b.symbols}
    stray = sorted(str(s) for s in residual.free_symbols - known)
    if stray:
        raise DerivationError(f"factor '{ftype.name}': residual uses symbols that are neither "
                              f"variables nor measurements: {stray}")
    for i, e in enumerate(residual):
        if e.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise DerivationError(f"factor '{ftype.name}': residual row {i} is not finite ({e})")


@cache
def storage_tangent_jacobian(t: type[LieGroup], prefix: str) -> sp.Matrix:
    """∂ storage(x.retract(δ)) / ∂δ at δ = 0, in the symbols of ``t.symbol(prefix)``."""
    x = t.symbol(prefix)
    delta = sp.Matrix(sp.symbols(f"_delta0:{t.dim}", real=True))
    moved = sp.Matrix(x.retract(delta).to_storage())
    jac = moved.jacobian(delta).subs({d: 0 for d in delta})
    return jac.applyfunc(sp.expand)


def _with_structure(sf: SymbolicFactor, ftype: FactorType) -> SymbolicFactor:
    """Classify each Jacobian entry; entries fixed at 0/±1 become exact constants."""
    probes = _probe_jacobians(sf, ftype)
    guarded = _guarded_symbols(sf.kernel)
    outputs = list(sf.kernel.outputs)
    structure, pos, m = [], sf.residual_dim, sf.residual_dim
    for k, block in enumerate(sf.variables):
        codes = []
        for i in range(m):
            row = []
            for j in range(block.dim):
                expr = sp.sympify(outputs[pos])
                # an entry through a singular-point convention can be constant at regular
                # points only (a bearing's ∂/∂θ is -1, GTSAM's 0 at the point itself)
                samples = None if probes is None or _is_guarded(expr, guarded) else \
                    np.array([p[k][i, j] for p in probes])
                code = _classify(expr, samples)
                if code != GENERAL:
                    outputs[pos] = sp.Integer(int(code))
                row.append(code)
                pos += 1
            codes.append(tuple(row))
        structure.append(tuple(codes))
    kernel = Kernel(sf.kernel.inputs, sf.kernel.assignments, tuple(outputs))
    kernel = Kernel(kernel.inputs, drop_dead(kernel.assignments, kernel.outputs), kernel.outputs)
    return SymbolicFactor(sf.name, sf.fingerprint, sf.variables, sf.measurements, sf.expression,
                          kernel, tuple(structure))


def _is_guarded(expr: sp.Expr, guarded: set) -> bool:
    return bool(expr.free_symbols & guarded) or expr.has(special.GuardedQuotient)


def _guarded_symbols(kernel: Kernel) -> set:
    """The kernel's intermediates that depend on a :class:`special.GuardedQuotient` (a
    singular-point convention), directly or through other intermediates."""
    guarded: set = set()
    for x, e in kernel.assignments:
        if _is_guarded(e, guarded):
            guarded.add(x)
    return guarded


def _classify(expr: sp.Expr, samples: np.ndarray | None) -> str:
    if expr.is_Number and expr in (0, 1, -1):
        return str(int(expr))
    if samples is None:
        return GENERAL
    for const in (0.0, 1.0, -1.0):
        if np.all(np.abs(samples - const) < _PROBE_TOL):
            return str(int(const))
    return GENERAL


def _probe_jacobians(sf: SymbolicFactor, ftype: FactorType) -> list[list[np.ndarray]] | None:
    """Jacobians at a few random points on the manifold: ``probes[p][k]`` is m × dim_k."""
    rng = np.random.default_rng(20240611)
    out = []
    with np.errstate(all="ignore"):
        for _ in range(_PROBES):
            values = [a.type.random(rng) for a in ftype.variables]
            measured = {a.name: random_measurement(a.type, rng) for a in ftype.measurements}
            _, jacs = sf.evaluate(values, measured)
            if not all(np.all(np.isfinite(j)) for j in jacs):
                return None  # cannot tell from this probe; keep every entry general
            out.append(jacs)
    return out


def random_measurement(t, rng: np.random.Generator) -> np.ndarray:
    """Random storage for a measurement of type ``t`` (valid group elements for geometry)."""
    if t is float:
        return np.array([rng.normal()])
    if isinstance(t, MatrixType):
        return rng.normal(size=t.storage_dim)
    return t.random(rng).storage_array()


# --------------------------------------------------------------------------------------------
# disk cache
# --------------------------------------------------------------------------------------------


@cache
def _code_version() -> str:
    """Hash of the code that shapes a derivation, so an fgc change invalidates the cache."""
    fgc_root = Path(__file__).resolve().parent.parent
    geometry = sorted(f"frontend/geometry/{f.name}"
                      for f in (fgc_root / "frontend" / "geometry").glob("*.py"))
    h = hashlib.sha256(source_digest("compiler/derive.py", "frontend/dsl.py", "compiler/kernel.py",
                                     "frontend/functions.py",
                                     *geometry))
    h.update(sp.__version__.encode())
    return h.hexdigest()[:16]
