"""fgc's robust special functions (:mod:`fgc.frontend.geometry.special`) as printed C++ bodies.

The header template defines ``lie_A`` … ``lie_D1`` as inline functions of ``t = θ²``: the Taylor
series (Horner form, coefficients from ``special.SERIES``) below ``t < 4`` and the closed form
above it. The closed forms are written here once as small sympy kernels — the same formulas as
``fgc/frontend/geometry/lie_closed_forms.py`` (NumPy, which the simulator copies) — and printed
by the backend's printer, so no arithmetic is spelled out in a template.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from fgc.compiler.kernel import Kernel, drop_dead
from fgc.frontend.geometry import special
from fgc_backends.cfamily.printer import HlsCodePrinter, print_kernel


@dataclass(frozen=True)
class CoefficientFunction:
    """One ``lie_<name>(t)``: Horner text of its series and its printed closed form."""

    name: str
    series: str
    closed_lines: tuple[str, ...]
    closed_result: str


def _closed_form_kernel(name: str) -> Kernel:
    t, th, s, c, a, b, cc, cot_half = sp.symbols("t th s c a b cc cot_half", real=True)
    steps = [(th, sp.sqrt(t)), (s, sp.sin(th)), (c, sp.cos(th)), (a, s / th),
             (b, 2 * sp.sin(th / 2) ** 2 / t), (cc, (th - s) / (th * t)),
             (cot_half, sp.cos(th / 2) / sp.sin(th / 2))]
    result = {
        "A": a, "B": b, "C": cc,
        "A1": (c - a) / (2 * t), "B1": (a / 2 - b) / t, "C1": (b - 3 * cc) / (2 * t),
        "D": 1 / t - cot_half / (2 * th),
        "D1": (-2 / (th * t) + 1 / (4 * th * sp.sin(th / 2) ** 2) + cot_half / (2 * t))
        / (2 * th),
    }[name]
    return Kernel((t,), drop_dead(tuple(steps), [result]), (result,))


def coefficient_functions() -> tuple[CoefficientFunction, ...]:
    """All coefficient functions, in ``special.COEFFICIENT_FUNCTIONS`` order."""
    printer = HlsCodePrinter({})
    out = []
    for name in special.COEFFICIENT_FUNCTIONS:
        coeffs = [float(c) for c in special.SERIES[name]]
        printed = print_kernel(_closed_form_kernel(name), ["t"], f"lie_{name}", prefix="c")
        out.append(CoefficientFunction(name, printer.horner(coeffs, "t"), printed.intermediates,
                                       printed.outputs[0]))
    return tuple(out)


SERIES_BELOW = special.SERIES_BELOW  # the switch point the numeric reference uses
