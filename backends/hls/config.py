"""Configuration of the HLS C++ backend: one documented, frozen dataclass.

Like SymForce's code-generation configs, the config answers where the backend's templates live
(:meth:`HlsConfig.template_dir`) and which sympy printer prints its kernels
(:meth:`HlsConfig.printer`). Everything that shapes the emitted C++ beyond the Program itself is
here; there are no global flags.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from fgc_backends.cfamily import scalars
from fgc_backends.cfamily.errors import CodegenError
from fgc_backends.cfamily.scalars import SCALARS

_PART = re.compile(r"^[A-Za-z0-9_-]{1,64}$")
CLOCK_TOLERANCE = 0.005  # relative: 7 ns (142.86 MHz) and 143 MHz are the same clock


QR_UNITS = ("householder", "stream")  # HlsConfig.qr_unit: fgc_qr.h, fgc_qr_stream.h


class HlsConfigError(CodegenError):
    """An HLS backend option is invalid, or the Program exceeds the backend's limits."""


@dataclass(frozen=True)
class HlsConfig(scalars.ScalarTypes):
    """Options of the HLS backend.

    - ``scalar``: the C++ scalar type ``T`` of the whole accelerator: ``"float"`` (paper A and B's
      hardware) or ``"double"``. ``fgc compile --scalar`` sets it. The vocabulary is the
      C-family one (:func:`fgc_backends.cfamily.scalars.check_scalar`), which also names
      ``"ap_fixed<W,I>"``; the dataflow design has no fixed-point units yet, so emitting it in
      fixed point is refused with that reason (the native backend builds it:
      ``fgc_backends.native``).
    - ``linear_scalar``: the scalar type ``L`` of the linear-equation solver alone (Hessian
      accumulation, elimination, back-substitution; ``"float"`` or ``"double"``, at least as
      wide as ``scalar``), the mixed design; ``None`` means ``scalar``, or ``"double"`` for a
      Program whose ``SolverConfig.linear_precision`` is float64.
    - ``part``: the FPGA part for ``run_hls.tcl``, the plan's fit verdict and operator table
      (``fgc_backends.hls.target.Target``; ZC706's xc7z045 by default).
    - ``clock_ns``: ``None`` (default): the Program's clock, ``SolverConfig.clock_mhz`` - the one
      source of the design's clock (the plan prices at it, ``run_hls.tcl`` gets its period). A
      period given here must be that clock (0.5 %, :func:`check_clock`); ``fgc ... --clock``
      sets both.
    - ``unit_sets``: QR/Cholesky unit sets that eliminate the steps of one level side by side;
      ``None`` means two on a two-ended chain (one per end, as in paper A) and one otherwise.
    - ``allocation``: the factor datapaths' ALLOCATION limits per operator kind (``add``,
      ``mul``, ``div``, ``sqrt``, ``trig``, ``special``), as ``((kind, limit), …)``; kinds not
      named keep the plan's default (``fgc_backends.hls.plan.DEFAULT_ALLOCATION``), which is
      what ``None`` means. The plan shares each limit out over the block types by instance
      count (``PlanOptions.allocation_scaling``). ``fgc compile --allocation mul=48,add=32``.
    - ``qr_unit``: the QR unit set the design eliminates with: ``"householder"`` (paper A's
      architecture: one DATAFLOW region per reflection, ``include/fgc_qr.h``) or ``"stream"``
      (n_u reflection stages the matrix streams through, ``include/fgc_qr_stream.h``; the
      batch design only). ``fgc compile --qr-unit``.
    - ``max_variables`` / ``max_step_columns``: the largest window (Program.max_variables) and the
      widest elimination step this backend accepts; larger Programs fail at emit time.
    - ``cxx`` / ``cxxflags``: compiler and flags of the Makefile's C simulation (portable: they
      are the testbench's; the native backend's ``NativeConfig`` starts from the same flags).
    LM's limits (``lambda_upper_bound``, ``absolute_error_tol``, ``mu_min``) are the Program's
    (:class:`fgc.ir.program.SolverConfig`), as for every backend.
    """

    scalar: str = "float"
    linear_scalar: str | None = None
    part: str = "xc7z045ffg900-2"
    clock_ns: float | None = None
    unit_sets: int | None = None
    allocation: tuple[tuple[str, int], ...] | None = None
    qr_unit: str = "householder"
    max_variables: int = 8192
    max_step_columns: int = 512
    cxx: str = "g++"
    cxxflags: tuple[str, ...] = ("-std=c++17", "-O2", "-ffp-contract=off", "-Wall", "-Wextra",
                                 "-Werror", "-Wno-unknown-pragmas")

    def check(self) -> None:
        """Raise :class:`HlsConfigError` naming the first invalid option."""
        scalars.check_scalar(self.scalar, HlsConfigError)
        if self.linear_scalar is not None:
            if self.linear_scalar not in SCALARS:
                raise HlsConfigError(f"linear solver scalar type {self.linear_scalar!r}: expected "
                                     "'float' or 'double'")
            if self.is_fixed_point and self.linear_scalar != self.scalar:
                raise HlsConfigError("a wider linear solver (linear_scalar) needs a floating-point "
                                     f"scalar, not {self.scalar}")
            if self.scalar == "double" and self.linear_scalar == "float":
                raise HlsConfigError("linear_scalar 'float' is narrower than scalar 'double': the "
                                     "linear solver can only be widened")
        if not _PART.match(self.part):
            raise HlsConfigError(f"FPGA part {self.part!r} is not a plain part name")
        from fgc_backends.hls.target import DEVICES, device_of

        if device_of(self.part) is None:
            raise HlsConfigError(f"FPGA part {self.part!r}: fgc knows no capacities for its "
                                 f"device (the plan's fit verdict and the lint's DSP budget need "
                                 f"them); known devices: {', '.join(DEVICES)} "
                                 "(backends/hls/target.py)")
        if self.clock_ns is not None and not (0.5 <= float(self.clock_ns) <= 1000.0):
            raise HlsConfigError(f"clock period {self.clock_ns} ns is outside 0.5 … 1000 ns")
        if self.qr_unit not in QR_UNITS:
            raise HlsConfigError(f"qr_unit {self.qr_unit!r}: expected one of {', '.join(QR_UNITS)}")
        if self.unit_sets is not None and not 1 <= int(self.unit_sets) <= 8:
            raise HlsConfigError(f"unit_sets must be 1 … 8, got {self.unit_sets}")
        if self.allocation is not None:
            from fgc_backends.hls.plan import DEFAULT_ALLOCATION

            kinds = dict(DEFAULT_ALLOCATION)
            for item in self.allocation:
                if not (isinstance(item, tuple) and len(item) == 2 and item[0] in kinds
                        and isinstance(item[1], int) and not isinstance(item[1], bool)):
                    raise HlsConfigError(f"allocation entry {item!r}: expected (kind, limit) "
                                         f"with kind one of {', '.join(kinds)}")
                if not 1 <= item[1] <= 4096:
                    raise HlsConfigError(f"allocation limit of {item[0]} must be 1 … 4096, got "
                                         f"{item[1]}")
            names = [k for k, _ in self.allocation]
            if len(set(names)) != len(names):
                raise HlsConfigError(f"allocation names a kind twice: {names}")
        for name in ("max_variables", "max_step_columns"):
            if int(getattr(self, name)) < 1:
                raise HlsConfigError(f"{name} must be ≥ 1, got {getattr(self, name)}")
        for flag in (self.cxx, *self.cxxflags):
            if not re.match(r"^[A-Za-z0-9_+=./-]+$", flag):
                raise HlsConfigError(f"compiler option {flag!r} has characters a Makefile would "
                                     "interpret")





    @staticmethod
    def template_dir() -> Path:
        """The folder of this backend's jinja templates."""
        return Path(__file__).resolve().parent / "templates"


