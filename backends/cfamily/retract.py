"""Retraction x ⊕ δ = x ∘ Exp(δ) of each variable type, as printed C++ kernels.

The state update is the one piece of the solver that depends on a variable's type, not on its
factors. Rather than hand-writing C++ per group, the retraction is derived symbolically from the
same :mod:`fgc.frontend.geometry` classes the factors use (so it has GTSAM's conventions by
construction)
and printed like a block kernel: ``retract_<kind>(x, d, out)`` reads the storage ``x`` and the
tangent step ``d`` and writes the new storage.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

import fgc.frontend.geometry as geometry
from fgc.compiler.kernel import Kernel
from fgc.frontend.geometry import LieGroup
from fgc.ir.program import Program
from fgc_backends.cfamily.errors import CodegenError
from fgc_backends.cfamily.printer import PrintedKernel, print_kernel


@dataclass(frozen=True)
class RetractKind:
    """One variable type: its index (``kind``), sizes, variables and printed retraction."""

    kind: int
    type_name: str
    storage_dim: int
    dim: int
    variables: tuple[int, ...]
    printed: PrintedKernel


def variable_class(type_name: str) -> type[LieGroup]:
    """The :mod:`fgc.frontend.geometry` class called ``type_name`` (``VectorN`` for any N)."""
    try:
        return geometry.type_named(type_name)
    except geometry.UnknownTypeError as exc:
        raise CodegenError(f"no C++ retraction for variable type {type_name!r}: {exc}") from exc


def retract_kernel(cls: type[LieGroup]) -> Kernel:
    """Kernel with inputs (storage, δ) and outputs the storage of ``x ∘ Exp(δ)``."""
    x = [sp.Symbol(f"x{i}", real=True) for i in range(cls.storage_dim)]
    d = [sp.Symbol(f"d{i}", real=True) for i in range(cls.dim)]
    value = cls.from_storage(list(x)).retract(sp.Matrix(d))
    outputs = [sp.sympify(v) for v in value.to_storage()]
    reps, reduced = sp.cse(outputs, symbols=sp.numbered_symbols("_r", real=True), order="none")
    return Kernel(tuple(x + d), tuple(reps), tuple(reduced))


def local_kernel(cls: type[LieGroup]) -> Kernel:
    """Kernel with inputs (storage of a, storage of b) and outputs Log(a⁻¹ b) (``a.local(b)``)."""
    a = [sp.Symbol(f"a{i}", real=True) for i in range(cls.storage_dim)]
    b = [sp.Symbol(f"b{i}", real=True) for i in range(cls.storage_dim)]
    tangent = cls.from_storage(list(a)).local(cls.from_storage(list(b)))
    outputs = [sp.sympify(tangent[i]) for i in range(cls.dim)]
    reps, reduced = sp.cse(outputs, symbols=sp.numbered_symbols("_l", real=True), order="none")
    return Kernel(tuple(a + b), tuple(reps), tuple(reduced))


@dataclass(frozen=True)
class LocalKind:
    """The local coordinates Log(a⁻¹b) of one variable type (a :class:`RetractKind`'s ``kind``)
    as a printed kernel ``local_<kind>(a, b, out)``; ``flat``: a vector space stored as its
    tangent, whose Log is b − a (the host stream takes it as that, and its derivative as I)."""

    kind: int
    type_name: str
    storage_dim: int
    dim: int
    flat: bool
    printed: PrintedKernel


def local_kinds(program: Program) -> tuple[LocalKind, ...]:
    """One :class:`LocalKind` per variable type of ``program``, in the order (and with the
    indices) of :func:`retract_kinds`."""
    kinds, seen = [], {}
    for spec in program.variables:
        seen.setdefault(spec.type_name, spec)
    for kind, name in enumerate(seen):
        cls = variable_class(name)
        names = [f"a[{i}]" for i in range(cls.storage_dim)] + [
            f"b[{i}]" for i in range(cls.storage_dim)]
        printed = print_kernel(local_kernel(cls), names, f"local coordinates of kind {kind}",
                               prefix="l")
        flat = issubclass(cls, geometry.VectorSpace) and cls.storage_dim == cls.dim
        kinds.append(LocalKind(kind, name, cls.storage_dim, cls.dim, flat, printed))
    return tuple(kinds)


def retract_kinds(program: Program, latencies=None) -> tuple[RetractKind, ...]:
    """One :class:`RetractKind` per variable type of ``program``, in first-appearance order;
    ``latencies``: its sums and products printed as that table's reduction trees
    (``print_kernel``)."""
    order: dict[str, list[int]] = {}
    for v, spec in enumerate(program.variables):
        order.setdefault(spec.type_name, []).append(v)
    kinds = []
    for kind, (name, variables) in enumerate(order.items()):
        cls = variable_class(name)
        spec = program.variables[variables[0]]
        if (cls.storage_dim, cls.dim) != (spec.storage_dim, spec.dim):
            raise CodegenError(f"variable type {name!r}: the Program's sizes do not match "
                                 "fgc.frontend.geometry's")
        kernel = retract_kernel(cls)
        names = [f"x[{i}]" for i in range(cls.storage_dim)] + [f"d[{i}]" for i in range(cls.dim)]
        printed = print_kernel(kernel, names, f"retraction of kind {kind}", prefix="r",
                               latencies=latencies)
        kinds.append(RetractKind(kind, name, cls.storage_dim, cls.dim, tuple(variables),
                                 printed))
    return tuple(kinds)
