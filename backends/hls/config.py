"""Configuration of the HLS C++ backend: two documented, frozen dataclasses.

:class:`DesignOptions` is the design's shape beyond the Program's solver settings: its target
(the FPGA part; the clock is the Program's, ``SolverConfig.clock_mhz``, and a period given here
must agree with it) and the units' options (unit sets, the factor datapaths' ALLOCATION). It is
the one place these are validated (:meth:`DesignOptions.check`) and the one source the
accelerator plan's options are built from (:meth:`DesignOptions.plan_options`;
``PlanOptions.for_config`` asks the config). :class:`HlsConfig` carries it (``config.design``)
beside the C++ it emits: the scalar types, the Program limits, the C simulation's compiler.

Like SymForce's code-generation configs, the config answers where the backend's templates live
(:meth:`HlsConfig.template_dir`) and which sympy printer prints its kernels
(:meth:`HlsConfig.printer`). Everything that shapes the emitted C++ beyond the Program itself is
here; there are no global flags.
"""

from __future__ import annotations

import dataclasses
import re
from dataclasses import InitVar, dataclass
from pathlib import Path

from fgc.ir.program import Program
from fgc_backends.cfamily import scalars
from fgc_backends.cfamily.errors import CodegenError
from fgc_backends.cfamily.scalars import SCALARS
from fgc_backends.cost.operators import BindError, normalise_bind
from fgc_backends.hls.plan.options import (
    CASCADE_LANES,
    DEFAULT_ALLOCATION,
    QR_ROWS,
    QR_UNITS,
    STATE_ALLOCATION,
    PlanOptions,
    scalar_precision,
)
from fgc_backends.hls.target import DEFAULT_PART, DEVICES, Target, device_of, target_of

PART_NAME = re.compile(r"^[A-Za-z0-9_-]{1,64}$")  # a part name is printed into run_hls.tcl
CLOCK_TOLERANCE = 0.005  # relative: 7 ns (142.86 MHz) and 143 MHz are the same clock
CLOCK_NS = (0.5, 1000.0)  # the clock periods fgc prices and synthesises (2 GHz … 1 MHz)
UNIT_SETS = (1, 8)  # QR/Cholesky unit sets eliminating one level's steps side by side
ALLOCATION_LIMIT = (1, 4096)  # one operator kind's ALLOCATION limit in a factor datapath
BACKSUB_LANES = (1, 2, 4)  # back-substitution's widths (fgc_backsub.h: 2, COND's four ports;
# 4: by columns, four update lanes per end of a two-ended chain)
BACKSUB_COLUMNS = 4  # the width by columns (units/backsub.py's COLUMN_LANES)
DATA_WIDTHS = (32, 64)  # the streaming top's `data` port: a float word a beat, or two (HP ports)


class HlsConfigError(CodegenError):
    """An HLS backend option is invalid, or the Program exceeds the backend's limits."""


