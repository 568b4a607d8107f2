"""The GTSAM import: a ``gtsam.NonlinearFactorGraph`` + ``Values`` as an fgc :class:`Graph`.

:func:`from_gtsam` is the inverse of :func:`fgc.interop.to_gtsam.to_gtsam` for the factors fgc has
built in
(one of the few places fgc imports gtsam on purpose, docs/design.md "Verification"):

- ``PriorFactor*`` / ``BetweenFactor*`` on Pose2, Pose3, Rot2, Rot3, Point2, Point3, Vector and
  ConstantBias; ``GPSFactor``; ``BearingRangeFactor2D``;
- ``RangeFactor2D`` / ``RangeFactor3D`` (pose to point) and ``RangeFactorPose2`` /
  ``RangeFactorPose3`` (pose to pose), as the DSL factors of :func:`range_factor_type`;
- ``CombinedImuFactor``. GTSAM's Python API hides the bias Jacobians of the preintegration, so they
  are read back through ``pim.predict``: GTSAM's tangent preintegration corrects ζ *linearly* in
  the bias, so predicting from the identity state at b̂ and at b̂ + δ·e_k gives column k of
  [H_acc H_gyro] up to rounding (≈1e-13); gravity comes from the same prediction. Every imported
  IMU factor is then checked against GTSAM's own ``unwhitenedError``/``error`` at the initial
  values and at a perturbed point, which also picks its error mode (Logmap or ComponentWise);
  a factor that does not agree to 1e-9 raises :class:`FgcError` instead of being approximated.

Noise models: Unit / Isotropic / Diagonal / Gaussian, and Robust with a Huber or Cauchy
``mEstimator`` under GTSAM's default (Block) reweighting; the width k is read back through the
estimator's ``weight`` and the whole robust model is checked on a probe linearisation.

Keys: a GTSAM ``Symbol`` whose character is a letter becomes its string (``X(1)`` → ``"X1"``,
``symbol('x', 1)`` → ``"x1"``); any other key stays the same int. ``key_names`` overrides both.
Only variables that some factor uses are imported, in ``values`` key order.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import cache

import gtsam
import numpy as np

from fgc.compiler.derive import derive
from fgc.errors import FgcError
from fgc.frontend.dsl import Factor, FactorType, Graph, Key, factor
from fgc.frontend.factors import BearingRangeFactor, BetweenFactor, GPSFactor, PriorFactor
from fgc.frontend.factors.imu import combined_imu_factor_type
from fgc.frontend.geometry import (
    TYPES,
    ImuBias,
    LieGroup,
    Point2,
    Point3,
    Pose2,
    Pose3,
    Rot2,
    Rot3,
    Vector3,
    VectorSpace,
    vector_type,
)
from fgc.frontend.noise import NoiseModel, RobustLoss, diagonal, isotropic, sqrt_information
from fgc.interop import twins
from fgc.interop.to_gtsam import value_from_gtsam, value_to_gtsam

_nm = gtsam.noiseModel
# fgc variable types by the twin tables' names (fgc.interop.twins: one table for both directions)
_TYPES = {**TYPES, "Vector": VectorSpace}  # the registry (fgc.geometry.TYPES) + any vector
_PRIORS = {getattr(gtsam, cls): _TYPES[t] for t, cls in twins.PRIOR.items()}
_BETWEENS = {getattr(gtsam, cls): _TYPES[t] for t, cls in twins.BETWEEN.items()}
_RANGES = {getattr(gtsam, cls): (_TYPES[a], _TYPES[b]) for (a, b), cls in twins.RANGE.items()}
_IMU_TYPES = (Pose3, Vector3, Pose3, Vector3, ImuBias, ImuBias)
_IMU_TOL = 1e-9  # relative agreement demanded of a reconstructed CombinedImuFactor


@dataclass(frozen=True)
class _Converted:
    """One GTSAM factor, understood: its variables' fgc types and how to build the fgc factor
    from the variables' fgc keys and initial values."""

    types: tuple[type[LieGroup], ...]
    build: Callable[[tuple, list], Factor]


