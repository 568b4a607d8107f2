"""The HLS C++ backend: a Program → a Vitis HLS project.

    from fgc_backends import hls
    project = hls.emit(program, "out/", hls.HlsConfig(scalar="double"))
    result = hls.run_csim(project, program, problem_data(graph, program))   # make csim

Emitted files (the dataflow accelerator, docs/hls.md): ``<name>.h``/``<name>.cpp`` (the
synthesisable kernel ``<name>_top``), ``tb_<name>.cpp`` (testbench), ``run_hls.tcl``, a
``Makefile`` (``make csim``), the unit headers in ``include/`` and the csim stand-in for
``hls_stream.h`` in ``csim_include/``. The fast CPU solver is its own backend,
:mod:`fgc_backends.native`.
"""

from fgc.ir.stream import StreamProgram
from fgc_backends.cfamily.printer import HlsCodePrinter, UnsupportedExpressionError
from fgc_backends.cfamily.results import HlsResult
from fgc_backends.hls import emitter
from fgc_backends.hls.build import HlsBuildError, HlsMismatchError, make, run, run_csim
from fgc_backends.hls.config import DesignOptions, HlsConfig, HlsConfigError
from fgc_backends.hls.emitter import HlsProject
from fgc_backends.hls.lint import HlsLintError, LintIssue, lint_source
from fgc_backends.hls.plan.update import NOT_EMITTED
from fgc_backends.hls.streaming import emit_window, on_chip, stream, update_model, window_model

Config = HlsConfig  # the backend contract's name (fgc_backends.CONTRACT)


def emit(program, out_dir, config=None, **options) -> HlsProject:
    """The contract's ``emit``: a Program's batch design (:func:`fgc_backends.hls.emitter.emit`,
    ``options`` passed on), or a :class:`~fgc.ir.stream.StreamProgram`'s on-chip streaming
    design with its testbench's stream inputs (:func:`fgc_backends.hls.streaming.emit_window`:
    the policy read from the StreamProgram)."""
    if isinstance(program, StreamProgram):
        return emit_window(program, out_dir, config)
    return emitter.emit(program, out_dir, config, **options)

__all__ = ["DesignOptions", "HlsBuildError", "HlsMismatchError", "HlsCodePrinter", "HlsConfig",
           "HlsConfigError", "HlsLintError", "HlsProject", "HlsResult", "LintIssue",
           "UnsupportedExpressionError", "NOT_EMITTED", "emit", "lint_source", "make", "on_chip",
           "run", "run_csim", "stream", "update_model", "window_model", "Config"]