@dataclass(frozen=True)
class DesignOptions:
    """The HLS design's options beyond the Program (``HlsConfig.design``).

    - ``part``: the FPGA part for ``run_hls.tcl``, the plan's fit verdict and operator table
      (:class:`fgc_backends.hls.target.Target`; ZC706's xc7z045 by default).
    - ``clock_ns``: ``None`` (default): the Program's clock, ``SolverConfig.clock_mhz`` - the one
      source of the design's clock (the plan prices at it, ``run_hls.tcl`` gets its period). A
      period given here must be that clock (0.5 %, :meth:`check`); ``fgc ... --clock`` sets both.
    - ``unit_sets``: QR/Cholesky unit sets that eliminate the steps of one level side by side;
      ``None`` means two on a two-ended chain (one per end, as in paper A) and one otherwise.
    - ``allocation``: the factor datapaths' ALLOCATION limits per operator kind (``add``,
      ``mul``, ``div``, ``sqrt``, ``trig``, ``special``), as ``((kind, limit), …)``; kinds not
      named keep the plan's default (``fgc_backends.hls.plan.DEFAULT_ALLOCATION``), which is
      what ``None`` means. The plan shares each limit out over the block types by instance
      count (``PlanOptions.allocation_scaling``). ``fgc compile --allocation mul=48,add=32``.
    - ``hgc_beside``: Cholesky (one cascade or two): the block type with the longest HGC
      region streams its Grams beside the elimination (the first solve of a linearisation
      factored while its HGC runs; docs/hls.md); ``False``: every block type's HGC before it.
    - ``qr_unit``: the QR unit set the design eliminates with: ``"householder"`` (paper A's
      architecture: one DATAFLOW region per reflection, ``include/fgc_qr.h``) or ``"stream"``
      (n_u reflection stages the matrix streams through, ``include/fgc_qr_stream.h``; the
      batch design only). ``fgc compile --qr-unit``.
    - ``backsub_lanes``: back-substitution's width (``include/fgc_backsub.h``): ``1``
      loads a conditional two words a cycle (COND's two ports) and runs the triangle one row
      a cycle; ``2`` partitions COND cyclic over two banks, loads four words a cycle and runs
      the triangle two rows a cycle, for more DSP (docs/hls.md, "Back-substitution"); ``4``
      solves by columns, a process per end of a two-ended chain (four update lanes each, the
      child's S xs inside its parent's columns, a loader streaming COND cyclic 4 to both ends;
      docs/hls.md, "Back-substitution by columns"); a tree is refused. ``None`` (default,
      ``--backsub-lanes auto``): the Program decides (:meth:`resolved`,
      :func:`auto_backsub_lanes`): 4 where the elimination tree is a chain (one end or two),
      faster and smaller there, and 1 on a tree and in the streaming designs (their update
      model prices one lane). The plan, the emitted text and the reports carry the resolved
      width.
    - ``cascade_lanes``: Cholesky: the words a cycle through each cascade
      (``include/fgc_cpe.h``'s ``STREAM_WORDS``): 1 (default), or 2 - every feed, tap, CPE and
      drain takes the pair of a row's words the assembly streams each cycle, so a step's ~w²/2
      words take half the cycles, at twice each CPE's multipliers and adders. ``fgc compile
      --cascade-lanes``.
    - ``hgc_third_lane``: two Cholesky cascades with the HGC beside: the streamed block type's
      Gram entries in three lanes, the third's into memories of its own, where the plan finds
      the first solve faster by it (units/cholesky.py's ``gram_third``: imu_window's IMU Grams
      at 166 words an instance instead of 248, for its K' multipliers; docs/hls.md); off by
      default (its DSP would push the fastest design that fits, #CPE 20 x2, over the part).
    - ``qr_rows``: the Householder unit's Update units one row a cycle (1, default) or two (2:
      ``include/fgc_qr.h``'s ``FGC_QR_TWO_ROWS``: the reflection's vector in two lanes by row
      parity, each unit's ``dot_axpy`` a row pair an iteration, one read and one write of each
      of its bank's two row-parity memories; about half a unit's cycles a reflection, at P + 3
      adders and 5 multipliers a unit instead of P + 1 and 3; docs/hls.md). ``fgc compile
      --qr-rows``.
    - ``bind``: the floating-point operators' binding, ``((kind, implementation), …)``: ``add``
      ``fulldsp`` (the default, 2 DSP a float adder) or ``fabric`` (LUTs only); ``mul``
      ``maxdsp`` (the default, 3 DSP), ``fulldsp``, ``meddsp`` or ``fabric``
      (``cost/operators.py``'s IMPLEMENTATIONS). ``run_hls.tcl`` gets one ``config_op <op>
      -impl X -latency N`` per Vitis operator of a bound kind (fadd and fsub, fmul; dadd, dsub,
      dmul in a double design), N the table's latency, so the cycles are the default's and the
      DSP / LUT / FF the bound implementation's. Kept canonical (the default implementations
      dropped, sorted): ``()`` (default) is Vitis's default binding and emits no config_op.
      ``fgc compile --bind add=fabric,mul=meddsp``; docs/hls.md, "Operator binding".
    - ``root_wave``: QR, two unit sets: the root step in a wavefront behind its two children
      (issue 33 item 2; docs/hls.md, "The root step in a wavefront"): the schedule's last two
      levels run as one region, the root on unit set 1 after that set's own child, each of the
      other child's passed rows streamed from set 0's collector and read into the root's banks
      before the root's first reflection that needs it. Under the one-step policy (the on-chip
      window's lin_level: level 0's sets beside the linearisation) that region is lin_level
      itself, the root's own rows streamed to set 1 by the datapaths (units/qr.py's
      ``lin_wave``). ``False`` (default): level by level. Refused (``PlanError``) on a
      schedule whose last level is not one root over two steps.
    - ``retire_special``: the special-function instances each retraction datapath of the state
      update may use (``retract_<k>``'s ALLOCATION; PlanOptions.state_limits), 1 … 3, or None:
      the design's default (1; 2 for back-substitution by columns). A Pose3 retraction calls 3
      special functions (II 12 each): 1 instance a variable every 36 cycles, 2 every 22 (its
      88 adds on 4 adders then bound it), +17 DSP an instance. Where the retire is on the path
      (the one-step stream: the last step's variables, then the trial cost's last instance)
      each of the last step's variables after the first is 14 cycles sooner at 2.
      ``fgc_backends.hls.units.state_update``; docs/hls.md, "Back-substitution after lin_level".
    - ``data_width``: the streaming top's ``data`` port (an m_axi bundle of its own), in bits a
      beat: 32 (default, one float word a beat) or 64 (two float words a beat, the width of
      Zynq-7000's HP ports; the host packs word k into beat k / 2, lane k % 2): the update's
      start (fgc_stream.h's start_data_task) then takes the call's keyframe words two an
      iteration, DATA_BUF in up to 8 cyclic banks (window.py's ``_start_tables``;
      docs/hls.md, "The update's start off the path"). The on-chip window and incremental
      designs in float only (a 64-bit beat is one double word): refused elsewhere.
      ``fgc compile --data-width 64``.

    The units' sizes (n_u Update units, #CPE) and the clock are the Program's solver settings
    (``SolverConfig.units``, ``cpe``, ``clock_mhz``): the simulator prices them too.
    """

    part: str = DEFAULT_PART
    clock_ns: float | None = None
    unit_sets: int | None = None
    allocation: tuple[tuple[str, int], ...] | None = None
    qr_unit: str = "householder"
    hgc_beside: bool = True
    backsub_lanes: int | None = None
    cascade_lanes: int = 1
    hgc_third_lane: bool = False
    qr_rows: int = 1
    bind: tuple[tuple[str, str], ...] = ()
    root_wave: bool = False
    retire_special: int | None = None
    data_width: int = 32

    def __post_init__(self):
        try:  # canonical, so equal designs compare (and hash, and cache) equal
            object.__setattr__(self, "bind", normalise_bind(self.bind))
        except BindError as exc:
            raise HlsConfigError(str(exc)) from None

    def check(self, program: Program | None = None) -> None:
        """Raise :class:`HlsConfigError` naming the first invalid option; with ``program``, also
        when ``clock_ns`` is not the Program's clock."""
        if not isinstance(self.part, str) or not PART_NAME.match(self.part):
            raise HlsConfigError(f"FPGA part {self.part!r} is not a plain part name")
        if device_of(self.part) is None:
            raise HlsConfigError(f"FPGA part {self.part!r}: fgc knows no capacities for its "
                                 f"device (the plan's fit verdict and the lint's DSP budget need "
                                 f"them); known devices: {', '.join(DEVICES)} "
                                 "(backends/hls/target.py)")
        low, high = CLOCK_NS
        if self.clock_ns is not None and not (low <= float(self.clock_ns) <= high):
            raise HlsConfigError(f"clock period {self.clock_ns} ns is outside {low:g} … {high:g} "
                                 "ns")
        low, high = UNIT_SETS
        if self.unit_sets is not None and not low <= int(self.unit_sets) <= high:
            raise HlsConfigError(f"unit_sets must be {low} … {high}, got {self.unit_sets}")
        if self.allocation is not None:
            _check_allocation(self.allocation)
        if self.backsub_lanes is not None and (self.backsub_lanes not in BACKSUB_LANES
                                               or isinstance(self.backsub_lanes, bool)):
            raise HlsConfigError(f"backsub_lanes must be one of "
                                 f"{', '.join(map(str, BACKSUB_LANES))} or None (auto), got "
                                 f"{self.backsub_lanes!r}")
        if self.cascade_lanes not in CASCADE_LANES or isinstance(self.cascade_lanes, bool):
            raise HlsConfigError(f"cascade_lanes must be one of {CASCADE_LANES} (the words a "
                                 f"cycle through a Cholesky cascade), got {self.cascade_lanes!r}")
        if not isinstance(self.root_wave, bool):
            raise HlsConfigError(f"root_wave must be True or False, got {self.root_wave!r}")
        if self.retire_special is not None and (self.retire_special not in (1, 2, 3)
                                                or isinstance(self.retire_special, bool)):
            raise HlsConfigError(f"retire_special must be 1, 2 or 3 (special-function "
                                 f"instances of a retraction) or None (the design's default), "
                                 f"got {self.retire_special!r}")
        if self.data_width not in DATA_WIDTHS or isinstance(self.data_width, bool):
            raise HlsConfigError(f"data_width must be one of {DATA_WIDTHS} (the bits a beat of "
                                 f"the streaming top's data port), got {self.data_width!r}")
        if not isinstance(self.hgc_third_lane, bool):
            raise HlsConfigError(f"hgc_third_lane must be True or False, got "
                                 f"{self.hgc_third_lane!r}")
        if self.qr_unit not in QR_UNITS:
            raise HlsConfigError(f"qr_unit {self.qr_unit!r}: expected one of "
                                 f"{', '.join(QR_UNITS)}")
        if self.qr_rows not in QR_ROWS or isinstance(self.qr_rows, bool):
            raise HlsConfigError(f"qr_rows must be one of {QR_ROWS} (the rows a cycle of the "
                                 f"Householder unit's Update units), got {self.qr_rows!r}")
        if self.qr_rows != 1 and self.qr_unit != "householder":
            raise HlsConfigError(f"qr_rows={self.qr_rows}: the Householder unit's Update "
                                 f"units (qr_unit householder), not qr_unit {self.qr_unit!r}")
        if program is not None:
            self.check_clock(program.solver.clock_mhz)
            if self.cascade_lanes != 1 and program.solver.linear != "cholesky":
                raise HlsConfigError(f"cascade_lanes={self.cascade_lanes}: the lanes of the "
                                     "Cholesky cascade; this Program solves with "
                                     f"{program.solver.linear}")
            if self.qr_rows != 1 and program.solver.linear != "qr":
                raise HlsConfigError(f"qr_rows={self.qr_rows}: the rows a cycle of the QR "
                                     "unit's Update units; this Program solves with "
                                     f"{program.solver.linear}")

    def check_clock(self, clock_mhz: float) -> None:
        """Raise :class:`HlsConfigError` if the cost model's clock (``SolverConfig.clock_mhz``)
        and ``clock_ns`` (``run_hls.tcl``'s period) are not the same clock (0.5 %); without a
        period the design takes the Program's."""
        if self.clock_ns is None:
            return
        tcl_mhz = 1000.0 / float(self.clock_ns)
        if abs(tcl_mhz - float(clock_mhz)) > CLOCK_TOLERANCE * float(clock_mhz):
            raise HlsConfigError(f"clock mismatch: the Program is costed at {clock_mhz:g} MHz "
                                 f"(SolverConfig.clock_mhz) but HlsConfig.clock_ns="
                                 f"{self.clock_ns:g} is {tcl_mhz:.4g} MHz; set both (fgc --clock "
                                 "sets both)")

    def target(self, program: Program) -> Target:
        """The design's :class:`Target`: this part at the Program's clock."""
        return target_of(self.part, program.solver.clock_mhz, self.bind)

    def resolved(self, program: Program, stream: bool = False) -> DesignOptions:
        """These options with the automatic ``backsub_lanes`` (None) decided for ``program``
        (:func:`auto_backsub_lanes`; ``stream``: the template of a streaming design); explicit
        values are kept (a width the design cannot take is refused where it is built)."""
        if self.backsub_lanes is not None:
            return self
        return dataclasses.replace(self, backsub_lanes=auto_backsub_lanes(program, stream))

    def plan_options(self, program: Program, precision: str | None = None,
                     les_precision: str | None = None, **changes) -> PlanOptions:
        """The accelerator plan's options of this design for ``program``: the Program's n_u and
        #CPE, these unit sets, part, QR unit and ALLOCATION limits (over the defaults),
        back-substitution's width (automatic: :meth:`resolved`, a batch design's), and the
        precisions the design computes in (None: the Program's)."""
        base = dict(unit_sets=self.unit_sets, part=self.part, qr_unit=self.qr_unit,
                    bind=self.bind,
                    precision=precision, les_precision=les_precision,
                    hgc_beside=bool(self.hgc_beside), cascade_lanes=int(self.cascade_lanes),
                    hgc_third_lane=bool(self.hgc_third_lane), qr_rows=int(self.qr_rows),
                    root_wave=bool(self.root_wave))
        if self.allocation:  # the design's limits over the defaults
            base["allocation"] = tuple({**dict(DEFAULT_ALLOCATION),
                                        **dict(self.allocation)}.items())
        if self.retire_special is not None:  # retract_<k>'s special-function instances
            base["state_limits"] = tuple(
                (k, int(self.retire_special) if k == "special" else n)
                for k, n in STATE_ALLOCATION)
        base.update(changes)
        if "backsub_lanes" not in base:
            lanes = self.backsub_lanes
            if lanes is None:  # columns are a frontal design's (units/backsub.py's build)
                lanes = (1 if base.get("hessian_storage", "frontal") != "frontal"
                         else auto_backsub_lanes(program))
            base["backsub_lanes"] = int(lanes)
        return PlanOptions.of(program, **base)


