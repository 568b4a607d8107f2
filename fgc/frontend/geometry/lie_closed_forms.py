"""The closed forms of the Lie coefficients A … D1 of t = θ² and the Horner evaluation of their
series: NumPy only, no fgc import, vectorised over arrays (any float dtype kept).

One source for two users: :mod:`fgc.frontend.geometry.special` evaluates the coefficients with
these, and the simulator backend copies this file byte for byte into every emitted simulator
(its run-time loads it beside ``fgc_sim_special.py``), so the simulator's Lie maps are fgc's,
not a copy of them. Keep it free of imports other than NumPy.
"""

import numpy


def horner(coeffs, t):
    """Σ coeffs[i] t^(n−1−i) (highest power first), in ``t``'s dtype."""
    acc = numpy.zeros_like(t)
    for c in coeffs:
        acc = acc * t + t.dtype.type(c)
    return acc


def closed_form(name, t):
    """Coefficient ``name`` (A, B, C, D, A1, B1, C1, D1) at t = θ² > 0 by its closed form."""
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
    if name == "D1":
        csc2 = 1.0 / numpy.sin(0.5 * th) ** 2
        d_dth = -2.0 / (th * t) + csc2 / (4.0 * th) + cot_half / (2.0 * t)
        return d_dth / (2.0 * th)
    raise KeyError(name)
