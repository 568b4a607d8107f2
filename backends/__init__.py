"""fgc backends (import package ``fgc_backends``): one sub-package per target.

Backends are registered here by name and imported only when asked for, so ``fgc`` never imports
one at module level::

    from fgc_backends import load
    sim = load("sim")            # the fgc_backends.sim module
"""

from __future__ import annotations

from importlib import import_module
from types import ModuleType

from fgc.errors import FgcError

BACKENDS: dict[str, str] = {
    "sim": "a standalone NumPy simulator of the accelerator (numerics, cycles, resources)",
    "hls": "Vitis HLS C++, testbench, tcl and Makefile",
    "native": "the solver as a CPU program: C++ built on this machine, called through ctypes",
}


def load(name: str) -> ModuleType:
    """The backend package registered as ``name``."""
    if name not in BACKENDS:
        raise FgcError(f"unknown backend {name!r}; available: {', '.join(sorted(BACKENDS))}")
    return import_module(f"{__name__}.{name}")
