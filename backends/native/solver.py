"""The native solver: the emitted CPU program built as a shared library and called through ctypes.

The solver (``<name>.cpp``, built by ``make native`` with the host's ISA) is wrapped by
``native_<name>.cpp``, whose ``fgc_run`` calls ``<name>_top`` on the caller's double arrays
(converted to the scalar type in static buffers when that is not double): the solver allocates
nothing. :func:`run` emits into a content-addressed folder under fgc's cache directory, builds
once and keeps the loaded library for later calls.

    from fgc_backends import native
    result = native.run(program, problem_data(graph, program))
"""

from __future__ import annotations

import atexit
import ctypes
import hashlib
import os
import shutil
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fgc.compiler.cache import (
    MANIFEST,
    cache_dir,
    check_manifest,
    discard_folder,
    unusable,
    write_manifest,
)
from fgc.errors import DataError
from fgc.ir.datafile import ProblemData, check_structure
from fgc.ir.program import Program
from fgc.version import __version__
from fgc_backends.cfamily.host import host_key
from fgc_backends.cfamily.names import identifier
from fgc_backends.cfamily.results import HlsResult, judge_precision, keyed, result_from_arrays
from fgc_backends.cfamily.scalars import check_fixed_data
from fgc_backends.cfamily.tables import factor_data_words
from fgc_backends.native.build import make
from fgc_backends.native.config import NativeConfig, NativeConfigError
from fgc_backends.native.emitter import NativeProject, emit

_INTS = np.ctypeslib.ndpointer(dtype=np.int32, flags="C_CONTIGUOUS")
# fgc_set_progress's hook: (iteration, cost, damping for the next iteration, relative decrease)
_PROGRESS = ctypes.CFUNCTYPE(None, ctypes.c_int, ctypes.c_double, ctypes.c_double,
                             ctypes.c_double)
_LOADED: dict[str, NativeSolver] = {}


def _address(a: np.ndarray, n: int, what: str) -> int:
    """The data address of ``a`` once it is checked to be what the kernel reads: n float64 in
    one C-contiguous run. (numpy's ``ndpointer`` argument check and ``a.ctypes`` cost about 2 µs
    an array per call, 5 % of a small problem's solve; and they did not check the size.)"""
    if (type(a) is not np.ndarray or a.dtype != np.float64 or not a.flags.c_contiguous
            or a.size != n):
        raise DataError(f"{what} must be a C-contiguous float64 array of {n} numbers (from "
                        f"NativeSolver.flatten), got {getattr(a, 'dtype', type(a).__name__)} "
                        f"of shape {getattr(a, 'shape', '?')}")
    return a.__array_interface__["data"][0]


