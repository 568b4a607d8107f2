"""The GTSAM bridge: an fgc Graph as a ``gtsam.NonlinearFactorGraph`` + ``Values``, and checks.

This is one of the few places fgc imports gtsam on purpose (docs/design.md, "Verification").
Built-in factors become GTSAM's own factor of the same meaning (``BetweenFactorPose3``,
``CombinedImuFactor`` re-integrated from the raw IMU samples, ...), so a comparison is between two
independent implementations. A user-written factor (one GTSAM does not ship) becomes a
``gtsam.CustomFactor`` that uses nothing of fgc's derivation: it calls the user's residual function
itself on numbers (fgc geometry values built from GTSAM's values, measurements as NumPy arrays) and
takes its Jacobians by central differences along GTSAM's retraction (:func:`numeric_residual`,
:data:`FD_STEP`). A stale or wrong derived kernel therefore shows up as a linearisation difference
above :data:`FD_TOLERANCE`, and as a different optimum.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np
import sympy as sp

from fgc.compiler.derive import derive
from fgc.errors import FgcError, caused_by_interrupt
from fgc.frontend.dsl import Factor, Graph, MatrixType
from fgc.frontend.geometry import (
    ImuBias,
    LieGroup,
    Point2,
    Point3,
    Pose2,
    Pose3,
    Rot2,
    Rot3,
    VectorSpace,
)
from fgc.frontend.noise import NoiseModel
from fgc.interop import twins


def _gtsam():
    try:
        import gtsam
    except ImportError as exc:  # pragma: no cover - gtsam is a core dependency
        if caused_by_interrupt(exc):  # Ctrl-C while its extension initialised: not missing
            raise KeyboardInterrupt from exc
        raise FgcError("the GTSAM bridge needs the 'gtsam' package (pip install gtsam)") from exc
    return gtsam


# --------------------------------------------------------------------------------------------
# values
# --------------------------------------------------------------------------------------------


def value_to_gtsam(value: LieGroup):
    """fgc value → the GTSAM object of the same meaning."""
    gtsam = _gtsam()
    if isinstance(value, Pose3):
        return gtsam.Pose3(gtsam.Rot3(value.r.R), np.asarray(value.t, float))
    if isinstance(value, Pose2):
        return gtsam.Pose2(float(value.x()), float(value.y()), float(value.theta()))
    if isinstance(value, Rot3):
        return gtsam.Rot3(value.R)
    if isinstance(value, Rot2):
        return gtsam.Rot2.fromCosSin(float(value.c), float(value.s))
    if isinstance(value, ImuBias):
        return gtsam.imuBias.ConstantBias(value.v[:3], value.v[3:])
    if isinstance(value, VectorSpace):
        return np.asarray(value.v, dtype=float)
    raise FgcError(f"no GTSAM type for {type(value).__name__}")


def value_from_gtsam(t: type[LieGroup], obj) -> LieGroup:
    """GTSAM object → fgc value of type ``t``."""
    if t is Pose3:
        return Pose3(Rot3(obj.rotation().matrix()), obj.translation())
    if t is Pose2:
        return Pose2(obj.x(), obj.y(), obj.theta())
    if t is Rot3:
        return Rot3(obj.matrix())
    if t is Rot2:
        return Rot2(obj.c(), obj.s())
    if t is ImuBias:
        return ImuBias(np.concatenate([obj.accelerometer(), obj.gyroscope()]))
    return t(np.asarray(obj, dtype=float).reshape(-1))


def _read_value(values, t: type[LieGroup], key: int) -> LieGroup:
    gtsam = _gtsam()
    readers = {Pose3: values.atPose3, Pose2: values.atPose2, Rot3: values.atRot3,
               Rot2: values.atRot2, ImuBias: values.atConstantBias}
    if t in readers:
        return value_from_gtsam(t, readers[t](key))
    if t in (Point2, Point3) or issubclass(t, VectorSpace):
        return value_from_gtsam(t, values.atVector(key) if t not in (Point2, Point3)
                                else (values.atPoint2 if t is Point2 else values.atPoint3)(key))
    raise FgcError(f"cannot read a {t.__name__} from gtsam.Values ({gtsam.__name__})")


_SYMBOL_KEY = re.compile(r"([A-Za-z])(\d+)")


def gtsam_key(key) -> int | None:
    """The GTSAM key an fgc key stands for: an int is itself, a string that is a letter and an
    index (``"x1"``, ``"l5"``: how :func:`fgc.from_gtsam` and the dataset reader name a
    ``gtsam.Symbol``) is that Symbol's key; None for any other key (``"landmark"``)."""
    if isinstance(key, (int, np.integer)) and not isinstance(key, bool):
        return int(key) if 0 <= key < 2**64 else None
    m = _SYMBOL_KEY.fullmatch(key) if isinstance(key, str) else None
    if m is None or int(m.group(2)) >= 2**56:  # a Symbol keeps 56 bits for the index
        return None
    return int(_gtsam().Symbol(m.group(1), int(m.group(2))).key())


