"""The user-facing DSL: factors as residual functions, and graphs of typed variables.

A factor type is a Python function decorated with :func:`factor`. Its positional parameters are the
*variables* it connects (annotated with a geometry type such as ``Pose3``); its keyword-only
parameters are *measurements* (annotated with ``float``, a geometry type or :func:`Matrix`). The
function returns the residual; fgc derives every Jacobian::

    @fgc.factor
    def range_factor(pose: Pose3, point: Point3, *, measured: float):
        return [pose.range(point) - measured]

    graph = fgc.Graph()
    graph.add_variable("x1", Pose3.identity())
    graph.add_variable("l1", Point3(1.0, 2.0, 3.0))
    graph.add(range_factor("x1", "l1", measured=3.7, noise=fgc.frontend.noise.isotropic(1, 0.1)))
"""

from __future__ import annotations

import hashlib
import inspect
import re
import sys
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, get_type_hints

import numpy as np
import sympy as sp

from fgc.errors import DataError, DslError, FgcError
from fgc.frontend.functions import check_residual, library_function_error, numpy_on_symbols
from fgc.frontend.geometry import LieGroup, Rot2, Rot3, VectorSpace
from fgc.frontend.noise import NoiseModel

# --------------------------------------------------------------------------------------------
# measurement types
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class MatrixType:
    """Annotation for a matrix-valued measurement of fixed shape (``Matrix(9, 3)``)."""

    rows: int
    cols: int

    @property
    def storage_dim(self) -> int:
        return self.rows * self.cols

    @property
    def __name__(self) -> str:  # used in messages
        return f"Matrix({self.rows}, {self.cols})"

    def symbol(self, prefix: str) -> sp.Matrix:
        return sp.Matrix(self.rows, self.cols,
                         [sp.Symbol(f"{prefix}__{i}_{j}", real=True)
                          for i in range(self.rows) for j in range(self.cols)])


MAX_MATRIX_ENTRIES = 4096  # a measurement matrix is traced symbolically, entry by entry


def Matrix(rows: int, cols: int) -> MatrixType:  # noqa: N802 - reads like a type
    """Annotation for a measurement that is a ``rows × cols`` matrix (positive integer sizes,
    at most :data:`MAX_MATRIX_ENTRIES` entries)."""
    for name, size in (("rows", rows), ("cols", cols)):
        if isinstance(size, bool) or not isinstance(size, (int, np.integer)) or size < 1:
            raise DslError(f"fgc.Matrix {name} must be a positive integer, got {size!r}")
    if rows * cols > MAX_MATRIX_ENTRIES:
        raise DslError(f"fgc.Matrix({rows}, {cols}) has more than {MAX_MATRIX_ENTRIES} entries")
    return MatrixType(int(rows), int(cols))


def type_name(t) -> str:
    return t.__name__ if hasattr(t, "__name__") else str(t)


def storage_dim(t) -> int:
    if t is float:
        return 1
    return t.storage_dim


def symbolic_value(t, prefix: str):
    """A symbolic stand-in for a value of measurement/variable type ``t``."""
    if t is float:
        return sp.Symbol(prefix, real=True)
    return t.symbol(prefix)


def storage_of(t, value, what: str) -> np.ndarray:
    """Flatten a numeric value of type ``t`` to its storage (validated: shape, finiteness)."""
    if t is float:
        if isinstance(value, (LieGroup, np.ndarray)) and np.size(value) != 1:
            raise DataError(f"{what}: expected a number, got {type(value).__name__}")
        arr = np.asarray([float(np.asarray(value).reshape(-1)[0])])
    elif isinstance(t, MatrixType):
        arr = np.asarray(value, dtype=np.float64)
        if arr.shape != (t.rows, t.cols):
            raise DataError(f"{what}: expected a {t.rows}×{t.cols} matrix, got shape {arr.shape}")
        arr = arr.reshape(-1)
    else:
        if isinstance(value, LieGroup) and not isinstance(value, t):
            raise DataError(f"{what}: expected a {t.__name__}, got {type(value).__name__}")
        if not isinstance(value, LieGroup):
            if issubclass(t, VectorSpace):
                value = t(np.asarray(value, dtype=np.float64).reshape(-1))
            else:
                raise DataError(f"{what}: expected a {t.__name__}, got {type(value).__name__}")
        arr = value.storage_array()
    if not np.all(np.isfinite(arr)):
        raise DataError(f"{what} is not finite: {arr.tolist()}")
    if isinstance(value, LieGroup) and _rotation_defect(value) > ROTATION_TOL:
        raise DataError(f"{what} is not a rotation: its rotation part is off by "
                        f"{_rotation_defect(value):.1e} (orthonormal, det +1, to "
                        f"{ROTATION_TOL:g}); re-orthonormalise it")
    return arr