# --------------------------------------------------------------------------------------------
# graph
# --------------------------------------------------------------------------------------------


def from_gtsam(graph: gtsam.NonlinearFactorGraph, values: gtsam.Values,
               key_names: Mapping[int, Key] | None = None) -> Graph:
    """Convert a GTSAM graph of supported factors and its values into an fgc :class:`Graph`.

    In: ``graph`` and ``values`` (every key a factor uses must have a value); optional
    ``key_names`` {GTSAM key: fgc key} overriding the default names (module docstring).
    Out: a new Graph with one variable per used key (initial value from ``values``) and one
    factor per GTSAM factor, in order. Raises FgcError naming the factor index and class for an
    unsupported factor or noise model, and the key for a missing or mistyped value.
    """
    gfactors = [(i, gf) for i in range(graph.size()) if (gf := graph.at(i)) is not None]
    converted = [(i, gf, _convert(gf, i)) for i, gf in gfactors]
    types = _variable_types(converted)
    value_keys = list(values.keys())
    names = _key_names(value_keys, types, key_names)
    out = Graph()
    for key in value_keys:
        if key in types:
            out.add_variable(names[key], _read_value(values, types[key], key, names[key]))
    for _, gf, conv in converted:
        keys = tuple(names[k] for k in list(gf.keys()))
        out.add(conv.build(keys, [out.variables[k].initial for k in keys]))
    return out


def _variable_types(converted: list) -> dict[int, type[LieGroup]]:
    types: dict[int, type[LieGroup]] = {}
    for i, gf, conv in converted:
        for key, t in zip(gf.keys(), conv.types, strict=True):
            if types.setdefault(key, t) is not t:
                raise FgcError(f"factor {i} ({type(gf).__name__}) uses key {_show(key)} as a "
                               f"{t.__name__}, but an earlier factor uses it as a "
                               f"{types[key].__name__}")
    return types


def _key_names(keys: list[int], types: dict, key_names: Mapping[int, Key] | None) -> dict:
    present = set(keys)
    missing = sorted(k for k in types if k not in present)
    if missing:
        shown = ", ".join(_show(k) for k in missing)
        raise FgcError(f"gtsam.Values has no value for key(s) {shown} used by the graph's "
                       "factors")
    names = {k: default_key_name(k) for k in types}
    names.update({k: v for k, v in (key_names or {}).items() if k in types})
    seen: dict = {}
    for k, name in names.items():
        if name in seen:
            raise FgcError(f"GTSAM keys {_show(seen[name])} and {_show(k)} both map to the fgc "
                           f"key {name!r}; pass key_names to tell them apart")
        seen[name] = k
    return names


def default_key_name(key: int) -> Key:
    """fgc key for a GTSAM key: the Symbol string when its character is a letter (``x1``),
    else the int itself (GTSAM's default key formatter makes the same choice)."""
    sym = gtsam.Symbol(key)
    return sym.string() if chr(sym.chr()).isalpha() else int(key)


def _show(key: int) -> str:
    name = default_key_name(key)
    return repr(name) if isinstance(name, str) else str(name)


_READERS = {Pose3: "atPose3", Pose2: "atPose2", Rot3: "atRot3", Rot2: "atRot2",
            ImuBias: "atConstantBias", Point2: "atPoint2", Point3: "atPoint3"}


def _read_value(values: gtsam.Values, t: type[LieGroup], key: int, name: Key) -> LieGroup:
    try:
        obj = getattr(values, _READERS.get(t, "atVector"))(key)
    except RuntimeError as exc:
        raise FgcError(f"variable {name!r}: the gtsam.Values entry is not a {t.__name__} "
                       f"({exc})") from None
    if t not in _READERS and np.size(obj) != t.dim:
        raise FgcError(f"variable {name!r}: expected a {t.dim}-vector, got {np.size(obj)} "
                       "entries")
    return value_from_gtsam(t, obj)


