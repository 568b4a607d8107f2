"""Readers for every pose-graph / SLAM file GTSAM's ``load2D`` / ``load3D`` read, as fgc Graphs.

fgc reads every line itself first (:func:`_scan`), and only a file whose every line passes goes
on to GTSAM's reader. Each line of a tag fgc accepts must have exactly its tag's fields (a
missing or extra token — a trailing token, two lines joined, one line split — is refused, where
GTSAM's stream reader would read on across the line or ignore the rest), ids written as
non-negative integers that fit a GTSAM key (``144.7`` is refused, not read as 144 and .7),
numbers written as finite decimal numbers (no ``nan``/``inf``, nothing that overflows a double),
noise that GTSAM turns into a positive-definite model whose information is finite (positive
sigmas and variances, a positive-definite information matrix, a 2D noise block in one of the two
layouts GTSAM's ``load2D`` recognises), a quaternion whose norm GTSAM can normalise, no vertex
declared twice, no edge from a vertex to itself, and references only to declared ids (module
rules below). A bad line raises :class:`DataError` naming file, line, tag, the field and what is
wrong with it.

Then GTSAM's reader builds the graph (``gtsam.load2D`` for 2D files, ``gtsam.load3D`` for files
with any 3D tag), so tags, noise layouts and conventions are GTSAM's own, and fgc checks what it
returned against its own reading, factor by factor (kind, keys and measurement): a difference is a
DataError naming the line, never a graph that both sides misread the same way. The graph is
converted with :func:`fgc.interop.from_gtsam.from_gtsam`.

Tags: the ones in ``_FORMATS``. A line whose tag is not there is refused (the error names the
line and the tag), never skipped; ``EQUIV``, ``FIX`` and the offset ``PARAMS_*`` lines are checked
and then passed over, as GTSAM does (fgc fixes the gauge with a prior instead); ``#`` starts a
comment line. ``EDGE_SE3_TRACKXYZ`` is refused by line: GTSAM makes a BearingRangeFactor3D of it,
which fgc cannot represent exactly (docs/datasets.md).

References: when a file declares any pose vertex, every edge and measurement must name declared
poses; a file without pose vertices (odometry only) declares its poses by its between edges, and
a bearing-range line must start at one of those. Likewise for landmarks: when a file declares any
landmark vertex, every measurement must name a declared landmark; otherwise a landmark is placed
by its first measurement.

Initial values: vertices from the file; variables without a vertex line get odometry chaining
along the between factors (breadth-first from the lowest key, roots at the identity) and, for a
landmark, the first bearing-range measurement from a placed pose; ``init="chordal"`` takes the
Pose3 rotations from GTSAM's chordal relaxation (``gtsam.InitializePose3``) instead.
"""

from __future__ import annotations

import math
import re
import tempfile
from collections import deque
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from fgc.errors import DataError, FgcError
from fgc.frontend.dsl import Graph

_MAX_ID = 2**56  # GTSAM keys are 64-bit; Symbol-style keys keep 56 bits for the index
INIT_METHODS = ("odometry", "chordal")

_ID = re.compile(r"[0-9]+\Z")
# a decimal number as C++'s stream extraction reads one whole (no hex, no '_', no nan/inf)
_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?\Z")
_NOT_FINITE = re.compile(r"[+-]?(?:nan|inf|infinity)\Z", re.IGNORECASE)
_BLANK = re.compile(r"[ \t\v\f\r]+")  # C++'s isspace in the C locale, less the newline


def _info_names(n: int) -> tuple[str, ...]:
    return tuple(f"I{r + 1}{c + 1}" for r in range(n) for c in range(r, n))


_NOISE2 = tuple(f"noise{i}" for i in range(1, 7))
_POSE2 = ("x", "y", "theta")
_POSE3_RPY = ("x", "y", "z", "roll", "pitch", "yaw")
_POSE3_QUAT = ("x", "y", "z", "qx", "qy", "qz", "qw")
_BETWEEN2 = ("dx", "dy", "dtheta") + _NOISE2
_EDGE3 = ("dx", "dy", "dz", "roll", "pitch", "yaw") + _info_names(6)
_EDGE_QUAT = ("dx", "dy", "dz", "qx", "qy", "qz", "qw") + _info_names(6)


@dataclass(frozen=True)
class _Format:
    """One tag: what GTSAM makes of it (kind), its dimension, its id and number fields."""

    kind: str  # pose | point | between | bearing_range | passed_over
    dim: int
    ids: tuple[str, ...]
    numbers: tuple[str, ...]
    more_ids: bool = False  # FIX: one or more ids

    @property
    def width(self) -> int:
        return len(self.ids) + len(self.numbers)


