"""The simulator backend: a Program → a standalone NumPy program that runs the accelerator's
algorithm (GN/LM, partial-QR or Cholesky elimination along the schedule) on a data file.

The run-time is the package :mod:`fgc_backends.sim.runtime`, copied verbatim into every emitted
project; only the problem module and the constants module are generated (see ``emitter``).

    from fgc_backends import sim
    files = sim.emit(program, "out/")  # out/<name>_sim.py, fgc_sim_constants.py, run-time
    result = sim.run(program, problem_data(graph, program), precision="float32")
    result.values["x3"], result.final_error, result.status

The emitted program runs on its own: ``python out/<name>_sim.py data.txt result.json``; its
result names each value by the variable's key (``"values": {"x3": {"key": "x3", "type": "Pose2",
"value": [...]}}``, an int key written as a JSON number), and ``sim.read_result(program,
"result.json")`` reads it back as the SimResult ``run`` returns.
"""

from .config import SimConfig
from .emitter import EmitError, emit
from .printer import SimPrinter
from .runner import SimResult, costs, linearize, read_result, remaining_step, run
from .streaming import stream

Config = SimConfig  # the backend contract's name (fgc_backends.CONTRACT)

__all__ = ["Config", "EmitError", "SimConfig", "SimPrinter", "SimResult", "costs", "emit",
           "linearize", "read_result", "remaining_step", "run", "stream"]
