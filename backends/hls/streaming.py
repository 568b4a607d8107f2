"""Streaming on the HLS design's C simulation (issue 19). The fixed-lag window runs on chip
(:class:`OnChipFixedLagStream`, :mod:`fgc_backends.hls.window`: one testbench run streams every
keyframe through the design's ``<name>_stream`` top). The incremental plan: per keyframe, the
emitted accelerator's testbench solves the update's window; the host holds the kept Bayes net.

The windows are the native stream's (:mod:`fgc_backends.native.streaming`): a *template* window
Program — the chain's first S keyframes with a ``MarginalPrior…`` factor on every keyframe — is
emitted once as an HLS project (:func:`fgc_backends.hls.emitter.emit`, ``double`` for agreement
with the simulator, ``float`` as the hardware; kept in fgc's cache directory by content hash,
with its built testbench once a stream has built it, and copied into each stream's own
folder), its C simulation built on the first update and re-run on every later update's numbers
(:func:`fgc_backends.hls.build.run_csim` with ``reference=False``: the testbench reads the new
``data.txt``, nothing is rebuilt).

What runs where. The C simulation runs each window's LM solve. Everything between updates runs
on the host, as for the native stream: the kept conditionals, the marginal prior τ a window's
oldest keyframe carries and the undamped store elimination at the window's optimum in Python;
the back-substitution down to keyframe 0 and the first-order re-expression of the newest kept
conditional in the native ``double`` build of the same template (``fgc_kept_walk``,
``fgc_local_jacobian``), which also gives the store elimination the window's whitened rows at
the optimum that the testbench does not report (``fgc_rows``). So in this path the kept Bayes
net lives on the host, not on chip as in paper A's accelerator; the on-chip state between calls
is not emitted.
"""

from __future__ import annotations

import atexit
import contextlib
import dataclasses
import hashlib
import os
import shutil
import tempfile
import weakref
from pathlib import Path

import numpy as np

import fgc_backends
from fgc.compiler.cache import (
    MANIFEST,
    cache_dir,
    check_manifest,
    discard_folder,
    unusable,
)
from fgc.compiler.stream import prefix_program
from fgc.ir.codes import REASONS, STATUSES
from fgc.ir.datafile import DataError, ProblemData, problem_data, write_data
from fgc.ir.stream import StreamError, StreamProgram
from fgc.version import __version__
from fgc_backends.cfamily.host import host_key
from fgc_backends.cfamily.names import identifier
from fgc_backends.cfamily.results import REFERENCE_FILE, read_result
from fgc_backends.cfamily.stream import IncrementalDriver, StreamState, TemplateSolver
from fgc_backends.cfamily.tables import factor_data_words
from fgc_backends.hls import build
from fgc_backends.hls.config import HlsConfig
from fgc_backends.hls.emitter import STREAM_MAGIC, STREAM_RESULT_MAGIC, HlsProject, emit
from fgc_backends.hls.plan import PlanOptions
from fgc_backends.hls.plan.stream import WindowUpdateModel
from fgc_backends.hls.plan.update import UpdateModel
from fgc_backends.hls.window import BatchLayout, OnChipWindowError, WindowLayout


