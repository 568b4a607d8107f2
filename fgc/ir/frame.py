"""The local frame of a float32 solve: positions relative to a reference the compiler chose.

float32 holds about 7 significant digits: a Pose2 chain at (1e4, 1e4) m stores its positions to
~1e-3 m, a tenth of a 1 cm sigma, and its residuals (differences of such numbers) and steps lose
as much again; far enough from the origin a float32 solve stops centimetres, then metres, from
the optimum. Real systems solve in a local frame, and so does fgc: a float32 Program (``Program
.frame``) records an ``origin`` (world coordinates) and the data file holds every position
relative to it; every reader of results (the simulator's, the HLS C simulation's, the native
solver's) adds it back, so results, ``fgc`` values and exports are in world coordinates.

**What moves.** The positions of ``Pose2`` / ``Pose3`` / ``Point2`` / ``Point3`` variables (a
pose's translation, a point's coordinates: :data:`POSITIONS`) and, per factor type, those of its
measurements that are absolute positions (a prior's value, a GPS fix, a landmark's position).
A translation d of every position leaves a factor's residual unchanged exactly when the factor
is translation-invariant (between, range, bearing, IMU: shift no measurement) or covariant
(prior, GPS: shift the measurement with the variables). fgc does not trust names for this, not
even its own: :func:`choose` evaluates every factor type's residual (the derived one, which every
backend executes) at up to three of its instances, each at three translations (the frame's own
and two seeded random ones), with each subset of its position-typed measurements shifted, and
keeps the first subset (fewest shifted first) under which the residual is unchanged to 1e-8
relative. A factor type for which no subset works — a custom factor that reads an absolute
position from a ``float`` or ``fgc.Matrix`` measurement, or treats a ``Point3`` as a velocity
beside a pose — is not shifted, and then nothing is: a translation is all or nothing, so the
problem is solved in world coordinates and the float32 resolution verdict
(:mod:`fgc.ir.conditioning`) judges it as before.

**The origin.** The mean of the variables' initial positions, rounded per axis to a multiple of
g, the smallest power of two ≥ the positions' extent (largest max − min over the axes, at least
1 m); only when that mean is at least ``FAR`` (4) g from the origin on some axis: a problem
within a few of its own extents of the origin has no frame (its Program and data are what they
were; every shipped example), one farther away gets local positions within 1.5 g of 0. The
origin is exact in float64, so ``x − origin`` is exact and restoring rounds only to the world
value's own float64 resolution.

The origin is part of the data layout, so a frame Program's structure fingerprint digests it
(:func:`fgc.ir.program.structure_summary`): data written for one frame is refused, with the
usual fingerprint message, by a Program of another frame or none — in Python, in the emitted
simulator and in the C++ testbench alike. The files the generated programs write (the
simulator's ``result.json``, the testbench's ``result.txt`` and ``reference.txt``) hold local
coordinates; fgc's readers (``fgc_backends.sim.read_result``,
``fgc_backends.cfamily.results.read_result``) return world ones.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

# type name → (storage entries that are a position, the world axis of each)
POSITIONS: dict[str, tuple[tuple[int, ...], tuple[int, ...]]] = {
    "Pose2": ((0, 1), (0, 1)),
    "Pose3": ((9, 10, 11), (0, 1, 2)),
    "Point2": ((0, 1), (0, 1)),
    "Point3": ((0, 1, 2), (0, 1, 2)),
}
INVARIANCE_TOL = 1e-8  # residual change allowed, relative to the positions' and shift's size
INSTANCES_CHECKED = 3  # per factor type: the first, middle and last instance
RANDOM_SHIFTS = 2  # per instance, beside the frame's own shift
FAR = 4.0  # a frame only for positions whose mean is this many grid steps from the origin
MAX_CANDIDATES = 4  # position-typed measurements per factor type tried in every subset


@dataclass(frozen=True)
class Frame:
    """``origin``: the local frame's origin in world coordinates (x, y, z; 2-D types use x, y);
    ``shifted``: the (factor type, measurement name) pairs that are absolute positions, moved
    with the variables."""

    origin: tuple[float, float, float]
    shifted: tuple[tuple[str, str], ...] = ()

    def to_dict(self) -> dict:
        return {"origin": list(self.origin), "shifted": [list(p) for p in self.shifted]}

    @classmethod
    def from_dict(cls, d: dict) -> Frame:
        return cls(tuple(float(x) for x in d["origin"]),
                   tuple((str(a), str(b)) for a, b in d["shifted"]))

    def move(self, type_name: str, storage, sign: float) -> np.ndarray:
        """``storage`` of a ``type_name`` value with its position moved by ``sign`` × origin
        (−1: world → local, +1: local → world); other types unchanged (a copy)."""
        out = np.array(storage, dtype=np.float64).reshape(-1)
        entry = POSITIONS.get(type_name)
        if entry is not None:
            idx, axes = entry
            out[list(idx)] += sign * np.asarray(self.origin)[list(axes)]
        return out

    def local_measured(self, factor) -> dict:
        """A graph factor's measurements (name → storage) with its absolute positions local."""
        types = {a.name: a.type for a in factor.type.measurements}
        return {name: (self.move(types[name].__name__, value, -1.0)
                       if (factor.type.name, name) in self.shifted else value)
                for name, value in factor.measured.items()}


