"""The second reader: what Vitis HLS would build from the emitted C++ text alone.

The accelerator plan says what each loop costs and the emitter prints the plan; this module
reads the printed text back without the plan and derives, per ``PIPELINE`` loop, what Vitis's
documented binding and scheduling rules (UG1399: pipelining, ``ALLOCATION``,
``ARRAY_PARTITION``, ``DEPENDENCE``) make of it:

- **operators**: the floating-point operations of one iteration, with constant-bound inner
  loops unrolled (as a pipelined loop's inner loops are) and the project functions it calls
  read in place (template arguments bound, so ``fold_partials<T, 11>`` counts its 10 adders).
  A pipelined loop is its own module: at II ``n`` it needs ``ceil(ops / n)`` instances of each
  operator kind, capped only by an ``ALLOCATION`` in the function that holds the loop or in
  the callee that holds the operations;
- **memories**: the accesses of one iteration to each array, against its ports: 2 a bank, and
  as many banks as the ``ARRAY_PARTITION`` where the array is declared (a parameter: the
  caller's array it is bound to) gives. ``ceil(accesses / (2 × banks))`` bounds the II;
- **recurrences**: an array element or scalar read and written by every iteration (a
  compound assignment whose index does not move with the pipelined loop's variable, or is
  data-dependent: read from another array) carries a dependence; without a ``DEPENDENCE ...
  inter false`` on it the II is at least the adder's latency;
- **ALLOCATION**: an iteration's operations of a kind go through the instances an
  ``ALLOCATION ... limit=k`` in scope allows within the II: ``ceil(ops / k)`` bounds it
  (exclusive branches share the instances: the largest counts);
- **DEPENDENCE claims**: ``inter false`` on an element read and written again P iterations
  later (an index modulo P) or every iteration (an index nothing moves) is refuted; on a
  data-dependent address it is unproven.

:func:`read_project` returns one :class:`LoopReading` per pipelined loop; :func:`check`
compares them with the II each loop's pragma declares (the plan's) and returns
:class:`fgc_backends.hls.lint.LintIssue` s (rules ``ii_ports``, ``ii_recurrence``,
``ii_allocation``, ``dependence_false``; with ``strict``, ``dependence_unproven``).
:func:`dsp_estimate` sums the operators over the module instances Vitis would make (every
call site its own instance, an unrolled call once per copy), each priced as ``run_hls.tcl``
binds it (:func:`emitted_ops`: its part, clock and ``config_op`` lines; a fabric adder has no
DSP). This reader knows nothing of the
plan; where it cannot resolve something (a bound it cannot evaluate, an array it cannot find)
it does not judge rather than guess.

Modules: ``text`` (text scanning), ``scope`` (declarations, constants, bindings, calls),
``count`` (operators, accesses, recurrences of a block), ``loops`` (pipelined loops: the
memory and II rules, :func:`check`), ``design`` (the instantiated design, :func:`check_dsp`).
"""

from fgc_backends.hls.reader.design import (
    DesignReading,
    check_dsp,
    dsp_table,
    emitted_files,
    emitted_ops,
    read_design,
    tcl_binding,
)
from fgc_backends.hls.reader.loops import LoopReading, check, read_project
from fgc_backends.hls.reader.text import FLOAT_TYPES, KINDS

__all__ = ["FLOAT_TYPES", "KINDS", "DesignReading", "LoopReading", "check", "check_dsp",
           "dsp_table", "emitted_files", "emitted_ops", "read_design", "read_project",
           "tcl_binding"]