def check_clock(clock_mhz: float, config: HlsConfig) -> None:
    """Raise :class:`HlsConfigError` if the cost model's clock (``SolverConfig.clock_mhz``) and
    ``config.clock_ns`` (``run_hls.tcl``'s period) are not the same clock (0.5 %); a config
    without a period takes the Program's."""
    if config.clock_ns is None:
        return
    tcl_mhz = 1000.0 / float(config.clock_ns)
    if abs(tcl_mhz - float(clock_mhz)) > CLOCK_TOLERANCE * float(clock_mhz):
        raise HlsConfigError(f"clock mismatch: the Program is costed at {clock_mhz:g} MHz "
                             f"(SolverConfig.clock_mhz) but HlsConfig.clock_ns={config.clock_ns:g} "
                             f"is {tcl_mhz:.4g} MHz; set both (fgc --clock sets both)")


def parse_clock(text: str) -> tuple[float, float]:
    """``"143"``, ``"143MHz"``, ``"7ns"`` → (MHz, ns). A bare number is MHz if ≥ 20, else ns
    (no FPGA clock here is below 20 MHz or above 2 GHz). Raises :class:`HlsConfigError`."""
    m = re.fullmatch(r"\s*([0-9]+(?:\.[0-9]*)?|\.[0-9]+)\s*(mhz|ns)?\s*", text, re.IGNORECASE)
    if not m:
        raise HlsConfigError(f"clock {text!r}: expected a frequency like 143MHz or a period "
                             "like 7ns")
    value, unit = float(m.group(1)), (m.group(2) or "").lower()
    if value <= 0:
        raise HlsConfigError(f"clock {text!r} must be positive")
    if not unit:
        unit = "mhz" if value >= 20 else "ns"
    mhz, ns = (value, 1000.0 / value) if unit == "mhz" else (1000.0 / value, value)
    if not 0.5 <= ns <= 1000.0:
        raise HlsConfigError(f"clock {text!r} ({mhz:.4g} MHz, {ns:.4g} ns) is outside 1 MHz … "
                             "2 GHz")
    return mhz, ns
