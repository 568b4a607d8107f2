"""Streaming on the native solver (issue 19): per keyframe the compiled C++ solves the window of
the newest keyframes, with the marginal prior of the keyframes that left it (fixed-lag) or the
kept Bayes net of paper A's incremental plan.

The template window (the chain's first S keyframes with a ``MarginalPrior…`` factor on each,
filled per update with the numbers of the window it holds) is the middle end's
(:mod:`fgc.compiler.stream`); the updates' loop, the marginalisation and the kept Bayes net on
the host are the C-family layer's (:mod:`fgc_backends.cfamily.stream`). This module binds them
to the native library (:func:`fgc_backends.native.solver.load`: built once per template) and
offers the backend contract's :func:`stream`.
"""

from __future__ import annotations

from fgc.compiler.stream import WindowTemplate, marginal_prior_type
from fgc.ir.datafile import ProblemData
from fgc.ir.stream import StreamError, StreamProgram
from fgc_backends.cfamily.stream import (
    FixedLagDriver,
    IncrementalDriver,
    KeptNet,
    StreamResult,
    TemplateSolver,
    _CompiledGeometry,
    as_prior,
)
from fgc_backends.native.solver import load as load_solver

# the names this module had before the shared layers held them
NativeStreamError = StreamError
NativeStreamResult = StreamResult
__all__ = ["FixedLagStream", "IncrementalStream", "KeptNet", "NativeStream", "NativeStreamError",
           "NativeStreamResult", "WindowSolver", "WindowTemplate", "_CompiledGeometry",
           "as_prior", "marginal_prior_type", "stream"]


def _loader(config):
    return lambda template: load_solver(template, config)


class WindowSolver(TemplateSolver):
    """The native solver compiled for a template window of ``size`` keyframes
    (:class:`~fgc_backends.cfamily.stream.TemplateSolver`)."""

    def __init__(self, graph, program, size: int, config=None):
        super().__init__(graph, program, size, _loader(config))


class FixedLagStream(FixedLagDriver):
    """The native solver compiled for a fixed-lag window of ``window`` keyframes over the chain
    ``program`` (compiled from ``graph``); :meth:`run` streams ``data``."""

    def __init__(self, graph, program, window: int, config=None):
        super().__init__(graph, program, window, _loader(config))


class IncrementalStream(IncrementalDriver):
    """The native solver running the simulator's incremental plan
    (:class:`~fgc_backends.cfamily.stream.IncrementalDriver`); ``window_solver`` makes the
    window solvers (default :class:`WindowSolver` with ``config``)."""

    def __init__(self, graph, program, config=None, progress_build=None, window_solver=None,
                 host: str = "native"):
        make = window_solver or (lambda size: WindowSolver(graph, program, size, config))
        super().__init__(graph, program, make, progress_build, host)


class NativeStream:
    """The contract's stream runner on the native solver: checked when made (a chain no
    template window can run is refused here, before anything runs), compiled on :meth:`run`."""

    who, timing_key = "native solver", "native"

    def __init__(self, sp: StreamProgram, config=None):
        sp.slots.check("the native solver", StreamError)
        self.sp, self.config = sp, config

    def run(self, data: ProblemData, progress=None, progress_build=None) -> StreamResult:
        """Stream ``data``: ``progress(record)`` after each update, ``progress_build(size,
        index, count)`` before each template window is compiled."""
        sp = self.sp
        if sp.window is not None:
            if progress_build is not None:
                progress_build(sp.window + 1, 0, 1)
            runner = FixedLagStream(sp.graph, sp.program, sp.window, self.config)
        else:
            runner = IncrementalStream(sp.graph, sp.program, self.config,
                                       progress_build=progress_build)
        return runner.run(data, progress)


def stream(sp: StreamProgram, config=None) -> NativeStream:
    """The backend contract's ``stream``: a runner of ``sp`` on the native solver."""
    return NativeStream(sp, config)