def values_to_gtsam(values: dict, keys: dict | None = None):
    """fgc values {key: value} (a solve's ``result.user_values``, ``graph_values``) as a
    ``gtsam.Values`` under the user's keys: an int key stays that int, ``"x1"`` / ``"l5"``
    become ``gtsam.Symbol('x', 1)`` / ``Symbol('l', 5)`` (:func:`gtsam_key`); ``keys``
    {fgc key: GTSAM key} names any other key (FgcError naming a key that has neither)."""
    gtsam = _gtsam()
    out, used = gtsam.Values(), {}
    for k, v in values.items():
        g = (keys or {}).get(k, gtsam_key(k))
        if g is None:
            raise FgcError(f"variable {k!r}: no GTSAM key for it (GTSAM keys are ints or "
                           "Symbols such as 'x1'); pass keys={fgc key: GTSAM key}")
        if g in used:
            raise FgcError(f"variables {used[g]!r} and {k!r} map to the same GTSAM key {g}")
        used[g] = k
        out.insert(int(g), value_to_gtsam(v))
    return out


# --------------------------------------------------------------------------------------------
# noise and factors
# --------------------------------------------------------------------------------------------


def noise_to_gtsam(noise: NoiseModel):
    gtsam = _gtsam()
    r = noise.sqrt_information
    if noise.kind == "isotropic":
        base = gtsam.noiseModel.Isotropic.Sigma(noise.dim, 1.0 / r[0, 0])
    elif noise.kind == "diagonal":
        base = gtsam.noiseModel.Diagonal.Sigmas(1.0 / np.diag(r))
    else:
        base = gtsam.noiseModel.Gaussian.SqrtInformation(r)
    if noise.robust is None:
        return base
    est = gtsam.noiseModel.mEstimator
    loss = (est.Huber if noise.robust.kind == "huber" else est.Cauchy).Create(noise.robust.k)
    return gtsam.noiseModel.Robust.Create(loss, base)


def twin_name(kind) -> str | None:
    """The GTSAM class of a built-in factor kind (``FactorType.gtsam_kind``), from the one twin
    table (:mod:`fgc.interop.twins`); ``None``: GTSAM's side is a numeric CustomFactor."""
    if kind is None:
        return None
    name, arg = kind
    if name == "prior":
        return twins.PRIOR.get(twins.table_key(arg))
    if name == "between":
        return twins.BETWEEN.get(twins.table_key(arg))
    if name == "range":
        return twins.RANGE.get(tuple(arg))
    return {"gps": twins.GPS, "bearing_range": twins.BEARING_RANGE,
            "combined_imu": twins.COMBINED_IMU}.get(name)


def factor_to_gtsam(f: Factor, keys: dict, graph: Graph):
    """One fgc factor → a GTSAM factor (native twin for built-ins, CustomFactor otherwise)."""
    gtsam = _gtsam()
    kind = getattr(f.type, "gtsam_kind", None)
    ks = [keys[k] for k in f.keys]
    noise = noise_to_gtsam(f.noise)
    types = [graph.variables[k].type for k in f.keys]
    if kind is not None:
        name, arg = kind
        twin = twin_name(kind)
        if name == "prior" and twin:
            val = types[0].from_storage(f.measured["prior"])
            return getattr(gtsam, twin)(ks[0], value_to_gtsam(val), noise)
        if name == "between" and twin:
            val = types[0].from_storage(f.measured["measured"])
            return getattr(gtsam, twin)(ks[0], ks[1], value_to_gtsam(val), noise)
        if name == "range" and twin:
            measured = float(np.asarray(f.measured["measured"], float).ravel()[0])
            return getattr(gtsam, twin)(ks[0], ks[1], measured, noise)
        if name == "gps":
            return gtsam.GPSFactor(ks[0], f.measured["position"], noise)
        if name == "bearing_range":
            bearing = Rot2(*f.measured["bearing"])
            return gtsam.BearingRangeFactor2D(ks[0], ks[1], value_to_gtsam(bearing),
                                              float(f.measured["range"][0]), noise)
        if name == "combined_imu" and f.source is not None:
            return _imu_to_gtsam(f, ks, arg)
    return _custom_factor(f, ks, noise)


