"""How far a solution can be trusted: rank deficiency and float32 conditioning, as warnings.

A backend that can diagnose its linear system (the simulator, ``SimConfig.diagnose``) reports
at the solution

- the variable whose elimination pivot vanishes (the factors leave it undetermined), and
- κ, the condition number of the whitened Jacobian J after scaling every row and every column
  to unit norm. Rounding in a float32 linearisation is relative to each row's own size and a
  change of units rounds the same, so this κ — not the raw one, which mixes metres, radians and
  bias units — is what float32 feels.

**Float32 bound.** A linear solve in precision eps loses about log10(κ_eff) digits, κ_eff being
the condition number of the matrix it factors: QR factors J itself (κ_eff = κ), Cholesky forms
H = JᵀJ (κ_eff = κ²). Once κ_eff·eps32 ≥ 1 the worst-determined direction has no correct digit
left, so fgc warns above

    κ > 1/eps32  ≈ 8.4e6   (QR)          κ > 1/√eps32 ≈ 2.9e3   (Cholesky).

**Distance to the optimum.** ρ is a bound on rounding one state; it does not see where the
solver's stopping rules leave it. The step rule ‖δ‖ ≤ 10 eps32·‖x‖ scales with the whole
state's norm: a 10-pose Pose2 chain at (6e3, 6e3) m in world coordinates (σ 1 cm) stops at
ρ = 0.29 up to 1.5 σ from GTSAM's optimum, at 1e4 m (ρ = 0.48) up to 2.9 σ — silently, under the
ρ ≥ 1 limit. So a low-precision run that says "converged" is judged once more on the host, in
float64, by the problem's own scale and noise: the whitened length ‖A·δ‖₂ of a Gauss-Newton
step δ from the returned state (the Mahalanobis distance, in σ, that the state still is from
the optimum to first order). ‖A·δ‖₂ ≥ :data:`STEP_LIMIT` (1 σ) turns "converged" into "failed",
reason "precision_limit" (``fgc_backends.sim.remaining_step``; the simulator and, through
``judge_precision``, the native solver and the C simulation). Measured on those chains (world
coordinates, 36 runs at 3e3 … 3e4 m, ``bench/bench_frame.py``): every run more than 1 σ off had
‖A·δ‖₂ ≥ 2.8, every run with ‖A·δ‖₂ < 1 was within 0.34 σ.

Measured on the shipped examples (``python bench/bench_property.py float32``: float32 solution
against float64, largest rotation / translation difference): pose3example κ = 6.1, w100 151,
lio N=30 32 and N=100 55 stay within 1e-4 m and 3e-6 rad with both solvers; the IMU window has
κ = 554 (N=20), 5.1e3 (N=50), 2.5e4 (N=80): float32 QR stays within 4e-5 m, float32 Cholesky
errs by 3.5e-3 m, 6.9e-2 m and 0.13 m — past the 1 cm bound exactly where κ crosses 1/√eps32,
which is where fgc starts to warn. (With numpy 2.4.6, float32 Cholesky at N = 20 no longer
stops: its cost falls below its own rounding noise and it runs to max_iterations, 5.5 mm off —
reported as not converged; ``tests/sim/test_sim_gtsam.py``.)
The raw κ (no equilibration) and the cheaper ratio max|R_ii|/min|R_ii| do not separate these
cases (both rank w100 and lio above imu N=20).
"""

from __future__ import annotations

import math
import sys
import warnings

import numpy as np

EPS32 = float(np.finfo(np.float32).eps)
FLOAT32_KAPPA_LIMIT = {"qr": 1.0 / EPS32, "cholesky": 1.0 / math.sqrt(EPS32)}


class FgcWarning(UserWarning):
    """Base class of the warnings fgc gives its users."""


class IllConditionedWarning(FgcWarning):
    """The problem is too ill-conditioned for float32 with the chosen linear solver."""


class PrecisionLimitWarning(FgcWarning):
    """The working precision cannot place a variable within its noise (a coordinate's float32
    resolution exceeds its σ): the solution is not the optimum to the data's accuracy."""


def precision_limit_message(key: str, type_name: str, rho: float, precision: str) -> str:
    """The text of a :class:`PrecisionLimitWarning`: ``rho`` is how many σ a rounding of the
    state to ``precision`` moves a whitened residual (see the simulator's ``resolution``)."""
    return (f"{precision} cannot place variable {key!r} ({type_name}) within its noise: "
            f"rounding its coordinates to {precision} moves a whitened residual by "
            f"{rho:.3g} σ (≥ 1: a coordinate's resolution exceeds its noise sigma, e.g. "
            "positions far from the origin or very small sigmas); the result is not the "
            "optimum to the data's accuracy — recentre the coordinates near the origin, rescale "
            "the noise models, or solve in float64")


STEP_LIMIT = 1.0  # σ: a converged low-precision run this far from the float64 optimum fails


def remaining_step_message(sigmas: float, precision: str) -> str:
    """The text of a :class:`PrecisionLimitWarning` for a run that stopped ``sigmas`` (the
    whitened length ‖A·δ‖ of a float64 Gauss-Newton step from the returned state) from the
    optimum."""
    return (f"{precision} stopped {sigmas:.3g} σ from the optimum: a float64 Gauss-Newton step "
            f"from the returned state still moves the whitened residuals by {sigmas:.3g} "
            "(≥ 1: the state is not the optimum to the data's accuracy; its coordinates are too "
            f"large for {precision}'s resolution, e.g. positions far from the origin that the "
            "local frame could not move, or very small sigmas) — recentre the coordinates near "
            "the origin, rescale the noise models, or solve in float64")