# --------------------------------------------------------------------------------------------
# factors
# --------------------------------------------------------------------------------------------


def _convert(gf, index: int) -> _Converted:
    """Dispatch on the GTSAM factor's class; the error names the factor index and class."""
    where = f"factor {index} ({type(gf).__name__})"
    try:
        for table, conv in ((_PRIORS, _prior), (_BETWEENS, _between), (_RANGES, _range)):
            for cls, arg in table.items():
                if isinstance(gf, cls):
                    return conv(gf, arg, noise_from_gtsam(gf.noiseModel()))
        if isinstance(gf, getattr(gtsam, twins.GPS)):
            pos = np.asarray(gf.measurementIn(), float)
            noise = noise_from_gtsam(gf.noiseModel())
            return _Converted((Pose3,), lambda k, _: GPSFactor(k[0], pos, noise))
        if isinstance(gf, getattr(gtsam, twins.BEARING_RANGE)):
            return _bearing_range(gf, noise_from_gtsam(gf.noiseModel()))
        if isinstance(gf, getattr(gtsam, twins.COMBINED_IMU)):
            return _imu(gf, index, noise_from_gtsam(gf.noiseModel()))
        if isinstance(gf, gtsam.BearingRangeFactor3D):
            raise FgcError("BearingRangeFactor3D (Pose3 → Point3) has no fgc built-in: GTSAM "
                           "expresses its bearing error in the tangent basis of the *predicted* "
                           "direction, a basis that switches with the direction's smallest "
                           "component, which fgc's smooth residuals cannot reproduce exactly")
    except FgcError as exc:
        raise FgcError(f"{where}: {exc}") from None
    raise FgcError(f"{where} is not supported by fgc's GTSAM import; supported are PriorFactor*, "
                   "BetweenFactor* (Pose2/3, Rot2/3, Point2/3, Vector, ConstantBias), GPSFactor, "
                   "BearingRangeFactor2D, RangeFactor2D/3D/Pose2/Pose3 and CombinedImuFactor")


def _measured_type(t: type[LieGroup], obj) -> type[LieGroup]:
    return vector_type(int(np.size(obj))) if t is VectorSpace else t


def _prior(gf, t: type[LieGroup], noise: NoiseModel) -> _Converted:
    obj = gf.prior()
    t = _measured_type(t, obj)
    value = value_from_gtsam(t, obj)
    return _Converted((t,), lambda k, _: PriorFactor(k[0], value, noise))


def _between(gf, t: type[LieGroup], noise: NoiseModel) -> _Converted:
    obj = gf.measured()
    t = _measured_type(t, obj)
    value = value_from_gtsam(t, obj)
    return _Converted((t, t), lambda k, _: BetweenFactor(k[0], k[1], value, noise))


def _range(gf, types: tuple, noise: NoiseModel) -> _Converted:
    ftype, measured = range_factor_type(*types), float(gf.measured())
    return _Converted(types, lambda k, _: ftype(*k, measured=measured, noise=noise))


def _bearing_range(gf, noise: NoiseModel) -> _Converted:
    m = gf.measured()
    bearing, rng = value_from_gtsam(Rot2, m.bearing()), float(m.range())
    return _Converted((Pose2, Point2),
                      lambda k, _: BearingRangeFactor(k[0], k[1], bearing, rng, noise))


@cache
def range_factor_type(pose_t: type[LieGroup], target_t: type[LieGroup]) -> FactorType:
    """GTSAM ``RangeFactor<pose_t, target_t>``: error = ‖target − pose.t‖ − measured, with the
    target a point (``RangeFactor2D``/``3D``) or another pose (``RangeFactorPose2``/``Pose3``)."""
    to_pose = target_t in (Pose2, Pose3)

    def range_factor(pose: pose_t, target: target_t, *, measured: float):
        return [pose.range(target.translation() if to_pose else target) - measured]

    range_factor.__annotations__ = {"pose": pose_t, "target": target_t, "measured": float}
    suffix = target_t.__name__ if to_pose else ("2D" if pose_t is Pose2 else "3D")
    ftype = factor(range_factor, name=f"RangeFactor{suffix}")
    ftype.gtsam_kind = ("range", (pose_t.__name__, target_t.__name__))
    return ftype


