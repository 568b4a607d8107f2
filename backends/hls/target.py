"""The target of a design: :class:`Target` — the FPGA part, looked up to its device's capacities
and family, the clock, and the operator table at that part and clock (:meth:`Target.ops`).

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

from fgc.errors import FgcError
from fgc_backends.hls import operators
from fgc_backends.hls.operators import OperatorTable


@dataclass(frozen=True)
class DeviceCapacity:
    """What one device holds."""

    name: str
    dsp: int
    bram36: int
    lut: int
    ff: int


DEVICES: dict[str, DeviceCapacity] = {d.name: d for d in (
    DeviceCapacity("xc7z010", 80, 60, 17_600, 35_200),
    DeviceCapacity("xc7z015", 160, 95, 46_200, 92_400),
    DeviceCapacity("xc7z020", 220, 140, 53_200, 106_400),
    DeviceCapacity("xc7z030", 400, 265, 78_600, 157_200),
    DeviceCapacity("xc7z035", 900, 500, 171_900, 343_800),
    DeviceCapacity("xc7z045", 900, 545, 218_600, 437_200),
    DeviceCapacity("xc7z100", 2020, 755, 277_400, 554_800),
    DeviceCapacity("xczu3eg", 360, 216, 70_560, 141_120),
    DeviceCapacity("xczu7ev", 1728, 312, 230_400, 460_800),
    DeviceCapacity("xczu9eg", 2520, 912, 274_080, 548_160),
)}
DEFAULT_PART = "xc7z045ffg900-2"  # the ZC706 board's part (paper A's platform)


class UnknownPartError(FgcError):
    """A part whose device is not in :data:`DEVICES` where its capacities are needed."""


def device_of(part: str) -> DeviceCapacity | None:
    """The device a part name belongs to (longest matching prefix), or None if unknown."""
    lower = part.lower()
    for name in sorted(DEVICES, key=len, reverse=True):
        if lower.startswith(name):
            return DEVICES[name]
    return None


def capacity(part: str) -> DeviceCapacity:
    """:func:`device_of`, refusing an unknown part with the devices that are known."""
    device = device_of(part)
    if device is None:
        raise UnknownPartError(f"part {part!r}: no capacities known for its device; known: "
                               f"{', '.join(DEVICES)}")
    return device


DEFAULT = capacity(DEFAULT_PART)


FAMILIES = {"xc7z": "7series", "xczu": "ultrascale+"}  # device name prefix -> part family


@dataclass(frozen=True)
class Target:
    """One design's target: ``part`` (a part name whose device is in :data:`DEVICES`) at
    ``clock_mhz``. ``device`` holds the capacities, ``family`` the part family the operator
    table is keyed by."""

    part: str = DEFAULT_PART
    clock_mhz: float = 143.0

    @property
    def device(self) -> DeviceCapacity:
        return capacity(self.part)

    @property
    def family(self) -> str:
        name = self.device.name
        return next(f for prefix, f in FAMILIES.items() if name.startswith(prefix))

    def ops(self, precision: str) -> OperatorTable:
        """The operator table of ``precision`` on this part's family at this clock."""
        return operators.table(precision, self.family, self.clock_mhz)


def target_of(part: str, clock_mhz: float) -> Target:
    """The :class:`Target` of ``part`` at ``clock_mhz``, refusing an unknown part
    (:class:`UnknownPartError`) or a clock that is not positive."""
    capacity(part)
    if not float(clock_mhz) > 0:
        raise UnknownPartError(f"clock {clock_mhz!r} MHz of part {part!r} must be positive")
    return Target(part, float(clock_mhz))
