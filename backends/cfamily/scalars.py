"""The scalar types the C-family backends build, and what fixed point needs of them.

One vocabulary for the HLS and native backends: ``float``, ``double`` or ``ap_fixed<W,I>``
(:func:`check_scalar`). Fixed point is declared ``ap_fixed<W, I, AP_RND_CONV, AP_SAT>`` (round
to nearest, saturate: no wrap-around, :func:`fixed_declaration`); a constant the emitted code
holds or a data value it reads that lies outside the format's range is refused, naming it
(:func:`check_fixed_constants`, :func:`check_fixed_data`), since saturating it would give a
wrong answer without saying so. The ``ap_types`` headers come from the optional ``hls4ml``
package (:func:`ap_types_include`); fgc never vendors them.

Each check raises the caller's error class (``error=``, a :class:`CodegenError` subclass such as
``HlsConfigError`` or ``NativeConfigError``), so a backend's user sees its own error type.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from pathlib import Path

from fgc_backends.cfamily.errors import CodegenError

SCALARS = ("float", "double")
AP_FIXED = re.compile(r"^ap_fixed<\s*(\d{1,4})\s*,\s*(-?\d{1,4})\s*>$")
AP_FIXED_MAX_WIDTH = 1024  # AP_INT_MAX_W, the ap_types headers' default limit on W
FIXED_QUANTIZATION = "AP_RND_CONV, AP_SAT"  # round to nearest (even); saturate, never wrap
# Xilinx's ap_types headers trip g++'s flow-based warnings once inlined into our code (-isystem
# cannot silence those); the warnings are theirs, so only these two are relaxed for ap_fixed.
FIXED_POINT_FLAGS = ("-Wno-uninitialized", "-Wno-maybe-uninitialized")


def check_scalar(text: str, error: type[CodegenError] = CodegenError) -> str:
    """``text`` if it is a scalar type the backends build, else ``error``: ``float``,
    ``double`` or ``ap_fixed<W,I>`` with 2 ≤ W ≤ 1024 total bits and 1 ≤ I ≤ W integer bits
    (sign included), so that there are a sign bit and at least one value bit."""
    if text in SCALARS:
        return text
    m = AP_FIXED.match(text)
    if not m:
        raise error(f"scalar type {text!r}: expected 'float', 'double' or 'ap_fixed<W,I>'")
    width, integer = int(m.group(1)), int(m.group(2))
    if not 2 <= width <= AP_FIXED_MAX_WIDTH:
        raise error(f"scalar type {text!r}: width W={width} must be 2 … {AP_FIXED_MAX_WIDTH} "
                    "bits")
    if not 1 <= integer <= width:
        raise error(f"scalar type {text!r}: integer bits I={integer} must be 1 … W={width} "
                    "(sign bit included)")
    return text


def is_fixed_point(scalar: str) -> bool:
    return AP_FIXED.match(scalar) is not None


def scalar_cxx(scalar: str) -> str:
    """The scalar type as C++ text (``ap_fixed<W, I>``, whitespace normalised)."""
    m = AP_FIXED.match(scalar)
    return f"ap_fixed<{m.group(1)}, {m.group(2)}>" if m else scalar


def fixed_format(scalar: str) -> tuple[int, int] | None:
    """(W, I) of an ``ap_fixed<W,I>`` scalar, None for floating point."""
    m = AP_FIXED.match(scalar)
    return (int(m.group(1)), int(m.group(2))) if m else None


def epsilon(scalar: str) -> float:
    """Machine epsilon of a scalar type (the LSB 2^-(W-I) for fixed point)."""
    if scalar == "float":
        return 2.0 ** -23
    if scalar == "double":
        return 2.0 ** -52
    width, integer = fixed_format(scalar)
    return 2.0 ** -(width - integer)


def fixed_declaration(scalar: str) -> str:
    """The C++ type the kernel declares ``T`` as: ``ap_fixed<W, I, AP_RND_CONV, AP_SAT>`` (an
    overflow saturates explicitly instead of wrapping round, a result rounds to nearest), or the
    floating-point type itself."""
    fmt = fixed_format(scalar)
    return f"ap_fixed<{fmt[0]}, {fmt[1]}, {FIXED_QUANTIZATION}>" if fmt else scalar


def fixed_range(scalar: str) -> tuple[float, float, float]:
    """(lowest, highest, LSB) of ``ap_fixed<W,I>``: -2^(I-1) … 2^(I-1) - 2^-(W-I)."""
    width, integer = fixed_format(scalar)
    lsb = 2.0 ** -(width - integer)
    return -(2.0 ** (integer - 1)), 2.0 ** (integer - 1) - lsb, lsb


def lsb_floor(value: float, scalar: str) -> float:
    """``value``, or one LSB of ``scalar`` where a nonzero floor or tolerance is smaller than
    that in magnitude (it would round to 0 in fixed point and switch its test off)."""
    if not is_fixed_point(scalar) or value == 0:
        return value
    lsb = epsilon(scalar)
    return value if abs(value) >= lsb else (lsb if value > 0 else -lsb)


_NAMED_CONSTANT = re.compile(r"\bconst\s+[TL]\s+([A-Z_][A-Z0-9_]*)\s*=\s*\(?(-?)[TL]\("
                             r"([-+0-9.eE]+)\)")
_T_LITERAL = re.compile(r"\b[TL]\(([-+]?[0-9][0-9.eE+-]*)\)")


def kernel_constants(files: Iterable[tuple[str, str]]) -> list[tuple[str, float]]:
    """(name, value) of every scalar constant in ``files`` ((file name, C++ text) pairs): named
    ``const T NAME = T(v)`` by their names, every other ``T(v)`` / ``L(v)`` literal by file and
    line."""
    out = []
    for file, text in files:
        named = set()
        for m in _NAMED_CONSTANT.finditer(text):
            named.add(m.start(3) - 2)  # where that constant's T( literal starts
            out.append((m.group(1), float(m.group(2) + m.group(3))))
        # line numbers counted on from the previous literal (counting from the file's start for
        # each literal took 10 s of a 10,000-variable emit)
        line, counted = 1, 0
        for m in _T_LITERAL.finditer(text):
            if m.start() not in named:
                line += text.count("\n", counted, m.start())
                counted = m.start()
                out.append((f"T({m.group(1)}) at {file}:{line}", float(m.group(1))))
    return out


def check_fixed_constants(scalar: str, constants: Iterable[tuple[str, float]],
                          error: type[CodegenError] = CodegenError,
                          hint: str = "a smaller constant") -> None:
    """Raise ``error`` naming the first of ``constants`` ((name, value) pairs: what the kernel
    would hold) outside the range of ``scalar`` (an ``ap_fixed<W,I>``), which the format could
    only saturate; floating-point scalars hold every finite constant. ``hint`` says which
    option shrinks the constant."""
    if fixed_format(scalar) is None:
        return
    lo, hi, _ = fixed_range(scalar)
    for name, value in constants:
        if not lo <= float(value) <= hi:
            raise error(f"constant {name} = {float(value)!r} does not fit {scalar_cxx(scalar)} "
                        f"(range {lo:g} … {hi:.6g}): the kernel would hold a saturated value. "
                        f"Use more integer bits or {hint}")


def check_fixed_data(scalar: str, program, data,
                     error: type[CodegenError] = CodegenError) -> None:
    """Raise ``error`` naming the variable or factor whose initial value or data
    (measurements, square-root information) does not fit ``scalar``'s range."""
    if fixed_format(scalar) is None:
        return
    import numpy as np

    lo, hi, _ = fixed_range(scalar)
    name = scalar_cxx(scalar)
    for v, values in zip(program.variables, data.variables, strict=True):
        values = np.asarray(values)
        bad = np.flatnonzero(~((values >= lo) & (values <= hi)))
        if bad.size:
            raise error(f"variable {v.key!r}: initial value entry {int(bad[0])} = "
                        f"{float(values[bad[0]])!r} does not fit {name} (range {lo:g} … "
                        f"{hi:.6g})")
    for index, (spec, values) in enumerate(zip(program.factors, data.factors, strict=True)):
        values = np.asarray(values)
        bad = np.flatnonzero(~((values >= lo) & (values <= hi)))
        if bad.size:
            block = program.blocks[spec.block].name
            raise error(f"factor instance {index} ({block} on {list(spec.keys)}): data entry "
                        f"{int(bad[0])} = {float(values[bad[0]])!r} does not fit {name} (range "
                        f"{lo:g} … {hi:.6g}; a square-root information 1/sigma counts)")