def to_local(program, storage: dict) -> dict:
    """``{variable key: storage}`` in world coordinates → the ``program``'s local frame (the
    same dict when the Program has no frame)."""
    return _moved(program, storage, -1.0)


def to_world(program, storage: dict) -> dict:
    """``{variable key: storage}`` in ``program``'s local frame → world coordinates."""
    return _moved(program, storage, 1.0)


def _moved(program, storage: dict, sign: float) -> dict:
    frame = getattr(program, "frame", None)
    if frame is None:
        return storage
    types = {v.key: v.type_name for v in program.variables}
    return {k: frame.move(types[k], v, sign) if k in types else v for k, v in storage.items()}


def choose(graph) -> Frame | None:
    """The local frame of ``graph`` (module doc): None when its positions are already within
    their extent of the origin, or when some factor type is neither translation-invariant nor
    covariant under any choice of shifted measurements."""
    origin = _origin(graph)
    if origin is None:
        return None
    shifted: list[tuple[str, str]] = []
    for ftype, factors in _by_type(graph).items():
        rule = _shift_rule(graph, ftype, factors, origin)
        if rule is None:
            return None
        shifted += [(ftype.name, name) for name in rule]
    return Frame(origin, tuple(sorted(shifted)))


def _positions(graph) -> np.ndarray:
    rows = []
    for var in graph.variables.values():
        entry = POSITIONS.get(var.type.__name__)
        if entry is None:
            continue
        row = np.full(3, np.nan)
        row[list(entry[1])] = var.initial.storage_array()[list(entry[0])]
        rows.append(row)
    return np.array(rows).reshape(-1, 3)


def _origin(graph) -> tuple[float, float, float] | None:
    pos = _positions(graph)
    if not len(pos):
        return None
    pos = np.where(np.isnan(pos), 0.0, pos)  # a 2-D position has z = 0
    extent = max(float(np.max(pos.max(0) - pos.min(0))), 1.0)
    grid = 2.0 ** int(np.ceil(np.log2(extent)))
    mean = pos.mean(0)
    if np.max(np.abs(mean)) < FAR * grid:
        return None  # within a few extents of the origin: world coordinates are as good
    return tuple(float(grid * np.round(m / grid)) + 0.0 for m in mean)  # no −0.0


def _by_type(graph) -> dict:
    out: dict = {}
    for f in graph.factors:
        out.setdefault(f.type, []).append(f)
    return out


def _shift_rule(graph, ftype, factors, origin) -> tuple[str, ...] | None:
    """The measurements of ``ftype`` to shift with the variables (a tuple of names), or None if
    no subset of its position-typed measurements leaves its residual unchanged."""
    candidates = [a.name for a in ftype.measurements if a.type.__name__ in POSITIONS]
    moved_vars = [a.type.__name__ in POSITIONS for a in ftype.variables]
    if not candidates and not any(moved_vars):
        return ()  # nothing of it moves
    if len(candidates) > MAX_CANDIDATES:
        return None
    from fgc.compiler.derive import derive

    derived = derive(ftype)
    picks = [factors[0], factors[len(factors) // 2], factors[-1]][:INSTANCES_CHECKED]
    rng = np.random.default_rng(0)
    base = np.asarray(origin)
    scale = max(1.0, float(np.max(np.abs(base))))
    shifts = [-base] + [rng.uniform(-scale, scale, 3) for _ in range(RANDOM_SHIFTS)]
    for size in range(len(candidates) + 1):
        for subset in itertools.combinations(candidates, size):
            if all(_invariant(graph, derived, ftype, f, set(subset), d)
                   for f in picks for d in shifts):
                return subset
    return None


def _invariant(graph, derived, ftype, factor, subset: set, d: np.ndarray) -> bool:
    frame = Frame(tuple(float(x) for x in -d))  # move by +d: origin −d, sign −1
    values = [graph.variables[k].initial.storage_array() for k in factor.keys]
    types = [a.type.__name__ for a in ftype.variables]
    mtypes = {a.name: a.type.__name__ for a in ftype.measurements}
    moved = [frame.move(t, v, -1.0) for t, v in zip(types, values, strict=True)]
    measured = {name: frame.move(mtypes[name], value, -1.0) if name in subset else value
                for name, value in factor.measured.items()}
    with np.errstate(all="ignore"):
        before = derived.evaluate_residual(values, factor.measured)
        after = derived.evaluate_residual(moved, measured)
    if not (np.all(np.isfinite(before)) and np.all(np.isfinite(after))):
        return False
    size = max([1.0, float(np.max(np.abs(d)))]
               + [float(np.max(np.abs(v))) for v in values if np.size(v)])
    return bool(np.max(np.abs(after - before), initial=0.0)
                <= INVARIANCE_TOL * size * (1.0 + float(np.max(np.abs(before), initial=0.0))))
