"""Small Programs for the unit tests: a Pose2 chain compiles in well under a second from a warm
cache."""

from __future__ import annotations

import fgc
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2
from fgc.ir.program import SolverConfig


def chain_graph(n: int = 5) -> fgc.Graph:
    """A Pose2 chain of ``n`` poses, a prior on the first."""
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"x{i}", Pose2(float(i), 0.1 * i, 0.0))
    g.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    for i in range(n - 1):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0),
                            fgc.noise.isotropic(3, 0.1)))
    return g


def chain(n: int = 5, **solver) -> fgc.ir.program.Program:
    """:func:`chain_graph` compiled in float32 (``solver``: the rest of its SolverConfig)."""
    return compile_graph(chain_graph(n), SolverConfig(precision="float32", **solver))
