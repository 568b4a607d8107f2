"""Figures for reports: trajectories, latency breakdowns, design-space Pareto fronts, storage steps.

matplotlib is an optional extra (``pip install "fgc[plots]"``), imported only when a figure is
drawn; without it every function raises :class:`FgcError` with that install hint (the one way
fgc handles a missing matplotlib: ``fgc simulate --plot``, ``fgc report --html`` and
``fgc sweep`` report it as exit 2). Each function returns its matplotlib ``Figure`` (a notebook
displays it) and, given ``path=``, also saves it by the suffix: ``.png``, ``.svg`` or ``.pdf``.
Figures are built without pyplot (no global state is touched). Saved output is deterministic for
a given matplotlib version: SVG ids come from a fixed ``svg.hashsalt``, and no date or
software-version metadata is written.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import numpy as np

from fgc.errors import FgcError

_METADATA = {".png": {"Software": None}, ".svg": {"Date": None, "Creator": None},
             ".pdf": {"CreationDate": None, "ModDate": None, "Producer": None, "Creator": None}}
_RC = {"svg.hashsalt": "fgc", "font.size": 9.0, "axes.grid": True, "grid.alpha": 0.3,
       "figure.dpi": 100.0, "savefig.dpi": 150.0}


def _matplotlib():
    try:
        import matplotlib
    except ImportError:
        raise FgcError('fgc.app.plots needs matplotlib: pip install "fgc[plots]"') from None
    return matplotlib


def _styled(func: Callable) -> Callable:
    """Run a plotting function with matplotlib imported and fgc's rcParams in force (rcParams
    are read when artists are created and when the figure is saved, so the whole body)."""

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        with _matplotlib().rc_context(_RC):
            return func(*args, **kwargs)

    return wrapper


def _figure(width: float = 6.4, height: float = 4.8):
    """A new Figure (no pyplot: a notebook shows it through its ``_repr_png_``), and its single
    Axes. Saving uses the Agg canvas whatever the session's backend."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    return fig, fig.add_subplot()


def _check_path(path: str | Path | None) -> Path | None:
    """The output path, checked before anything is drawn (None: do not save)."""
    if path is None:
        return None
    path = Path(path)
    if path.suffix.lower() not in _METADATA:
        raise FgcError(f"{path}: unsupported figure format {path.suffix!r}; use one of "
                       f"{sorted(_METADATA)}")
    return path


def _finish(fig, path: str | Path | None):
    """Save ``fig`` at ``path`` if given (Agg canvas, fixed metadata); return ``fig``."""
    path = _check_path(path)
    if path is not None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        FigureCanvasAgg(fig)
        fig.savefig(path, metadata=_METADATA[path.suffix.lower()])
    return fig


# --------------------------------------------------------------------------------------------
# trajectory
# --------------------------------------------------------------------------------------------


def _positions(values) -> np.ndarray:
    """(N, 3) positions of an fgc values dict / trajectory (fgc.app.metrics) or a gtsam.Values."""
    from fgc.app.metrics import Trajectory, as_trajectory

    if isinstance(values, (Mapping, Trajectory, Sequence)):
        return as_trajectory(values).positions
    if type(values).__name__ == "Values":  # gtsam.Values: read its poses without their types
        import gtsam

        p3 = gtsam.utilities.extractPose3(values)
        if len(p3):
            return np.asarray(p3)[:, 9:12]
        p2 = np.asarray(gtsam.utilities.extractPose2(values))
        return np.column_stack([p2[:, :2], np.zeros(len(p2))])
    raise FgcError(f"cannot read positions from a {type(values).__name__}")


# the x-y extents of a trajectory plot are drawn to scale (equal aspect) when neither is more
# than this many times the other; a long, thin trajectory gets free axes (said in the title)
EQUAL_ASPECT_UP_TO = 4.0


def _points(points) -> np.ndarray | None:
    """(N, 3) positions of landmarks: an fgc values dict (its Point2 / Point3 entries), or an
    (N, 2|3) array; None when there are none."""
    if points is None:
        return None
    if isinstance(points, Mapping):
        from fgc.frontend.geometry import Point2, Point3

        rows = [np.append(np.asarray(v.to_storage(), float), [0.0] * (v.dim == 2))
                for v in points.values() if isinstance(v, (Point2, Point3))]
        return np.array(rows) if rows else None
    arr = np.asarray(points, float).reshape(len(points), -1)
    if arr.size == 0:
        return None
    return np.column_stack([arr[:, :2], arr[:, 2] if arr.shape[1] > 2 else np.zeros(len(arr))])


