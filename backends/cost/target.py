"""Device capacities by part: one table of what each FPGA holds, read through
:class:`fgc_backends.hls.target.Target` by the accelerator plan's fit verdict and the HLS lint's
DSP budget, and by the analytic cost model (``params.Device``) for its default device. It sits in
``cost`` (backend-neutral, no imports) so the analytic model reads it without importing the HLS
backend.

Capacities are the AMD/Xilinx product tables' figures per device (Zynq-7000 SoC and Zynq
UltraScale+ MPSoC product selection guides): DSP slices, 36 Kb block RAMs, LUTs, flip-flops.
A part name (``xc7z045ffg900-2``) selects its device by prefix; package and speed grade do not
change the capacities.
"""

from __future__ import annotations

from dataclasses import dataclass

from fgc.errors import FgcError


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
