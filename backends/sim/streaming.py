"""The backend contract's ``stream`` on the simulator: the emitted simulator's incremental module
runs the StreamProgram's policy keyframe by keyframe (the reference semantics every other
backend's stream is checked against)."""

from __future__ import annotations

from fgc.ir.datafile import ProblemData
from fgc.ir.stream import StreamProgram

from .config import SimConfig
from .runner import SimResult, run


class SimStream:
    """A runner of ``sp`` on the simulator (``precision``: overrides the Program's)."""

    who = timing_key = "simulator"

    def __init__(self, sp: StreamProgram, config: SimConfig | None = None,
                 precision: str | None = None):
        self.sp, self.config, self.precision = sp, config, precision

    def run(self, data: ProblemData, progress=None, progress_build=None) -> SimResult:
        """Stream ``data``: ``progress(record)`` after each update (``progress_build`` is not
        called: the simulator compiles no template window)."""
        sp = self.sp
        return run(sp.program, data, precision=self.precision, config=self.config,
                   policy=sp.policy, progress=progress)


def stream(sp: StreamProgram, config: SimConfig | None = None,
           precision: str | None = None) -> SimStream:
    """The backend contract's ``stream``: a runner of ``sp`` on the simulator."""
    return SimStream(sp, config, precision)