@dataclass
class NativeSolver:
    """A loaded native build of one Program: :meth:`solve` on flat arrays, :meth:`run` on data."""

    program: Program
    project: NativeProject
    library: ctypes.CDLL
    n_x: int
    n_data: int

    def __post_init__(self) -> None:
        # the results land in buffers of this solver (copied out), so a call makes no ctypes
        # objects: the kernel's own buffers are static, so a solver is not re-entrant anyway
        self._out, self._errors = np.empty(self.n_x), np.empty(2)
        self._info = np.zeros(3, dtype=np.int32)
        self._outputs = tuple(ctypes.c_void_p(a.__array_interface__["data"][0])
                              for a in (self._out, self._errors, self._info))
        self._run = self.library.fgc_run

    @classmethod
    def load(cls, program: Program, project: NativeProject) -> NativeSolver:
        lib = ctypes.CDLL(str(project.library))
        lib.fgc_sizes.argtypes = [_INTS]
        lib.fgc_run.argtypes = [ctypes.c_void_p] * 5
        lib.fgc_run.restype = None
        lib.fgc_probe.argtypes = [ctypes.c_void_p] * 3
        lib.fgc_probe.restype = None
        lib.fgc_rows.argtypes = [ctypes.c_void_p] * 3
        lib.fgc_rows.restype = None
        lib.fgc_structure.argtypes = []
        lib.fgc_structure.restype = ctypes.c_char_p
        sizes = np.zeros(4, dtype=np.int32)
        lib.fgc_sizes(sizes)
        built = lib.fgc_structure().decode("ascii")
        if (sizes[0], sizes[1]) != (len(program.variables), len(program.factors)) or (
                built != program.structure_fingerprint):
            raise DataError(f"{project.library} was built for another structure: "
                            f"structure fingerprint {built}, the Program has "
                            f"{program.structure_fingerprint}")
        return cls(program, project, lib, int(sizes[2]), int(sizes[3]))

    def flatten(self, data: ProblemData) -> tuple[np.ndarray, np.ndarray]:
        """The data as the kernel's two flat arrays, checked against the compiled layout and
        structure fingerprint, and for a fixed-point build against the format's range (a value
        outside it is a :class:`NativeConfigError` naming it: saturating it is no answer)."""
        p = self.program
        check_structure(data, p)
        if len(data.variables) != len(p.variables) or len(data.factors) != len(p.factors):
            raise DataError(f"the data has {len(data.variables)} variables and "
                            f"{len(data.factors)} factors; the Program {len(p.variables)} and "
                            f"{len(p.factors)}")
        for i, (v, spec) in enumerate(zip(data.variables, p.variables, strict=True)):
            if len(v) != spec.storage_dim:
                raise DataError(f"variable {i} ('{spec.key}') needs {spec.storage_dim} numbers, "
                                f"got {len(v)}")
        for i, (f, spec) in enumerate(zip(data.factors, p.factors, strict=True)):
            if len(f) != factor_data_words(p, spec.block):
                raise DataError(f"factor instance {i} needs {factor_data_words(p, spec.block)} "
                                f"numbers, got {len(f)}")
        check_fixed_data(self.project.config.scalar_cxx, p, data, NativeConfigError)
        x = np.ascontiguousarray(np.concatenate(data.variables), dtype=np.float64)
        d = np.ascontiguousarray(np.concatenate(data.factors), dtype=np.float64)
        return x, d

    def solve(self, x: np.ndarray, d: np.ndarray, progress=None
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Run on flat arrays (from :meth:`flatten`); returns (x_out, errors, info), new arrays.

        ``progress`` (optional) is called after each accepted iteration with a dict:
        ``iteration``, ``error`` (the cost after it), ``lambda`` (LM's damping for the next
        iteration) and ``relative_decrease``; without it the kernel runs with no hook."""
        x_at, d_at = _address(x, self.n_x, "x"), _address(d, self.n_data, "the factor data")
        if progress is None:
            self._run(x_at, d_at, *self._outputs)
        else:
            def hook(it: int, cost: float, mu: float, change: float) -> None:
                progress({"iteration": it, "error": cost, "lambda": mu,
                          "relative_decrease": change})

            setter = self.library.fgc_set_progress
            setter.argtypes, setter.restype = [_PROGRESS], None
            c_hook = _PROGRESS(hook)  # kept alive until the hook is cleared below
            setter(c_hook)
            try:
                self._run(x_at, d_at, *self._outputs)
            finally:
                setter(_PROGRESS())
        return self._out.copy(), self._errors.copy(), self._info.copy()

    def probe(self, x: np.ndarray, d: np.ndarray) -> tuple[float, float]:
        """(cost, rounding noise) at flat ``x`` with data ``d``, computed by the kernel: the
        cost (GTSAM's error) and how far it moves when x is rounded to the scalar type, which
        the step test allows a step that does not lower the cost."""
        out = np.empty(2)
        self.library.fgc_probe(_address(x, self.n_x, "x"),
                               _address(d, self.n_data, "the factor data"),
                               out.__array_interface__["data"][0])
        return float(out[0]), float(out[1])

    def row_layout(self) -> list[tuple[int, int, int, int]]:
        """Per block type of the Program: (first word in :meth:`rows`' output, instances,
        residual rows m, columns d + 1), the instances in Program order of that block type."""
        out, pos = [], 0
        for b, block in enumerate(self.program.blocks):
            count = sum(1 for f in self.program.factors if f.block == b)
            m, cols = block.residual_dim, sum(block.variable_dims) + 1
            out.append((pos, count, m, cols))
            pos += count * m * cols
        return out

    def rows(self, x: np.ndarray, d: np.ndarray) -> np.ndarray:
        """The whitened rows [A | b] (b = −W·r, GTSAM's convention) of every factor instance at
        flat ``x``, as the solver linearises them, laid out as :meth:`row_layout` says."""
        if not hasattr(self, "_rows_out"):
            layout = self.row_layout()
            last = layout[-1] if layout else (0, 0, 0, 0)
            self._rows_out = np.empty(last[0] + last[1] * last[2] * last[3])
        self.library.fgc_rows(_address(x, self.n_x, "x"),
                              _address(d, self.n_data, "the factor data"),
                              self._rows_out.__array_interface__["data"][0])
        return self._rows_out.copy()

    def run(self, data: ProblemData, progress=None) -> HlsResult:
        """Solve ``data`` (``progress``: as in :meth:`solve`); the result carries the host-side
        float32 verdict
        (:func:`fgc_backends.cfamily.results.judge_precision`: a float build that cannot place the
        state within its noise says "failed", reason "precision_limit", never "converged")."""
        x, errors, info = self.solve(*self.flatten(data), progress=progress)
        return judge_precision(self.program, data,
                               result_from_arrays(self.program, x, errors, *info),
                               self.project.config.scalar)


def project_key(program: Program, config: NativeConfig) -> str:
    """Content hash of everything the build depends on (Program, config, templates, fgc, the
    host CPU)."""
    h = hashlib.sha256(program.to_json().encode())
    h.update(repr(config).encode())
    h.update(host_key().encode())
    h.update(__version__.encode())
    # the Makefile appends $(FGC_NATIVE_FLAGS) from the environment: another library
    h.update(os.environ.get("FGC_NATIVE_FLAGS", "").encode())
    for template in sorted(NativeConfig.template_dir().glob("*.jinja")):
        h.update(template.read_bytes())
    # this backend's modules and the C-family layer it prints with (fgc_backends.cfamily);
    # not the streaming drivers (streaming.py, cfamily's stream.py), which call builds but print
    # nothing into them
    backends = Path(__file__).resolve().parent.parent
    # and the C++ both kernels share (cfamily's common.jinja and fgc_lm.h)
    for module in sorted([*(backends / "native").glob("*.py"),
                          *(backends / "cfamily").glob("*.py"),
                          *(backends / "cfamily" / "templates").glob("*.jinja"),
                          *(backends / "cfamily" / "include").glob("*.h")]):
        if module.name not in ("stream.py", "streaming.py"):
            h.update(module.read_bytes())
    return h.hexdigest()[:24]


def default_config(program: Program) -> NativeConfig:
    """The Program's own precision: ``double`` for float64, ``float`` for float32."""
    return NativeConfig(scalar="double" if program.solver.precision == "float64" else "float")


def load(program: Program, config: NativeConfig | None = None) -> NativeSolver:
    """Emit, build and load ``program``'s library, once per content hash: the build lives in
    ``<fgc cache>/native/<hash>`` and the loaded library is kept for the process. A cached build
    is used only if its manifest says it was built for this hash and every file (the library
    above all) is byte for byte what was built; else it is rebuilt, with one warning. A cache
    directory that cannot be written (read-only, full) gives one warning and the build is done
    in a temporary folder, removed when the process exits."""
    config = config or default_config(program)
    key = project_key(program, config)
    if key not in _LOADED:
        _LOADED[key] = NativeSolver.load(program, _project(program, config, key))
    return _LOADED[key]


def _project(program: Program, config: NativeConfig, key: str) -> NativeProject:
    """The built project of ``key``: the cached one if intact, else a new build in the cache,
    else (the cache cannot be written) one in a temporary folder."""
    name = identifier(program.name)
    root = cache_dir()
    if root is not None:
        folder = root / "native" / key
        if folder.exists():
            why = check_manifest(folder, key, required=(f"lib{name}.so",))
            if why is None:
                return NativeProject(folder, name, _files(folder), config)
            discard_folder(folder, why)
        try:
            return _build(program, config, folder, key)
        except OSError as exc:  # read-only or full: build outside the cache
            unusable(root, f"cannot write {folder.parent}: {exc.strerror or exc}")
    tmp = Path(tempfile.mkdtemp(prefix="fgc-native-"))
    atexit.register(shutil.rmtree, tmp, True)  # the loaded library stays mapped
    return _build(program, config, tmp / key, key)


def _files(folder: Path) -> tuple[Path, ...]:
    return tuple(sorted(p for p in folder.iterdir() if p.name != MANIFEST))


def _build(program: Program, config: NativeConfig, folder: Path, key: str) -> NativeProject:
    """Emit and build in a private folder, record its manifest, then move it into place
    (parallel builds of the same Program do not see each other's half-written files; an
    interrupted or failed build leaves no folder behind)."""
    staging = folder.with_name(f"{folder.name}.tmp{os.getpid()}")
    shutil.rmtree(staging, ignore_errors=True)
    try:
        project = emit(program, staging, config)
        make(project, "native")
        write_manifest(staging, key)
        try:
            os.replace(staging, folder)
        except OSError:  # another process finished first: use its build if it is intact
            if check_manifest(folder, key, required=(project.library.name,)) is not None:
                shutil.rmtree(folder, ignore_errors=True)
                os.replace(staging, folder)
    finally:  # nothing left behind: moved into place, or removed (failed, interrupted)
        shutil.rmtree(staging, ignore_errors=True)
    return NativeProject(folder, project.name, tuple(folder / p.name for p in project.files),
                         config)


def run(program: Program, data: ProblemData, config: NativeConfig | None = None,
        progress=None, timings: dict | None = None) -> HlsResult:
    """Solve ``data`` with the native build of ``program`` (default: the Program's precision).

    Like the simulator's result: ``values`` are fgc values (Pose3, …) by Program key and
    ``storage`` the raw arrays (:meth:`NativeSolver.run` returns the arrays as ``values``).
    ``progress``: called after each iteration (:meth:`NativeSolver.solve`); if it has a
    ``start()`` method (:class:`fgc.app.progress.Progress`) that is called once the library is
    loaded, just before the solve. ``timings`` (a
    dict, optional) receives ``build_seconds`` (emit + g++ on a first run, else finding the
    cached library), ``load_seconds`` (ctypes loading it; 0 when this process has it already),
    ``solve_seconds`` (the solve call alone) and ``built`` (whether g++ ran)."""
    t0 = time.perf_counter()
    key = project_key(program, config or default_config(program))
    loaded = key in _LOADED
    cached = loaded or (cache_dir() / "native" / key / f"lib{identifier(program.name)}.so"
                        ).is_file()
    solver = load(program, config)
    t1 = time.perf_counter()
    if progress is not None and callable(getattr(progress, "start", None)):
        progress.start()  # a display's clock times the solve, not the build before it
    result = solver.run(data, progress)
    t2 = time.perf_counter()
    if timings is not None:
        # load() builds (if needed) and loads in one call: a cached library's share is its
        # loading, a first run's is mostly g++
        # (finding a cached library includes its content hash over the Program's JSON)
        timings.update({"built": not cached, "build_seconds": 0.0 if cached else t1 - t0,
                        "load_seconds": 0.0 if loaded else (t1 - t0 if cached else 0.0),
                        "solve_seconds": t2 - t1})
    return keyed(result, program)