_FORMATS = {
    **{t: _Format("pose", 2, ("id",), _POSE2) for t in ("VERTEX2", "VERTEX_SE2", "VERTEX")},
    "VERTEX_XY": _Format("point", 2, ("id",), ("x", "y")),
    **{t: _Format("between", 2, ("id1", "id2"), _BETWEEN2)
       for t in ("EDGE2", "EDGE_SE2", "EDGE", "ODOMETRY")},
    "BR": _Format("bearing_range", 2, ("pose_id", "landmark_id"),
                  ("bearing", "range", "sigma_bearing", "sigma_range")),
    "LANDMARK": _Format("bearing_range", 2, ("pose_id", "landmark_id"),
                        ("x", "y", "cov_xx", "cov_xy", "cov_yy")),
    "VERTEX3": _Format("pose", 3, ("id",), _POSE3_RPY),
    "VERTEX_SE3:QUAT": _Format("pose", 3, ("id",), _POSE3_QUAT),
    "VERTEX_TRACKXYZ": _Format("point", 3, ("id",), ("x", "y", "z")),
    "EDGE3": _Format("between", 3, ("id1", "id2"), _EDGE3),
    "EDGE_SE3:QUAT": _Format("between", 3, ("id1", "id2"), _EDGE_QUAT),
    "EQUIV": _Format("passed_over", 0, ("id1", "id2"), ()),
    "FIX": _Format("passed_over", 0, ("id",), (), more_ids=True),
    "PARAMS_SE2OFFSET": _Format("passed_over", 0, ("id",), _POSE2),
    "PARAMS_SE3OFFSET": _Format("passed_over", 0, ("id",), _POSE3_QUAT),
}
_UNSUPPORTED = {
    "EDGE_SE3_TRACKXYZ": "GTSAM's reader makes a BearingRangeFactor3D (Pose3 → Point3) of it, "
                         "which has no fgc built-in: GTSAM expresses its bearing error in the "
                         "tangent basis of the predicted direction, a basis that switches with "
                         "that direction's smallest component, which fgc's smooth residuals "
                         "cannot reproduce exactly",
}
# GTSAM factor classes by the kind of line they come from
_FACTOR_CLASS = {("between", 2): "BetweenFactorPose2", ("between", 3): "BetweenFactorPose3",
                 ("bearing_range", 2): "BearingRangeFactor2D"}


@dataclass
class _Line:
    """One checked data line: where, its tag and format, its ids and numbers."""

    where: str
    tag: str
    fmt: _Format
    ids: list[int]
    nums: list[float]


@dataclass
class _Scan:
    """What fgc's own pass over the file found."""

    path: Path
    vertices: dict = field(default_factory=dict)  # (namespace, id) → (dim, where)
    edges: list[_Line] = field(default_factory=list)  # between and bearing-range lines, in order
    dims: dict = field(default_factory=dict)  # dimension → its first line
    vertex_lines: int = 0
    clean: list = field(default_factory=list)  # the checked data lines, blanks made single


def _fields(line: str) -> list[str]:
    return [f for f in _BLANK.split(line) if f]