class _Csim:
    """The C simulation of a template window: emitted into ``out_dir`` (a private temporary
    folder if None), built on the first :meth:`solve`."""

    def _emit_csim(self, scalar: str, out_dir) -> None:
        self.scalar = scalar
        _working_copy(self, scalar, out_dir, f"window{self.size}")
        t = self.template
        self._factor_words = [factor_data_words(t, spec.block) for spec in t.factors]

    def _data(self, x: np.ndarray, d: np.ndarray) -> ProblemData:
        return template_data(self.template, x, d, self._factor_words)

    def solve(self, x: np.ndarray, d: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The window's LM solve by the C simulation: (x, errors, info) in the native solver's
        layout (x the template's flat storage, errors (initial, final), info (iterations,
        status code, reason code))."""
        data = self._data(x, d)
        if self.scalar == "double":
            result = build.run_csim(self.project, self.template, data, reference=False)
        else:
            # run_csim's float verdict re-checks the window's conditioning in the simulator,
            # which refuses the template's absent factors (zero square-root information): the
            # same testbench run, its result read without that verdict (the stream is judged
            # against the simulator per keyframe instead)
            folder = self.project.directory
            write_data(data, folder / build.DATA_FILE)
            (folder / REFERENCE_FILE).unlink(missing_ok=True)
            (folder / build.RESULT_FILE).unlink(missing_ok=True)
            build.make(self.project, "csim")
            result = read_result(folder / build.RESULT_FILE, self.template)
        if not self._built:  # the first run built the testbench: keep the build for later
            _keep_build(self.project, self._cached.directory)
            self._built = True
        x_out = np.concatenate([np.asarray(result.values[v.key], dtype=np.float64)
                                for v in self.template.variables])
        info = np.array([result.iterations, STATUSES.index(result.status),
                         REASONS.index(result.reason)], dtype=np.int32)
        return x_out, np.array([result.initial_error, result.final_error]), info


def template_data(t, x: np.ndarray, d: np.ndarray, factor_words=None) -> ProblemData:
    """The template Program ``t``'s flat storage ``x`` and factor data ``d`` as a ProblemData
    (per variable its storage, per block instance its words; ``factor_words``: the instances'
    word counts, if already known)."""
    if factor_words is None:
        factor_words = [factor_data_words(t, spec.block) for spec in t.factors]
    variables, pos = [], 0
    for v in t.variables:
        variables.append(x[pos:pos + v.storage_dim])
        pos += v.storage_dim
    factors, pos = [], 0
    for n in factor_words:
        factors.append(d[pos:pos + n])
        pos += n
    return ProblemData(tuple(variables), tuple(factors), t.structure_fingerprint)


def _working_copy(owner, scalar: str, out_dir, name: str, stream=None, qr_rows: int = 1,
                  design=None) -> None:
    """``owner.project``: a copy, in ``out_dir`` (a private temporary folder if None, removed
    with ``owner``), of ``owner.template``'s project from the cache (:func:`_cached_project`,
    with ``stream``'s on-chip design), its mtimes too: a built one stays built; ``owner._cached``
    and ``owner._built`` say where it came from and whether it is built. ``qr_rows``: the QR
    Update units' rows a cycle (HlsConfig.qr_rows)."""
    if out_dir is None:
        tmp = tempfile.mkdtemp(prefix="fgc-hls-stream-")
        weakref.finalize(owner, _remove, tmp)
        out_dir = tmp
    # one back-substitution lane, as the stream's update models price it (the host-kept path's
    # batch template too, not the batch default's columns)
    # (``design``: the design's options, e.g. HlsConfig.root_wave; its back-substitution one lane)
    rows = {"qr_rows": qr_rows} if qr_rows != 1 else {}
    config = HlsConfig(scalar=scalar, backsub_lanes=1, **rows) if design is None else HlsConfig(
        scalar=scalar, design=dataclasses.replace(design, backsub_lanes=1, **rows))
    owner._cached = _cached_project(owner.template, config, stream)
    work = Path(out_dir) / name
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(owner._cached.directory, work, ignore=shutil.ignore_patterns(MANIFEST))
    owner.project = HlsProject(work, owner._cached.name,
                               tuple(work / f.name for f in owner._cached.files), config)
    owner._built = (owner._cached.directory / _BUILT).is_file()


def _remove(folder: str) -> None:
    shutil.rmtree(folder, ignore_errors=True)


_BUILT = ".fgc-stream-built"


