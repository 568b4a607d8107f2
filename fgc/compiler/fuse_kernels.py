"""How one block type's kernels are built (the "fuse + CSE" arithmetic behind
:mod:`fgc.compiler.fuse`).

Members' residuals are renamed onto the block's variable symbols and stacked; one
:func:`fgc.compiler.kernel.jacobian_kernel` over the stack gives the residual + Jacobian kernel
(fixed 0/±1
entries from the members' derivations made exact), and its residual program plus each member's
½‖W r‖² gives the cost-mode kernel — the same circuits in both modes, as in the papers. Op counts
before sharing are the members' separately derived kernels, summed.
"""

from __future__ import annotations

from dataclasses import astuple, dataclass, replace

import numpy as np
import sympy as sp

from fgc.compiler.derive import KernelInput, SymbolicFactor, tangent_seeds, whitening_matrix
from fgc.compiler.kernel import Kernel, drop_dead, jacobian_kernel, tidy
from fgc.frontend.dsl import FactorType


@dataclass(frozen=True)
class OpCounts:
    """Operations of a kernel by kind (see :meth:`fgc.compiler.kernel.Kernel.op_counts`)."""

    add: int = 0
    mul: int = 0
    div: int = 0
    sqrt: int = 0
    trig: int = 0
    special: int = 0

    @classmethod
    def of(cls, kernel: Kernel) -> OpCounts:
        return cls(**kernel.op_counts())

    def __add__(self, other: OpCounts) -> OpCounts:
        return OpCounts(*(a + b for a, b in zip(astuple(self), astuple(other), strict=True)))

    @property
    def total(self) -> int:
        return sum(astuple(self))


@dataclass(frozen=True)
class BlockOps:
    """Op counts before sharing (members' separately derived kernels, summed) and after (the
    fused kernel), for mode "jacobian" (residual + Jacobians) and mode "cost" (residual + cost).
    Cost mode before sharing includes the n − 1 additions that sum the members' costs."""

    jacobian_before: OpCounts
    jacobian_after: OpCounts
    cost_before: OpCounts
    cost_after: OpCounts

    def saving(self, mode: str = "jacobian") -> float:
        """Fraction of all operations removed by sharing, 1 − after/before."""
        before, after = ((self.jacobian_before, self.jacobian_after) if mode == "jacobian"
                         else (self.cost_before, self.cost_after))
        return 1.0 - after.total / before.total if before.total else 0.0


@dataclass(frozen=True)
class Member:
    """One factor type inside a block type."""

    name: str  # factor type name
    fingerprint: str  # its derivation's fingerprint
    positions: tuple[int, ...]  # block-variable index of each of its variables
    rows: tuple[int, int]  # [start, stop) in the stacked residual
    noise_kind: str
    prefix: str  # prefix of its measurement and whitening symbols ("m1_")
    measurement_names: tuple[str, ...]  # its measurement arguments, in kernel input order
    noise_symbols: tuple[sp.Symbol, ...]  # whitening symbols, NoiseModel.params() order


def prefixed(sym: sp.Symbol, prefix: str) -> sp.Symbol:
    """A member's measurement symbol made distinct within its block (``m1_measured__R00``)."""
    return sp.Symbol(prefix + sym.name, real=True)


def noise_symbols(kind: str, dim: int, prefix: str) -> tuple[sp.Symbol, ...]:
    """The whitening symbols of a member, in :meth:`fgc.frontend.noise.NoiseModel.params` order."""
    w = whitening_matrix(kind, dim, f"{prefix}noise")
    if kind == "isotropic":
        return (w[0, 0],)
    if kind == "diagonal":
        return tuple(w[i, i] for i in range(dim))
    return tuple(w[i, j] for i, j in zip(*np.triu_indices(dim), strict=True))


def _renaming(sf: SymbolicFactor, member: Member, variables: tuple[KernelInput, ...]) -> dict:
    """Member symbols → block symbols: variables onto the block's, measurements prefixed."""
    out = {}
    for p, b in zip(member.positions, sf.variables, strict=True):
        out.update(zip(b.symbols, variables[p].symbols, strict=True))
    for b in sf.measurements:
        out.update({s: prefixed(s, member.prefix) for s in b.symbols})
    return out