class RankDeficientWarning(FgcWarning):
    """The factors leave a variable undetermined; the returned value is one of many minimisers."""


def float32_kappa_limit(linear: str, linear_precision: str = "float32") -> float:
    """The κ above which a float32 solve with ``linear`` ("qr" or "cholesky") has no correct
    digit in its worst-determined direction. With a float64 linear solver (``linear_precision``,
    the mixed design) only the float32 linearisation limits it, as QR: κ·eps32 < 1."""
    if linear not in FLOAT32_KAPPA_LIMIT:
        raise ValueError(f"unknown linear solver {linear!r}")
    if linear_precision == "float64":
        return FLOAT32_KAPPA_LIMIT["qr"]
    return FLOAT32_KAPPA_LIMIT[linear]


def float32_ok(kappa: float | None, linear: str, linear_precision: str = "float32"
               ) -> bool | None:
    """Whether κ is below the float32 limit of ``linear`` (None when κ is unknown)."""
    if kappa is None:
        return None
    return kappa <= float32_kappa_limit(linear, linear_precision)


def ill_conditioned_message(kappa: float, linear: str, linear_precision: str = "float32") -> str:
    """The text of an :class:`IllConditionedWarning`."""
    limit = float32_kappa_limit(linear, linear_precision)
    mixed = linear_precision == "float64"
    hint = ""
    if linear == "cholesky" and not mixed:
        hint = (f" (QR tolerates up to {FLOAT32_KAPPA_LIMIT['qr']:.2g}, and so does Cholesky "
                "with a float64 linear solver: --linear-precision float64)")
    what = f"float32 {linear}" + (" with a float64 linear solver" if mixed else "")
    return (f"the problem is too ill-conditioned for {what}: condition number "
            f"κ ≈ {kappa:.2g} (rows and columns equilibrated) exceeds {limit:.2g}{hint}; "
            "solve in float64 or rescale the problem")


def warn(message: str, category: type[FgcWarning]) -> None:
    """``warnings.warn`` attributed to the first caller outside fgc and its backends."""
    frame, level = sys._getframe(1), 2  # stacklevel 2: the caller of warn()
    while frame is not None and frame.f_globals.get("__name__", "").startswith(_OWN_MODULES):
        frame, level = frame.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)


_OWN_MODULES = ("fgc.", "fgc_backends.", "fgc_cli")  # fgc_cli: the console script's entry


def warn_if_ill_conditioned(kappa: float | None, linear: str, precision: str,
                            linear_precision: str | None = None) -> str | None:
    """Warn (:class:`IllConditionedWarning`) when a ``precision`` = "float32" solve with
    ``linear`` (its solver in ``linear_precision``, default the same) has κ above its limit;
    returns the message, or None when there is no warning."""
    les = linear_precision or precision
    if precision != "float32" or float32_ok(kappa, linear, les) is not False:
        return None
    message = ill_conditioned_message(kappa, linear, les)
    warn(message, IllConditionedWarning)
    return message


def rank_deficient_message(key: str, type_name: str, component: int, ratio: float,
                           tolerance: float) -> str:
    """The text naming a variable the factors leave undetermined."""
    return (f"variable {key!r} ({type_name}, tangent component {component}) is not determined "
            f"by its factors: its elimination pivot is {ratio:.1e} × its column norm, at or "
            f"below the tolerance {tolerance:g} (a free gauge, an unexcited bias, a point seen "
            "along one line); add a prior or a measurement that constrains it")


# --------------------------------------------------------------------------------------------
# float32 resolution of the state: the host-side verdict of the native solver and C simulation
# --------------------------------------------------------------------------------------------

RESOLUTION_LIMIT = 1.0  # ρ at or above it: the precision cannot place the state within its noise
SCALAR_PRECISION = {"float": "float32", "double": "float64"}  # C++ scalar → its numpy precision


def resolution(parts, storage, dims, precision: str = "float32") -> tuple[float, int]:
    """(ρ, variable) at the state ``storage`` (one array per variable, Program order; ``dims``
    their tangent dimensions): ρ is the largest whitened-residual change, in σ, that rounding the
    state to ``precision`` can cause — one row's eps·Σ_j |A_ij|·scale_j, scale_j the largest
    |storage entry| of column j's variable (at least 1) — and ``variable`` indexes the variable
    of that row's largest term. ``parts`` pairs whitened Jacobian rows A (instances × rows ×
    columns, evaluated in float64) with their global tangent columns (instances × columns).

    The same formula as the simulator's ``resolution`` (which evaluates A in the working
    precision); ρ ≥ :data:`RESOLUTION_LIMIT` means a coordinate's resolution exceeds its σ."""
    eps = float(np.finfo(np.dtype(precision)).eps)
    scale = np.array([max(float(np.max(np.abs(v))) if np.size(v) else 0.0, 1.0)
                      for v in storage])
    columns = np.repeat(scale, np.asarray(dims, dtype=np.intp))
    offsets = np.concatenate([[0], np.cumsum(dims)]).astype(np.intp)
    best, column = 0.0, 0
    for a, cols in parts:
        a = np.asarray(a, dtype=np.float64)
        if a.size == 0:
            continue
        cols = np.asarray(cols, dtype=np.intp)
        terms = eps * np.abs(a) * columns[cols][:, None, :]
        rows = terms.sum(axis=-1)
        n, m = np.unravel_index(int(np.argmax(rows)), rows.shape)
        if rows[n, m] > best:
            best, column = float(rows[n, m]), int(cols[n, int(np.argmax(terms[n, m]))])
    return best, int(np.searchsorted(offsets, column, side="right") - 1)