def _project_key(template, config) -> str:
    """Content hash of what the emitted and built testbench depends on: the template Program,
    the config, fgc, the HLS backend's and C-family layer's sources and the host."""
    h = hashlib.sha256(template.to_json().encode())
    h.update(repr(config).encode())
    h.update(__version__.encode())
    h.update(host_key().encode())
    # the Makefile appends $(FGC_CSIM_FLAGS) from the environment: a cached build is another one
    h.update(os.environ.get("FGC_CSIM_FLAGS", "").encode())
    backends = Path(__file__).resolve().parent.parent
    # cfamily's shared C++ (common.jinja, fgc_lm.h) is printed into the kernel too
    for path in sorted([*(backends / "hls").rglob("*"), *(backends / "cfamily").rglob("*.py"),
                        *(backends / "cfamily" / "templates").glob("*"),
                        *(backends / "cfamily" / "include").glob("*")]):
        if path.is_file() and path.name not in ("stream.py", "streaming.py") and \
                "__pycache__" not in path.parts:
            h.update(str(path.relative_to(backends)).encode())
            h.update(path.read_bytes())
    return h.hexdigest()[:24]


def _cached_project(template, config, stream=None):
    """The template's emitted project in ``<fgc cache>/hls-stream/<hash>`` (emitted once per
    content hash; a stream copies it into its own folder, as two streams may run at once);
    ``stream``: the on-chip window's layout (emitted with its stream top). A cached project is
    used only if its manifest (the hash, the SHA-256 of every file) holds, else it is emitted
    again with one warning; an unwritable cache emits into a temporary folder (one warning)."""
    key = _project_key(template, config)
    if stream is not None:
        key = f"{key}-w{stream.window}" + (f"-kept{stream.kept}" if stream.kept else "")
        if stream.batch is not None:
            b = stream.batch
            key += "-b" + hashlib.sha256(f"{b.template.to_json()}{b.keyframes}".encode()
                                         ).hexdigest()[:12]
        if getattr(stream, "sweep", None) is not None:  # the batch steps' table (IS_BATCH)
            key += "-s" + "_".join(map(str, stream.sweep))
    root, folder = cache_dir(), None
    if root is not None:
        folder = root / "hls-stream" / key
        if folder.exists() and (why := check_manifest(folder, key)) is not None:
            discard_folder(folder, why)
        if not folder.is_dir():
            try:
                _emit_into(template, config, stream, folder)
            except OSError as exc:  # read-only or full: emit outside the cache
                unusable(root, f"cannot write {folder.parent}: {exc.strerror or exc}")
                folder = None
    if folder is None:
        tmp = tempfile.mkdtemp(prefix="fgc-hls-stream-")
        atexit.register(_remove, tmp)
        folder = Path(tmp) / key
        _emit_into(template, config, stream, folder)
    files = tuple(sorted(p for p in folder.iterdir()
                         if p.is_file() and p.name not in (_BUILT, MANIFEST)))
    return HlsProject(folder, identifier(template.name), files, config)


def _emit_into(template, config, stream, folder: Path) -> None:
    """Emit into a private staging folder with its manifest, then move it to ``folder`` (first
    one wins); the staging folder never outlives this call, interrupted or not."""
    from fgc.compiler.cache import write_manifest
    from fgc_backends.hls.emitter import emit

    staging = folder.with_name(f"{folder.name}.tmp{os.getpid()}")
    shutil.rmtree(staging, ignore_errors=True)
    try:
        if stream is not None and stream.batch is not None:
            staging.mkdir(parents=True)
            emit(stream.batch.template, staging, config, stream=stream.batch, kernel_only=True)
        emit(template, staging, config, stream=stream)
        write_manifest(staging, folder.name)
        with contextlib.suppress(OSError):  # another process finished first: use its project
            os.replace(staging, folder)
    finally:
        shutil.rmtree(staging, ignore_errors=True)