ROTATION_TOL = 1e-6  # max |RᵀR − I| (or |c² + s² − 1|) of a numeric rotation


def _rotation_defect(value: LieGroup) -> float:
    """How far the rotation part of a numeric value is from a rotation (0: none to check)."""
    r = getattr(value, "r", value)  # Pose2 / Pose3 hold their rotation as .r
    if isinstance(r, Rot2):
        return abs(float(r.c) ** 2 + float(r.s) ** 2 - 1.0)
    if isinstance(r, Rot3):
        m = np.asarray(r.R, dtype=np.float64)
        return float(np.abs(m.T @ m - np.eye(3)).max()) if np.linalg.det(m) > 0 else np.inf
    return 0.0


# --------------------------------------------------------------------------------------------
# factor types
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Argument:
    name: str
    type: Any


_GENERATION = [0]  # bumped whenever a Graph is created or grown


class FactorType:
    """A factor definition: a residual function over variables (positional) and measurements."""

    def __init__(self, func, name: str | None = None):
        self.func = func
        self.name = name or func.__name__
        self.variables, self.measurements = _parse_signature(func, self.name)
        self._residual_dim: int | None = None
        self._traced: tuple | None = None

    def __repr__(self) -> str:
        return f"FactorType({self.name!r})"

    # -- definition identity -----------------------------------------------------------------
    def fingerprint(self) -> str:
        """Hash of the definition (source of the function and the helpers it calls, types)."""
        h = hashlib.sha256(self.name.encode())
        for arg in self.variables + self.measurements:
            h.update(f"{arg.name}:{type_name(arg.type)};".encode())
        for src in _function_sources(self.func):
            h.update(src.encode())
        return h.hexdigest()

    # -- tracing -----------------------------------------------------------------------------
    def traced(self) -> tuple[dict, dict, sp.Matrix]:
        """:meth:`trace`, memoised until the next graph is created or grown (a residual may read
        values that a spec's ``build()`` sets before building its graph, so a trace is only
        reused while no graph has changed; the cache key is a digest of it, see
        fgc.compiler.derive)."""
        memo = self._traced
        if memo is None or memo[0] != _GENERATION[0]:
            memo = self._traced = (_GENERATION[0], self.trace())
        return memo[1]

    def trace(self) -> tuple[dict, dict, sp.Matrix]:
        """Call the function on symbolic stand-ins; returns (variables, measurements, residual)."""
        vars_ = {a.name: symbolic_value(a.type, a.name) for a in self.variables}
        meas = {a.name: symbolic_value(a.type, a.name) for a in self.measurements}
        try:
            with _truth_of_symbols_forbidden():
                out = self.func(*vars_.values(), **meas)
        except TypeError as exc:
            if (error := library_function_error(self.name, exc)) is not None:
                raise error from None
            if (numpy_error := numpy_on_symbols(self.name, exc)) is not None:
                raise numpy_error from None
            if _is_symbolic_branch(exc):
                raise DslError(
                    f"factor '{self.name}': the residual function used a symbolic value in a "
                    f"Python condition or float conversion ({exc}); residuals must be "
                    "straight-line math on the variables (no `if` on variables, no math.*)"
                ) from None
            raise DslError(f"factor '{self.name}': calling the residual function failed: {exc}") \
                from exc
        except FgcError as exc:  # e.g. a geometry DataError: say which factor's function raised it
            if str(exc).startswith(f"factor '{self.name}'"):
                raise
            raise type(exc)(f"factor '{self.name}' ({self._signature()}): {exc}") from exc
        except Exception as exc:
            if (error := library_function_error(self.name, exc)) is not None:
                raise error from None
            if (numpy_error := numpy_on_symbols(self.name, exc)) is not None:
                raise numpy_error from None
            if type(exc).__name__ == "ShapeError":  # sympy's, on values of different sizes
                raise DslError(self._shape_message(exc)) from None
            raise DslError(f"factor '{self.name}': calling the residual function failed: "
                           f"{type(exc).__name__}: {exc}") from exc
        return vars_, meas, check_residual(self.name, residual_vector(out, self.name))

    def _signature(self) -> str:
        """``pose: Pose2, beacon: Point3; measured: float`` (the annotations, for messages)."""
        def show(args):
            return ", ".join(f"{a.name}: {type_name(a.type)}" for a in args)
        return show(self.variables) + (f"; {show(self.measurements)}" if self.measurements
                                       else "")

    def _shape_message(self, exc: Exception) -> str:
        """A size mismatch while tracing, with the arguments of each size it involves (a Point2
        variable annotated Point3 meets a Pose2's 2-vector: both are named, with their types)."""
        sizes = [int(n) for n in re.findall(r"\((\d+), 1\)", str(exc))]
        groups = []
        for size in dict.fromkeys(sizes):
            args = [a for a in self.variables + self.measurements if _extent(a.type) == size]
            if args:
                groups.append(f"{size}D: " + ", ".join(f"'{a.name}' ({type_name(a.type)})"
                                                       for a in args))
        which = ("; ".join(groups) + "; one of these annotations is likely wrong (e.g. a Point2 "
                 "variable annotated Point3)") if len(groups) > 1 else (
            f"the annotations are {self._signature()}")
        return (f"factor '{self.name}': the residual function combines vectors of different "
                f"sizes (sympy: {exc}): {which}")

    @property
    def residual_dim(self) -> int:
        if self._residual_dim is None:
            self._residual_dim = self.trace()[2].rows
        return self._residual_dim

    # -- instances ---------------------------------------------------------------------------
    def __call__(self, *keys, noise: NoiseModel | None = None, name: str | None = None,
                 source=None, **measured) -> Factor:
        """A factor of this type on variable ``keys`` with measurements given by keyword.

        ``source`` optionally records where the measurements came from (e.g. the IMU
        preintegration object), for the GTSAM bridge."""
        if noise is None:
            raise DslError(f"factor '{name or self.name}' on {list(keys)}: no noise model; pass "
                           "noise=fgc.noise.isotropic(d, sigma) (or diagonal / covariance), d "
                           "the residual's dimension")
        return Factor.create(self, keys, measured, noise, name, source)