def auto_backsub_lanes(program: Program, stream: bool = False) -> int:
    """``DesignOptions.backsub_lanes = None``'s width for ``program``: :data:`BACKSUB_COLUMNS`
    (by columns, a process per end) where its elimination tree is a chain of one end or two
    (``units/backsub.py``'s ``column_chain``, the rule the column design is built or refused
    by), else 1 (a tree); 1 for ``stream`` (the on-chip window and incremental designs and the
    host-kept path's template: their update model, ``plan/update.py``, prices one lane)."""
    if stream:
        return 1
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.backsub import column_chain

    return BACKSUB_COLUMNS if not isinstance(column_chain(_tables(program)), str) else 1


def _check_allocation(allocation) -> None:
    kinds = dict(DEFAULT_ALLOCATION)
    low, high = ALLOCATION_LIMIT
    for item in allocation:
        if not (isinstance(item, tuple) and len(item) == 2 and item[0] in kinds
                and isinstance(item[1], int) and not isinstance(item[1], bool)):
            raise HlsConfigError(f"allocation entry {item!r}: expected (kind, limit) with kind "
                                 f"one of {', '.join(kinds)}")
        if not low <= item[1] <= high:
            raise HlsConfigError(f"allocation limit of {item[0]} must be {low} … {high}, got "
                                 f"{item[1]}")
    names = [k for k, _ in allocation]
    if len(set(names)) != len(names):
        raise HlsConfigError(f"allocation names a kind twice: {names}")