def _keep_build(project, cached: Path) -> None:
    """Copy a stream's built project back into the cache (atomically; first one wins), with its
    manifest; a cache that cannot take it is left as it was (one warning)."""
    from fgc.compiler.cache import unusable, write_manifest

    staging = cached.with_name(f"{cached.name}.built{os.getpid()}")
    old = cached.with_name(f"{cached.name}.old{os.getpid()}")
    shutil.rmtree(staging, ignore_errors=True)
    try:
        shutil.copytree(project.directory, staging)
        (staging / _BUILT).write_text("built\n")
        write_manifest(staging, cached.name)
        if cached.is_dir():  # (gone if the cache was cleared meanwhile)
            os.replace(cached, old)
        os.replace(staging, cached)
    except OSError as exc:
        if not cached.is_dir() and old.is_dir():  # put the unbuilt project back
            with contextlib.suppress(OSError):
                os.replace(old, cached)
        unusable(cached.parent.parent, f"cannot write {cached.parent}: {exc.strerror or exc}")
    finally:
        shutil.rmtree(staging, ignore_errors=True)
        shutil.rmtree(old, ignore_errors=True)


def _native_double(template):
    """The native backend's double build of ``template``, reached through the registry (the
    host's rows at the optimum and the kept net's compiled walk: what the testbench does not
    report)."""
    native = fgc_backends.load("native")
    return native.load(template, native.Config(scalar="double"))


class CsimWindow(_Csim, TemplateSolver):
    """A template window solved by its HLS C simulation (``scalar`` "double" or "float"); the
    host's rows at the optimum from the native double build of the same template."""

    def __init__(self, graph, program, size: int, scalar: str = "double", out_dir=None):
        TemplateSolver.__init__(self, graph, program, size, _native_double)
        self._emit_csim(scalar, out_dir)


def incremental_stream(graph, program, scalar: str = "double", out_dir=None,
                       progress_build=None) -> IncrementalDriver:
    """The incremental plan with every window solved by the C simulation of its template."""
    return IncrementalDriver(graph, program, progress_build=progress_build,
                             window_solver=lambda size: CsimWindow(graph, program, size, scalar,
                                                                   out_dir))


