"""The native backend: the generated solver as a CPU program, built on this machine and called
through ctypes (timed against GTSAM's LM by bench/bench_native.py).

    from fgc_backends import native
    result = native.run(program, problem_data(graph, program))   # emit, build once, solve
    project = native.emit(program, "out/", native.NativeConfig(scalar="double"))

Emitted files: ``<name>.h``/``<name>.cpp`` (the solver, ``<name>_top``), ``native_<name>.cpp``
(C entry points) and a ``Makefile`` (``make native`` → ``lib<name>.so``). It is not a hardware
design: a CPU program (SIMD lanes, host-only paths, no fused multiply-add) that meets the
simulator's numbers to 1e-9 (double), as the HLS C simulation does.
"""

from fgc_backends.native.build import NativeBuildError, make
from fgc_backends.native.config import NativeConfig, NativeConfigError, host_flags
from fgc_backends.native.emitter import NativeProject, emit
from fgc_backends.native.solver import NativeSolver, default_config, load, run
from fgc_backends.native.streaming import stream

Config = NativeConfig  # the backend contract's name (fgc_backends.CONTRACT)

__all__ = ["Config", "NativeBuildError", "NativeConfig", "NativeConfigError", "NativeProject",
           "NativeSolver", "default_config", "emit", "host_flags", "load", "make", "run", "stream"]
