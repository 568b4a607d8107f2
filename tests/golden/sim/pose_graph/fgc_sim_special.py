# generated from template fgc_sim_special.py.jinja by fgc — do not edit
# fgc 0.1.0
"""Vectorised special functions of the fgc simulator.

Robust Lie coefficients of t = θ² (A = sin θ/θ, B = (1 − cos θ)/θ², C = (θ − sin θ)/θ³,
D = 1/θ² − (1 + cos θ)/(2θ sin θ) and their t-derivatives A1 … D1), the SO(3) logarithm and the
retraction (x ∘ Exp(δ)) of every variable type. The math is fgc's (fgc/frontend/geometry/special.py and
groups.py), rewritten to act on arrays of many instances at once: branches become numpy.where.
Every function keeps its inputs' float dtype, so a float32 run computes in float32 throughout.
"""

import numpy

# Taylor series (in t) below this t, closed forms above it (see fgc/frontend/geometry/special.py).
SERIES_BELOW = 4.0
# Series coefficients c_0, c_1, … of each coefficient function, highest power first (Horner).
SERIES = {
    "A": (-3.868170170630684e-23, 1.9572941063391263e-20, -8.22063524662433e-18, 2.8114572543455206e-15, -7.647163731819816e-13, 1.6059043836821613e-10, -2.505210838544172e-08, 2.7557319223985893e-06, -0.0001984126984126984, 0.008333333333333333, -0.16666666666666666, 1.0),
    "A1": (-4.254987187693753e-22, 1.9572941063391261e-19, -7.398571721961897e-17, 2.2491658034764165e-14, -5.353014612273871e-12, 9.635426302092969e-10, -1.252605419272086e-07, 1.1022927689594357e-05, -0.0005952380952380953, 0.016666666666666666, -0.16666666666666666),
    "B": (-1.6117375710961184e-24, 8.896791392450574e-22, -4.110317623312165e-19, 1.5619206968586225e-16, -4.779477332387385e-14, 1.1470745597729725e-11, -2.08767569878681e-09, 2.755731922398589e-07, -2.48015873015873e-05, 0.001388888888888889, -0.041666666666666664, 0.5),
    "B1": (-1.77291132820573e-23, 8.896791392450573e-21, -3.6992858609809485e-18, 1.249536557486898e-15, -3.3456341326711696e-13, 6.882447358637835e-11, -1.043837849393405e-08, 1.1022927689594355e-06, -7.440476190476191e-05, 0.002777777777777778, -0.041666666666666664),
    "C": (-6.446950284384474e-26, 3.868170170630684e-23, -1.9572941063391263e-20, 8.22063524662433e-18, -2.8114572543455206e-15, 7.647163731819816e-13, -1.6059043836821613e-10, 2.505210838544172e-08, -2.7557319223985893e-06, 0.0001984126984126984, -0.008333333333333333, 0.16666666666666666),
    "C1": (-7.091645312822921e-25, 3.868170170630684e-22, -1.7615646957052136e-19, 6.576508197299464e-17, -1.9680200780418645e-14, 4.58829823909189e-12, -8.029521918410807e-10, 1.0020843354176688e-07, -8.267195767195768e-06, 0.0003968253968253968, -0.008333333333333333),
    "D": (1.5174548844682903e-35, 5.990671762482134e-34, 2.36502241570063e-32, 9.336734257095045e-31, 3.6859949406653103e-29, 1.455172475614865e-27, 5.744790668872202e-26, 2.267952452337683e-24, 8.953517427037546e-23, 3.534707039629467e-21, 1.3954464685812522e-19, 5.5090028283602295e-18, 2.174868698558062e-16, 8.586062056277845e-15, 3.3896802963225827e-13, 1.3382536530684679e-11, 5.284190138687493e-10, 2.08767569878681e-08, 8.267195767195768e-07, 3.306878306878307e-05, 0.001388888888888889, 0.08333333333333333),
    "D1": (3.1866552573834097e-34, 1.1981343524964268e-32, 4.4935425898311966e-31, 1.6806121662771081e-29, 6.266191399131027e-28, 2.328275960983784e-26, 8.617186003308303e-25, 3.1751334332727565e-23, 1.163957265514881e-21, 4.241648447555361e-20, 1.5349911154393775e-18, 5.5090028283602297e-17, 1.9573818287022555e-15, 6.868849645022276e-14, 2.372776207425808e-12, 8.029521918410807e-11, 2.6420950693437467e-09, 8.35070279514724e-08, 2.48015873015873e-06, 6.613756613756614e-05, 0.001388888888888889),
}


