# fgc simulator run-time (fgc_sim_special.py): copied verbatim into every emitted simulator
"""Vectorised special functions of the fgc simulator.

Robust Lie coefficients of t = θ² (A = sin θ/θ, B = (1 − cos θ)/θ², C = (θ − sin θ)/θ³,
D = 1/θ² − (1 + cos θ)/(2θ sin θ) and their t-derivatives A1 … D1) and the SO(3) logarithm: the
numeric routines that the printed kernels call (``lie_A(t)``, ``so3_log(R…)``). The math is
fgc's (``fgc.frontend.geometry.special``), rewritten to act on arrays of many instances at once:
branches become numpy.where. The Taylor series and the switch point are not written here: the
emitted constants module (``fgc_sim_constants``) holds them as printed from fgc, and
:func:`lie_functions` takes them. Every function keeps its inputs' float dtype, so a float32 run
computes in float32 throughout.

The closed forms are fgc's own (``fgc/frontend/geometry/lie_closed_forms.py``, copied beside
this file and handed in); the branches of the vectorised logarithm are the one part of the
simulator's geometry written here (the per-type retraction and local coordinates are printed
from ``fgc.frontend.geometry`` into the problem module); the backend's tests hold it to fgc's.
"""

import numpy


def lie_functions(series_below, series, forms):
    """{name: f(t)} of every coefficient in ``series`` (name → its Taylor coefficients c_0, c_1,
    … in t, highest power first), each by its series below t = ``series_below`` and its closed
    form above; ``forms`` is fgc's ``lie_closed_forms`` module (copied beside this one)."""
    return {name: _coefficient_function(name, series_below, coeffs, forms)
            for name, coeffs in series.items()}


def _coefficient_function(name, series_below, coeffs, forms):
    def lie(t):
        return coefficient(name, t, series_below, coeffs, forms)

    lie.__name__ = f"lie_{name}"
    return lie


def coefficient(name, t, series_below, coeffs, forms):
    """Coefficient ``name`` at t = θ² (array or scalar, dtype kept): its series ``coeffs``
    (highest power first) below ``series_below``, its closed form above (``forms``: fgc's
    ``lie_closed_forms``)."""
    t = numpy.asarray(t)
    small = t < series_below
    series = forms.horner(coeffs, t)
    if numpy.all(small):
        return series
    safe = numpy.where(small, t.dtype.type(series_below), t)
    with numpy.errstate(all="ignore"):
        closed = forms.closed_form(name, safe)
    return numpy.where(small, series, closed).astype(t.dtype, copy=False)


def so3_log(r00, r01, r02, r10, r11, r12, r20, r21, r22):
    """Rotation vectors (ωx, ωy, ωz) of rotation matrices given entry-wise as arrays.

    θ = atan2(sin θ, cos θ); the axis comes from the skew part where cos θ ≥ 0 and from the
    symmetric part (R + Rᵀ)/2 − cos θ·I = (1 − cos θ)·n nᵀ elsewhere, so θ → π loses no digits.
    """
    r = numpy.stack(numpy.broadcast_arrays(r00, r01, r02, r10, r11, r12, r20, r21, r22), -1)
    dt = r.dtype.type
    r = r.reshape(r.shape[:-1] + (3, 3))
    skew = numpy.stack([r[..., 2, 1] - r[..., 1, 2], r[..., 0, 2] - r[..., 2, 0],
                        r[..., 1, 0] - r[..., 0, 1]], -1)
    cos_t = dt(0.5) * (r[..., 0, 0] + r[..., 1, 1] + r[..., 2, 2] - dt(1))
    sin_t = dt(0.5) * numpy.sqrt(numpy.sum(skew * skew, -1))
    theta = numpy.arctan2(sin_t, cos_t)
    with numpy.errstate(divide="ignore", invalid="ignore"):  # θ / sin θ → 1 as θ → 0
        near = dt(0.5) * numpy.where(sin_t > 0, theta / sin_t, dt(1))
    omega = near[..., None] * skew
    far = cos_t < 0
    if numpy.any(far):
        omega = numpy.where(far[..., None], _log_near_pi(r, skew, cos_t, theta), omega)
    return omega[..., 0], omega[..., 1], omega[..., 2]


def _log_near_pi(r, skew, cos_t, theta):
    """θ·n from the symmetric part, for rotations with cos θ < 0 (others give garbage)."""
    dt = r.dtype.type
    sym = (dt(0.5) * (r + numpy.swapaxes(r, -1, -2))
           - cos_t[..., None, None] * numpy.eye(3, dtype=dt))
    diag = numpy.diagonal(sym, 0, -2, -1)
    k = numpy.argmax(diag, -1)
    col = numpy.take_along_axis(sym, k[..., None, None], -1)[..., 0]
    with numpy.errstate(all="ignore"):
        skk = numpy.take_along_axis(diag, k[..., None], -1)[..., 0]
        axis = col / numpy.sqrt(skk * (dt(1) - cos_t))[..., None]
        axis = axis / numpy.sqrt(numpy.sum(axis * axis, -1))[..., None]
    sign = numpy.where(numpy.sum(axis * skew, -1) < 0, dt(-1), dt(1))
    return (sign * theta)[..., None] * axis


# --------------------------------------------------------------------------------------------
# per-type kernels over instances
# --------------------------------------------------------------------------------------------


def over_instances(kernel):
    """A printed per-type kernel (``retract_<k>`` or ``local_<k>`` of the problem module, over
    (inputs × instances)) as f(part, …) of (instances × size) arrays, joined in order as the
    kernel's inputs; returns (instances × outputs)."""
    def apply(*parts):
        joined = numpy.concatenate(parts, -1)
        return kernel(numpy.ascontiguousarray(joined.T)).T

    return apply