def _extent(t) -> int | None:
    """The size of the vectors a value of type ``t`` takes part in (a pose's translation)."""
    if t is float:
        return 1
    if isinstance(t, MatrixType):
        return t.rows
    if isinstance(t, type) and issubclass(t, VectorSpace):
        return t.dim
    return {"Pose2": 2, "Rot2": 2, "Pose3": 3, "Rot3": 3}.get(getattr(t, "__name__", ""))


def _parse_signature(func, name: str) -> tuple[tuple[Argument, ...], tuple[Argument, ...]]:
    sig = inspect.signature(func)
    try:
        hints = get_type_hints(func)
    except Exception:  # annotations that are not importable names: fall back to raw ones
        hints = {p.name: p.annotation for p in sig.parameters.values()}
    variables, measurements = [], []
    for p in sig.parameters.values():
        ann = hints.get(p.name, p.annotation)
        if ann is inspect.Parameter.empty:
            raise DslError(f"factor '{name}': argument '{p.name}' needs a type annotation")
        if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD):
            if not (isinstance(ann, type) and issubclass(ann, LieGroup)):
                raise DslError(f"factor '{name}': variable argument '{p.name}' must be annotated "
                               f"with a geometry type (Pose3, Point3, ...), got {ann!r}")
            variables.append(Argument(p.name, ann))
        elif p.kind == p.KEYWORD_ONLY:
            ok = ann is float or isinstance(ann, MatrixType) or (
                isinstance(ann, type) and issubclass(ann, LieGroup))
            if not ok:
                raise DslError(f"factor '{name}': measurement '{p.name}' must be annotated with "
                               f"float, a geometry type or fgc.Matrix(r, c), got {ann!r}")
            measurements.append(Argument(p.name, ann))
        else:
            raise DslError(f"factor '{name}': *args/**kwargs are not supported ('{p.name}')")
    if not variables:
        raise DslError(f"factor '{name}' has no variable arguments")
    return tuple(variables), tuple(measurements)


# Modules whose source is already part of the derivation's code version (fgc.compiler.derive), or
# that are third-party: functions from them are not hashed into a factor's fingerprint.
_NOT_FINGERPRINTED = ("fgc.frontend.dsl", "fgc.compiler.derive", "fgc.frontend.geometry", "sympy",
                      "numpy")
_SCALARS = (bool, int, float, complex, str, bytes, type(None))


