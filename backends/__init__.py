"""fgc backends (import package ``fgc_backends``): one sub-package per target, one registry.

Every backend module offers the same contract::

    backend = load("native")                           # the fgc_backends.native module
    backend.Config                                     # its frozen config (name, options)
    backend.emit(program, out_dir, config=None)        # write the project; returns its files
    backend.run(program, data, config=config)          # emit, build, solve → a result
    runner = backend.stream(stream_program, config=None)   # a chain fed keyframe by keyframe
    runner.run(data, progress=None, progress_build=None)   # → a result with ``updates``

``stream`` takes a :class:`fgc.ir.stream.StreamProgram` (the middle end's stream stage,
:func:`fgc.compiler.stream.compile_stream`: the chain Program, its policy ``FixedLag(W)`` or
``Incremental(K, batch_every)`` and its slot layout) and returns a runner, checked when made: a
stream the backend cannot run is refused then (an ``FgcError``), before anything is printed or
built. ``runner.who`` names what solves ("simulator", "native solver", "HLS C simulation"),
``runner.timing_key`` its wall times in reports ("simulator", "native", "csim");
``runner.run`` streams ``data`` (``fgc.ir.datafile.ProblemData``), calling ``progress(record)``
after each keyframe's update (``keyframe``, ``mode``, ``first``, ``iterations``, ``status``,
``cost``, ``values`` …) and ``progress_build(size, index, count)`` before compiling each template
window. A backend whose ``BackendInfo.stream_design`` is set also emits a StreamProgram
(``emit(stream_program, out_dir, config)``: a streaming hardware design).

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
    # emit takes a StreamProgram too: a design that keeps the stream's window between calls
    stream_design: bool = False


BACKENDS: dict[str, BackendInfo] = {
    "sim": BackendInfo("sim", "a standalone NumPy simulator of the accelerator's algorithm",
                       hardware=False),
    "hls": BackendInfo("hls", "the dataflow accelerator as Vitis HLS C++ (testbench, tcl, "
                              "Makefile; run = the C simulation, make csim)", hardware=True,
                       stream_design=True),
    "native": BackendInfo("native", "the solver as a CPU program: C++ built on this machine, "
                                    "called through ctypes", hardware=False),
}
CONTRACT = ("Config", "emit", "run", "stream")


def names() -> tuple[str, ...]:
    """The registered backends' names, in registry order."""
    return tuple(BACKENDS)


def load(name: str) -> ModuleType:
    """The backend package registered as ``name``."""
    if name not in BACKENDS:
        raise FgcError(f"unknown backend {name!r}; available: {', '.join(sorted(BACKENDS))}")
    return import_module(f"{__name__}.{name}")