def _imu_to_gtsam(f: Factor, ks: list[int], error_mode: str):
    """Re-integrate the factor's raw IMU samples with GTSAM and build its CombinedImuFactor."""
    gtsam = _gtsam()
    pim = f.source
    p = pim.params
    params = gtsam.PreintegrationCombinedParams(np.asarray(p.n_gravity, float))
    params.setAccelerometerCovariance(p.accelerometer_covariance)
    params.setGyroscopeCovariance(p.gyroscope_covariance)
    params.setIntegrationCovariance(p.integration_covariance)
    params.setBiasAccCovariance(p.bias_acc_covariance)
    params.setBiasOmegaCovariance(p.bias_omega_covariance)
    mode = {"logmap": gtsam.ImuFactorErrorMode.Logmap,
            "componentwise": gtsam.ImuFactorErrorMode.ComponentWise}[error_mode]
    params.setImuFactorErrorMode(mode)
    bias = gtsam.imuBias.ConstantBias(pim.bias_hat[:3], pim.bias_hat[3:])
    gpim = gtsam.PreintegratedCombinedMeasurements(params, bias)
    for acc, gyro, dt in pim.samples:
        gpim.integrateMeasurement(acc, gyro, dt)
    return gtsam.CombinedImuFactor(*ks, gpim)


def _custom_factor(f: Factor, ks: list[int], noise):
    """A gtsam.CustomFactor evaluating the user's residual function on numbers, with
    central-difference Jacobians (nothing of fgc's derivation)."""
    gtsam = _gtsam()
    types = [a.type for a in f.type.variables]
    measured = numeric_measurements(f)
    check_numeric_evaluation(f)

    def error(this, values, jacobians):
        gvals = [_read_gtsam(values, t, k) for t, k in zip(types, this.keys(), strict=True)]
        vals = [value_from_gtsam(t, g) for t, g in zip(types, gvals, strict=True)]
        r = numeric_residual(f, vals, measured)
        if jacobians is not None:
            for i, (t, g) in enumerate(zip(types, gvals, strict=True)):
                jacobians[i] = _central_differences(f, vals, i, t, g, measured)
        return r

    return gtsam.CustomFactor(noise, ks, error)


# --------------------------------------------------------------------------------------------
# user residual functions on numbers (the independent side of a custom factor)
# --------------------------------------------------------------------------------------------

# Central differences (r(x ⊕ h e_j) − r(x ⊕ −h e_j)) / 2h along GTSAM's retraction: truncation
# error ~h²·|r‴|/6 ≈ 2e-11, rounding ~eps·|r|/h ≈ 2e-11·|r|. For a vector-space variable h is
# scaled by its magnitude (a point 1e3 m away gets h = 1e-2).
FD_STEP = 1e-5
# Largest accepted difference between fgc's derived, whitened (A, b) and the central-difference
# one, relative to max(1, |A|max, |b|max) (the finite differences' own error is ~1e-10).
FD_TOLERANCE = 1e-6


class NumericMatrix(np.ndarray):
    """A measurement of ``fgc.Matrix`` type as numbers, with the meaning sympy gives it while
    tracing: ``*`` between two arrays is the matrix product, ``H[k]`` the k-th entry in row-major
    order, and ``rows``/``cols``/``row``/``col``/``inv``/``det``/``norm`` as on a sympy Matrix."""

    def __new__(cls, values):
        return np.asarray(values, dtype=np.float64).view(cls)

    def __mul__(self, other):
        if np.ndim(other) == 0:
            return np.multiply(self, other)
        return np.asarray(np.asarray(self) @ np.asarray(other))

    def __rmul__(self, other):
        if np.ndim(other) == 0:
            return np.multiply(other, self)
        return np.asarray(np.asarray(other) @ np.asarray(self))

    def __getitem__(self, key):
        if isinstance(key, (int, np.integer)) and self.ndim == 2:
            return np.asarray(self).reshape(-1)[key]
        return super().__getitem__(key)

    @property
    def rows(self) -> int:
        return self.shape[0]

    @property
    def cols(self) -> int:
        return self.shape[1] if self.ndim == 2 else 1

    def row(self, i: int):
        return NumericMatrix(np.asarray(self)[i, :].reshape(1, -1))

    def col(self, j: int):
        return NumericMatrix(np.asarray(self)[:, j].reshape(-1, 1))

    def inv(self):
        return NumericMatrix(np.linalg.inv(np.asarray(self)))

    def det(self):
        return float(np.linalg.det(np.asarray(self)))

    def norm(self):
        return float(np.linalg.norm(np.asarray(self)))