def _function_sources(func, seen: set | None = None) -> list[str]:
    """Source of ``func`` and of the functions and constants it references, transitively.

    Referenced functions are module-level names or closure cells (a factory's inner helpers);
    constants are scalars, tuples of scalars and arrays read from globals or closure cells (a
    factory's parameters, a module-level ``SCALE = 2.0``), so changing any of them re-derives."""
    seen = seen if seen is not None else set()
    if func in seen:
        return []
    seen.add(func)
    try:
        out = [inspect.getsource(func)]
    except (OSError, TypeError):
        out = [repr(func.__code__.co_code)]
    refs = [(name, func.__globals__[name]) for name in sorted(func.__code__.co_names)
            if name in func.__globals__]
    for name, cell in zip(func.__code__.co_freevars, func.__closure__ or (), strict=True):
        try:
            refs.append((name, cell.cell_contents))
        except ValueError:  # cell not filled yet
            continue
    for name, ref in refs:
        if inspect.isfunction(ref):
            if not ref.__module__.startswith(_NOT_FINGERPRINTED):
                out += _function_sources(ref, seen)
        elif (isinstance(ref, _SCALARS) or isinstance(ref, tuple)
              and all(isinstance(x, _SCALARS) for x in ref)):
            out.append(f"{name}={ref!r}")
        elif isinstance(ref, np.ndarray):
            out.append(f"{name}=ndarray({ref.dtype},{ref.shape},"
                       f"{hashlib.sha256(ref.tobytes()).hexdigest()})")
    return out


class _SymbolTruthError(TypeError):
    pass


_LIBRARY_CALLERS = ("sympy", "numpy", "fgc.")


def _no_truth_value(self):
    # sympy's own code relies on every non-numeric expression being truthy (e.g. "if Cij:" in
    # matrix products); only a truth test written in the user's residual function is an error.
    caller = sys._getframe(1).f_globals.get("__name__", "")
    if caller.startswith(_LIBRARY_CALLERS):
        return True
    raise _SymbolTruthError(f"cannot determine the truth value of symbolic {self}")


@contextmanager
def _truth_of_symbols_forbidden():
    """While tracing, ``if x:`` / ``bool(x)`` on a non-constant symbolic value raises.

    sympy gives every expression the default truth value True, so ``if pose.x():`` would silently
    take one branch; comparisons (``x > 0``) already raise in sympy itself.
    """
    classes = (sp.Symbol, sp.Add, sp.Mul, sp.Pow, sp.Function)
    saved = {c: c.__dict__.get("__bool__") for c in classes}
    for c in classes:
        c.__bool__ = _no_truth_value
    try:
        yield
    finally:
        for c, old in saved.items():
            if old is None:
                del c.__bool__
            else:
                c.__bool__ = old


def _is_symbolic_branch(exc: TypeError) -> bool:
    if isinstance(exc, _SymbolTruthError):
        return True
    msg = str(exc)
    return "truth value" in msg or "convert" in msg and "float" in msg or "Relational" in msg


def residual_vector(out, factor_name: str) -> sp.Matrix:
    """Normalise a residual function's result to a sympy column vector."""
    if isinstance(out, VectorSpace):
        out = out.v
    elif isinstance(out, LieGroup):
        raise DslError(f"factor '{factor_name}' returned a {type(out).__name__}; return a vector "
                       "such as measured.local(prediction)")
    if isinstance(out, (sp.Expr, int, float)):
        out = [out]
    try:
        vec = sp.Matrix(out) if not isinstance(out, np.ndarray) else sp.Matrix(list(out.ravel()))
    except (TypeError, ValueError) as exc:
        raise DslError(f"factor '{factor_name}': the residual must be a vector, got "
                       f"{type(out).__name__} ({exc})") from None
    if vec.cols != 1:
        if vec.rows == 1:
            vec = vec.T
        else:
            raise DslError(f"factor '{factor_name}': the residual must be a vector, got a "
                           f"{vec.rows}×{vec.cols} matrix")
    if vec.rows == 0:
        raise DslError(f"factor '{factor_name}' returned an empty residual")
    return vec


def factor(func=None, *, name: str | None = None):
    """Decorator turning a residual function into a :class:`FactorType`."""
    if func is None:
        return lambda f: FactorType(f, name)
    return FactorType(func, name)


# --------------------------------------------------------------------------------------------
# graph
# --------------------------------------------------------------------------------------------


Key = str | int


