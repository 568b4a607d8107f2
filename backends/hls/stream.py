"""Streaming on the HLS design's C simulation (issue 19): per keyframe, the emitted accelerator's
testbench solves the update's window; the host holds the kept Bayes net.

The windows are the native stream's (:mod:`fgc_backends.native.stream`): a *template* window
Program — the chain's first S keyframes with a ``MarginalPrior…`` factor on every keyframe — is
emitted once as an HLS project (:func:`fgc_backends.hls.emitter.emit`, ``double`` for agreement
with the simulator, ``float`` as the hardware), its C simulation built on the first update and
re-run on every later update's numbers (:func:`fgc_backends.hls.build.run_csim` with
``reference=False``: the testbench reads the new ``data.txt``, nothing is rebuilt).

What runs where. The C simulation runs each window's LM solve. Everything between updates runs
on the host in Python, as for the native stream: the kept conditionals, the marginal prior τ a
window's oldest keyframe carries, the undamped store elimination at the window's optimum, the
back-substitution down to keyframe 0 and the first-order re-expression of the newest kept
conditional. The store elimination needs the window's whitened rows at the optimum, which the
testbench does not report: the host linearises with the native ``double`` build of the same
template (``fgc_rows``). So in this path the kept Bayes net lives on the host, not on chip as in
paper A's accelerator; the on-chip state between calls is not emitted.
"""

from __future__ import annotations

import tempfile
import weakref
from pathlib import Path

import numpy as np

from fgc.ir.codes import REASONS, STATUSES
from fgc.ir.datafile import ProblemData
from fgc_backends.cfamily.tables import factor_data_words
from fgc_backends.native.stream import FixedLagStream, IncrementalStream, WindowSolver


class _Csim:
    """The C simulation of a template window: emitted into ``out_dir`` (a private temporary
    folder if None), built on the first :meth:`solve`."""

    def _emit_csim(self, scalar: str, out_dir) -> None:
        from fgc_backends.hls.config import HlsConfig
        from fgc_backends.hls.emitter import emit

        if out_dir is None:
            tmp = tempfile.mkdtemp(prefix="fgc-hls-stream-")
            weakref.finalize(self, _remove, tmp)
            out_dir = tmp
        self.scalar = scalar
        self.project = emit(self.template, Path(out_dir) / f"window{self.size}",
                            HlsConfig(scalar=scalar))
        t = self.template
        self._factor_words = [factor_data_words(t, spec.block) for spec in t.factors]

    def _data(self, x: np.ndarray, d: np.ndarray) -> ProblemData:
        t = self.template
        variables, pos = [], 0
        for v in t.variables:
            variables.append(x[pos:pos + v.storage_dim])
            pos += v.storage_dim
        factors, pos = [], 0
        for n in self._factor_words:
            factors.append(d[pos:pos + n])
            pos += n
        return ProblemData(tuple(variables), tuple(factors), t.structure_fingerprint)

    def solve(self, x: np.ndarray, d: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The window's LM solve by the C simulation: (x, errors, info) in the native solver's
        layout (x the template's flat storage, errors (initial, final), info (iterations,
        status code, reason code))."""
        from fgc_backends.hls import build

        data = self._data(x, d)
        if self.scalar == "double":
            result = build.run_csim(self.project, self.template, data, reference=False)
        else:
            # run_csim's float verdict re-checks the window's conditioning in the simulator,
            # which refuses the template's absent factors (zero square-root information): the
            # same testbench run, its result read without that verdict (the stream is judged
            # against the simulator per keyframe instead)
            from fgc.ir.datafile import write_data
            from fgc_backends.cfamily.results import REFERENCE_FILE, read_result

            folder = self.project.directory
            write_data(data, folder / build.DATA_FILE)
            (folder / REFERENCE_FILE).unlink(missing_ok=True)
            (folder / build.RESULT_FILE).unlink(missing_ok=True)
            build.make(self.project, "csim")
            result = read_result(folder / build.RESULT_FILE, self.template)
        x_out = np.concatenate([np.asarray(result.values[v.key], dtype=np.float64)
                                for v in self.template.variables])
        info = np.array([result.iterations, STATUSES.index(result.status),
                         REASONS.index(result.reason)], dtype=np.int32)
        return x_out, np.array([result.initial_error, result.final_error]), info


def _remove(folder: str) -> None:
    import shutil

    shutil.rmtree(folder, ignore_errors=True)


def _native_double():
    from fgc_backends.native.config import NativeConfig

    return NativeConfig(scalar="double")


class CsimWindow(_Csim, WindowSolver):
    """A template window solved by its HLS C simulation (``scalar`` "double" or "float"); the
    host's rows at the optimum from the native double build of the same template."""

    def __init__(self, graph, program, size: int, scalar: str = "double", out_dir=None):
        WindowSolver.__init__(self, graph, program, size, _native_double())
        self._emit_csim(scalar, out_dir)


class CsimFixedLagStream(_Csim, FixedLagStream):
    """The fixed-lag window of ``window`` keyframes, each update solved by the C simulation."""

    def __init__(self, graph, program, window: int, scalar: str = "double", out_dir=None):
        FixedLagStream.__init__(self, graph, program, window, _native_double())
        self._emit_csim(scalar, out_dir)


def incremental_stream(graph, program, scalar: str = "double", out_dir=None,
                       progress_build=None) -> IncrementalStream:
    """The incremental plan with every window solved by the C simulation of its template."""
    return IncrementalStream(graph, program, progress_build=progress_build,
                             window_solver=lambda size: CsimWindow(graph, program, size, scalar,
                                                                   out_dir))
