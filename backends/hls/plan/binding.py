"""Operator instances as Vitis HLS binds them (issue 32 part 2): the one rule every unit prices
its operators by.

Vitis turns every pipelined loop into its own module with its own operators (UG1399,
pipelining): a loop whose one iteration issues ``n`` operations of a kind at initiation
interval ``II`` needs ``ceil(n × op II / II)`` instances of that kind (``op II``: the
operator's own initiation interval, 1 for the pipelined floating-point cores), whatever other
loops of the same function hold. A function-level ``ALLOCATION`` caps the instances of the
loops and code inside that function (the emitted ``ALLOCATION`` only: a limit that is not
printed caps nothing). Every call site of a function, every copy of an unrolled call and every
instantiation of a template is its own RTL instance, so its operators count once per copy.
Sequential (not pipelined) code needs at least one instance of each kind it uses.

Use:

- :func:`loop_operators`: one pipelined loop's instances by kind (``ops``: its operations per
  iteration, ``ii``, the emitted ``allocation`` limits, ``copies``);
- :class:`BoundLoop` and :func:`bound_unit`: a unit made of several pipelined loops (and
  sequential code): its operators are the sum over its loops (no sharing between loops), what
  :func:`fgc_backends.hls.plan.cost.plan_cost` prices (DSP/LUT/FF = Σ instances × the operator
  table's figures, plus memories);
- :func:`loop_ii`: the smallest II a loop's memory accesses allow (accesses per iteration to one
  array over ``PORTS`` × its banks where the loop touches it), the plan's II must be at least
  this (the second reader, ``backends/hls/reader/``, holds the emitted text to the same rule).

The second reader re-derives these figures from the emitted text; ``check_dsp`` fails when the
plan's sum is below the text's.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.plan.model import PORTS, Unit


def loop_operators(ops: Mapping[str, int], ii: int, allocation: Mapping[str, int] | None = None,
                   copies: int = 1, table: OperatorTable | None = None) -> dict[str, int]:
    """Operator instances by kind of one pipelined loop (or sequential code when ``ii`` is 0):
    ``ceil(n × op II / ii)`` per kind (``table`` gives each kind's own II; 1 without it),
    capped by ``allocation`` (the emitted function-level limits), times ``copies`` (call sites,
    unrolled copies, template instantiations). ``ii == 0``: sequential code, one instance of
    each kind used (or its cap)."""
    if ii < 0 or copies < 0:
        raise ValueError(f"loop_operators: ii {ii} and copies {copies} must be >= 0")
    cap = dict(allocation or {})
    out: dict[str, int] = {}
    for kind, n in ops.items():
        if n <= 0:
            continue
        op_ii = table.op(kind).ii if table is not None else 1
        need = 1 if ii == 0 else math.ceil(n * op_ii / ii)
        if kind in cap:
            need = min(need, cap[kind])
        out[kind] = out.get(kind, 0) + need * copies
    return out


def loop_ii(accesses: Iterable[tuple[int, int]]) -> int:
    """The smallest II that ``accesses`` allow: ``(accesses per iteration, banks)`` per array
    the loop touches; each bank gives :data:`PORTS` accesses a cycle."""
    return max([1] + [math.ceil(n / (PORTS * max(1, banks))) for n, banks in accesses])


@dataclass(frozen=True)
class BoundLoop:
    """One pipelined loop (``ii >= 1``) or one piece of sequential code (``ii == 0``) of a unit
    as the emitted text holds it: its operations of one iteration by kind, the II it is
    emitted at, the ``ALLOCATION`` limits of the function holding it and how many RTL copies
    of it exist (call sites × unrolled copies)."""
    name: str
    ops: tuple[tuple[str, int], ...]
    ii: int
    allocation: tuple[tuple[str, int], ...] = ()
    copies: int = 1

    def instances(self, table: OperatorTable | None = None) -> dict[str, int]:
        return loop_operators(dict(self.ops), self.ii, dict(self.allocation), self.copies,
                              table)


def sum_operators(loops: Iterable[BoundLoop], table: OperatorTable | None = None
                  ) -> tuple[tuple[str, int], ...]:
    """Instances by kind over ``loops`` (no sharing between loops), sorted by kind."""
    total: dict[str, int] = {}
    for lp in loops:
        for kind, n in lp.instances(table).items():
            total[kind] = total.get(kind, 0) + n
    return tuple(sorted((k, n) for k, n in total.items() if n))


def bound_unit(name: str, role: str, loops: Iterable[BoundLoop], instances: int = 1,
               table: OperatorTable | None = None, extra_dsp: int = 0) -> Unit:
    """The plan's :class:`Unit` of ``loops``: its operators are the sum of the loops' instances
    (:func:`sum_operators`), ``instances`` copies of the whole unit (unit sets, call sites)."""
    return Unit(name, role, instances, sum_operators(loops, table), extra_dsp)