def _horner(name, t):
    acc = numpy.zeros_like(t)
    for c in SERIES[name]:
        acc = acc * t + t.dtype.type(c)
    return acc


def _closed_form(name, t):
    th = numpy.sqrt(t)
    s, c = numpy.sin(th), numpy.cos(th)
    a = s / th
    b = 2.0 * numpy.sin(0.5 * th) ** 2 / t
    cc = (th - s) / (th * t)
    if name == "A":
        return a
    if name == "B":
        return b
    if name == "C":
        return cc
    if name == "A1":
        return (c - a) / (2.0 * t)
    if name == "B1":
        return (0.5 * a - b) / t
    if name == "C1":
        return (b - 3.0 * cc) / (2.0 * t)
    cot_half = numpy.cos(0.5 * th) / numpy.sin(0.5 * th)
    if name == "D":
        return 1.0 / t - cot_half / (2.0 * th)
    csc2 = 1.0 / numpy.sin(0.5 * th) ** 2
    d_dth = -2.0 / (th * t) + csc2 / (4.0 * th) + cot_half / (2.0 * t)
    return d_dth / (2.0 * th)


def coefficient(name, t):
    """Coefficient ``name`` at t = θ² (array or scalar, dtype kept): series or closed form."""
    t = numpy.asarray(t)
    small = t < SERIES_BELOW
    series = _horner(name, t)
    if numpy.all(small):
        return series
    safe = numpy.where(small, t.dtype.type(SERIES_BELOW), t)
    with numpy.errstate(all="ignore"):
        closed = _closed_form(name, safe)
    return numpy.where(small, series, closed).astype(t.dtype, copy=False)


def lie_A(t):
    return coefficient("A", t)


def lie_A1(t):
    return coefficient("A1", t)


def lie_B(t):
    return coefficient("B", t)


def lie_B1(t):
    return coefficient("B1", t)


def lie_C(t):
    return coefficient("C", t)


def lie_C1(t):
    return coefficient("C1", t)


def lie_D(t):
    return coefficient("D", t)


def lie_D1(t):
    return coefficient("D1", t)


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
    sym = dt(0.5) * (r + numpy.swapaxes(r, -1, -2)) - cos_t[..., None, None] * numpy.eye(3, dtype=dt)
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
# retraction x ∘ Exp(δ) per variable type: x is (n, storage), δ is (n, dim); returns (n, storage)
# --------------------------------------------------------------------------------------------


def _hat(w):
    z = numpy.zeros_like(w[:, 0])
    return numpy.stack([z, -w[:, 2], w[:, 1], w[:, 2], z, -w[:, 0], -w[:, 1], w[:, 0], z],
                       -1).reshape(-1, 3, 3)


def _so3_exp_parts(w):
    """Exp(ω) and the left Jacobian Jl(ω) (n × 3 × 3) with robust coefficients."""
    t = numpy.sum(w * w, -1)
    wx = _hat(w)
    wx2 = wx @ wx
    a, b, c = (coefficient(n, t)[:, None, None] for n in ("A", "B", "C"))
    eye = numpy.eye(3, dtype=w.dtype)
    return eye + a * wx + b * wx2, eye + b * wx + c * wx2