@_styled
def plot_trajectory(fgc_values, gtsam_values=None, gps=None,
                    title: str = "Trajectory (top view)", path: str | Path | None = None,
                    landmarks=None, gtsam_landmarks=None):
    """Top view (x–y) of fgc's estimate, optionally GTSAM's, GPS fixes and landmarks.

    In: ``fgc_values`` an fgc values dict (``Solution.values``: its Pose3, else Pose2, entries in
    order) or anything :func:`fgc.app.metrics.as_trajectory` accepts; ``gtsam_values`` the same or a
    ``gtsam.Values``; ``gps`` an (N, 2|3) array of positions; ``landmarks`` /
    ``gtsam_landmarks`` fgc's and GTSAM's landmark (beacon) estimates: a values dict (its Point2 /
    Point3 entries) or an (N, 2|3) array; ``path`` to save. The axes are to scale when the x and
    y extents are within :data:`EQUAL_ASPECT_UP_TO` of each other, else free (the title says
    "axes not to scale"). Out: the Figure.
    """
    _check_path(path)
    fig, ax = _figure()
    est = _positions(fgc_values)
    ax.plot(est[:, 0], est[:, 1], "o-", ms=3, lw=1.5, color="tab:blue", label="fgc")
    drawn = [est]
    if gtsam_values is not None:
        ref = _positions(gtsam_values)
        ax.plot(ref[:, 0], ref[:, 1], "s--", ms=4, lw=1.0, mfc="none", color="tab:orange",
                label="GTSAM")
        drawn.append(ref)
    if gps is not None:
        g = np.asarray(gps, float).reshape(len(gps), -1)
        ax.scatter(g[:, 0], g[:, 1], marker="x", s=25, color="tab:green", label="GPS", zorder=3)
        drawn.append(np.column_stack([g[:, :2], np.zeros(len(g))]))
    for pts, style in ((_points(landmarks), dict(marker="*", s=60, color="tab:red",
                                                  label="landmarks (fgc)", zorder=4)),
                       (_points(gtsam_landmarks), dict(marker="D", s=40, facecolors="none",
                                                       edgecolors="tab:purple", zorder=4,
                                                       label="landmarks (GTSAM)"))):
        if pts is not None:
            ax.scatter(pts[:, 0], pts[:, 1], **style)
            drawn.append(pts)
    ax.plot(est[0, 0], est[0, 1], "k^", ms=8, label="start")
    allpts = np.vstack(drawn)
    span = np.ptp(allpts[:, :2], axis=0)
    to_scale = (min(span) > 0 and max(span) / min(span) <= EQUAL_ASPECT_UP_TO) or max(span) == 0
    ax.set(xlabel="x [m]", ylabel="y [m]", aspect="equal" if to_scale else "auto",
           title=title if to_scale else f"{title} (axes not to scale)")
    ax.legend(loc="best")
    return _finish(fig, path)


def _attitude(values) -> tuple[list, np.ndarray]:
    """(keys, (N, 3) roll, pitch, yaw in degrees, unwrapped along the keys) of the Rot3 entries
    of a values dict, or (keys, (N, 1) angle) of its Rot2 entries."""
    from fgc.frontend.geometry import Rot2, Rot3

    rot3 = [(k, np.asarray(v.R, float)) for k, v in values.items() if isinstance(v, Rot3)]
    if rot3:
        r = np.array([m for _, m in rot3])
        angles = np.column_stack([np.arctan2(r[:, 2, 1], r[:, 2, 2]),
                                  -np.arcsin(np.clip(r[:, 2, 0], -1.0, 1.0)),
                                  np.arctan2(r[:, 1, 0], r[:, 0, 0])])
        return [k for k, _ in rot3], np.degrees(np.unwrap(angles, axis=0))
    rot2 = [(k, v) for k, v in values.items() if isinstance(v, Rot2)]
    if not rot2:
        raise FgcError("plot_attitude: the values hold no Rot3 or Rot2 entries")
    theta = np.unwrap([np.arctan2(float(v.s), float(v.c)) for _, v in rot2])
    return [k for k, _ in rot2], np.degrees(theta)[:, None]