def build_kernels(lead: FactorType, derived: list[SymbolicFactor], members: list[Member],
                  variables: tuple[KernelInput, ...],
                  meas_blocks: tuple[KernelInput, ...]) -> tuple:
    """(kernel, cost kernel, structure, ops) of a block type; ``members`` lead first."""
    renames = [_renaming(sf, m, variables) for sf, m in zip(derived, members, strict=True)]
    structure = _structure(derived, members, variables)
    if len(members) == 1:  # nothing to share: the derivation's kernel, renamed
        kernel = _renamed(derived[0].kernel, renames[0])
    else:
        residual = sp.Matrix.vstack(*[_rename(sf.expression, r)
                                      for sf, r in zip(derived, renames, strict=True)])
        seeds = tangent_seeds(lead, variables, meas_blocks)
        kernel, _ = jacobian_kernel(residual, seeds, sum(b.dim for b in variables))
        kernel = _fix_structure(_by_variable(kernel, len(structure[0]), variables), structure)
    noise = tuple(s for m in members for s in m.noise_symbols)
    cost = _cost_kernel(kernel, noise, members)
    cost_before = OpCounts(add=len(members) - 1)  # summing the separately computed costs
    jac_before = OpCounts()
    for sf, m in zip(derived, members, strict=True):
        own = replace(m, rows=(0, sf.residual_dim))
        cost_before += OpCounts.of(_cost_kernel(sf.kernel, m.noise_symbols, [own]))
        jac_before += OpCounts.of(sf.kernel)
    ops = BlockOps(jac_before, OpCounts.of(kernel), cost_before, OpCounts.of(cost))
    return kernel, cost, structure, ops


def _rename(matrix: sp.Matrix, renaming: dict) -> sp.Matrix:
    """``matrix.xreplace(renaming)`` for symbols, visiting each shared subtree once (a traced
    residual is a DAG whose tree form has millions of nodes)."""
    memo: dict[int, sp.Expr] = {}

    def visit(e: sp.Basic) -> sp.Basic:
        out = memo.get(id(e))
        if out is None:
            if e.is_Symbol or not e.args:
                out = renaming.get(e, e)
            else:
                args = tuple(visit(a) for a in e.args)
                changed = any(a is not b for a, b in zip(args, e.args, strict=True))
                out = e.func(*args) if changed else e
            memo[id(e)] = out
        return out

    return matrix.applyfunc(visit)


def _renamed(kernel: Kernel, renaming: dict) -> Kernel:
    return Kernel(tuple(renaming.get(s, s) for s in kernel.inputs),
                  tuple((x, e.xreplace(renaming)) for x, e in kernel.assignments),
                  tuple(sp.sympify(e).xreplace(renaming) for e in kernel.outputs))


def _by_variable(kernel: Kernel, m: int, variables: tuple[KernelInput, ...]) -> Kernel:
    """Outputs [r; J (m × n) row-major] → [r; J_1 row-major; J_2 row-major; …]."""
    n = sum(b.dim for b in variables)
    jac, outs, start = kernel.outputs[m:], list(kernel.outputs[:m]), 0
    for b in variables:
        outs += [jac[i * n + start + j] for i in range(m) for j in range(b.dim)]
        start += b.dim
    return Kernel(kernel.inputs, kernel.assignments, tuple(outs))


def _structure(derived: list[SymbolicFactor], members: list[Member],
               variables: tuple[KernelInput, ...]) -> tuple:
    """Each member's derived structure in its rows; "0" where it does not touch a variable."""
    out = []
    for k, vb in enumerate(variables):
        rows: list[tuple[str, ...]] = []
        for sf, m in zip(derived, members, strict=True):
            if k in m.positions:
                rows += sf.structure[m.positions.index(k)]
            else:
                rows += [("0",) * vb.dim] * sf.residual_dim
        out.append(tuple(rows))
    return tuple(out)


def _fix_structure(kernel: Kernel, structure: tuple) -> Kernel:
    """Make the fixed 0/±1 Jacobian entries exact constants and drop what they made dead."""
    outputs = list(kernel.outputs)
    pos = len(structure[0]) if structure else 0
    for codes in structure:
        for code in (c for row in codes for c in row):
            if code != "x":
                outputs[pos] = sp.Integer(int(code))
            pos += 1
    return Kernel(kernel.inputs, drop_dead(kernel.assignments, outputs), tuple(outputs))


def _cost_kernel(kernel: Kernel, noise: tuple, members: list[Member]) -> Kernel:
    """The cost mode of a residual + Jacobian ``kernel``: its residual program (shared circuits,
    as in the papers' two modes) with inputs + ``noise``; outputs the residual, each member's
    ½‖W r‖² and their sum."""
    r = sp.Matrix(kernel.outputs[: members[-1].rows[1]])
    costs = []
    for m in members:
        wr = whitening_matrix(m.noise_kind, m.rows[1] - m.rows[0], f"{m.prefix}noise") * \
            r[m.rows[0]:m.rows[1], :]
        costs.append(sp.Add(*[e**2 for e in wr]) / 2)
    outputs = (*r, *costs, sp.Add(*costs))
    return tidy(Kernel(kernel.inputs + noise, drop_dead(kernel.assignments, outputs), outputs))
