"""Configuration of the native backend: the scalar types, the host lanes and the compiler.

The native backend builds the generated C++ as a CPU program, so of the HLS backend's options it
keeps only what shapes a host build: no FPGA part, no clock, no unit sets (the CPU runs the unit
sets' steps one after another, as the C simulation does). The scalar vocabulary is the C-family
one the HLS backend uses too (:mod:`fgc_backends.cfamily.scalars`).
"""

from __future__ import annotations

import platform
import re
from dataclasses import dataclass, field
from pathlib import Path

from fgc_backends.cfamily import scalars
from fgc_backends.cfamily.errors import CodegenError
from fgc_backends.cfamily.scalars import SCALARS


class NativeConfigError(CodegenError):
    """A native backend option is invalid, or the Program exceeds the backend's limits."""


def host_flags(machine: str | None = None) -> tuple[str, ...]:
    """The native build's extra flags on ``machine`` (default: this one's architecture)."""
    machine = (machine or platform.machine()).lower()
    if machine in ("x86_64", "amd64", "i686", "i386"):
        return ("-O3", "-march=native", "-mno-fma", "-mprefer-vector-width=512")
    return ("-O3",)  # elsewhere -ffp-contract=off alone keeps the rounding; ISA flags differ


@dataclass(frozen=True)
class NativeConfig(scalars.ScalarTypes):
    """Options of the native backend.

    - ``scalar``: the C++ scalar type ``T``: ``"float"``, ``"double"`` or ``"ap_fixed<W,I>"``
      (:func:`fgc_backends.cfamily.scalars.check_scalar`). ``fgc run --scalar`` sets it;
      :func:`fgc_backends.native.default_config` takes it from the Program's precision. Fixed
      point needs the optional ``hls4ml`` package's ``ap_types`` headers and is declared
      ``ap_fixed<W, I, AP_RND_CONV, AP_SAT>`` (round to nearest, saturate, never wrap); every
      constant the solver holds is range-checked at emit time and refused, naming it, if it
      does not fit (LM's default ``lambda_upper_bound`` 1e10 needs I ≥ 35 integer bits), and so
      is the data before a solve (:meth:`NativeSolver.flatten`); floors and tolerances below
      one LSB are raised to one LSB. sqrt and the trigonometric, exponential and logarithmic
      functions are computed in ``double`` and rounded back to ``T``.
    - ``linear_scalar``: the linear solver's scalar ``L`` (``"float"`` or ``"double"``, at
      least as wide as ``scalar``); ``None`` means ``scalar``, or ``"double"`` for a Program
      whose ``SolverConfig.linear_precision`` is float64.
    - ``lanes``: factor instances a block evaluates side by side, one lane each of a GCC/Clang
      vector type; ``None`` means one vector register, chosen by the compiler's target: 64 bytes
      where the build has AVX-512 (8 doubles, 16 floats), else 32. Fixed point uses one. Each
      lane computes exactly the scalar kernel, so results do not depend on it.
    - ``cxx`` / ``cxxflags``: compiler and base flags, the HLS C simulation's (so that both
      builds round alike): ``-ffp-contract=off``, warnings as errors.
    - ``host_flags``: added on top, for the machine that runs the library: ``-O3
      -march=native`` (AVX on x86, AVX-512 at full width where the CPU has it) but no fused
      multiply-add (``-mno-fma``), so every operation rounds as in the C simulation and the
      two give bit-identical results. GCC 12 still emits ``vfmaddsub`` under
      ``-ffp-contract=off -mno-fma`` where AVX-512 is on, so with ``-mno-fma`` the Makefile
      checks the library (``objdump``) and builds it again with ``-mno-avx512f`` if it holds
      any fused multiply-add. Set ``()`` to build with ``cxxflags`` alone.
    - ``max_variables`` / ``max_step_columns``: optional bounds on the window and on the widest
      elimination step, for a build that must stay within a size (a hardware-like budget);
      ``None`` (the default) accepts any size: the kernel's buffers are sized from the Program
      (its tables' widths and counts), so a CPU build has no limit of its own.
    LM's limits (``lambda_upper_bound``, ``absolute_error_tol``, ``mu_min``) are the Program's
    (:class:`fgc.ir.program.SolverConfig`), as for every backend.
    """

    scalar: str = "double"
    linear_scalar: str | None = None
    lanes: int | None = None
    cxx: str = "g++"
    cxxflags: tuple[str, ...] = ("-std=c++17", "-O2", "-ffp-contract=off", "-Wall", "-Wextra",
                                 "-Werror", "-Wno-unknown-pragmas")
    host_flags: tuple[str, ...] = field(default_factory=lambda: host_flags())
    max_variables: int | None = None
    max_step_columns: int | None = None

    def check(self) -> None:
        """Raise :class:`NativeConfigError` naming the first invalid option."""
        scalars.check_scalar(self.scalar, NativeConfigError)
        if self.linear_scalar is not None:
            if self.linear_scalar not in SCALARS:
                raise NativeConfigError(f"linear solver scalar type {self.linear_scalar!r}: "
                                        "expected 'float' or 'double'")
            if self.is_fixed_point and self.linear_scalar != self.scalar:
                raise NativeConfigError("a wider linear solver (linear_scalar) needs a "
                                        f"floating-point scalar, not {self.scalar}")
            if self.scalar == "double" and self.linear_scalar == "float":
                raise NativeConfigError("linear_scalar 'float' is narrower than scalar "
                                        "'double': the linear solver can only be widened")
        if self.lanes is not None and self.lanes not in (1, 2, 4, 8, 16):
            raise NativeConfigError(f"lanes must be 1, 2, 4, 8 or 16, got {self.lanes}")
        for name in ("max_variables", "max_step_columns"):
            if getattr(self, name) is not None and int(getattr(self, name)) < 1:
                raise NativeConfigError(f"{name} must be ≥ 1, got {getattr(self, name)}")
        for flag in (self.cxx, *self.cxxflags, *self.host_flags):
            if not re.match(r"^[A-Za-z0-9_+=./-]+$", flag):
                raise NativeConfigError(f"compiler option {flag!r} has characters a Makefile "
                                        "would interpret")

    @staticmethod
    def template_dir() -> Path:
        """The folder of this backend's jinja templates."""
        return Path(__file__).resolve().parent / "templates"