# --------------------------------------------------------------------------------------------
# CombinedImuFactor
# --------------------------------------------------------------------------------------------


def _imu(gf, index: int, noise: NoiseModel) -> _Converted:
    measured = imu_measurements(gf.preintegratedMeasurements())

    def build(keys: tuple, initial: list) -> Factor:
        return _matching_imu_factor(gf, index, keys, initial, measured, noise)

    return _Converted(_IMU_TYPES, build)


def _predict(pim, bias: np.ndarray) -> np.ndarray:
    """GTSAM's prediction from the identity state at rest: [Log R_j, p_j, v_j]."""
    state = pim.predict(gtsam.NavState(), gtsam.imuBias.ConstantBias(bias[:3], bias[3:]))
    return np.concatenate([gtsam.Rot3.Logmap(state.attitude()), state.position(),
                           state.velocity()])


def imu_measurements(pim: gtsam.PreintegratedCombinedMeasurements) -> dict:
    """The measurement arguments of fgc's CombinedImuFactor for a GTSAM preintegration.

    In: a GTSAM ``PreintegratedCombinedMeasurements``. Out: {preintegrated ζ, H_bias_acc,
    H_bias_omega, bias_hat, delta_t, gravity} (module docstring: bias Jacobians and gravity from
    ``pim.predict``, exact up to rounding because GTSAM's bias correction is linear in the bias).
    """
    b_hat = np.asarray(pim.biasHatVector(), float)
    dt = float(pim.deltaTij())
    if not dt > 0:
        raise FgcError(f"the preintegration spans deltaTij = {dt}; nothing was integrated")
    zeta = np.concatenate([gtsam.Rot3.Logmap(pim.deltaRij()), pim.deltaPij(), pim.deltaVij()])
    base = _predict(pim, b_hat)
    step = 0.1 / max(1.0, dt)  # keeps the probed rotation well inside Logmap's range
    h = np.empty((9, 6))
    for k in range(6):
        h[:, k] = (_predict(pim, b_hat + step * np.eye(6)[k]) - base) / step
    gravity = (base[6:] - zeta[6:]) / dt
    return {"preintegrated": zeta, "H_bias_acc": h[:, :3], "H_bias_omega": h[:, 3:],
            "bias_hat": ImuBias(b_hat), "delta_t": dt, "gravity": Vector3(gravity)}


def _matching_imu_factor(gf, index: int, keys: tuple, initial: list, measured: dict,
                         noise: NoiseModel) -> Factor:
    """The fgc CombinedImuFactor (error mode tried in turn) that reproduces GTSAM's factor at
    the initial values and at a seeded perturbation of them; FgcError if none does."""
    rng = np.random.default_rng(index)
    points = [initial, [v.retract(0.1 * rng.normal(size=type(v).dim)) for v in initial]]
    worst = {}
    for mode in ("logmap", "componentwise"):
        f = combined_imu_factor_type(mode)(*keys, noise=noise, **measured)
        worst[mode] = max(_imu_disagreement(gf, f, p) for p in points)
        if worst[mode] <= _IMU_TOL:
            return f
    raise FgcError(
        f"factor {index} (CombinedImuFactor) could not be reconstructed exactly from GTSAM's "
        f"Python API (relative disagreement {worst}, tolerance {_IMU_TOL}); its preintegration "
        "is not GTSAM 4.3's tangent preintegration with zero Coriolis and no body_P_sensor, "
        "which are all fgc's CombinedImuFactor models")


