"""The IR: what a backend may depend on. The :class:`~fgc.ir.program.Program` (structure, tables,
sizes, solver choices), the run-time data file, and the judgement of a result's trust
(``conditioning``: rank deficiency, float32 precision limits)."""