@dataclass(frozen=True)
class Factor:
    """One factor in a graph: a factor type applied to variable keys, with data and noise."""

    type: FactorType
    keys: tuple
    measured: dict = field(compare=False)  # name → storage array (validated, finite)
    noise: NoiseModel
    name: str
    source: object = field(default=None, compare=False, repr=False)

    @classmethod
    def create(cls, ftype: FactorType, keys, measured: dict, noise, name, source=None) -> Factor:
        label = name or ftype.name
        if len(keys) != len(ftype.variables):
            raise DslError(f"factor '{label}' takes {len(ftype.variables)} variable keys "
                           f"({', '.join(a.name for a in ftype.variables)}), got {len(keys)}")
        for k in keys:
            _check_key(k, f"factor '{label}'")
        known = {a.name: a for a in ftype.measurements}
        unknown = sorted(set(measured) - set(known))
        if unknown:
            raise DslError(f"factor '{label}': unknown measurement argument(s) {unknown}; "
                           f"expected {sorted(known)}")
        missing = sorted(set(known) - set(measured))
        if missing:
            raise DslError(f"factor '{label}': missing measurement argument(s) {missing}")
        data = {a: storage_of(known[a].type, measured[a], f"factor '{label}' measurement '{a}'")
                for a in known}
        if not isinstance(noise, NoiseModel):
            raise DslError(f"factor '{label}': noise must be an fgc.frontend.noise model, got "
                           f"{type(noise).__name__}")
        if noise.dim != ftype.residual_dim:
            raise DslError(f"factor '{label}': noise model has dimension {noise.dim} but the "
                           f"residual has {ftype.residual_dim} rows")
        return cls(ftype, tuple(keys), data, noise, label, source)


def _check_key(k, where: str) -> None:
    if isinstance(k, bool) or not isinstance(k, (str, int)):
        raise DslError(f"{where}: variable keys must be str or int, got {k!r}")


@dataclass
class Variable:
    key: Key
    type: type
    initial: LieGroup


class Graph:
    """Typed variables with initial values, and the factors between them."""

    def __init__(self):
        self.variables: dict[Key, Variable] = {}
        self.factors: list[Factor] = []
        _GENERATION[0] += 1  # factor traces taken before are not reused (FactorType.traced)

    def add_variable(self, key: Key, initial: LieGroup, type_: type | None = None) -> Graph:
        """Add variable ``key`` with its initial value (its type is the value's class)."""
        _check_key(key, f"variable {key!r}")
        if key in self.variables:
            raise DslError(f"duplicate variable key {key!r}")
        t = type_ or type(initial)
        if not (isinstance(t, type) and issubclass(t, LieGroup)):
            raise DslError(f"variable {key!r}: initial value must be a geometry value, got "
                           f"{type(initial).__name__}")
        storage_of(t, initial, f"variable {key!r} initial value")
        if not isinstance(initial, t):
            initial = t.from_storage(storage_of(t, initial, f"variable {key!r}"))
        self.variables[key] = Variable(key, t, initial)
        return self

    def add(self, f: Factor) -> Graph:
        """Add a factor; its keys must name variables of the types the factor expects."""
        if not isinstance(f, Factor):
            raise DslError(f"Graph.add expects a factor, got {type(f).__name__}")
        self._check_factor(f)
        self.factors.append(f)
        _GENERATION[0] += 1
        return self

    def _check_factor(self, f: Factor) -> None:
        if len(set(f.keys)) != len(f.keys):
            raise DslError(f"factor '{f.name}' uses a key twice: {list(f.keys)}")
        for key, arg in zip(f.keys, f.type.variables, strict=True):
            var = self.variables.get(key)
            if var is None:
                raise DslError(f"factor '{f.name}': unknown variable key {key!r} "
                               f"(argument '{arg.name}'); add it with Graph.add_variable first")
            if var.type is not arg.type:
                raise DslError(f"factor '{f.name}': variable {key!r} is a {var.type.__name__} "
                               f"but argument '{arg.name}' expects a {arg.type.__name__}")

    def error(self, values: dict | None = None) -> float:
        """Total error Σ ½‖R r‖² (GTSAM's ``graph.error``) at ``values`` (default: initial)."""
        from fgc.compiler.derive import derive  # late import: derive is heavier than the DSL

        total = 0.0
        for f in self.factors:
            vals = [self._value(values, k) for k in f.keys]
            r = derive(f.type).evaluate_residual(vals, f.measured)
            total += f.noise.error(r)
        return total

    def _value(self, values, key):
        if values is not None and key in values:
            return values[key]
        return self.variables[key].initial

    def __repr__(self) -> str:
        return f"Graph({len(self.variables)} variables, {len(self.factors)} factors)"