class OnChipFixedLagStream:
    """The fixed-lag window of ``window`` keyframes on the accelerator itself
    (:mod:`fgc_backends.hls.window`): one emitted design whose ``<name>_stream`` top keeps the
    window, its factors' words and τ in its memories between calls. Its C simulation runs the
    whole stream in one testbench run (``tb --stream``): the reset call with the template's
    slots, then per keyframe only that keyframe's storage and data words; the host reads back
    each update's window. ``scalar``: the design's T ("double" for agreement, "float" the
    hardware). Nothing of the window is assembled or eliminated on the host."""

    kept = False  # the incremental subclass keeps the keyframes that leave
    mode = "fixed-lag"

    def __init__(self, graph, program, window: int, scalar: str = "double", out_dir=None,
                 layout=None, qr_rows: int = 1, design=None):
        self.layout = layout or WindowLayout(graph, program, window, kept=self.kept)
        self.program, self.window, self.scalar = program, window, scalar
        self.template = self.layout.template
        _working_copy(self, scalar, out_dir,
                      f"window{window}_onchip{'_kept' if self.kept else ''}", self.layout,
                      qr_rows, design)

    def run(self, data: ProblemData, progress=None, estimates_at_end: bool = False):
        """Stream ``data``'s keyframes through the C simulation; a
        :class:`~fgc_backends.cfamily.stream.StreamResult` with the fixed-lag records
        (``seconds``: NaN — a C simulation's wall time is not the accelerator's; its latency is
        the update model's). Incremental: the kept keyframes' estimates are asked for after
        every update (``stream_call`` op 3, not part of the update), or with
        ``estimates_at_end`` after the last one only (the records before it then hold the kept
        keyframes as last returned)."""
        stream = StreamState(self.program)
        estimate = stream._start(data)
        folder = self.project.directory
        count = write_stream_inputs(self.layout, estimate, folder)
        exe = f"tb_{self.project.name}"
        build.run_command(self.project, ["make", "-s", exe], f"make {exe}")
        mode = "--stream-estimates-at-end" if estimates_at_end and self.kept else "--stream"
        build.run_command(self.project, [f"./{exe}", mode, build.DATA_FILE, STREAM_FILE,
                                         STREAM_RESULT_FILE], f"{exe} {mode}")
        if not self._built:
            _keep_build(self.project, self._cached.directory)
            self._built = True
        lay, window = self.layout, self.window
        records, initial_error = [], None
        kf = lay.kf_words
        batches = set(lay.batch_keyframes)
        for j, (head, x_out, x_kept) in enumerate(_read_stream_result(
                folder / STREAM_RESULT_FILE, count, lay.n_x, self.kept)):
            first = max(0, j - window)  # the window's oldest keyframe
            if head["SLOT"] != min(j, lay.size - 1):
                raise OnChipWindowError(f"keyframe {j}: the accelerator put it in slot "
                                        f"{head['SLOT']}, the host expected "
                                        f"{min(j, lay.size - 1)}")
            if head["MARGINAL"] == 2:
                raise OnChipWindowError(f"keyframe {first}: the marginal prior it passes to the "
                                        "next keyframe is singular (the accelerator did not "
                                        "write it)")
            if j == 0:
                initial_error = head["INITIAL_ERROR"]
            lay.store(estimate, x_out, first, j)
            if self.kept and x_kept is not None:  # the kept keyframes 0 … first − 1, walked
                if x_kept.size != first * kf:
                    raise OnChipWindowError(f"keyframe {j}: the accelerator returned "
                                            f"{x_kept.size // kf} kept keyframes, expected {first}")
                clusters = self.program.schedule.clusters
                for c in range(first):
                    pos = 0
                    for k in clusters[c]:
                        n = estimate[k].size
                        estimate[k][:] = x_kept[c * kf + pos:c * kf + pos + n]
                        pos += n
            batch = j in batches
            records.append({"keyframe": j, "mode": "batch" if batch else self.mode,
                            "first": 0 if batch else first,
                            "iterations": head["ITERATIONS"], "status": head["STATUS"],
                            "reason": head["REASON"], "cost": head["FINAL_ERROR"],
                            "seconds": float("nan"), "marginal": head["MARGINAL"] == 1,
                            "values": stream._snapshot(
                                estimate, 0 if self.kept else max(0, j - window + 1), j)})
            if progress is not None:
                progress(records[-1])
        return stream._result(estimate, records, initial_error, self.template)


class OnChipIncrementalStream(OnChipFixedLagStream):
    """The incremental plan on the accelerator itself: the on-chip window of the newest K
    keyframes (W = K − 1 in :class:`OnChipFixedLagStream`'s terms) plus the kept Bayes net in the
    design's memories — each keyframe that leaves is kept as its conditional from the QR unit,
    the newest kept one re-expressed at its parent's new estimate each update, and every kept
    keyframe walked back when their estimates are asked for or a batch step starts from them
    (fgc_stream.h's ``reexpress``, ``keep``, ``kept_walk``). Plans with
    batch steps are refused: a batch step re-solves the whole chain, which the K-keyframe design
    does not hold (:class:`~fgc_backends.hls.window.OnChipWindowError`; the host-kept C
    simulation, :func:`incremental_stream`, runs them)."""

    kept = True
    mode = "incremental"

    def __init__(self, graph, program, scalar: str = "double", out_dir=None, sweep=None,
                 qr_rows: int = 1, design=None):
        super().__init__(graph, program, program.schedule.incremental.window - 1, scalar,
                         out_dir, incremental_layout(graph, program, sweep), qr_rows, design)


