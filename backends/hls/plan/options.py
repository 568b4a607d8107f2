"""The design options of an accelerator plan (:class:`PlanOptions`) and their defaults.

The factor datapath's and the state update's default ``ALLOCATION`` limits live here as the
options' defaults; the units that apply them are :mod:`fgc_backends.hls.units.datapath` and
:mod:`fgc_backends.hls.units.state_update`.
"""

from __future__ import annotations

from dataclasses import dataclass

from fgc.ir.program import Program
from fgc_backends.hls.plan.model import PlanError
from fgc_backends.hls.target import DEFAULT_PART

# default ALLOCATION limits of the factor datapath, per kernel operator kind (design: the sim
# model's factor pool, so both models share one datapath size)
DEFAULT_ALLOCATION = (("add", 16), ("mul", 24), ("div", 4), ("sqrt", 2), ("trig", 2),
                      ("special", 2))

# default ALLOCATION limits of the state update's datapath per variable type (design: it runs
# once per trial step over the variables, so it is kept small; a Pose3 retraction at these
# limits takes a variable every 36 cycles, set by its special functions)
STATE_ALLOCATION = (("add", 4), ("mul", 6), ("div", 1), ("sqrt", 1), ("trig", 2), ("special", 1))

# the state update of back-substitution by columns (backsub_lanes = 4): its two ends send
# their solutions side by side, each a variable every ~50 cycles on LIO and imu_window, so the
# one retire loop must take a variable in half the time to keep up with both. A Pose3
# retraction's II is set by its 3 special functions (II 12 each) on one instance (36): two
# instances give a variable every 22 cycles (+17 DSP; then its 88 adds on 4 adders bound it,
# a fifth adder would buy 4 cycles a variable, ~10 an iteration), the cheapest way to do it
# (a retire per end would be a second copy of every retraction datapath, ~+57 DSP)
STATE_ALLOCATION_COLUMNS = (("add", 4), ("mul", 6), ("div", 1), ("sqrt", 1), ("trig", 2),
                            ("special", 2))


ALLOCATION_SCALING = ("instances", "uniform")

JACOBIAN_STORAGE = ("whitened", "raw")

HESSIAN_STORAGE = ("frontal", "dense", "blocked")

CASCADE_LANES = (1, 2)  # PlanOptions.cascade_lanes: fgc_cpe.h's STREAM_WORDS

QR_UNITS = ("householder", "stream")  # PlanOptions.qr_unit: fgc_qr.h, fgc_qr_stream.h

QR_ROWS = (1, 2)  # PlanOptions.qr_rows: fgc_qr.h's Update units one row a cycle, or two