def _numeric_measurement(t, storage: np.ndarray):
    if t is float:
        return float(storage[0])
    if isinstance(t, MatrixType):
        return NumericMatrix(np.asarray(storage, dtype=np.float64).reshape(t.rows, t.cols))
    return t.from_storage(np.asarray(storage, dtype=np.float64))


def numeric_measurements(f: Factor) -> dict:
    """The factor's measurements as numbers of their declared types (float, a geometry value,
    a :class:`NumericMatrix` for ``fgc.Matrix``)."""
    return {a.name: _numeric_measurement(a.type, f.measured[a.name])
            for a in f.type.measurements}


def numeric_residual(f: Factor, values: list, measured: dict | None = None) -> np.ndarray:
    """The user's residual function of ``f`` called on numeric fgc values: a float64 vector.

    Raises FgcError naming the factor when the function does not run on numbers or returns
    something that is not a vector of the factor's residual dimension."""
    measured = numeric_measurements(f) if measured is None else measured
    ftype = f.type
    try:
        r = _as_float_vector(ftype.func(*values, **measured))
    except Exception as exc:
        raise FgcError(_cannot_run(f, f"{type(exc).__name__}: {exc}")) from None
    if r.shape != (ftype.residual_dim,):
        raise FgcError(_cannot_run(f, f"on numbers it returned {r.size} entries, on fgc's "
                                      f"symbolic stand-ins {ftype.residual_dim}"))
    return r


def _cannot_run(f: Factor, why: str) -> str:
    return (f"fgc verify cannot check factor '{f.name}' ({f.type.name}) independently: its "
            f"residual function does not run on numeric values ({why}); the GTSAM side calls it "
            "on numbers (fgc geometry values, NumPy arrays for fgc.Matrix measurements)")


def _as_float_vector(out) -> np.ndarray:
    if isinstance(out, VectorSpace):
        out = out.v
    elif isinstance(out, LieGroup):
        raise FgcError(f"it returned a {type(out).__name__}; return a vector")
    if isinstance(out, sp.MatrixBase):
        out = list(out)
    arr = np.asarray(out, dtype=object)
    if arr.ndim == 2 and 1 in arr.shape:
        arr = arr.reshape(-1)
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim != 1:
        raise FgcError(f"the residual must be a vector, got shape {list(arr.shape)}")
    return np.array([float(x) for x in arr], dtype=np.float64)


def check_numeric_evaluation(f: Factor, rtol: float = 1e-9) -> None:
    """Check, once per factor type, that the residual function means the same on numbers as on
    fgc's symbolic stand-ins, at random values near the identity and ``f``'s measurements.

    A construct whose meaning differs (``*`` of two NumPy vectors is element-wise, of two sympy
    matrices a product) would otherwise make the independent side silently wrong. The symbolic
    side here is a fresh trace of the function (not the derived kernel, not the cache)."""
    ftype = f.type
    if getattr(ftype, "_numeric_check_passed", False):  # once per factor type object
        return
    rng = np.random.default_rng(0)
    values = [a.type.identity().retract(rng.normal(size=a.type.dim) * 0.3)
              for a in ftype.variables]
    numeric = numeric_residual(f, values)
    vars_, meas, residual = ftype.trace()
    subs = {}
    for a, v in zip(ftype.variables, values, strict=True):
        for sym, num in zip(vars_[a.name].to_storage(), v.storage_array(), strict=True):
            subs[sym] = sp.Float(float(num), 30)
    for a in ftype.measurements:
        stand_in, storage = meas[a.name], f.measured[a.name]
        syms = [stand_in] if a.type is float else (
            list(stand_in) if isinstance(a.type, MatrixType) else stand_in.to_storage())
        for sym, num in zip(syms, storage, strict=True):
            subs[sym] = sp.Float(float(num), 30)
    try:
        traced = np.array([complex(e.xreplace(subs).evalf(20)).real for e in residual])
    except (TypeError, ValueError) as exc:
        raise FgcError(_cannot_run(f, f"its symbolic trace does not reduce to numbers for the "
                                      f"comparison: {exc}")) from None
    scale = max(1.0, float(np.abs(traced).max()))
    diff = float(np.abs(numeric - traced).max()) / scale
    if not diff <= rtol and np.all(np.isfinite(traced)):
        raise FgcError(_cannot_run(f, f"on numbers it gives {numeric.tolist()}, on fgc's "
                                      f"symbolic stand-ins {traced.tolist()} at the same values; "
                                      "a construct means something else in NumPy than in "
                                      "sympy, e.g. `*` of two vectors"))
    ftype._numeric_check_passed = True