def incremental_layout(graph, program, sweep: bool | None = None):
    """The on-chip incremental design's layout: the window of the newest K keyframes with the
    kept net and, when the plan has batch steps, either the batch kernel of keyframes 0 … the
    last batch step (:class:`~fgc_backends.hls.window.BatchLayout`: its own units) or
    (``sweep``) each batch step a sweep through the window's own units (fgc_stream.h's
    ``FGC_STREAM_SWEEP``; one set of units, docs/hls.md). ``sweep`` None: the sweep under the
    one-step policy (``SolverConfig.one_step``: one Gauss-Newton step an update, whose batch
    step is one elimination of the chain oldest first, what the window does to its slot 0),
    the batch kernel under LM to convergence; a sweep asked for under LM to convergence is
    refused by name (the sweep takes one step: LM's iterations would each need one)."""
    check_incremental_on_chip(program)
    plan = program.schedule.incremental
    if not plan.batch_keyframes:
        return WindowLayout(graph, program, plan.window - 1, kept=True)
    one_step = program.solver.one_step
    if sweep is None:
        sweep = one_step
    if sweep:
        if not one_step:
            raise OnChipWindowError(
                "batch steps as sweeps through the window (one set of units) take one "
                "Gauss-Newton step: the Program's solver is LM to convergence "
                f"({program.solver.method}, max_iterations {program.solver.max_iterations}); "
                "compile it with one_step_solver() (fgc stream --solver gn --max-iterations 1) "
                "or keep the batch kernel")
        return WindowLayout(graph, program, plan.window - 1, kept=True,
                            sweep=plan.batch_keyframes)
    batch = BatchLayout(graph, program, max(plan.batch_keyframes) + 1, plan.batch_keyframes)
    return WindowLayout(graph, program, plan.window - 1, kept=True, batch=batch)


def check_incremental_on_chip(program) -> None:
    """:class:`~fgc_backends.hls.window.OnChipWindowError` unless ``program``'s incremental plan
    runs on chip: every incremental update the newest K keyframes, every batch step keyframes
    0 … j, K ≥ 2."""
    plan = program.schedule.incremental
    if plan is None:
        raise OnChipWindowError("the Program has no incremental plan (--incremental K)")
    k = plan.window
    for u in plan.updates:
        if u.mode == "batch":
            if tuple(u.clusters) != tuple(range(u.keyframe + 1)):
                raise OnChipWindowError(f"keyframe {u.keyframe}: a batch step that re-eliminates "
                                        f"keyframes {list(u.clusters)}, not 0 … {u.keyframe}")
            continue
        if u.mode != "incremental" or tuple(u.clusters) != tuple(
                range(max(0, u.keyframe - k + 1), u.keyframe + 1)):
            raise OnChipWindowError(f"keyframe {u.keyframe}: its update re-eliminates "
                                    f"keyframes {list(u.clusters)}, not the newest {k}: the "
                                    "on-chip window slides one keyframe a call")
    if k < 2:
        raise OnChipWindowError("--incremental 1 keeps no window to slide: K ≥ 2 on chip")


STREAM_FILE, STREAM_RESULT_FILE = "stream.txt", "stream_result.txt"


def write_stream_inputs(layout, estimate: dict, folder: Path) -> int:
    """The on-chip window's testbench inputs in ``folder``: data.txt (the reset call: the
    template's slots at ``estimate``, its factors with zero information, its priors held) and
    stream.txt (per keyframe its storage and its data words, in lines of at most 16 numbers);
    returns the number of keyframes. Each keyframe is checked against what the window holds
    (:meth:`~fgc_backends.hls.window.WindowLayout.check_holds`)."""
    t = layout.template
    x, d = layout.reset_words(estimate)
    write_data(template_data(t, x, d), Path(folder) / build.DATA_FILE)
    clusters = layout.program.schedule.clusters
    lines = [f"{STREAM_MAGIC} {t.structure_fingerprint}", f"KEYFRAMES {len(clusters)}"]
    batch = layout.batch
    if batch is not None:
        bx, bd = batch.reset_words(estimate)
        lines += ["BATCH_RESET", *_chunks(bx), *_chunks(bd)]
    held = None
    for j, keys in enumerate(clusters):
        held = layout.check_holds(held, j)
        x_new = np.concatenate([estimate[k] for k in keys])
        _, words = layout.keyframe_words(j, x_new)
        if batch is not None and j < batch.size:
            words = np.concatenate([words, batch.keyframe_words(j, x_new)])
        lines += _chunks(x_new) + _chunks(words)
    (Path(folder) / STREAM_FILE).write_text("\n".join(lines) + "\n")
    return len(clusters)