def _parse_line(tag: str, fields: list[str], where: str) -> _Line:
    """Field count, integer ids, finite numbers (module docstring); DataError otherwise."""
    fmt = _FORMATS[tag]
    got = len(fields) - 1
    whole = _WHOLE.get(tag)
    if whole and got == fmt.width and whole.match(" ".join(fields[1:])):  # the common case
        n = len(fmt.ids)
        if all(len(t) <= 16 for t in fields[1:1 + n]):  # < 10**16 < _MAX_ID
            nums = [float(t) for t in fields[1 + n:]]
            if all(map(math.isfinite, nums)):
                line = _Line(where, tag, fmt, [int(t) for t in fields[1:1 + n]], nums)
                _check_values(line)
                return line
    if fmt.more_ids and got >= 1:
        names = tuple(f"id{i + 1}" for i in range(got))
    elif got != fmt.width:
        names = fmt.ids + fmt.numbers
        hint = (" (a field missing, or the line split?)" if got < fmt.width else
                " (a trailing token, or two lines joined?)")
        shown = " ".join(names).replace(" ".join(_info_names(6)), "I11 … I66 (upper triangle)")
        raise DataError(f"{where}: {tag} takes {fmt.width} fields after the tag ({shown}), "
                        f"got {got}{hint}")
    else:
        names = fmt.ids + fmt.numbers
    n_ids = got if fmt.more_ids else len(fmt.ids)
    ids = []
    for name, tok in zip(names[:n_ids], fields[1:1 + n_ids], strict=True):
        if not _ID.match(tok):
            raise DataError(f"{where}: {tag} {name} is {_shown(tok)}, not a non-negative integer "
                            "id")
        if len(tok.lstrip("0")) > 20 or int(tok) >= _MAX_ID:
            raise DataError(f"{where}: {tag} {name} {_shown(tok)} does not fit a GTSAM key "
                            f"(at most {_MAX_ID - 1})")
        ids.append(int(tok))
    nums = []
    for name, tok in zip(names[n_ids:], fields[1 + n_ids:], strict=True):
        if _NOT_FINITE.match(tok):
            raise DataError(f"{where}: {tag} {name} is {_shown(tok)}: a non-finite number")
        if not _NUMBER.match(tok):
            raise DataError(f"{where}: {tag} {name} is {_shown(tok)}, not a number")
        value = float(tok)
        if not math.isfinite(value):
            raise DataError(f"{where}: {tag} {name} is {_shown(tok)}, which overflows a double "
                            "(non-finite)")
        nums.append(value)
    line = _Line(where, tag, fmt, ids, nums)
    _check_values(line)
    return line


_ID_RE, _NUMBER_RE = _ID.pattern[:-2], _NUMBER.pattern[:-2]
_WHOLE = {t: re.compile(" ".join([_ID_RE] * len(f.ids) + [_NUMBER_RE] * len(f.numbers)) + r"\Z")
          for t, f in _FORMATS.items() if not f.more_ids}


def _shown(token: str) -> str:
    """A token for a message: quoted, at most 40 characters."""
    return repr(token if len(token) <= 40 else token[:37] + "...")


def _check_values(line: _Line) -> None:
    """What the numbers must satisfy for GTSAM's reading of them to be a valid model."""
    tag, where, nums = line.tag, line.where, line.nums
    if "qw" in line.fmt.numbers:
        q = nums[line.fmt.numbers.index("qx"):][:4]
        norm2 = sum(v * v for v in q)  # Python floats: an overflow is inf, with no warning
        if not 0.0 < norm2 < math.inf:
            raise DataError(f"{where}: {tag} quaternion ({', '.join(map(repr, q))}) has zero "
                            "or non-finite norm; GTSAM normalises it, so its squared norm must "
                            "be a positive finite double")
    if line.fmt.kind == "between" and line.fmt.dim == 2:
        _variances_2d(line)
    elif line.fmt.kind == "between":
        info = np.zeros((6, 6))
        info[np.triu_indices(6)] = nums[-21:]
        _positive_definite(info + np.triu(info, 1).T, f"{where}: {tag} information matrix")
    elif tag == "BR":
        bearing, rng, s_b, s_r = nums
        if rng < 0:
            raise DataError(f"{where}: BR range is {rng!r}: a range cannot be negative")
        for name, s in (("sigma_bearing", s_b), ("sigma_range", s_r)):
            _positive(s, f"{where}: BR {name}", square=True)
    elif tag == "LANDMARK":
        cxx, cxy, cyy = nums[2:]
        _positive_definite(np.array([[cxx, cxy], [cxy, cyy]]),
                           f"{where}: LANDMARK covariance [[cov_xx, cov_xy], [cov_xy, cov_yy]]")
        if cxy != 0.0 or not abs(cxx - cyy) < 1e-4:
            raise DataError(
                f"{where}: LANDMARK covariance cov_xx {cxx!r}, cov_xy {cxy!r}, cov_yy {cyy!r}: "
                "GTSAM's reader models a landmark's noise from cov_xx alone (σ_bearing = "
                "√(cov_xx/10), σ_range = √cov_xx) when cov_xy = 0 and |cov_xx − cov_yy| < 1e-4, "
                "and otherwise replaces it by σ = 1, 1; fgc refuses a covariance GTSAM would drop")
        _positive(cxx / 10.0, f"{where}: LANDMARK cov_xx / 10 (GTSAM's bearing variance)")


