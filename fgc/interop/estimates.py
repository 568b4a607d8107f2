"""Estimates out: solver results as the graph's own keys, as JSON, and as g2o / TUM / CSV files.

Backends key their results by the Program's variable keys (``str`` of the graph's keys);
:func:`graph_values` maps them back to the user's key objects (an int key stays an int).
A ``gtsam.Values`` under the same keys: :func:`fgc.interop.to_gtsam.values_to_gtsam` (or a
result's ``gtsam_values()``).

File formats, chosen by :func:`write_values` from the extension:

- ``.g2o``: ``VERTEX_SE2 id x y θ``, ``VERTEX_SE3:QUAT id x y z qx qy qz qw``, ``VERTEX_XY id x
  y``, ``VERTEX_TRACKXYZ id x y z``, written so that GTSAM's readers (``readG2o``, ``load2D``,
  ``load3D``) give back the graph's keys: a pose's int key is its id; a point keyed ``"l<j>"``
  (GTSAM's landmark Symbol ``L(j)``, as a dataset's landmarks are keyed) is written with id
  ``j``, which those readers key as ``L(j)`` again. Other keys get their index in the graph's
  variable order, listed first as ``# fgc key <id> <key>`` comment lines (an int-keyed point is
  written with its int, which GTSAM reads back as ``L(int)``). Variables of other types
  (velocities, biases, rotations) cannot be g2o vertices and are refused.
- ``.tum`` / ``.txt``: TUM trajectory lines ``t x y z qx qy qz qw`` for the Pose2 / Pose3
  variables (a Pose2 at z = 0, rotated about z). fgc graphs carry no times, so ``t`` is the
  pose's index in key order (0, 1, 2, …); other variables are not written.
- ``.csv``: a header ``key,type,<names>`` and one row per variable; the names are the union of
  the variables' ``storage_names`` in order of first use (Pose2 ``x y c s``, Pose3 ``R00..R22
  tx ty tz``, Point3 ``x y z``, ...), each row filling its own type's columns and leaving the
  others empty. A key is written as it is (an int as its digits).
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

import numpy as np

from fgc.errors import FgcError
from fgc.frontend.dsl import Graph, Key
from fgc.frontend.geometry import LieGroup, Point2, Point3, Pose2, Pose3

FORMATS = {".g2o": "g2o", ".tum": "tum", ".txt": "tum", ".csv": "csv"}


def graph_values(graph: Graph, result_values: dict) -> dict[Key, LieGroup]:
    """{graph key: value} from a backend result keyed by the graph's keys or their ``str``."""
    out = {}
    for k in graph.variables:
        if k in result_values:
            out[k] = result_values[k]
        elif str(k) in result_values:
            out[k] = result_values[str(k)]
        else:
            raise FgcError(f"the result has no value for variable {k!r}")
    return out


def values_from_storage(program, storage: dict) -> dict[str, LieGroup]:
    """Raw storage arrays per Program key (the native / C-simulation result) → fgc values, as
    the simulator returns them."""
    from fgc.frontend import geometry
    out = {}
    for spec in program.variables:
        name = spec.type_name
        try:
            cls = geometry.type_named(name, spec.dim)
        except geometry.UnknownTypeError as exc:
            raise FgcError(f"variable {spec.key!r}: {exc}") from exc
        out[spec.key] = cls.from_storage(storage[spec.key])
    return out


def values_json(values: dict[Key, LieGroup]) -> dict:
    """JSON-able {str(key): {"key": key (int stays int), "type": name, "value": storage}}, and
    ``"gtsam_key"`` (the int GTSAM key: the int itself, or the Symbol's key for ``"x1"``) when
    the key stands for one."""
    from fgc.interop.to_gtsam import gtsam_key

    out = {}
    for k, v in values.items():
        entry = {"key": k, "type": type(v).__name__,
                 "value": [float(x) for x in np.asarray(v.to_storage(), float)]}
        if (g := gtsam_key(k)) is not None:
            entry["gtsam_key"] = g
        out[str(k)] = entry
    return out


