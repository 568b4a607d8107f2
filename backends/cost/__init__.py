"""The accelerator cost model: cycles, latency, resources, power, energy and memory of a Program.

    report = estimate(program, iterations=8)           # CostParams() defaults: xc7z045, 143 MHz
    report.latency_ms, report.solve, report.resources, report.power_w, report.to_dict()

The model follows the two papers' units (docs/design.md): a pipelined factor block with two modes,
partial-QR blocks with one Evaluate and n_u Update units (paper A) or an HGC unit and a cascade of
#CPE Cholesky process elements (paper B), back-substitution, state update and control. Every
latency, unit size and resource or power coefficient is a documented field of
:class:`CostParams` (``describe()`` prints the table). The numerics never depend on this package.

Modules: ``params`` (all numbers), ``kernels`` (factor block: critical path, initiation
interval), ``structure`` (structural non-zeros), ``qr`` and ``cholesky`` (linear solvers),
``resources`` (resources, memory, power), ``report`` (output), ``estimate`` (the pipeline).
"""

from .estimate import estimate
from .params import (
    FLOAT32,
    FLOAT64,
    CostParams,
    Device,
    OperatorCost,
    OperatorCounts,
    OperatorTable,
    describe,
)
from .report import CostReport, MemoryWords, Resources, UnitCycles, UnitResources, Utilization

__all__ = [
    "FLOAT32",
    "FLOAT64",
    "CostParams",
    "CostReport",
    "Device",
    "MemoryWords",
    "OperatorCost",
    "OperatorCounts",
    "OperatorTable",
    "Resources",
    "UnitCycles",
    "UnitResources",
    "Utilization",
    "describe",
    "estimate",
]
