"""The GTSAM bridge: an fgc Graph as a ``gtsam.NonlinearFactorGraph`` + ``Values``, and checks.

This is one of the few places fgc imports gtsam on purpose (DESIGN.md, "How it is checked").
Built-in factors become GTSAM's own factor of the same meaning (``BetweenFactorPose3``,
``CombinedImuFactor`` re-integrated from the raw IMU samples, ...), so a comparison is between two
independent implementations. A user-written factor becomes a ``gtsam.CustomFactor`` that calls
fgc's derived kernel: good for comparing *solvers*, not the factor itself.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fgc.derive import derive
from fgc.dsl import Factor, Graph
from fgc.errors import FgcError
from fgc.geometry import ImuBias, LieGroup, Point2, Point3, Pose2, Pose3, Rot2, Rot3, VectorSpace
from fgc.noise import NoiseModel


def _gtsam():
    try:
        import gtsam
    except ImportError as exc:  # pragma: no cover - gtsam is a core dependency
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


_BETWEEN = {"Pose3": "BetweenFactorPose3", "Pose2": "BetweenFactorPose2",
            "Rot3": "BetweenFactorRot3", "Rot2": "BetweenFactorRot2",
            "Point3": "BetweenFactorPoint3", "Point2": "BetweenFactorPoint2",
            "ImuBias": "BetweenFactorConstantBias"}
_PRIOR = {"Pose3": "PriorFactorPose3", "Pose2": "PriorFactorPose2", "Rot3": "PriorFactorRot3",
          "Rot2": "PriorFactorRot2", "Point3": "PriorFactorPoint3", "Point2": "PriorFactorPoint2",
          "ImuBias": "PriorFactorConstantBias", "Vector3": "PriorFactorVector"}


def factor_to_gtsam(f: Factor, keys: dict, graph: Graph):
    """One fgc factor → a GTSAM factor (native twin for built-ins, CustomFactor otherwise)."""
    gtsam = _gtsam()
    kind = getattr(f.type, "gtsam_kind", None)
    ks = [keys[k] for k in f.keys]
    noise = noise_to_gtsam(f.noise)
    types = [graph.variables[k].type for k in f.keys]
    if kind is not None:
        name, arg = kind
        if name == "prior" and arg in _PRIOR:
            val = types[0].from_storage(f.measured["prior"])
            return getattr(gtsam, _PRIOR[arg])(ks[0], value_to_gtsam(val), noise)
        if name == "between" and arg in _BETWEEN:
            val = types[0].from_storage(f.measured["measured"])
            return getattr(gtsam, _BETWEEN[arg])(ks[0], ks[1], value_to_gtsam(val), noise)
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
    """A gtsam.CustomFactor evaluating fgc's derived kernel (for solver comparisons)."""
    gtsam = _gtsam()
    sf = derive(f.type)
    types = [a.type for a in f.type.variables]

    def error(this, values, jacobians):
        vals = [_read_value(values, t, k) for t, k in zip(types, this.keys(), strict=True)]
        r, jacs = sf.evaluate(vals, f.measured)
        if jacobians is not None:
            for i, j in enumerate(jacs):
                jacobians[i] = j
        return r

    return gtsam.CustomFactor(noise, ks, error)


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


def linearization_error(graph: Graph, values: dict | None = None) -> float:
    """Largest relative difference between fgc's and GTSAM's whitened linearisation (A, b) of
    any factor of ``graph`` at ``values`` (default: the initial values)."""
    problem = to_gtsam(graph, values)
    worst = 0.0
    for i, f in enumerate(graph.factors):
        a_fgc, b_fgc = linearize_factor(f, [_value(graph, values, k) for k in f.keys])
        a_g, b_g = problem.graph.at(i).linearize(problem.values).jacobian()
        scale = max(1.0, np.abs(a_g).max(), np.abs(b_g).max())
        worst = max(worst, np.abs(a_fgc - a_g).max() / scale, np.abs(b_fgc - b_g).max() / scale)
    return worst


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
