"""Readers for every pose-graph / SLAM file GTSAM's ``load2D`` / ``load3D`` read, as fgc Graphs.

fgc checks each line it knows itself (malformed numbers, bad ids, self-loops, duplicate or
undeclared vertices, a vertex of the other pose type: a :class:`DataError` naming file and line),
then lets GTSAM's reader build the graph (``gtsam.load2D`` for 2D files, ``gtsam.load3D`` for
files with any 3D tag) and converts it with :func:`fgc.interop.from_gtsam.from_gtsam`, so tags,
noise
layouts (TORO vs g2o, GTSAM's auto-detection) and conventions are GTSAM's own.

Nothing is dropped silently: a line whose tag neither GTSAM nor fgc reads is refused (the error
names the line and the tag), and so is a kind of edge line of which GTSAM's reader returned fewer
factors than the file holds (e.g. TORO ``EDGE3`` lines without an information matrix, which
GTSAM stops reading after the first). Only ``EQUIV``, ``FIX`` and the offset ``PARAMS_*`` lines
are passed over, as GTSAM does (fgc fixes the gauge with a prior instead).

Initial values: vertices from the file; variables without a vertex line get odometry chaining
along the between factors (breadth-first from the lowest key, roots at the identity) and, for a
landmark, the first bearing-range measurement from a placed pose; ``init="chordal"`` takes the
Pose3 rotations from GTSAM's chordal relaxation (``gtsam.InitializePose3``) instead.
"""

from __future__ import annotations

from collections import Counter, deque
from pathlib import Path

import numpy as np

from fgc.errors import DataError, FgcError
from fgc.frontend.dsl import Graph

_PASSED_OVER = {"EQUIV", "FIX", "PARAMS_SE2OFFSET", "PARAMS_SE3OFFSET"}
_WIDTH = {"VERTEX2": 5, "VERTEX_SE2": 5, "EDGE2": 12, "EDGE_SE2": 12,
          "VERTEX_SE3:QUAT": 9, "EDGE_SE3:QUAT": 31}
# every other tag GTSAM's readers understand: its kind (what GTSAM makes of it) and dimension
_GTSAM_TAGS = {"VERTEX": ("pose", 2), "EDGE": ("between", 2), "ODOMETRY": ("between", 2),
               "BR": ("bearing_range", 2), "LANDMARK": ("bearing_range", 2),
               "VERTEX_XY": ("point", 2), "VERTEX3": ("pose", 3), "EDGE3": ("between", 3),
               "VERTEX_TRACKXYZ": ("point", 3), "EDGE_SE3_TRACKXYZ": ("bearing_range", 3)}
_KIND = {"VERTEX2": ("pose", 2), "VERTEX_SE2": ("pose", 2), "EDGE2": ("between", 2),
         "EDGE_SE2": ("between", 2), "VERTEX_SE3:QUAT": ("pose", 3),
         "EDGE_SE3:QUAT": ("between", 3), **_GTSAM_TAGS}
_FACTOR_KIND = {"BetweenFactorPose2": "between", "BetweenFactorPose3": "between",
                "BearingRangeFactor2D": "bearing_range", "BearingRangeFactor3D": "bearing_range"}
_MAX_ID = 2**56  # GTSAM keys are 64-bit; Symbol-style keys keep 56 bits for the index
INIT_METHODS = ("odometry", "chordal")


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