@dataclass(frozen=True)
class PlanOptions:
    units: int = 4  # n_u Update units per QR unit set
    cpe: int = 20  # Cholesky process elements
    unit_sets: int | None = None  # QR unit sets: None = 2 for two-ended chains, else 1
    # the QR unit set: "householder" (fgc_qr.h, one region per reflection) or "stream"
    # (fgc_qr_stream.h, n_u reflection stages the matrix streams through; units/qr_stream.py)
    qr_unit: str = "householder"
    # the Householder unit's Update units: 1 row a cycle, or 2 (fgc_qr.h's FGC_QR_TWO_ROWS: the
    # vector in two lanes by row parity, dot_axpy a row pair an iteration; units/qr.py)
    qr_rows: int = 1
    allocation: tuple[tuple[str, int], ...] = DEFAULT_ALLOCATION
    # how a block type's datapath gets its share of ``allocation``: "instances" (default): the
    # heaviest type (most operations × instances) gets the limits, every other type
    # ⌈limit × min(1, n / n_heaviest)⌉ (at least 1) for its n instances, so a prior evaluated
    # once a linearisation does not hold the IMU datapath's operators (the factor_jacobian
    # phase runs the types one after another; a few-instance type's loop is short whatever
    # its II); "uniform": every type gets the whole limit (capped by its own operation counts
    # in both rules)
    allocation_scaling: str = "instances"
    # retract_<k>'s ALLOCATION limits; None: the design's default (:attr:`state_allocation`)
    state_limits: tuple[tuple[str, int], ...] | None = None
    hgc_lanes: int = 32  # multipliers of each block type's Gram entries loop (HGC)
    # Cholesky (one cascade or two): the block type with the longest HGC region streams its
    # Grams beside the elimination (units/cholesky.py's _beside: linearize_solve), the first
    # solve of a linearisation factored there; False: every linearize_<b> region before it
    hgc_beside: bool = True
    # back-substitution's width (fgc_backsub.h): 1, cond_load two words a cycle (COND's two
    # ports) and the triangle one row a cycle; 2, COND cyclic over two banks, cond_load_wide
    # four words a cycle and the triangle two rows a cycle (units/backsub.py)
    backsub_lanes: int = 1
    # Cholesky: the words a cycle through each cascade (fgc_cpe.h's STREAM_WORDS: 1, or 2, the
    # pair of a row's words the assembly streams a cycle; units/cholesky.py's cpe_step_loops,
    # each CPE's operators times the lanes)
    cascade_lanes: int = 1
    # two Cholesky cascades with the HGC beside: a third Gram entries lane where the first solve
    # is faster by it (units/cholesky.py's gram_third; DesignOptions.hgc_third_lane)
    hgc_third_lane: bool = False
    # "whitened": each factor's A = W·J and b = -W·r, dense, as the factor datapath leaves them;
    # "raw": the papers' choice - the unwhitened Jacobians' structurally non-zero entries (0 and
    # ±1 entries are not stored), the residual and W's parameters, whitened while stacking
    # (a "whiten_stack" phase of multiply-accumulates before the linear solver)
    jacobian_storage: str = "whitened"
    # Cholesky: "frontal" (emitted): each elimination step's frontal [H | g] through the cascade
    # in turn (multifrontal); what-if, not emitted: "dense", the whole lower triangle of [H | g]
    # as one matrix; "blocked", only H's envelope in chain (variable) order - Cholesky fills no
    # entry outside it - and the cascade streams only that
    hessian_storage: str = "frontal"
    # the precisions the design computes in (operator table, word width): None = the Program's
    # (SolverConfig.precision, and its les_precision for the linear solver); an HLS design
    # emitted in another scalar than the Program's sets them (for_config)
    precision: str | None = None
    les_precision: str | None = None
    # the FPGA part whose device capacities the fit verdict uses (hls/target.py; an HLS
    # design's HlsConfig.part, which run_hls.tcl names)
    part: str = DEFAULT_PART
    # the operators' binding (DesignOptions.bind; run_hls.tcl's config_op lines): ((kind,
    # implementation), ...) in canonical form (cost/operators.py's normalise_bind: sorted, the
    # default implementations left out); () = Vitis's default, fulldsp adders and maxdsp
    # multipliers. The plan prices every operator through the bound table (Target.ops)
    bind: tuple[tuple[str, str], ...] = ()
    # QR: the root step in a wavefront behind its two children (issue 33 item 2,
    # units/qr.py's wave_steps): the last two levels one region, the root on unit set 1 after
    # its own child, fed the other child's passed rows by stream as they are final
    root_wave: bool = False

    @property
    def state_allocation(self) -> tuple[tuple[str, int], ...]:
        """retract_<k>'s ALLOCATION limits: ``state_limits`` if given, else
        :data:`STATE_ALLOCATION`, or :data:`STATE_ALLOCATION_COLUMNS` for back-substitution by
        columns (``backsub_lanes`` 4: two ends feed the one retire)."""
        if self.state_limits is not None:
            return self.state_limits
        return STATE_ALLOCATION_COLUMNS if self.backsub_lanes == 4 else STATE_ALLOCATION

    def precisions(self, program: Program) -> tuple[str, str]:
        """The design's (scalar, linear solver) precisions: these options' if set, else the
        Program's; a design emitted in one scalar (``precision`` set, ``les_precision`` not)
        solves in that scalar too."""
        precision = self.precision or program.solver.precision
        les = self.les_precision or (program.solver.les_precision if self.precision is None
                                     else precision)
        return precision, les

    @classmethod
    def of(cls, program: Program, **changes) -> PlanOptions:
        base = dict(units=program.solver.units, cpe=program.solver.cpe)
        base.update(changes)
        return cls(**base)

    @classmethod
    def for_config(cls, config, program: Program, **changes) -> PlanOptions:
        """The options of the design an HLS config emits for ``program``, built from its
        design options in the scalar types it emits (``HlsConfig.plan_options``)."""
        return config.plan_options(program, **changes)


def scalar_precision(scalar_cxx: str) -> str:
    """The operator-table precision of an emitted C++ scalar type."""
    if scalar_cxx == "float":
        return "float32"
    if scalar_cxx == "double":
        return "float64"
    raise PlanError(f"no operator table for the scalar type {scalar_cxx!r} (float32 and float64 "
                    "only: fgc has no fixed-point operator table)")
