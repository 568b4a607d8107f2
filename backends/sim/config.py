"""Configuration of the simulator backend (one explicit, documented dataclass)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from .printer import SimPrinter
from .runtime import module_paths

# the generated files: the problem module and the constants module (templates/), rendered; the
# run-time modules (runtime/) are copied as they are
PROGRAM_TEMPLATE = "sim.py.jinja"
CONSTANTS_TEMPLATE = "fgc_sim_constants.py.jinja"


@dataclass(frozen=True)
class SimConfig:
    """How the simulator is emitted and run.

    LM's limits (``lambda_upper_bound``, ``absolute_error_tol``, ``mu_min``) are the Program's
    (:class:`fgc.ir.program.SolverConfig`), as for every backend.
    - ``name``: file-name stem of the problem module (``<name>_sim.py``); default: the Program's
      name, sanitised to an identifier.
    - ``pivot_tolerance_float64`` / ``pivot_tolerance_float32``: an elimination pivot at most
      this many times its column's norm is singular (status "failed", reason "singular" in
      Gauss-Newton; LM grows μ). An exactly dependent column keeps ~√rows·eps of its norm
      (1e-15 / 1e-6); the smallest pivot ratio of the shipped examples is ~1e-4.
    - ``diagnose``: after a batch solve, eliminate the undamped, row-equilibrated system at the
      solution once more in float64: names a variable the factors leave undetermined (also
      when LM's damping hid it) and estimates the condition number κ (see
      :mod:`fgc.ir.conditioning`), with ``condition_iterations`` power iterations per extreme
      singular value.
    - ``singular_lm_fails``: whether LM reports a rank-deficient solution (found by the
      diagnosis) as status "failed", reason "singular"; by default it keeps LM's status, names
      the variable in ``SimResult.singular_variable`` and warns (``RankDeficientWarning``).
    """

    name: str | None = None
    pivot_tolerance_float64: float = 1e-10
    pivot_tolerance_float32: float = 1e-5
    diagnose: bool = True
    condition_iterations: int = 12
    singular_lm_fails: bool = False

    @staticmethod
    def template_dir() -> Path:
        return Path(__file__).parent / "templates"

    @staticmethod
    def printer() -> SimPrinter:
        return SimPrinter()

    def stem(self, program_name: str) -> str:
        """The problem module's file-name stem: an identifier made of the given name."""
        return identifier(self.name or program_name)

    def files(self, program_name: str) -> tuple[tuple[str, str], ...]:
        """(template, emitted file name) of every generated file, problem module first."""
        return ((PROGRAM_TEMPLATE, f"{self.stem(program_name)}_sim.py"),
                (CONSTANTS_TEMPLATE, CONSTANTS_TEMPLATE.removesuffix(".jinja")))

    @staticmethod
    def runtime_files() -> tuple[Path, ...]:
        """The run-time modules every emitted simulator holds a byte-identical copy of."""
        return module_paths()


def identifier(text: str) -> str:
    """``text`` reduced to a safe Python identifier (letters, digits, underscores)."""
    out = re.sub(r"[^A-Za-z0-9_]", "_", text)[:60].strip("_") or "fgc_problem"
    return f"p_{out}" if out[0].isdigit() else out


def comment(text: str) -> str:
    """``text`` made safe to place in a comment or docstring of emitted code."""
    return re.sub(r"[^A-Za-z0-9_.+\-]", "_", text)[:60]