def _variances_2d(line: _Line) -> None:
    """The 2D edge's six noise numbers as GTSAM's ``load2D`` (NoiseFormatAUTO) reads them: the
    TORO layout ``c_xx 0 c_yy c_tt 0 0`` or the g2o-order ``c_xx 0 0 c_yy 0 c_tt``, both taken
    as a diagonal covariance; any other pattern GTSAM's reader rejects."""
    v0, v1, v2, v3, v4, v5 = line.nums[3:]
    if v1 == 0.0 and v4 == 0.0 and v0 != 0.0 and v3 != 0.0 and (v2 == 0.0) != (v5 == 0.0):
        variances = (v0, v2, v3) if v5 == 0.0 else (v0, v3, v5)
        if min(variances) > 0.0 and 1.0 / min(variances) < math.inf:
            return
    else:
        raise DataError(
            f"{line.where}: {line.tag} noise {' '.join(map(repr, line.nums[3:]))} fits neither "
            "layout GTSAM's load2D reads (TORO 'c_xx 0 c_yy c_tt 0 0' or g2o-order 'c_xx 0 0 "
            "c_yy 0 c_tt', both a diagonal covariance); off-diagonal terms and zero variances "
            "are not read")
    for name, var in zip(("c_xx", "c_yy", "c_tt"), variances, strict=True):
        _positive(var, f"{line.where}: {line.tag} variance {name}")


def _positive(value: float, what: str, square: bool = False) -> None:
    """A sigma (``square``) or variance: positive, and its information 1/value(²) finite."""
    var = value * value if square else value
    if not value > 0.0:
        raise DataError(f"{what} is {value!r}; it must be positive")
    if not (0.0 < var < math.inf and 0.0 < 1.0 / var < math.inf):
        raise DataError(f"{what} is {value!r}: its information (1/{'σ²' if square else 'var'}) "
                        "overflows or underflows a double")


def _positive_definite(matrix: np.ndarray, what: str) -> None:
    with np.errstate(all="ignore"):
        try:
            chol = np.linalg.cholesky(matrix)
        except np.linalg.LinAlgError:
            chol = None
        ok = chol is not None and bool(np.all(np.isfinite(chol))) and np.all(np.diag(chol) > 0)
        if ok:  # the covariance, which GTSAM forms for a diagonal information, must be finite
            inv = np.linalg.inv(chol)
            ok = bool(np.all(np.isfinite(inv.T @ inv)))
    if not ok:
        raise DataError(f"{what} is not positive definite (or not representable as one in "
                        "double precision)")


def _scan(path: Path, prefix: str | None) -> _Scan:
    scan = _Scan(path)
    for lineno, text in enumerate(_read_lines(path), start=1):
        fields = _fields(text)
        if not fields or fields[0].startswith("#"):
            continue
        tag, where = fields[0], f"{path.name}:{lineno}"
        if tag in _UNSUPPORTED:
            raise DataError(f"{where}: {tag} lines are refused: {_UNSUPPORTED[tag]}")
        if tag not in _FORMATS:
            raise DataError(f"{where}: tag {tag!r} is read by neither GTSAM's readers nor fgc; "
                            "fgc refuses the file rather than drop the line (known tags: "
                            f"{', '.join(sorted(_FORMATS))})")
        line = _parse_line(tag, fields, where)
        kind = line.fmt.kind
        if kind == "passed_over":
            continue
        scan.clean.append(" ".join(fields))
        scan.dims.setdefault(line.fmt.dim, (lineno, where))
        if kind in ("pose", "point"):
            scan.vertex_lines += 1
            key = (kind, line.ids[0])
            if key in scan.vertices:
                raise DataError(f"{where}: {kind} vertex {line.ids[0]} declared twice (first at "
                                f"{scan.vertices[key][1]})")
            scan.vertices[key] = (line.fmt.dim, where)
        else:
            if kind == "between" and line.ids[0] == line.ids[1]:
                raise DataError(f"{where}: {tag} edge from vertex {line.ids[0]} to itself")
            scan.edges.append(line)
    _check_references(scan, prefix)
    if len(scan.dims) > 1:
        (_, first), (_, other) = sorted(scan.dims.values())
        kind = {w: f"{d}D" for d, (_, w) in scan.dims.items()}
        raise DataError(f"{other}: a {kind[other]} line in a file of {kind[first]} lines (the "
                        f"first at {first}); GTSAM's readers take one or the other")
    return scan


