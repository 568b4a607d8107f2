"""fgc backends (import package ``fgc_backends``): one sub-package per target, one registry.

Every backend module offers the same contract::

    backend = load("native")                           # the fgc_backends.native module
    backend.Config                                     # its frozen config (name, options)
    backend.emit(program, out_dir, config=None)        # write the project; returns its files
    backend.run(program, data, config=config)          # emit, build, solve → a result

``run``'s result has ``status``, ``reason``, ``iterations``, ``initial_error``,
``final_error`` and ``values``: the estimate keyed by the Program's variable keys as fgc values
(``fgc.geometry`` objects). The CLI's ``--backend`` choices and the tests read :data:`BACKENDS`;
a new backend is a sub-package plus one entry here. Backends are imported only when asked for,
so ``fgc`` never imports one at module level. Shared layers that are not backends:
``cfamily`` (C++ printing for hls and native) and ``cost`` (the analytic hardware cost model).
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import import_module
from types import ModuleType

from fgc.errors import FgcError


@dataclass(frozen=True)
class BackendInfo:
    """A registered backend: what it emits, and whether its figures describe hardware (then
    every cycle / resource figure is a model estimate until a vendor tool checks it)."""

    name: str
    summary: str
    hardware: bool


BACKENDS: dict[str, BackendInfo] = {
    "sim": BackendInfo("sim", "a standalone NumPy simulator of the accelerator's algorithm",
                       hardware=False),
    "hls": BackendInfo("hls", "the dataflow accelerator as Vitis HLS C++ (testbench, tcl, "
                              "Makefile; run = the C simulation, make csim)", hardware=True),
    "native": BackendInfo("native", "the solver as a CPU program: C++ built on this machine, "
                                    "called through ctypes", hardware=False),
}
CONTRACT = ("Config", "emit", "run")


def names() -> tuple[str, ...]:
    """The registered backends' names, in registry order."""
    return tuple(BACKENDS)


def load(name: str) -> ModuleType:
    """The backend package registered as ``name``."""
    if name not in BACKENDS:
        raise FgcError(f"unknown backend {name!r}; available: {', '.join(sorted(BACKENDS))}")
    return import_module(f"{__name__}.{name}")
