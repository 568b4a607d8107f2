"""Readers for pose-graph files: g2o (``VERTEX_SE2``/``EDGE_SE2``, ``VERTEX_SE3:QUAT``/
``EDGE_SE3:QUAT``) and TORO (``VERTEX2``/``EDGE2``), into an fgc Graph of between factors.

Conventions follow GTSAM's ``readG2o``/``load2D``: information matrices are given as their upper
triangle; g2o's SE(3) information is ordered [translation, rotation] and is permuted into GTSAM's
tangent order [rotation, translation]; TORO's EDGE2 lists I11 I12 I22 I33 I13 I23.
Errors name the file and line.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from fgc.dsl import Graph
from fgc.errors import DataError, FgcError
from fgc.factors import BetweenFactor
from fgc.geometry import Pose2, Pose3, Rot3
from fgc.noise import NoiseModel, sqrt_information

_IGNORED = {"EQUIV", "FIX", "PARAMS_SE2OFFSET", "PARAMS_SE3OFFSET"}
_WIDTH = {"VERTEX2": 5, "VERTEX_SE2": 5, "EDGE2": 12, "EDGE_SE2": 12,
          "VERTEX_SE3:QUAT": 9, "EDGE_SE3:QUAT": 31}


def _info_noise(upper: np.ndarray, n: int, where: str, perm=None) -> NoiseModel:
    info = np.zeros((n, n))
    info[np.triu_indices(n)] = upper
    info = info + np.triu(info, 1).T
    if perm is not None:
        info = info[np.ix_(perm, perm)]
    try:
        r = np.linalg.cholesky(info).T
    except np.linalg.LinAlgError:
        raise DataError(f"{where}: information matrix is not positive definite") from None
    return sqrt_information(r)


def _quat_to_rot(qx, qy, qz, qw, where: str) -> Rot3:
    q = np.array([qw, qx, qy, qz])
    n = np.linalg.norm(q)
    if not np.isfinite(n) or n < 1e-12:
        raise DataError(f"{where}: quaternion has zero or non-finite norm")
    w, x, y, z = q / n
    return Rot3(np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]))


def _parse_line(tag: str, fields: list[str], where: str) -> tuple[list[int], np.ndarray]:
    need = _WIDTH[tag]
    if len(fields) < need:
        raise DataError(f"{where}: {tag} needs {need - 1} values, got {len(fields) - 1}")
    n_ids = 1 if tag.startswith("VERTEX") else 2
    try:
        ids = [int(f) for f in fields[1:1 + n_ids]]
        nums = np.array([float(f) for f in fields[1 + n_ids:need]])
    except ValueError as exc:
        raise DataError(f"{where}: malformed {tag} line ({exc})") from None
    if any(i < 0 for i in ids):
        raise DataError(f"{where}: negative vertex id {ids}")
    if not np.all(np.isfinite(nums)):
        raise DataError(f"{where}: non-finite number in {tag} line")
    return ids, nums


def _vertex(tag: str, nums: np.ndarray, where: str):
    if tag in ("VERTEX2", "VERTEX_SE2"):
        return Pose2(*nums[:3])
    return Pose3(_quat_to_rot(*nums[3:7], where), nums[:3])


def _edge(tag: str, nums: np.ndarray, where: str):
    if tag == "EDGE_SE2":
        return Pose2(*nums[:3]), _info_noise(nums[3:9], 3, where)
    if tag == "EDGE2":  # TORO: I11 I12 I22 I33 I13 I23
        i11, i12, i22, i33, i13, i23 = nums[3:9]
        upper = np.array([i11, i12, i13, i22, i23, i33])
        return Pose2(*nums[:3]), _info_noise(upper, 3, where)
    pose = Pose3(_quat_to_rot(*nums[3:7], where), nums[:3])
    return pose, _info_noise(nums[7:28], 6, where, perm=[3, 4, 5, 0, 1, 2])


def read_pose_graph(path: str | Path, key_prefix: str = "x") -> Graph:
    """Read a g2o or TORO file into a Graph (variables ``x<id>``, BetweenFactors).

    Unknown tags and ``EQUIV``/``FIX`` lines are skipped; a malformed line raises DataError
    naming the file and line number; edges to undeclared vertices too.
    """
    path = Path(path)
    graph = Graph()
    edges = []
    for lineno, line in enumerate(_read_lines(path), start=1):
        fields = line.split()
        if not fields or fields[0].startswith("#") or fields[0] in _IGNORED:
            continue
        tag, where = fields[0], f"{path.name}:{lineno}"
        if tag not in _WIDTH:
            continue
        ids, nums = _parse_line(tag, fields, where)
        if tag.startswith("VERTEX"):
            key = f"{key_prefix}{ids[0]}"
            if key in graph.variables:
                raise DataError(f"{where}: vertex {ids[0]} declared twice")
            graph.add_variable(key, _vertex(tag, nums, where))
        else:
            edges.append((ids, *_edge(tag, nums, where), where))
    for (i, j), measured, noise, where in edges:
        _add_edge(graph, f"{key_prefix}{i}", f"{key_prefix}{j}", measured, noise, where)
    if not graph.variables:
        raise DataError(f"{path}: no vertices found (is this a g2o/TORO file?)")
    return graph


def _read_lines(path: Path) -> list[str]:
    """The file's lines; DataError if it is missing, unreadable or not text."""
    if not path.is_file():
        raise DataError(f"{path}: no such file")
    try:
        return path.read_text(encoding="utf-8").splitlines()
    except OSError as exc:
        raise DataError(f"{path}: cannot read ({exc.strerror})") from None
    except UnicodeDecodeError as exc:
        line = path.read_bytes()[:exc.start].count(b"\n") + 1
        raise DataError(f"{path.name}:{line}: not a text file (byte {exc.start} is not UTF-8)"
                        ) from None


def _add_edge(graph: Graph, a: str, b: str, measured, noise: NoiseModel, where: str) -> None:
    """A between factor a → b; DataError naming the line for a self-loop, an undeclared vertex
    or a vertex of the other pose type."""
    if a == b:
        raise DataError(f"{where}: edge from vertex {a!r} to itself")
    for key in (a, b):
        if key not in graph.variables:
            raise DataError(f"{where}: edge refers to undeclared vertex {key!r}")
    try:
        graph.add(BetweenFactor(a, b, measured, noise))
    except FgcError as exc:
        raise DataError(f"{where}: {exc}") from None