def _check_references(scan: _Scan, prefix: str | None) -> None:
    """Every id an edge names is declared (module docstring) and of the edge's dimension."""
    def shown(i: int) -> str:
        return repr(f"{prefix}{i}") if prefix is not None else str(i)

    declared = {ns for ns, _ in scan.vertices}
    chained = {i for e in scan.edges if e.fmt.kind == "between" for i in e.ids}
    for e in scan.edges:
        refs = [("pose", i) for i in e.ids] if e.fmt.kind == "between" else \
            [("pose", e.ids[0]), ("point", e.ids[1])]
        for ns, i in refs:
            have = scan.vertices.get((ns, i))
            name = shown(i) if ns == "pose" else repr(f"l{i}")
            if have is None and ns in declared:
                what = "pose" if ns == "pose" else "landmark"
                raise DataError(f"{e.where}: {e.tag} refers to undeclared {what} {name} (the "
                                f"file declares its {what}s with vertex lines)")
            if have is None and ns == "pose" and i not in chained:
                raise DataError(f"{e.where}: {e.tag} measurement from undeclared pose {name}: "
                                "no vertex line and no between edge declares it")
            if have is not None and ns == "pose" and have[0] != e.fmt.dim:
                raise DataError(f"{e.where}: vertex {name} is a Pose{have[0]}, but this {e.tag} "
                                f"edge needs a Pose{e.fmt.dim}")


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
    if not scan.edges:
        raise DataError(f"{path}: {scan.vertex_lines} vertices but no edge lines GTSAM's readers "
                        "turn into factors; nothing to solve" if scan.vertex_lines else
                        f"{path}: no edges that GTSAM's readers turn into factors (no vertices "
                        "found either)")
    is3d = 3 in scan.dims
    # GTSAM's reader gets the checked data lines alone (no comments, passed-over lines or odd
    # blanks: its load2D reads two ids from every line that is not a between edge, and a
    # comment's words stop it reading the rest of the file)
    with tempfile.TemporaryDirectory(prefix="fgc-read-") as tmp:
        clean = Path(tmp) / ("data" + path.suffix)
        clean.write_text("\n".join(scan.clean) + "\n", encoding="ascii")
        try:
            graph, values = (gtsam.load3D if is3d else gtsam.load2D)(str(clean))
        except (RuntimeError, ValueError) as exc:
            raise DataError(f"{path}: GTSAM's {'load3D' if is3d else 'load2D'} rejects the "
                            f"file: {exc}") from None
    _check_against_gtsam(scan, graph)
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
                        f"{'/'.join(sorted({e.tag for e in scan.edges}))} lines)") from None


def _check_against_gtsam(scan: _Scan, graph) -> None:
    """GTSAM's factors, in file order, are the file's edge lines as fgc read them: the same
    class and keys, the same measurement (1e-9 relative) and information matrix (1e-9 of its
    largest entry); DataError naming the first line that differs, so nothing both readers
    misread alike, and nothing GTSAM dropped, reaches the Program."""
    import gtsam

    factors = [graph.at(i) for i in range(graph.size())]
    if len(factors) != len(scan.edges) or any(gf is None for gf in factors):
        n = next((i for i, gf in enumerate(factors) if gf is None), len(factors))
        n = min(n, len(scan.edges) - 1)
        raise DataError(f"{scan.edges[n].where}: GTSAM's reader returned {len(factors)} factors "
                        f"for the file's {len(scan.edges)} edge lines; fgc refuses the file "
                        "rather than drop or add lines")
    groups: dict[str, list[int]] = {}
    for n, (line, gf) in enumerate(zip(scan.edges, factors, strict=True)):
        cls = _FACTOR_CLASS[(line.fmt.kind, line.fmt.dim)]
        if type(gf).__name__ != cls:
            _differ(line, f"a {type(gf).__name__} instead of a {cls}")
        keys = ((line.ids[0], gtsam.symbol("l", line.ids[1])) if line.fmt.kind ==
                "bearing_range" else tuple(line.ids))
        if tuple(gf.keys()) != keys:
            _differ(line, f"a factor on keys {tuple(gf.keys())} instead of {keys}")
        groups.setdefault(line.tag, []).append(n)
    for tag, rows in groups.items():
        lines = [scan.edges[n] for n in rows]
        measured, info = _expected_measurements(tag, np.array([ln.nums for ln in lines]))
        got = np.array([_gtsam_measurement(factors[n].measured()) for n in rows])
        r = np.array([factors[n].noiseModel().R() for n in rows], float)
        got_info = np.einsum("nki,nkj->nij", r, r)
        bad_m = np.any(np.abs(got - measured) > 1e-9 * np.maximum(1.0, np.abs(measured)), axis=1)
        scale = np.abs(info).max(axis=(1, 2))[:, None, None]
        bad_i = np.any(np.abs(got_info - info) > 1e-9 * scale, axis=(1, 2))
        if bad_m.any() or bad_i.any():
            k = int(np.argmax(bad_m | bad_i))
            _differ(lines[k], "another measurement" if bad_m[k] else "another noise model")