def _check_numbers(nums: np.ndarray, tag: str, where: str) -> None:
    if tag == "VERTEX_SE3:QUAT" or tag == "EDGE_SE3:QUAT":
        q = nums[3:7]
        if not np.linalg.norm(q) > 1e-12:
            raise DataError(f"{where}: quaternion has zero or non-finite norm")
    if tag.startswith("EDGE"):
        n = 3 if tag in ("EDGE2", "EDGE_SE2") else 6
        upper = nums[n if n == 3 else 7:][: n * (n + 1) // 2]
        if tag == "EDGE2":  # TORO I11 I12 I22 I33 I13 I23, or g2o's order (GTSAM detects)
            i11, i12, i22, i33, i13, i23 = upper
            layouts = [np.array([i11, i12, i13, i22, i23, i33]), upper]
        else:
            layouts = [upper]
        if not any(_positive_definite(u, n) for u in layouts):
            raise DataError(f"{where}: information matrix is not positive definite")


def _positive_definite(upper: np.ndarray, n: int) -> bool:
    info = np.zeros((n, n))
    info[np.triu_indices(n)] = upper
    info = info + np.triu(info, 1).T
    try:
        np.linalg.cholesky(info)
    except np.linalg.LinAlgError:
        return False
    return True


class _Scan:
    """What fgc's own pass over the file found: vertex dimensions, edge lines by kind."""

    def __init__(self, path: Path):
        self.path = path
        self.vertex_dim: dict[tuple[str, int], int] = {}
        self.edges: list[tuple[str, list[int], str]] = []  # (tag, ids, where) of checked edges
        self.lines_by_kind: dict[str, list[tuple[str, str]]] = {}  # kind → [(tag, where)]
        self.dims: set[int] = set()
        self.vertex_lines = 0


def _scan(path: Path, prefix: str | None) -> _Scan:
    scan = _Scan(path)
    for lineno, line in enumerate(_read_lines(path), start=1):
        fields = line.split()
        if not fields or fields[0].startswith("#") or fields[0] in _PASSED_OVER:
            continue
        tag, where = fields[0], f"{path.name}:{lineno}"
        if tag not in _KIND:
            raise DataError(f"{where}: tag {tag!r} is read by neither GTSAM's readers nor fgc; "
                            "fgc refuses the file rather than drop the line")
        kind, dim = _KIND[tag]
        scan.dims.add(dim)
        if kind in ("pose", "point"):
            scan.vertex_lines += 1
        else:
            scan.lines_by_kind.setdefault(f"{kind}{dim}", []).append((tag, where))
        if tag not in _WIDTH:
            continue
        ids, nums = _parse_line(tag, fields, where)
        if any(i >= _MAX_ID for i in ids):
            raise DataError(f"{where}: vertex id {max(ids)} does not fit a GTSAM key "
                            f"(at most {_MAX_ID - 1})")
        _check_numbers(nums, tag, where)
        if kind == "pose":
            if ("pose", ids[0]) in scan.vertex_dim:
                raise DataError(f"{where}: vertex {ids[0]} declared twice")
            scan.vertex_dim[("pose", ids[0])] = dim
        else:
            if ids[0] == ids[1]:
                raise DataError(f"{where}: edge from vertex {ids[0]} to itself")
            scan.edges.append((tag, ids, where))
    def shown(i: int) -> str:
        return repr(f"{prefix}{i}") if prefix is not None else str(i)

    for tag, ids, where in scan.edges:
        dim = _KIND[tag][1]
        for i in ids:
            have = scan.vertex_dim.get(("pose", i))
            if have is None and scan.vertex_dim:
                raise DataError(f"{where}: edge refers to undeclared vertex {shown(i)}")
            if have is not None and have != dim:
                raise DataError(f"{where}: vertex {shown(i)} is a Pose{have}, but this {tag} edge "
                                f"needs a Pose{dim}")
    if len(scan.dims) > 1:
        raise DataError(f"{path}: mixes 2D and 3D tags; GTSAM's readers take one or the other")
    return scan


def read_pose_graph(path: str | Path, key_prefix: str | None = "x",
                    init: str = "odometry") -> Graph:
    """Read a g2o or TORO file (any tag GTSAM's ``load2D``/``load3D`` read) into a Graph.

    In: the file; ``key_prefix`` names the pose variables ``<prefix><id>`` (``None``: the int
    ids themselves); landmarks keep GTSAM's ``l<id>`` names; ``init`` "odometry" or "chordal"
    (module docstring) for variables without a vertex line. Out: a Graph with GTSAM's factors,
    in GTSAM's order, and no prior (the caller fixes the gauge). DataError naming the file and
    line for a malformed line, an unreadable tag or a line GTSAM's reader did not return;
    FgcError naming the factor for a GTSAM factor fgc cannot represent.
    """
    import gtsam

    from fgc.interop.from_gtsam import default_key_name, from_gtsam

    if init not in INIT_METHODS:
        raise DataError(f"unknown init {init!r}; use one of {', '.join(INIT_METHODS)}")
    path = Path(path)
    scan = _scan(path, key_prefix)
    if not scan.lines_by_kind:
        what = f"{scan.vertex_lines} vertices but " if scan.vertex_lines else ""
        raise DataError(f"{path}: {what}no edges that GTSAM's readers turn into factors (no "
                        "vertices found either)" if not scan.vertex_lines else
                        f"{path}: {what}no edge lines GTSAM's readers turn into factors; "
                        "nothing to solve")
    is3d = 3 in scan.dims
    try:
        graph, values = (gtsam.load3D if is3d else gtsam.load2D)(str(path))
    except (RuntimeError, ValueError) as exc:
        raise DataError(f"{path}: GTSAM's {'load3D' if is3d else 'load2D'} rejects the file: "
                        f"{exc}") from None
    _check_nothing_dropped(scan, graph, is3d)
    if init == "chordal" and is3d:
        values = _chordal(graph, values)
    values = _complete_values(graph, values, is3d, path)

    def name(key: int):
        default = default_key_name(key)
        if isinstance(default, str) or key_prefix is None:
            return default
        return f"{key_prefix}{key}"

    factors = [graph.at(i) for i in range(graph.size()) if graph.at(i) is not None]
    keys = {k for gf in factors for k in list(gf.keys())}
    try:
        return from_gtsam(graph, values, key_names={k: name(k) for k in keys})
    except DataError:
        raise
    except FgcError as exc:
        raise DataError(f"{path}: {exc} (made by GTSAM's reader from the file's "
                        f"{_tags(scan)} lines)") from None


def _tags(scan: _Scan) -> str:
    return "/".join(sorted({t for lines in scan.lines_by_kind.values() for t, _ in lines}))


def _check_nothing_dropped(scan: _Scan, graph, is3d: bool) -> None:
    got = Counter()
    for i in range(graph.size()):
        gf = graph.at(i)
        if gf is not None:
            got[f"{_FACTOR_KIND.get(type(gf).__name__, type(gf).__name__)}{3 if is3d else 2}"] += 1
    for kind, lines in scan.lines_by_kind.items():
        n = got.get(kind, 0)
        if n < len(lines):
            tag, where = lines[n]
            raise DataError(f"{where}: GTSAM's reader returned {n} factors for the file's "
                            f"{len(lines)} {kind.rstrip('23')} lines ({tag} here and after is "
                            "missing); fgc refuses the file rather than drop lines")


def _chordal(graph, values):
    """Pose3 initial values from GTSAM's chordal relaxation of the between factors."""
    import gtsam

    sub = gtsam.NonlinearFactorGraph()
    for i in range(graph.size()):
        gf = graph.at(i)
        if isinstance(gf, gtsam.BetweenFactorPose3):
            sub.add(gf)
    if sub.size() == 0:
        return values
    first = min(k for i in range(sub.size()) for k in list(sub.at(i).keys()))
    anchor = values.atPose3(first) if values.exists(first) else gtsam.Pose3()
    sub.add(gtsam.PriorFactorPose3(first, anchor, gtsam.noiseModel.Unit.Create(6)))
    guess = gtsam.Values()
    for k in list(values.keys()):
        if _is_pose_key(k):
            guess.insert(k, values.atPose3(k))
    guess = _complete_values(sub, guess, True, None)
    chordal = gtsam.InitializePose3.initialize(sub, guess, False)
    out = gtsam.Values(values)
    for k in list(chordal.keys()):
        if out.exists(k):
            out.update(k, chordal.atPose3(k))
        else:
            out.insert(k, chordal.atPose3(k))
    return out


def _is_pose_key(key: int) -> bool:
    import gtsam

    return not chr(gtsam.Symbol(key).chr()).isalpha()


def _complete_values(graph, values, is3d: bool, path):
    """Insert a value for every key the factors use and ``values`` lacks (module docstring)."""
    import gtsam

    pose_t = gtsam.Pose3 if is3d else gtsam.Pose2
    at = values.atPose3 if is3d else values.atPose2
    factors = [graph.at(i) for i in range(graph.size()) if graph.at(i) is not None]
    used = sorted({k for gf in factors for k in list(gf.keys())})
    missing = [k for k in used if not values.exists(k)]
    if not missing:
        return values
    adjacent: dict[int, list] = {}
    for gf in factors:
        ks = list(gf.keys())
        if len(ks) == 2:
            adjacent.setdefault(ks[0], []).append(gf)
            adjacent.setdefault(ks[1], []).append(gf)
    placed = {k: at(k) for k in used if values.exists(k) and _is_pose_key(k)}
    for root in [k for k in used if _is_pose_key(k)]:
        if root not in placed:
            placed[root] = pose_t()
        queue = deque([root])
        while queue:
            k = queue.popleft()
            for gf in adjacent.get(k, []):
                a, b = list(gf.keys())
                if isinstance(gf, (gtsam.BetweenFactorPose2, gtsam.BetweenFactorPose3)):
                    if a == k and b not in placed:
                        placed[b] = placed[a].compose(gf.measured())
                        queue.append(b)
                    elif b == k and a not in placed:
                        placed[a] = placed[b].compose(gf.measured().inverse())
                        queue.append(a)
                elif b not in placed and not values.exists(b):
                    m = gf.measured()
                    if is3d:
                        local = np.asarray(m.bearing().point3()) * m.range()
                    else:
                        th = m.bearing().theta()
                        local = np.array([np.cos(th), np.sin(th)]) * m.range()
                    placed[b] = placed[a].transformFrom(local)
    out = gtsam.Values(values)
    for k in missing:
        if k not in placed:
            raise DataError(f"{path}: no initial value can be derived for key "
                            f"{gtsam.DefaultKeyFormatter(k)}")
        out.insert(k, placed[k])
    return out


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