def retract_pose3(x, d):
    """Pose3 storage [R row-major, t], tangent [ω, v]: (R, t) ∘ (Exp ω, Jl(ω) v)."""
    r = x[:, :9].reshape(-1, 3, 3)
    rot, jl = _so3_exp_parts(d[:, :3])
    t_step = (jl @ d[:, 3:, None])[..., 0]
    t_new = x[:, 9:] + (r @ t_step[..., None])[..., 0]
    return numpy.concatenate([(r @ rot).reshape(-1, 9), t_new], -1)


def retract_rot3(x, d):
    """Rot3 storage R row-major, tangent ω: R · Exp(ω)."""
    rot, _ = _so3_exp_parts(d)
    return (x.reshape(-1, 3, 3) @ rot).reshape(-1, 9)


def _rot2_compose(c, s, w):
    ce, se = numpy.cos(w), numpy.sin(w)
    return c * ce - s * se, s * ce + c * se


def retract_pose2(x, d):
    """Pose2 storage [x, y, cos, sin], tangent [vx, vy, ω] (GTSAM's order)."""
    w = d[:, 2]
    t = w * w
    a, wb = coefficient("A", t), w * coefficient("B", t)
    ux, uy = a * d[:, 0] - wb * d[:, 1], wb * d[:, 0] + a * d[:, 1]
    c, s = x[:, 2], x[:, 3]
    c_new, s_new = _rot2_compose(c, s, w)
    return numpy.stack([x[:, 0] + c * ux - s * uy, x[:, 1] + s * ux + c * uy, c_new, s_new], -1)


def retract_rot2(x, d):
    """Rot2 storage [cos, sin], tangent [θ]."""
    return numpy.stack(_rot2_compose(x[:, 0], x[:, 1], d[:, 0]), -1)


def retract_vector(x, d):
    """Vector spaces (points, velocities, IMU biases): x + δ."""
    return x + d


# --------------------------------------------------------------------------------------------
# local coordinates Log(a⁻¹ b) per variable type: a, b are (n, storage); returns (n, dim)
# --------------------------------------------------------------------------------------------


def local_rot3(a, b):
    rel = numpy.swapaxes(a.reshape(-1, 3, 3), -1, -2) @ b.reshape(-1, 3, 3)
    return numpy.stack(so3_log(*rel.reshape(-1, 9).T), -1)


def local_pose3(a, b):
    """[ω, v] = Log(a⁻¹ b): ω = Log(R_aᵀ R_b), v = Jl⁻¹(ω) R_aᵀ (t_b − t_a)."""
    rt = numpy.swapaxes(a[:, :9].reshape(-1, 3, 3), -1, -2)
    w = local_rot3(a[:, :9], b[:, :9])
    t = (rt @ (b[:, 9:] - a[:, 9:])[..., None])[..., 0]
    wx = _hat(w)
    d = coefficient("D", numpy.sum(w * w, -1))[:, None, None]
    jl_inv = numpy.eye(3, dtype=a.dtype) - 0.5 * wx + d * (wx @ wx)
    return numpy.concatenate([w, (jl_inv @ t[..., None])[..., 0]], -1)


def local_rot2(a, b):
    return numpy.arctan2(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0],
                         a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1])[:, None]


def local_pose2(a, b):
    """[vx, vy, ω] = Log(a⁻¹ b) with GTSAM's Pose2 Logmap."""
    c, s = a[:, 2], a[:, 3]
    dx, dy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
    tx, ty = c * dx + s * dy, -s * dx + c * dy
    w = local_rot2(a[:, 2:], b[:, 2:])[:, 0]
    t = w * w
    aa, wb = coefficient("A", t), w * coefficient("B", t)
    det = aa * aa + wb * wb
    return numpy.stack([(aa * tx + wb * ty) / det, (-wb * tx + aa * ty) / det, w], -1)


def local_vector(a, b):
    return b - a


LOCAL = {"pose3": local_pose3, "rot3": local_rot3, "pose2": local_pose2, "rot2": local_rot2,
         "vector": local_vector}
RETRACT = {"pose3": retract_pose3, "rot3": retract_rot3, "pose2": retract_pose2,
           "rot2": retract_rot2, "vector": retract_vector}