def _imu_disagreement(gf, f: Factor, point: list) -> float:
    gvals = gtsam.Values()
    for key, v in zip(gf.keys(), point, strict=True):
        gvals.insert(key, value_to_gtsam(v))
    r_g = np.asarray(gf.unwhitenedError(gvals), float)
    r_f = derive(f.type).evaluate_residual(point, f.measured)
    e_g, e_f = float(gf.error(gvals)), f.noise.error(r_f)
    return max(np.abs(r_f - r_g).max() / max(1.0, np.abs(r_g).max()),
               abs(e_f - e_g) / max(1.0, e_g))


# --------------------------------------------------------------------------------------------
# noise models
# --------------------------------------------------------------------------------------------


def noise_from_gtsam(model) -> NoiseModel:
    """GTSAM noise model → fgc noise model of the same meaning (inverse of
    :func:`fgc.interop.to_gtsam.noise_to_gtsam`).

    In: a ``gtsam.noiseModel`` Unit, Isotropic, Diagonal, Gaussian or Robust (Huber / Cauchy,
    Block reweighting). Out: an fgc :class:`NoiseModel`. Constrained models and other robust
    losses raise FgcError.
    """
    if isinstance(model, _nm.Robust):
        return _robust(model)
    if isinstance(model, _nm.Constrained):
        raise FgcError("constrained (hard) noise models are not supported; fgc's solvers are "
                       "least-squares only")
    if isinstance(model, _nm.Isotropic):
        return isotropic(int(model.dim()), float(model.sigma()))
    if isinstance(model, _nm.Diagonal):
        return diagonal(np.asarray(model.sigmas(), float))
    if isinstance(model, _nm.Gaussian):
        r = np.asarray(model.R(), float)
        return sqrt_information(np.sign(np.diag(r))[:, None] * r)  # same RᵀR, positive diagonal
    raise FgcError(f"noise model {type(model).__name__} is not supported")


def _robust(model) -> NoiseModel:
    base = noise_from_gtsam(model.noise())
    est = model.robust()
    if isinstance(est, _nm.mEstimator.Huber):
        loss = RobustLoss("huber", _huber_width(est))
    elif isinstance(est, _nm.mEstimator.Cauchy):
        loss = RobustLoss("cauchy", _cauchy_width(est))
    else:
        raise FgcError(f"robust loss {type(est).__name__} is not supported (fgc has Huber and "
                       "Cauchy)")
    noise = base.with_robust(loss)
    _check_robust(model, noise)
    return noise


def _huber_width(est) -> float:
    """Huber's k: w(e) = k/e for e > k, read at a huge e."""
    e = 1e100
    return float(est.weight(e)) * e


def _cauchy_width(est) -> float:
    """Cauchy's k: w(e) = k²/(k² + e²) solved for k; repeated at e ≈ k, where w ≈ ½ loses least."""
    e, k2 = 1.0, 1.0
    for _ in range(4):
        w = float(est.weight(e))
        if not 0.0 < w < 1.0:
            raise FgcError(f"cannot read the Cauchy width (weight({e}) = {w})")
        k2 = w * e * e / (1.0 - w)
        e = float(np.sqrt(k2))
    return e


def _check_robust(model, noise: NoiseModel) -> None:
    """Linearise a probe prior under ``model`` and compare with fgc's Block reweighting: catches
    GTSAM's Scalar reweight scheme and a misread width."""
    n = noise.dim
    v = np.linspace(1.0, 2.0, n)
    v *= 3.0 * noise.robust.k / np.linalg.norm(noise.whiten(v))  # well inside the robust part
    probe = gtsam.PriorFactorVector(0, np.zeros(n), model)
    vals = gtsam.Values()
    vals.insert(0, v)
    a_g, _ = probe.linearize(vals).jacobian()
    expected = np.sqrt(noise.robust.weight(3.0 * noise.robust.k)) * noise.sqrt_information
    if np.abs(a_g - expected).max() > 1e-9 * max(1.0, np.abs(expected).max()):
        raise FgcError(f"robust noise model ({type(model.robust()).__name__}) does not "
                       "reweight as fgc does: only GTSAM's default Block reweight scheme is "
                       "supported")
