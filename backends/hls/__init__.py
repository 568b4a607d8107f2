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

from fgc_backends.cfamily.printer import HlsCodePrinter, UnsupportedExpressionError
from fgc_backends.cfamily.results import HlsResult
from fgc_backends.hls.build import HlsBuildError, HlsMismatchError, make, run, run_csim
from fgc_backends.hls.config import HlsConfig, HlsConfigError
from fgc_backends.hls.emitter import HlsProject, emit
from fgc_backends.hls.lint import HlsLintError, LintIssue, lint_source

Config = HlsConfig  # the backend contract's name (fgc_backends.CONTRACT)

__all__ = ["HlsBuildError", "HlsMismatchError", "HlsCodePrinter", "HlsConfig", "HlsConfigError",
           "HlsLintError", "HlsProject", "HlsResult", "LintIssue", "UnsupportedExpressionError",
           "emit", "lint_source", "make", "run", "run_csim", "Config"]