def _read_gtsam(values, t: type[LieGroup], key: int):
    readers = {Pose3: values.atPose3, Pose2: values.atPose2, Rot3: values.atRot3,
               Rot2: values.atRot2, ImuBias: values.atConstantBias, Point2: values.atPoint2,
               Point3: values.atPoint3}
    return readers[t](key) if t in readers else values.atVector(key)


def _central_differences(f: Factor, vals: list, i: int, t: type[LieGroup], g,
                         measured: dict) -> np.ndarray:
    """∂r/∂δ_i by central differences, δ_i in the tangent space of variable ``i`` as GTSAM
    retracts it (``g.retract(δ)`` for rotations and poses, addition for vector spaces)."""
    lie = t in (Pose3, Pose2, Rot3, Rot2)
    h = FD_STEP if lie else FD_STEP * max(1.0, float(np.abs(vals[i].storage_array()).max()))
    cols = []
    for j in range(t.dim):
        step = np.zeros(t.dim)
        step[j] = h
        out = []
        for d in (step, -step):
            moved = value_from_gtsam(t, g.retract(d)) if lie else vals[i].retract(d)
            out.append(numeric_residual(f, [*vals[:i], moved, *vals[i + 1:]], measured))
        cols.append((out[0] - out[1]) / (2 * h))
    return np.column_stack(cols)


# --------------------------------------------------------------------------------------------
# graphs
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class GtsamProblem:
    """A graph translated to GTSAM; ``keys`` maps fgc keys to GTSAM's integer keys."""

    graph: object
    values: object
    keys: dict


def to_gtsam(graph: Graph, values: dict | None = None) -> GtsamProblem:
    """Convert an fgc graph (and optionally other values than its initial ones) to GTSAM."""
    gtsam = _gtsam()
    keys = {k: i for i, k in enumerate(graph.variables)}
    gvalues = gtsam.Values()
    for k, var in graph.variables.items():
        v = values[k] if values is not None and k in values else var.initial
        gvalues.insert(keys[k], value_to_gtsam(v))
    gg = gtsam.NonlinearFactorGraph()
    for f in graph.factors:
        gg.add(factor_to_gtsam(f, keys, graph))
    return GtsamProblem(gg, gvalues, keys)


def values_from_gtsam(graph: Graph, problem: GtsamProblem, gvalues) -> dict:
    """GTSAM Values → {fgc key: fgc value} for the variables of ``graph``."""
    return {k: _read_value(gvalues, var.type, problem.keys[k])
            for k, var in graph.variables.items()}


def is_custom(ftype) -> bool:
    """Whether GTSAM's side of a factor type is the numeric CustomFactor (no native twin)."""
    kind = getattr(ftype, "gtsam_kind", None)
    return twin_name(kind) is None