_DESIGN_FIELDS = tuple(f.name for f in dataclasses.fields(DesignOptions))


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
    - ``design``: the design's :class:`DesignOptions` (part, clock period, unit sets,
      ALLOCATION limits, QR unit). The old keywords still work and read through:
      ``HlsConfig(part="xczu9eg-ffvb1156-2-e", unit_sets=2)`` is
      ``HlsConfig(design=DesignOptions(part=…, unit_sets=2))`` and ``config.part`` is
      ``config.design.part``. An old keyword given as ``None`` keeps the design's value (to
      clear one, replace the design: ``dataclasses.replace(config.design, unit_sets=None)``).
    - ``max_variables`` / ``max_step_columns``: the largest window (Program.max_variables) and the
      widest elimination step this backend accepts; larger Programs fail at emit time.
    - ``cxx`` / ``cxxflags``: compiler and flags of the Makefile's C simulation (portable: they
      are the testbench's; the native backend's ``NativeConfig`` starts from the same flags).
    LM's limits (``lambda_upper_bound``, ``absolute_error_tol``, ``mu_min``) are the Program's
    (:class:`fgc.ir.program.SolverConfig`), as for every backend.
    """

    scalar: str = "float"
    linear_scalar: str | None = None
    design: DesignOptions = DesignOptions()
    max_variables: int = 8192
    max_step_columns: int = 512
    cxx: str = "g++"
    cxxflags: tuple[str, ...] = ("-std=c++17", "-O2", "-ffp-contract=off", "-Wall", "-Wextra",
                                 "-Werror", "-Wno-unknown-pragmas")
    # the design's options by their old names (HlsConfig(part=…)): folded into ``design``
    part: InitVar[str | None] = None
    clock_ns: InitVar[float | None] = None
    unit_sets: InitVar[int | None] = None
    allocation: InitVar[tuple[tuple[str, int], ...] | None] = None
    qr_unit: InitVar[str | None] = None
    hgc_beside: InitVar[bool | None] = None
    backsub_lanes: InitVar[int | None] = None
    cascade_lanes: InitVar[int | None] = None
    hgc_third_lane: InitVar[bool | None] = None
    qr_rows: InitVar[int | None] = None
    bind: InitVar[tuple[tuple[str, str], ...] | None] = None
    root_wave: InitVar[bool | None] = None
    retire_special: InitVar[int | None] = None
    data_width: InitVar[int | None] = None

    def __post_init__(self, part, clock_ns, unit_sets, allocation, qr_unit, hgc_beside,
                      backsub_lanes, cascade_lanes, hgc_third_lane, qr_rows, bind,
                      root_wave, retire_special, data_width) -> None:
        if not isinstance(self.design, DesignOptions):
            raise HlsConfigError(f"HlsConfig.design must be a DesignOptions, got "
                                 f"{type(self.design).__name__}")
        old = (part, clock_ns, unit_sets, allocation, qr_unit, hgc_beside, backsub_lanes,
               cascade_lanes, hgc_third_lane, qr_rows, bind, root_wave, retire_special,
               data_width)
        given = {name: value for name, value in zip(_DESIGN_FIELDS, old, strict=True)
                 if value is not None}
        if given:
            object.__setattr__(self, "design", dataclasses.replace(self.design, **given))

    def check(self, program: Program | None = None) -> None:
        """Raise :class:`HlsConfigError` naming the first invalid option; with ``program``, also
        a design clock that is not the Program's (:meth:`DesignOptions.check`)."""
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
        self.design.check(program)
        if self.design.data_width != 32 and self.scalar != "float":
            raise HlsConfigError(f"data_width={self.design.data_width}: two float words a beat "
                                 f"of the data port; this design's scalar is {self.scalar} "
                                 "(a 64-bit beat holds one double word: nothing to gain)")
        for name in ("max_variables", "max_step_columns"):
            if int(getattr(self, name)) < 1:
                raise HlsConfigError(f"{name} must be ≥ 1, got {getattr(self, name)}")
        for flag in (self.cxx, *self.cxxflags):
            if not re.match(r"^[A-Za-z0-9_+=./-]+$", flag):
                raise HlsConfigError(f"compiler option {flag!r} has characters a Makefile would "
                                     "interpret")

    @property
    def data_words(self) -> int:
        """Words of T a beat of the streaming top's ``data`` port (``design.data_width``)."""
        return self.design.data_width // 32 if self.scalar == "float" else 1

    def resolved(self, program: Program, stream: bool = False) -> HlsConfig:
        """This config with its design's automatic options decided for ``program``
        (:meth:`DesignOptions.resolved`): what :func:`~fgc_backends.hls.emitter.emit` builds
        and its project carries."""
        design = self.design.resolved(program, stream)
        return self if design is self.design else dataclasses.replace(self, design=design)

    def plan_options(self, program: Program, **changes) -> PlanOptions:
        """The options of the design this config emits for ``program``
        (:meth:`DesignOptions.plan_options`) priced in the scalar types it emits
        (``scalar_cxx`` for the whole accelerator, ``linear_cxx`` for the linear solver), not
        the Program's precision: a float design of a float64 Program is priced in float32
        operators."""
        return self.design.plan_options(program, scalar_precision(self.scalar_cxx),
                                        scalar_precision(self.linear_cxx), **changes)

    @staticmethod
    def template_dir() -> Path:
        """The folder of this backend's jinja templates."""
        return Path(__file__).resolve().parent / "templates"


def check_clock(clock_mhz: float, config: HlsConfig) -> None:
    """Raise :class:`HlsConfigError` if ``config``'s clock period is not ``clock_mhz``
    (:meth:`DesignOptions.check_clock`)."""
    config.design.check_clock(clock_mhz)


# the design's options read through the config (config.part is config.design.part); set after
# the dataclass is made, so its __init__ still takes them as keywords (the InitVars above)
for _name in _DESIGN_FIELDS:
    setattr(HlsConfig, _name, property(lambda self, _name=_name: getattr(self.design, _name),
                                       doc=f"``design.{_name}`` (:class:`DesignOptions`)"))


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