def ap_types_include(error: type[CodegenError] = CodegenError) -> Path:
    """The folder holding ``ap_fixed.h`` from the optional ``hls4ml`` package.

    hls4ml ships Xilinx's Apache-2.0 ``ap_types`` headers; fgc never vendors them. Raises
    ``error`` with the install command when they are missing. The package is located, not
    imported (importing hls4ml pulls in its own dependencies, which fgc does not need).
    """
    import importlib.util

    spec = importlib.util.find_spec("hls4ml")
    if spec is not None and spec.submodule_search_locations:
        root = Path(next(iter(spec.submodule_search_locations)))
        for candidate in sorted(root.glob("templates/*/ap_types")):
            if (candidate / "ap_fixed.h").is_file():
                if not re.match(r"^[A-Za-z0-9_./+-]+$", str(candidate)):
                    raise error(f"the ap_types folder {str(candidate)!r} has characters a "
                                "Makefile or tcl script would interpret")
                return candidate
    raise error("scalar type ap_fixed needs Xilinx's ap_types headers, which fgc takes from the "
                "optional hls4ml package: pip install 'fgc[hls-fixed]' (or pip install --no-deps "
                "hls4ml)")


class ScalarTypes:
    """The scalar-type views of a C++ backend's config (HlsConfig, NativeConfig): both hold
    ``scalar`` (float, double or ap_fixed<W,I>) and ``linear_scalar`` (None: the same)."""

    __slots__ = ()

    @property
    def is_fixed_point(self) -> bool:
        return is_fixed_point(self.scalar)

    @property
    def scalar_cxx(self) -> str:
        """The scalar type as C++ text (whitespace normalised)."""
        return scalar_cxx(self.scalar)

    @property
    def linear_cxx(self) -> str:
        """The linear solver's scalar type as C++ text (``scalar_cxx`` unless widened)."""
        return self.linear_scalar or self.scalar_cxx

    @property
    def mixed(self) -> bool:
        """Whether the linear solver is wider than the rest of the design."""
        return self.linear_cxx != self.scalar_cxx