@dataclass(frozen=True)
class LinearizationCheck:
    """fgc's whitened (A, b) of every factor of one type against GTSAM's: the largest relative
    difference, the tolerance it is held to and what GTSAM's side is.

    Only custom factors have a tolerance (:data:`FD_TOLERANCE`): a built-in is compared with
    GTSAM's own factor, whose Jacobians can be inexact (GTSAM 4.3's BetweenFactorPose2 on
    w10000.graph's initial values: b agrees to 3e-12, A differs by up to 4e-3 where the rotation
    residual is ~2e-5 rad and the translation residual ~4 m; central differences of GTSAM's own
    error agree with fgc's A, not GTSAM's), so its difference is reported, and the factor is
    judged by the optimum it leads to."""

    factor_type: str
    factors: int  # factors compared
    error: float
    tolerance: float | None
    custom: bool
    # custom factors at a singular point of their residual (coincident points of a norm or a
    # bearing): not differentiable there, fgc's Jacobian is GTSAM's convention and central
    # differences are no reference, so only their residual b is compared
    singular: int = 0
    sampled: bool = False  # a built-in type checked on an evenly spaced sample of its factors

    @property
    def passed(self) -> bool | None:
        return None if self.tolerance is None else bool(self.error <= self.tolerance)

    @property
    def method(self) -> str:
        return ("numerical derivatives (central differences)" if self.custom
                else "GTSAM's own factor")


def linearization_checks(graph: Graph, values: dict | None = None,
                         problem: GtsamProblem | None = None,
                         builtin_sample: int | None = None) -> list[LinearizationCheck]:
    """Per factor type, in order of first appearance: the largest relative difference between
    fgc's and GTSAM's whitened linearisation (A, b) of its factors at ``values`` (default: the
    initial values), relative to max(1, |A|max, |b|max).

    ``builtin_sample``: a built-in type (reported, never judged: see
    :class:`LinearizationCheck`) with more factors than this is compared on that many of them,
    evenly spaced (:func:`sample_factors`); a custom type always on all of its factors."""
    problem = problem if problem is not None else to_gtsam(graph, values)
    worst: dict[str, list] = {}
    chosen = None
    if builtin_sample is not None:
        chosen = set(sample_factors(graph, builtin_sample))
    for i, f in enumerate(graph.factors):
        custom = is_custom(f.type)
        if chosen is not None and not custom and i not in chosen:
            worst.setdefault(f.type.name, [0, 0.0, custom, 0, False])[4] = True
            continue
        point = [_value(graph, values, k) for k in f.keys]
        a_fgc, b_fgc = linearize_factor(f, point)
        a_g, b_g = problem.graph.at(i).linearize(problem.values).jacobian()
        singular = custom and singular_at(f, point)
        scale = max(1.0, np.abs(a_g).max(), np.abs(b_g).max())
        err = np.abs(b_fgc - b_g).max() / scale
        if not singular:
            err = max(np.abs(a_fgc - a_g).max() / scale, err)
        entry = worst.setdefault(f.type.name, [0, 0.0, custom, 0, False])
        entry[0] += 1
        entry[1] = float(max(entry[1], err)) if np.isfinite(err) else float("inf")
        entry[3] += int(singular)
    return [LinearizationCheck(name, n, err, FD_TOLERANCE if custom else None,
                               custom, singular, sampled)
            for name, (n, err, custom, singular, sampled) in worst.items()]


def singular_at(f: Factor, values: list) -> bool:
    """Whether factor ``f`` is at a singular point of its residual at ``values`` (a norm of a
    zero vector, a bearing to a coincident point), where its derived Jacobian follows GTSAM's
    convention (:mod:`fgc.frontend.geometry.special`) and no derivative exists to compare."""
    with np.errstate(all="ignore"):
        return derive(f.type).singular_at(values, f.measured)


# At most this many factors of one type are checked at each point (evenly spaced, so the same
# ones every run); the simulator evaluates all of them, the reference side is the costly one.
EXECUTED_SAMPLE = 200


@dataclass(frozen=True)
class ExecutedCheck:
    """The linearisation the backend executes (the simulator's printed, fused block kernels)
    against a reference, for the factors of one type, at the initial values and at the final
    estimate: the largest relative difference of the whitened (A, b), relative to
    max(1, |A|max, |b|max), and where it was found.

    The reference of a custom factor is GTSAM's numerical CustomFactor (central differences of
    the user's function); of a built-in, fgc's own per-factor derivation of it
    (:func:`linearize_factor`, itself compared with GTSAM's factor by :class:`LinearizationCheck`),
    so a fused kernel that differs from its members' derivations — wrong, stale, mis-shared —
    fails either way."""

    factor_type: str
    block: str
    checked: int  # factor evaluations compared (over both points)
    factors: int  # factors of this type in the graph
    error: float
    where: str  # the point of the largest difference
    tolerance: float
    custom: bool
    sampled: bool = False  # more than EXECUTED_SAMPLE factors: a sample of them was checked
    singular: int = 0  # custom evaluations at a singular point: residual compared, not A

    @property
    def passed(self) -> bool:
        return bool(self.error <= self.tolerance)

    @property
    def reference(self) -> str:
        return ("numerical derivatives (central differences)" if self.custom
                else "fgc's per-factor derivation")


