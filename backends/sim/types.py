"""Each variable type's retraction x ∘ Exp(δ) and local coordinates Log(a⁻¹ b), as kernels.

The simulator updates the state with the retraction and, keyframe by keyframe, keeps the prior
on a marginalised window in local coordinates. Neither is written per type: both are derived
symbolically from the :mod:`fgc.frontend.geometry` class of the variable (the one its factors
use, so GTSAM's conventions hold by construction) and printed into the problem module like a
block kernel, by the same derivation the C-family backends print their retraction from
(:mod:`fgc_backends.cfamily.retract`).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

from fgc.compiler.kernel import Kernel
from fgc.frontend.geometry import LieGroup
from fgc.ir.program import Program
from fgc_backends.cfamily import retract
from fgc_backends.cfamily.errors import CodegenError
from fgc_backends.cfamily.retract import retract_kernel, variable_class

from .config import comment


@dataclass(frozen=True)
class VariableType:
    """One variable type of a Program: its index (``kind``), sizes, variables and kernels."""

    kind: int
    type_name: str
    storage_dim: int
    dim: int
    variables: tuple[int, ...]
    retract: Kernel  # inputs (storage x, tangent δ) → storage of x ∘ Exp(δ)
    local: Kernel  # inputs (storage a, storage b) → tangent Log(a⁻¹ b)


@functools.cache
def _retract(cls: type[LieGroup]) -> Kernel:
    return retract_kernel(cls)


# Log(a⁻¹ b) (a.local(b)), derived once per type: the C-family backends print the same kernel
local_kernel = functools.cache(retract.local_kernel)


def variable_types(program: Program, error: type[Exception]) -> tuple[VariableType, ...]:
    """One :class:`VariableType` per variable type of ``program``, in first-appearance order;
    raises ``error`` for a type :mod:`fgc.frontend.geometry` does not know or whose sizes
    disagree with the Program's."""
    order: dict[str, list[int]] = {}
    for v, spec in enumerate(program.variables):
        order.setdefault(spec.type_name, []).append(v)
    out = []
    for kind, (name, variables) in enumerate(order.items()):
        spec = program.variables[variables[0]]
        try:
            cls = variable_class(name)
        except CodegenError:
            cls = None
        if cls is None or (cls.storage_dim, cls.dim) != (spec.storage_dim, spec.dim):
            raise error(f"the simulator has no retraction for variable type "
                        f"'{comment(name)}' (dim {spec.dim}, storage {spec.storage_dim})")
        out.append(VariableType(kind, name, cls.storage_dim, cls.dim, tuple(variables),
                                _retract(cls), local_kernel(cls)))
    return tuple(out)
