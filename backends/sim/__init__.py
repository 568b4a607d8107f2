"""The simulator backend: a Program → a standalone NumPy program that runs the accelerator's
algorithm (GN/LM, partial-QR or Cholesky elimination along the schedule) on a data file.

    from fgc_backends import sim
    files = sim.emit(program, "out/")                  # out/<name>_sim.py + run-time modules
    result = sim.run(program, problem_data(graph, program), precision="float32")
    result.values["x3"], result.final_error, result.status

The emitted program runs on its own: ``python out/<name>_sim.py data.txt result.json``.
"""

from .config import SimConfig
from .emitter import EmitError, emit
from .printer import SimPrinter
from .runner import SimResult, linearize, run

__all__ = ["EmitError", "SimConfig", "SimPrinter", "SimResult", "emit", "linearize", "run"]