@_styled
def plot_attitude(fgc_values: Mapping, gtsam_values: Mapping | None = None,
                  title: str = "Attitude over the variables", path: str | Path | None = None):
    """Attitude against the rotation variables' order (a rotation-only problem has no
    trajectory to draw): roll, pitch, yaw (ZYX, degrees, unwrapped) of the Rot3 entries, or the
    angle of the Rot2 entries, fgc solid and GTSAM dashed. In: fgc values dicts; ``path`` to
    save. Out: the Figure."""
    _check_path(path)
    fig, ax = _figure(7.2, 4.2)
    keys, ours = _attitude(fgc_values)
    names = ("roll", "pitch", "yaw") if ours.shape[1] == 3 else ("angle",)
    colors = ("tab:blue", "tab:orange", "tab:green")
    index = np.arange(len(keys))
    for j, name in enumerate(names):
        ax.plot(index, ours[:, j], "o-", ms=3, lw=1.5, color=colors[j], label=f"{name} (fgc)")
    if gtsam_values is not None:
        _, ref = _attitude(gtsam_values)
        for j, name in enumerate(names):
            ax.plot(index, ref[:, j], "--", lw=1.0, color=colors[j], label=f"{name} (GTSAM)")
    step = max(1, len(keys) // 12)
    ax.set_xticks(index[::step], [str(k) for k in keys[::step]])
    ax.set(xlabel="variable (key order)", ylabel="angle [deg]", title=title)
    ax.legend(loc="best", ncols=2 if gtsam_values is not None else 1)
    return _finish(fig, path)


# --------------------------------------------------------------------------------------------
# latency, Pareto front, storage
# --------------------------------------------------------------------------------------------


@_styled
def plot_latency_breakdown(cycles_by_unit: Mapping[str, float],
                           title: str = "Latency breakdown (model estimate)",
                           path: str | Path | None = None):
    """Horizontal bars of cycles per hardware unit, in the given order, each labelled with its
    cycles and share of the total. In: {unit name: cycles}; ``path`` to save. Out: the Figure."""
    _check_path(path)
    if not cycles_by_unit:
        raise FgcError("plot_latency_breakdown: no units given")
    names = [str(k) for k in cycles_by_unit]
    cycles = np.array([float(v) for v in cycles_by_unit.values()])
    if np.any(cycles < 0) or not np.all(np.isfinite(cycles)):
        raise FgcError(f"plot_latency_breakdown: cycles must be finite and ≥ 0, got {cycles}")
    total = cycles.sum()
    fig, ax = _figure(6.4, 0.9 + 0.35 * len(names))
    y = np.arange(len(names))
    ax.barh(y, cycles, color="tab:blue")
    for yi, c in zip(y, cycles, strict=True):
        share = 100.0 * c / total if total > 0 else 0.0
        ax.annotate(f" {c:,.0f} ({share:.1f}%)", (c, yi), va="center", fontsize=8)
    ax.set_yticks(y, names)
    ax.invert_yaxis()
    ax.set_xlim(0, 1.35 * cycles.max() if cycles.max() > 0 else 1.0)  # room for the labels
    ax.set(xlabel="cycles", title=f"{title} — total {total:,.0f} cycles")
    ax.grid(axis="y", visible=False)
    return _finish(fig, path)


def pareto_front(points: Sequence[Mapping], x: str = "dsp", y: str = "latency_ms") -> list[int]:
    """Indices of the points not dominated when minimising both ``x`` and ``y``, by x then y."""
    xy = [(float(p[x]), float(p[y])) for p in points]
    front = [i for i, (a, b) in enumerate(xy)
             if not any(c <= a and d <= b and (c < a or d < b) for c, d in xy)]
    return sorted(front, key=lambda i: xy[i])


@_styled
def plot_pareto(points: Sequence[Mapping], x: str = "dsp", y: str = "latency_ms",
                title: str = "Design space", path: str | Path | None = None):
    """Scatter of design points with the Pareto front (min x, min y) marked and joined.

    In: points as dicts with keys ``x``, ``y`` and optionally ``label``; ``path`` to save.
    Out: the Figure.
    """
    _check_path(path)
    if not points:
        raise FgcError("plot_pareto: no points given")
    missing = [i for i, p in enumerate(points) if x not in p or y not in p]
    if missing:
        raise FgcError(f"plot_pareto: points {missing} lack {x!r} or {y!r}")
    xs, ys = (np.array([float(p[k]) for p in points]) for k in (x, y))
    front = pareto_front(points, x, y)
    fig, ax = _figure()
    ax.scatter(xs, ys, s=25, color="0.6", label="design points")
    ax.step(xs[front], ys[front], where="post", color="tab:red", lw=1.2)
    ax.scatter(xs[front], ys[front], s=45, color="tab:red", zorder=3, label="Pareto front")
    for i, p in enumerate(points):
        if "label" in p:
            ax.annotate(str(p["label"]), (xs[i], ys[i]), xytext=(4, 4),
                        textcoords="offset points", fontsize=7)
    ax.set(xlabel=x, ylabel=y, title=title)
    ax.legend(loc="best")
    return _finish(fig, path)


@_styled
def plot_accuracy(solutions: Sequence[Mapping], title: str = "Accuracy vs GTSAM",
                  path: str | Path | None = None):
    """Largest rotation (rad) and translation (m) difference from a reference solution, one
    column per solution, on a log axis of the errors themselves (an exact match, 0, is drawn
    at the floor 1e-18 and labelled "0").

    In: dicts with ``label``, ``rotation`` and ``translation``; ``path`` to save. Out: the
    Figure."""
    _check_path(path)
    if not solutions:
        raise FgcError("plot_accuracy: no solutions given")
    floor = 1e-18
    fig, ax = _figure(max(4.8, 1.2 + 1.1 * len(solutions)), 4.2)
    xpos = np.arange(len(solutions))
    for key, unit, marker, color, dx in (("rotation", "rad", "o", "tab:blue", -0.08),
                                         ("translation", "m", "s", "tab:orange", 0.08)):
        vals = np.array([float(s[key]) for s in solutions])
        if np.any(vals < 0) or not np.all(np.isfinite(vals)):
            raise FgcError(f"plot_accuracy: {key} errors must be finite and ≥ 0, got {vals}")
        shown = np.maximum(vals, floor)
        ax.scatter(xpos + dx, shown, marker=marker, s=40, color=color,
                   label=f"max {key} error [{unit}]", zorder=3)
        for xi, v, sv in zip(xpos + dx, vals, shown, strict=True):
            ax.annotate(f"{v:.1e}" if v > 0 else "0", (xi, sv), xytext=(5, -3),
                        textcoords="offset points", fontsize=7)
    ax.set_yscale("log")
    ax.set_xticks(xpos, [str(s["label"]) for s in solutions], rotation=15, ha="right")
    ax.set_xlim(-0.6, len(solutions) - 0.2)
    ax.set(ylabel="error vs reference (rad / m, log scale)", title=title)
    ax.grid(axis="x", visible=False)
    ax.legend(loc="best")
    return _finish(fig, path)


def _steps(step_words: Sequence) -> list[tuple[str, float]]:
    out = []
    for i, s in enumerate(step_words, start=1):
        if hasattr(s, "words"):  # fgc.compiler.storage.StorageStep
            out.append((f"{i}. {getattr(s, 'name', 'step')}", float(s.words)))
        elif isinstance(s, tuple):
            out.append((str(s[0]), float(s[1])))
        else:
            out.append((f"step {i}", float(s)))
    return out


@_styled
def plot_storage_steps(dense_words: float, step_words: Sequence, title: str = "Storage",
                       path: str | Path | None = None):
    """Bars of words stored: dense, then after each step, on a linear axis (bar heights compare
    as the word counts do), each labelled with its words and the reduction dense / words.

    In: ``step_words`` as numbers, (label, words) pairs or ``fgc.compiler.storage.StorageStep``s;
    ``path`` to save. Out: the Figure."""
    _check_path(path)
    bars = [("dense", float(dense_words)), *_steps(step_words)]
    words = np.array([w for _, w in bars])
    if np.any(words <= 0) or not np.all(np.isfinite(words)):
        raise FgcError(f"plot_storage_steps: word counts must be positive, got {words}")
    fig, ax = _figure(6.4, 4.0)
    xpos = np.arange(len(bars))
    colors = ["0.55"] + ["tab:blue"] * (len(bars) - 1)
    ax.bar(xpos, words, color=colors)
    for i, (xi, w) in enumerate(zip(xpos, words, strict=True)):
        ratio = "dense" if i == 0 else f"{words[0] / w:.1f}× smaller"
        ax.annotate(f"{w:,.0f}\n{ratio}", (xi, w), ha="center", va="bottom",
                    fontsize=8, xytext=(0, 2), textcoords="offset points")
    ax.set_ylim(0, words.max() * 1.2)
    ax.set_xticks(xpos, [name for name, _ in bars], rotation=15, ha="right")
    ax.set(ylabel="words (linear scale)", title=title)
    ax.grid(axis="x", visible=False)
    return _finish(fig, path)