def layout_of(sp: StreamProgram, sweep: bool | None = None):
    """The on-chip design's layout of ``sp``: the fixed-lag window of its policy's W, or its
    incremental plan's window with the kept net (:func:`incremental_layout`; ``sweep``: its
    batch steps' design, there)."""
    if sp.window is None:
        return incremental_layout(sp.graph, sp.program, sweep)
    return WindowLayout(sp.graph, sp.program, sp.window)


def on_chip(sp: StreamProgram) -> bool:
    """Whether the HLS design runs ``sp`` on chip (:mod:`fgc_backends.hls.window`): a QR design
    with a fixed-lag window, or with an incremental plan whose updates the on-chip design runs
    (K ≥ 2: the newest K keyframes, batch steps on its batch kernel)."""
    if sp.program.solver.linear != "qr":
        return False
    if sp.window is not None:
        return True
    try:
        check_incremental_on_chip(sp.program)
    except OnChipWindowError:
        return False
    return True


def emit_window(sp: StreamProgram, out_dir, config, data: ProblemData | None = None):
    """``fgc compile --backend hls --window W | --incremental K``: the on-chip design for
    ``sp``'s chain (its policy: a fixed-lag window, or an incremental plan) emitted into
    ``out_dir`` (its synthesis top ``<name>_stream``) with its testbench's inputs for ``data``'s
    stream (default the graph's own: data.txt, stream.txt: ``make`` builds, ``tb_<name> --stream
    data.txt stream.txt stream_result.txt`` runs it). Returns the project."""

    layout = layout_of(sp)
    if layout.batch is not None:  # its second file first: the window's lint reads it
        emit(layout.batch.template, out_dir, config, stream=layout.batch, kernel_only=True)
    project = emit(layout.template, out_dir, config, stream=layout)
    data = data if data is not None else problem_data(sp.graph, sp.program)
    estimate = StreamState(sp.program)._start(data)
    write_stream_inputs(layout, estimate, project.directory)
    extra = tuple(project.directory / f for f in ("data.txt", STREAM_FILE))
    return dataclasses.replace(project, files=project.files + extra)


class HlsStream:
    """The contract's stream runner on the HLS design's C simulation: on chip
    (:class:`OnChipFixedLagStream`, :class:`OnChipIncrementalStream`) when :func:`on_chip`,
    else the host-kept incremental path (:func:`incremental_stream`). ``config``: an HlsConfig
    (its ``scalar``, default the Program's precision: ``double`` for float64)."""

    def __init__(self, sp: StreamProgram, config=None):
        sp.slots.check("the HLS design", StreamError)
        self.sp = sp
        scalar = getattr(config, "scalar", None)
        self.scalar = scalar or ("double" if sp.program.solver.precision == "float64"
                                 else "float")
        self.on_chip = on_chip(sp)
        self.who, self.timing_key = "HLS C simulation", "csim"

    def run(self, data: ProblemData, progress=None, progress_build=None):
        """Stream ``data`` (as :meth:`fgc_backends.native.streaming.NativeStream.run`)."""
        sp = self.sp
        if sp.incremental and self.on_chip:
            if progress_build is not None:
                progress_build(sp.program.schedule.incremental.window, 0, 1)
            runner = OnChipIncrementalStream(sp.graph, sp.program, self.scalar)
        elif sp.incremental:
            runner = incremental_stream(sp.graph, sp.program, self.scalar,
                                        progress_build=progress_build)
        else:
            if progress_build is not None:
                progress_build(sp.window + 1, 0, 1)
            runner = OnChipFixedLagStream(sp.graph, sp.program, sp.window, self.scalar)
        return runner.run(data, progress)