def _differ(line: _Line, what: str):
    raise DataError(f"{line.where}: GTSAM's reader made {what} of this {line.tag} line than "
                    "fgc reads; fgc refuses the file rather than solve either reading")


def _gtsam_measurement(m) -> list[float]:
    import gtsam

    if isinstance(m, gtsam.Pose2):
        return [m.x(), m.y(), m.rotation().c(), m.rotation().s()]
    if isinstance(m, gtsam.Pose3):
        return [*m.translation(), *np.asarray(m.rotation().matrix()).ravel()]
    return [m.bearing().c(), m.bearing().s(), m.range()]  # BearingRange2D


def _expected_measurements(tag: str, nums: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """What GTSAM's reader makes of checked edge lines of one tag (rows of ``nums``), computed
    by fgc: measurements as rows [c, s, range] (bearing-range), [x, y, c, s] (Pose2) or
    [t, rotation matrix row-major] (Pose3), and information matrices."""
    n = len(nums)
    if tag in ("BR", "LANDMARK"):
        if tag == "BR":
            bearing, rng, s_b, s_r = nums.T
        else:  # GTSAM's conversion of a landmark's (x, y) and covariance
            x, y, cxx, _, cyy = nums.T
            bearing, rng = np.arctan2(y, x), np.sqrt(x * x + y * y)
            same = np.abs(cxx - cyy) < 1e-4
            s_b = np.where(same, np.sqrt(np.abs(cxx) / 10.0), 1.0)
            s_r = np.where(same, np.sqrt(np.abs(cxx)), 1.0)
        info = np.zeros((n, 2, 2))
        info[:, 0, 0], info[:, 1, 1] = 1.0 / s_b**2, 1.0 / s_r**2
        return np.stack([np.cos(bearing), np.sin(bearing), rng], axis=1), info
    if _FORMATS[tag].dim == 2:
        x, y, th, v0, _, v2, v3, _, v5 = nums.T
        var = np.stack([v0, np.where(v5 == 0.0, v2, v3), np.where(v5 == 0.0, v3, v5)], axis=1)
        info = np.zeros((n, 3, 3))
        info[:, [0, 1, 2], [0, 1, 2]] = 1.0 / var
        return np.stack([x, y, np.cos(th), np.sin(th)], axis=1), info
    upper = np.zeros((n, 6, 6))
    upper[:, *np.triu_indices(6)] = nums[:, -21:]
    info = upper + np.triu(upper, 1).transpose(0, 2, 1)
    if tag == "EDGE3":
        rot = np.array([_ypr(yaw, pitch, roll) for roll, pitch, yaw in nums[:, 3:6]])
    else:  # g2o orders the information (t, R); GTSAM's tangent is (R, t)
        q = nums[:, 3:7]
        q = q / np.sqrt(np.sum((q / np.abs(q).max(axis=1)[:, None]) ** 2, axis=1))[:, None] \
            / np.abs(q).max(axis=1)[:, None]
        rot = np.array([_quat_matrix(*row) for row in q])
        swap = [3, 4, 5, 0, 1, 2]
        info = info[:, swap][:, :, swap]
    return np.concatenate([nums[:, :3], rot.reshape(n, 9)], axis=1), info


def _ypr(yaw: float, pitch: float, roll: float) -> np.ndarray:
    """Rz(yaw) Ry(pitch) Rx(roll), GTSAM's Rot3.Ypr."""
    cy, sy, cp, sp, cr, sr = (math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch),
                              math.cos(roll), math.sin(roll))
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    return rz @ ry @ rx


def _quat_matrix(x: float, y: float, z: float, w: float) -> np.ndarray:
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


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
        # lines end at '\n' only, as for GTSAM's reader ('\r', '\v', '\f' are blanks)
        return path.read_bytes().decode("utf-8").split("\n")
    except OSError as exc:
        raise DataError(f"{path}: cannot read ({exc.strerror})") from None
    except UnicodeDecodeError as exc:
        line = path.read_bytes()[:exc.start].count(b"\n") + 1
        raise DataError(f"{path.name}:{line}: not a text file (byte {exc.start} is not UTF-8)"
                        ) from None
