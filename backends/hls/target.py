"""The target of a design: :class:`Target` — the FPGA part, looked up to its device's capacities
(``cost/target.py``) and family, the clock, and the operator table at that part and clock
(``cost/operators.py``, :meth:`Target.ops`), bound as the design binds its adders and
multipliers (:attr:`Target.bind`: DSP or fabric, Vitis's ``config_op``).

Every pricer reads the hardware through a Target: the accelerator plan (its operators, its fit
verdict), the update and window models (through the plan), the HLS lint's DSP budget; the
analytic cost model (``cost.params.Device``) takes its default device from :data:`DEFAULT`.
The part comes from ``HlsConfig.part`` (``PlanOptions.part``; ``run_hls.tcl`` names it), the
clock from the Program (``SolverConfig.clock_mhz``: the one source; ``HlsConfig.clock_ns``, when
given, must agree with it: ``hls.config.check_clock``).

Capacities are the AMD/Xilinx product tables' figures per device (Zynq-7000 SoC and Zynq
UltraScale+ MPSoC product selection guides): DSP slices, 36 Kb block RAMs, LUTs, flip-flops.
A part name (``xc7z045ffg900-2``) selects its device by prefix; package and speed grade do not
change the capacities (the speed grade changes the operators' achievable clock, which the
operator table's latencies assume: -2 at 143 MHz).
"""

from __future__ import annotations

from dataclasses import dataclass

from fgc_backends.cost import operators
from fgc_backends.cost.operators import OperatorTable
from fgc_backends.cost.target import (  # the capacities, read through the Target
    DEFAULT,
    DEFAULT_PART,
    DEVICES,
    DeviceCapacity,
    UnknownPartError,
    capacity,
    device_of,
)

FAMILIES = {"xc7z": "7series", "xczu": "ultrascale+"}  # device name prefix -> part family


@dataclass(frozen=True)
class Target:
    """One design's target: ``part`` (a part name whose device is in :data:`DEVICES`) at
    ``clock_mhz``. ``device`` holds the capacities, ``family`` the part family the operator
    table is keyed by."""

    part: str = DEFAULT_PART
    clock_mhz: float = 143.0
    # the design's operator binding (``((kind, implementation), ...)``, canonical: the
    # default implementations left out; ``cost/operators.py``'s IMPLEMENTATIONS): () is
    # Vitis's default binding, what every table entry prices
    bind: tuple[tuple[str, str], ...] = ()

    @property
    def device(self) -> DeviceCapacity:
        return capacity(self.part)

    @property
    def family(self) -> str:
        name = self.device.name
        return next(f for prefix, f in FAMILIES.items() if name.startswith(prefix))

    def ops(self, precision: str) -> OperatorTable:
        """The operator table of ``precision`` on this part's family at this clock, its add and
        mul bound as :attr:`bind` says (``operators.bound``)."""
        return operators.bound(operators.table(precision, self.family, self.clock_mhz),
                               self.bind)


def target_of(part: str, clock_mhz: float, bind=()) -> Target:
    """The :class:`Target` of ``part`` at ``clock_mhz`` with the operator binding ``bind``,
    refusing an unknown part (:class:`UnknownPartError`) or a clock that is not positive (a bad
    binding: ``operators.BindError``)."""
    capacity(part)
    if not float(clock_mhz) > 0:
        raise UnknownPartError(f"clock {clock_mhz!r} MHz of part {part!r} must be positive")
    return Target(part, float(clock_mhz), operators.normalise_bind(bind))


__all__ = ["DEFAULT", "DEFAULT_PART", "DEVICES", "FAMILIES", "DeviceCapacity", "Target",
           "UnknownPartError", "capacity", "device_of", "target_of"]
