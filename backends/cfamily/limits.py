"""What a C++ backend (hls, native) can build, checked before anything is emitted, and the
linear solver's scalar a Program asks for. One copy for both backends; each raises its own
error class and names its own config in the message."""

from __future__ import annotations

import dataclasses

from fgc.ir.program import Program
from fgc_backends.cfamily.scalars import ap_types_include


def for_program(program: Program, config):
    """``config`` with a ``double`` linear solver for a Program compiled with
    ``linear_precision="float64"`` (the mixed design), unless ``config.linear_scalar`` says
    otherwise."""
    if config.linear_scalar is None and program.solver.mixed:
        return dataclasses.replace(config, linear_scalar="double")
    return config


def check_limits(program: Program, config, error: type[Exception], backend: str,
                 config_name: str) -> None:
    """Raise ``error`` if ``program`` exceeds what ``config`` can build: its window, its widest
    elimination step, an incremental plan (both C++ backends run batch solves), a fixed-point
    scalar without the ap_types headers. A bound of ``None`` (the native backend's default) is
    no bound."""
    if config.max_variables is not None and program.max_variables > config.max_variables:
        raise error(f"the Program's window of {program.max_variables} variables exceeds "
                    f"{backend}'s maximum of {config.max_variables} "
                    f"({config_name}.max_variables)")
    if len(program.variables) > program.max_variables:
        raise error(f"{len(program.variables)} variables exceed the compiled maximum "
                    f"{program.max_variables}")
    widest = max(s.frontal_dim + s.separator_dim for s in program.schedule.steps)
    if config.max_step_columns is not None and widest > config.max_step_columns:
        raise error(f"an elimination step has {widest} columns, more than {backend}'s "
                    f"{config.max_step_columns} ({config_name}.max_step_columns)")
    if program.schedule.incremental is not None:
        raise error(f"{backend} runs batch solves only; compile without incremental_k")
    if config.is_fixed_point:
        ap_types_include(error)  # a clear error now, not a missing header in g++