def sample_factors(graph: Graph, limit: int = EXECUTED_SAMPLE) -> list[int]:
    """Indices of the factors the executed-kernel check compares: every factor of a type with at
    most ``limit`` factors, else ``limit`` of them evenly spaced in graph order."""
    by_type: dict[str, list[int]] = {}
    for i, f in enumerate(graph.factors):
        by_type.setdefault(f.type.name, []).append(i)
    out: list[int] = []
    for indices in by_type.values():
        if len(indices) <= limit:
            out += indices
        else:
            out += [indices[int(j)] for j in np.unique(
                np.linspace(0, len(indices) - 1, limit).round().astype(int))]
    return sorted(out)


def executed_checks(graph: Graph, program, points: list[tuple[str, dict | None, GtsamProblem]],
                    executed: list[dict[int, tuple[np.ndarray, np.ndarray]]],
                    limit: int = EXECUTED_SAMPLE) -> list[ExecutedCheck]:
    """Per factor type (order of first appearance): the executed linearisation ``executed[p]``
    ({graph factor index: (A, b)}, e.g. from ``fgc_backends.sim.linearize``) at each point
    ``points[p] = (name, {key: value} or None for the initial values, its GtsamProblem)``
    against the reference (:class:`ExecutedCheck`), on :func:`sample_factors`."""
    block_of = {f: program.blocks[spec.block].name for spec in program.factors
                for f in spec.factors}
    worst: dict[str, list] = {}
    sample = sample_factors(graph, limit)
    for (where, values, problem), rows in zip(points, executed, strict=True):
        for i in sample:
            f = graph.factors[i]
            custom = is_custom(f.type)
            point = [_value(graph, values, k) for k in f.keys]
            singular = custom and singular_at(f, point)
            if custom:
                a_ref, b_ref = problem.graph.at(i).linearize(problem.values).jacobian()
            else:
                a_ref, b_ref = linearize_factor(f, point)
            a_ex, b_ex = rows[i]
            scale = max(1.0, np.abs(a_ref).max(), np.abs(b_ref).max())
            err = np.abs(b_ex - b_ref).max()
            if singular:  # the executed A against fgc's own derivation (GTSAM's convention)
                a_ref = linearize_factor(f, point)[0]
            err = max(np.abs(a_ex - a_ref).max(), err) / scale
            err = float(err) if np.isfinite(err) else float("inf")
            entry = worst.setdefault(f.type.name,
                                     [block_of.get(i, "?"), 0, 0.0, where, custom, 0])
            entry[1] += 1
            entry[5] += int(singular)
            if err > entry[2]:
                entry[0], entry[2], entry[3] = block_of.get(i, "?"), err, where
    totals: dict[str, int] = {}
    for f in graph.factors:
        totals[f.type.name] = totals.get(f.type.name, 0) + 1
    return [ExecutedCheck(name, block, n, totals[name], err, where, FD_TOLERANCE, custom,
                          totals[name] > limit, singular)
            for name, (block, n, err, where, custom, singular) in worst.items()]


def linearization_error(graph: Graph, values: dict | None = None) -> float:
    """Largest relative difference between fgc's and GTSAM's whitened linearisation (A, b) of
    any factor of ``graph`` at ``values`` (default: the initial values)."""
    return max((c.error for c in linearization_checks(graph, values)), default=0.0)


def _value(graph: Graph, values, key):
    return values[key] if values is not None and key in values else graph.variables[key].initial


def linearize_factor(f: Factor, values: list) -> tuple[np.ndarray, np.ndarray]:
    """fgc's whitened linearisation of one factor as GTSAM builds it: (A, b = −R·r), robust
    reweighting included."""
    sf = derive(f.type)
    r, jacs = sf.evaluate(values, f.measured)
    w = f.noise.sqrt_information
    a, b = w @ np.hstack(jacs), -(w @ r)
    if f.noise.robust is not None:
        s = np.sqrt(f.noise.robust.weight(float(np.linalg.norm(b))))
        a, b = s * a, s * b
    return a, b