def _quaternion(m: np.ndarray) -> tuple[float, float, float, float]:
    """(qx, qy, qz, qw), qw ≥ 0, of a rotation matrix (largest-pivot branch, stable)."""
    tr = np.trace(m)
    if tr > 0:
        s = 2.0 * np.sqrt(1.0 + tr)
        q = [(m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, s / 4]
    else:
        i = int(np.argmax(np.diag(m)))
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * np.sqrt(1.0 + m[i, i] - m[j, j] - m[k, k])
        q = [0.0] * 4
        q[i], q[j], q[k] = s / 4, (m[j, i] + m[i, j]) / s, (m[k, i] + m[i, k]) / s
        q[3] = (m[k, j] - m[j, k]) / s
    q = np.array(q) / np.linalg.norm(q)
    return tuple(float(x) for x in (q if q[3] >= 0 else -q))


def _pose3_parts(v) -> tuple[np.ndarray, tuple]:
    s = np.asarray(v.to_storage(), float)
    return s[9:12], _quaternion(s[:9].reshape(3, 3))


def _pose2_parts(v) -> tuple[np.ndarray, tuple]:
    x, y, c, s = np.asarray(v.to_storage(), float)
    th = np.arctan2(s, c)
    return np.array([x, y, 0.0]), (0.0, 0.0, float(np.sin(th / 2)), float(np.cos(th / 2)))


def _fmt(numbers) -> str:
    return " ".join(f"{float(x):.17g}" for x in numbers)


def _landmark_index(key) -> int | None:
    """j for a point keyed ``"l<j>"`` (GTSAM's ``L(j)``, which its g2o readers give a
    ``VERTEX_XY j`` / ``VERTEX_TRACKXYZ j``)."""
    if isinstance(key, str) and key[:1] == "l" and key[1:].isdigit() and key[1:].isascii():
        return int(key[1:])
    return None


def g2o_ids(values: dict[Key, LieGroup]) -> tuple[dict, list[str]]:
    """{key: g2o vertex id} and the ``# fgc key`` comment lines (module docstring)."""
    ids, header = {}, []
    for i, (k, v) in enumerate(values.items()):
        point = isinstance(v, (Point2, Point3))
        if isinstance(k, int) and not isinstance(k, bool) and k >= 0:
            ids[k] = k
        elif point and _landmark_index(k) is not None:
            ids[k] = _landmark_index(k)
        else:
            ids[k] = i
            header.append(f"# fgc key {i} {k}")
    for kind in (False, True):  # poses and points are separate key spaces in GTSAM's readers
        taken: dict = {}
        for k, v in values.items():
            if isinstance(v, (Point2, Point3)) == kind:
                if ids[k] in taken:
                    raise FgcError(f"g2o export: variables {taken[ids[k]]!r} and {k!r} would "
                                   f"both be vertex {ids[k]}; use .csv")
                taken[ids[k]] = k
    return ids, header


def g2o_text(values: dict[Key, LieGroup]) -> str:
    ids, header = g2o_ids(values)
    lines = []
    for k, v in values.items():
        if isinstance(v, Pose2):
            x, y, c, s = np.asarray(v.to_storage(), float)
            lines.append(f"VERTEX_SE2 {ids[k]} {_fmt([x, y, np.arctan2(s, c)])}")
        elif isinstance(v, Pose3):
            t, q = _pose3_parts(v)
            lines.append(f"VERTEX_SE3:QUAT {ids[k]} {_fmt([*t, *q])}")
        elif isinstance(v, Point2):
            lines.append(f"VERTEX_XY {ids[k]} {_fmt(v.to_storage())}")
        elif isinstance(v, Point3):
            lines.append(f"VERTEX_TRACKXYZ {ids[k]} {_fmt(v.to_storage())}")
        else:
            raise FgcError(f"g2o export: variable {k!r} is a {type(v).__name__}, which g2o has "
                           "no vertex for; use .csv")
    return "\n".join(header + lines) + "\n"


def tum_text(values: dict[Key, LieGroup]) -> str:
    lines = []
    poses = [(k, v) for k, v in values.items() if isinstance(v, (Pose2, Pose3))]
    if not poses:
        raise FgcError("TUM export: the graph has no Pose2/Pose3 variables; use .csv")
    for i, (_, v) in enumerate(poses):
        t, q = _pose3_parts(v) if isinstance(v, Pose3) else _pose2_parts(v)
        lines.append(f"{i} {_fmt([*t, *q])}")
    return "\n".join(lines) + "\n"


def csv_text(values: dict[Key, LieGroup]) -> str:
    names = list(dict.fromkeys(n for v in values.values() for n in type(v).storage_names))
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["key", "type", *names])
    for k, v in values.items():
        cells = dict(zip(type(v).storage_names, v.to_storage(), strict=True))
        w.writerow([k, type(v).__name__, *(f"{float(cells[n]):.17g}" if n in cells else ""
                                           for n in names)])
    return buf.getvalue()


def write_values(path: str | Path, values: dict[Key, LieGroup]) -> str:
    """Write ``values`` to ``path`` in the format of its extension; returns the format name."""
    path = Path(path)
    fmt = FORMATS.get(path.suffix.lower())
    if fmt is None:
        raise FgcError(f"{path}: unknown values format {path.suffix!r}; use "
                       f"{', '.join(FORMATS)}")
    text = {"g2o": g2o_text, "tum": tum_text, "csv": csv_text}[fmt](values)
    try:
        path.write_text(text)
    except OSError as exc:
        raise FgcError(f"{path}: cannot write ({exc.strerror})") from None
    return fmt