def stream(sp: StreamProgram, config=None) -> HlsStream:
    """The backend contract's ``stream``: a runner of ``sp`` on the C simulation."""
    return HlsStream(sp, config)


def window_model(sp: StreamProgram, scalar: str | None = None, config: HlsConfig | None = None,
                 sweep: bool | None = None):
    """The on-chip design's :class:`~fgc_backends.hls.plan.stream.WindowUpdateModel` (the design
    ``fgc compile --backend hls`` emits for ``sp``; ``scalar`` default the Program's;
    ``config``: the design's HlsConfig — unit sets, ALLOCATION — default the default design;
    ``sweep``: batch steps as sweeps or on the batch kernel, :func:`incremental_layout`)."""
    scalar = scalar or ("double" if sp.program.solver.precision == "float64" else "float")
    config = dataclasses.replace(config, scalar=scalar) if config is not None else None
    return WindowUpdateModel(layout_of(sp, sweep), config or HlsConfig(scalar=scalar))


def update_model(graph, program, units: int | None = None, cpe: int | None = None):
    """The accelerator plan's update model of a stream over the chain ``program`` (compiled
    from ``graph``; :class:`fgc_backends.hls.plan.update.
    UpdateModel`; model estimates, the accelerator's incremental mode is not emitted): ``units``
    / ``cpe`` default to the Program's; a batch keyframe j is priced on the batch Program of
    its j + 1 keyframes (:func:`fgc.compiler.stream.prefix_program`)."""
    changes = {k: v for k, v in (("units", units), ("cpe", cpe)) if v is not None}
    options = PlanOptions.of(program, **changes)
    return UpdateModel(program, options,
                       batch_program=lambda j: prefix_program(graph, program, j + 1))


def _chunks(values: np.ndarray, size: int = 16) -> list[str]:
    vals = np.asarray(values, dtype=np.float64).reshape(-1)
    if not np.all(np.isfinite(vals)):

        raise DataError("refusing to write a non-finite number to a stream file")
    return [" ".join([str(len(vals[i:i + size]))] + [repr(float(v)) for v in vals[i:i + size]])
            for i in range(0, len(vals), size)]


def _read_stream_result(path: Path, count: int, n_x: int, kept: bool = False):
    """(head fields, x, kept keyframes' storage) per keyframe from the testbench's stream
    result."""
    lines = path.read_text().splitlines()
    if not lines or lines[0] != STREAM_RESULT_MAGIC:
        raise DataError(f"{path}:1: expected '{STREAM_RESULT_MAGIC}'")
    per = 3 if kept else 2
    if len(lines) != 1 + per * count:
        raise DataError(f"{path}: {(len(lines) - 1) // per} keyframes, expected {count}")
    out = []
    for j in range(count):
        words = lines[1 + per * j].split()
        head = dict(zip(words[0::2], words[1::2], strict=True))
        for key in ("KEYFRAME", "SLOT", "ITERATIONS", "MARGINAL"):
            head[key] = int(head[key])
        for key in ("INITIAL_ERROR", "FINAL_ERROR"):
            head[key] = float(head[key])
        if head["KEYFRAME"] != j or head["STATUS"] not in STATUSES or \
                head["REASON"] not in REASONS:
            raise DataError(f"{path}:{2 + per * j}: a malformed keyframe line")
        x = lines[2 + per * j].split()
        if x[:2] != ["X", str(n_x)] or len(x) != n_x + 2:
            raise DataError(f"{path}:{3 + per * j}: expected 'X {n_x} <numbers>'")
        held = np.zeros(0)
        if kept:
            k = lines[3 + per * j].split()
            if k == ["KEPT", "-1"]:  # not asked for after this update
                held = None
            elif k[:1] != ["KEPT"] or len(k) != int(k[1]) + 2:
                raise DataError(f"{path}:{4 + per * j}: expected 'KEPT <count> <numbers>'")
            else:
                held = np.array([float(v) for v in k[2:]])
        out.append((head, np.array([float(v) for v in x[2:]]), held))
    return out
