"""The latency floor of one GN/LM iteration: the longest chain of dependent operators.

However many operators a design has, one iteration cannot end before its longest chain of
operations that each need the previous one's result, every operation taking its latency in the
design's operator table (``backends/cost/operators.py`` through the design's ``Target``: part,
clock, precision). :func:`latency_floor` computes that chain from the Program alone, part by
part, and says exactly what it counts:

- **linearise**: the deepest factor kernel (residual + whitened Jacobian), its critical path
  through the kernel's expression DAG (``cost.kernels.critical_path``, balanced sums). Every
  factor is independent, so one kernel's depth is on the chain.
- **eliminate**: the elimination tree's heaviest leaf-to-root path. A step's pivots depend on
  one another (pivot j + 1's column is the one pivot j updated), and a parent's first pivot
  column holds the rows its children pass up, which their last pivot updated, so the path's
  pivots form one chain. Per pivot:

  - QR (Householder, exact): the column's squared norm over its ``m`` remaining rows (multiply,
    ⌈log₂ m⌉ adds in a tree) → √ (sqrt) → v's first entry against the next column
    (α·y₀: multiply, add; ``xᵀy`` runs beside the norm) → β = vᵀy / vᵀv (divide) → the next
    column's update y − β·v (multiply, add). ``m`` is the step's stacked rows less the pivots
    before it.
  - Cholesky (multifrontal): √ of the pivot (sqrt) → the column scaled by it (divide) → the next
    pivot's Schur update a − l² (multiply, add); a step with children first adds their updates
    (one add: the extend-add), and the path's leaf first forms its H entries (multiply,
    ⌈log₂ m⌉ adds over its ``m`` rows).
- **back-substitute**: the same path root to leaf, one unknown after another: an unknown
  waits for the previous one's product and the subtraction (multiply, add; the diagonal's
  reciprocals are formed off the chain).
- **update**: the deepest retraction x ⊕ δ over the variable types (its kernel's critical path).
- **cost + decision** (LM only: its accept/reject gates the next linearisation point): the
  deepest cost kernel, the sum over the factors (⌈log₂ #factors⌉ adds), the gain-ratio
  decision (divide, two multiplies, two adds, a compare). GN takes every step, so its cost
  pass overlaps the next linearisation and is not on the chain.

Not counted (so the floor stays a floor): memory and stream latencies, handshakes, control,
the gradient Aᵀb (beside the elimination), and anything a design may overlap.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from fgc.errors import FgcError
from fgc.ir.program import Program

PARTS = ("linearise", "eliminate", "back-substitute", "update", "cost + decision")

# the plan's phase groups (fgc_backends.hls.plan.phase_group) -> the floor part they do
PHASE_PART = {"factor_jacobian": "linearise", "gradient": "linearise", "whiten_stack": "eliminate",
              "hgc": "eliminate", "qr_stack": "eliminate", "qr": "eliminate",
              "qr_commit": "eliminate", "assemble": "eliminate", "cholesky": "eliminate",
              "store": "eliminate", "hgc_beside": "eliminate", "hgc_producer": "eliminate",
              "reassemble": "eliminate", "recholesky": "eliminate",
              "backsub": "back-substitute", "state_update": "update",
              "factor_cost": "cost + decision", "lm_iteration": "cost + decision",
              "lm_control": "cost + decision", "lm_accept": "cost + decision",
              "lm_restore": "cost + decision"}


@dataclass(frozen=True)
class Floor:
    """One iteration's floor, cycles per part (:data:`PARTS`), and what the chain holds."""

    parts: tuple[tuple[str, int], ...]
    pivots: int  # pivots on the elimination tree's heaviest path
    steps: int  # elimination steps on it
    unknowns: int  # unknowns back-substituted one after another
    per_pivot: str  # the operator chain of one pivot, as text
    clock_mhz: float
    linear: str

    @property
    def cycles(self) -> int:
        return sum(c for _, c in self.parts)

    @property
    def latency_ms(self) -> float:
        return self.cycles / (self.clock_mhz * 1e3)

    def part(self, name: str) -> int:
        return dict(self.parts)[name]

    def describe(self) -> str:
        """One line: the total and its parts."""
        parts = ", ".join(f"{name} {c:,}" for name, c in self.parts if c)
        return (f"latency floor {self.cycles:,} cycles = {self.latency_ms:.4f} ms ({parts}; "
                f"{self.pivots} {self.linear} pivots in {self.steps} steps on the elimination "
                f"tree's heaviest path, each {self.per_pivot}; {self.unknowns} unknowns "
                "back-substituted in turn)")


def _ceil_log2(n: int) -> int:
    return math.ceil(math.log2(n)) if n > 1 else 0


def latency_floor(program: Program, ops=None) -> Floor:
    """The floor of one iteration of ``program`` at the operator table ``ops`` (default: the
    Program's precision on the default part at its clock)."""
    from fgc_backends.cfamily.retract import retract_kernel, variable_class
    from fgc_backends.cost.kernels import critical_path
    from fgc_backends.cost.params import view
    from fgc_backends.hls.target import Target

    if ops is None:
        ops = Target(clock_mhz=program.solver.clock_mhz).ops(program.solver.precision)
    steps = program.schedule.steps
    if not steps:
        raise FgcError(f"program {program.name!r}: no elimination steps, no iteration to floor")
    la, lm, ld, ls = ops.add.latency, ops.mul.latency, ops.div.latency, ops.sqrt.latency
    linear = program.solver.linear
    kernel_ops = view(ops)

    def step_chain(step) -> int:
        if linear == "qr":
            return sum(lm + _ceil_log2(max(step.rows - j, 1)) * la + ls + lm + la + ld + lm + la
                       for j in range(step.frontal_dim))
        return (la if step.children else 0) + step.frontal_dim * (ls + ld + lm + la)

    # the heaviest leaf-to-root path (children before parents: steps are in elimination order)
    best: dict[int, tuple[int, int, int, int]] = {}  # step -> (cycles, pivots, steps, leaf)
    for step in steps:
        below = max((best[c] for c in step.children), default=(0, 0, 0, step.index))
        own = step_chain(step)
        best[step.index] = (below[0] + own, below[1] + step.frontal_dim, below[2] + 1, below[3])
    cycles, pivots, depth, leaf = max(best[r] for r in program.schedule.roots)
    if linear != "qr":  # the leaf's H entries before its first pivot
        cycles += lm + _ceil_log2({s.index: s for s in steps}[leaf].rows) * la
    per_pivot = (f"mul + ⌈log₂ m⌉ add + sqrt + mul + add + div + mul + add = {lm} + "
                 f"⌈log₂ m⌉·{la} + {ls} + {lm} + {la} + {ld} + {lm} + {la} cycles"
                 if linear == "qr" else
                 f"sqrt + div + mul + add = {ls + ld + lm + la} cycles")
    linearise = max(critical_path(b.kernel, kernel_ops) for b in program.blocks)
    update = max(critical_path(_kernel_text(retract_kernel(variable_class(t))), kernel_ops)
                 for t in sorted({v.type_name for v in program.variables}))
    decision = 0
    if program.solver.method == "lm":
        decision = (max(critical_path(b.cost_kernel, kernel_ops) for b in program.blocks)
                    + _ceil_log2(len(program.factors)) * la
                    + ld + 2 * lm + 2 * la + ops.compare.latency)
    unknowns = _backsub_unknowns(program)
    parts = (("linearise", linearise), ("eliminate", cycles),
             ("back-substitute", unknowns * (lm + la)), ("update", update),
             ("cost + decision", decision))
    return Floor(parts, pivots, depth, unknowns, per_pivot, program.solver.clock_mhz, linear)


def _kernel_text(kernel):
    from fgc.ir.program import KernelText

    return KernelText.of(kernel)


def _backsub_unknowns(program: Program) -> int:
    """Unknowns on the longest root-to-leaf path of the elimination tree."""
    total: dict[int, int] = {}
    for step in reversed(program.schedule.steps):  # parents before children
        above = total[step.parent] if step.parent is not None else 0
        total[step.index] = above + step.frontal_dim
    return max(total.values())


def phase_excess(floor: Floor, phase_cycles) -> list[tuple[str, int, int]]:
    """(floor part, the design's cycles on it, the floor's cycles), largest design share first:
    ``phase_cycles`` is a plan Cost's ``phase_cycles`` (phase name, cycles); phases the floor
    does not know go under "other" (floor 0)."""
    from fgc_backends.hls.plan import phase_group

    design: dict[str, int] = {}
    for name, c in phase_cycles:
        part = PHASE_PART.get(phase_group(name), "other")
        design[part] = design.get(part, 0) + c
    floors = dict(floor.parts)
    return sorted(((part, c, floors.get(part, 0)) for part, c in design.items()),
                  key=lambda t: -t[1])


def limits_line(floor: Floor, cost) -> str:
    """What limits a design (a plan Cost) against the floor: the part with the most cycles, its
    cycles against its floor, and the whole iteration's ratio to the floor."""
    rows = phase_excess(floor, cost.phase_cycles)
    part, c, f = rows[0]
    others = "; ".join(f"{p} {d:,} (floor {g:,})" for p, d, g in rows[1:])
    return (f"{cost.cycles / floor.cycles:.1f}× the floor; limited by {part}: {c:,} cycles "
            f"({c / cost.cycles:.0%} of the iteration; its floor {f:,}); {others}")
