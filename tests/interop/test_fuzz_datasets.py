"""Fuzzing fgc's data-file reader (fgc.interop.datasets.read_pose_graph).

Mutated copies of real files from the gtsam wheel (excerpts of w100.graph, example.graph,
victoria_park.txt, w20000.txt, sphere2500.txt and whole noisyToyGraph.txt, pose3example.txt,
pose3example-offdiagonal.txt, Klaus3.g2o) and of small files written here for the tags those do
not use (VERTEX, EDGE, VERTEX_XY, VERTEX3, VERTEX_TRACKXYZ, FIX, PARAMS_*), every mutation
drawn from a seeded generator, so the same files every run. Each outcome is classified:

- clean refusal: an FgcError whose message starts with ``<file>:<line>:`` (or, for the two
  file-level refusals, names the file);
- accepted as written: the Graph's factors (keys, measurements, information matrices) and
  declared vertices equal an independent parse of the mutated file, done here with GTSAM's
  conventions, to 1e-9 relative — only for mutations that leave a valid file (whitespace,
  comments, another valid number, a new odometry-chained pose, ...);
- anything else fails the test: a traceback (any other exception), a warning (numpy's overflow
  warnings included), a refusal without file and line, an accepted file that differs from the
  independent parse, or an accepted file whose mutation must be refused (a silent misread).

The default run reads ``FAST`` files spread over every mutation kind; ``-m heavy`` reads all
``len(CASES)`` (≥ 300). ``python tests/interop/test_fuzz_datasets.py`` prints the counts per
outcome.
"""

from __future__ import annotations

import math
import random
import re
import warnings
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from fgc.errors import FgcError

# tag → (kind, dimension, number of ids)
TAGS = {
    "VERTEX2": ("pose2", 1), "VERTEX_SE2": ("pose2", 1), "VERTEX": ("pose2", 1),
    "VERTEX_XY": ("point2", 1), "VERTEX3": ("pose3rpy", 1), "VERTEX_SE3:QUAT": ("pose3q", 1),
    "VERTEX_TRACKXYZ": ("point3", 1),
    "EDGE2": ("between2", 2), "EDGE_SE2": ("between2", 2), "EDGE": ("between2", 2),
    "ODOMETRY": ("between2", 2), "BR": ("br", 2), "LANDMARK": ("landmark", 2),
    "EDGE3": ("between3rpy", 2), "EDGE_SE3:QUAT": ("between3q", 2),
    "EQUIV": ("skip", 2), "FIX": ("skip", 1), "PARAMS_SE2OFFSET": ("skip", 1),
    "PARAMS_SE3OFFSET": ("skip", 1),
}
VERTEX_KINDS = ("pose2", "point2", "pose3rpy", "pose3q", "point3")
EDGE_KINDS = ("between2", "br", "landmark", "between3rpy", "between3q")
FAST = 60


def _upper(n: int, diag: float, off: float) -> str:
    return " ".join(str(diag if r == c else off) for r in range(n) for c in range(r, n))


# small files for the tags the wheel's files do not use (all valid as written)
SMALL = {
    "small2d.g2o": [
        "VERTEX 0 0 0 0", "VERTEX 1 1.0 0.05 0.1", "VERTEX 2 2.0 0.1 -0.2",
        "VERTEX_XY 7 1.5 2.0", "VERTEX_XY 8 2.5 -1.0",
        "EDGE 0 1 1.0 0.05 0.1 0.01 0 0.02 0.003 0 0",
        "EDGE 1 2 1.0 0.05 -0.3 0.01 0 0 0.02 0 0.004",
        "BR 0 7 0.9 2.5 0.05 0.1", "BR 1 8 -1.2 2.1 0.02 0.2",
        "LANDMARK 2 7 -0.5 2.0 0.4 0 0.4", "LANDMARK 2 8 1.0 -2.0 0.3 0 0.30005",
        "FIX 0", "EQUIV 1 1", "PARAMS_SE2OFFSET 0 0.1 0 0",
    ],
    "small3d.graph": [
        "VERTEX3 0 0 0 0 0 0 0", "VERTEX3 1 1 0.1 0 0.05 -0.02 0.3",
        "VERTEX3 2 2 0.2 0.1 0.1 0.02 0.6", "VERTEX_TRACKXYZ 4 1 2 3",
        "EDGE3 0 1 1 0.1 0 0.05 -0.02 0.3 " + _upper(6, 100, 1),
        "EDGE3 1 2 1 0.1 0.1 0.05 0.04 0.3 " + _upper(6, 50, -2),
        "PARAMS_SE3OFFSET 0 0 0 0 0 0 0 1",
    ],
}
REAL = ["w100.graph", "example.graph", "victoria_park.txt", "w20000.txt", "sphere2500.txt",
        "noisyToyGraph.txt", "pose3example.txt", "pose3example-offdiagonal.txt", "Klaus3.g2o"]


def _split(line: str) -> list[str]:
    return [t for t in re.split(r"[ \t\v\f\r]+", line) if t]


def _excerpt(lines: list[str], k: int = 6, most: int = 18) -> list[str]:
    """Vertices with id < k, edges between them (bearing-range lines: from them), the first
    two passed-over lines; at most ``most`` lines, a valid file again."""
    out, skipped = [], 0
    for line in lines:
        f = _split(line)
        if not f or f[0] not in TAGS:
            continue
        kind, n_ids = TAGS[f[0]]
        ids = [int(t) for t in f[1:1 + n_ids]]
        if kind == "skip":
            skipped += 1
            if skipped <= 2:
                out.append(line)
        elif kind in ("br", "landmark"):
            if ids[0] < k:
                out.append(line)
        elif all(i < k for i in ids):
            out.append(line)
        if len(out) >= most:
            break
    return out


def base_files() -> dict[str, list[str]]:
    from fgc.interop.gtsam_data import gtsam_data_dir

    out = {}
    for name in REAL:
        lines = (gtsam_data_dir() / name).read_text().splitlines()
        out[name] = _excerpt(lines)
    out.update(SMALL)
    return out


# --------------------------------------------------------------------------------------------
# mutations
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Case:
    base: str
    mutation: str
    lines: tuple[str, ...]
    must_refuse: bool
    why: str  # why an accepted file is right (empty when it must be refused)

    @property
    def name(self) -> str:
        return f"{self.base}-{self.mutation}"


def _kind(line: str) -> tuple[str, int, list[str]]:
    f = _split(line)
    return (*TAGS[f[0]], f) if f and f[0] in TAGS else ("", 0, f)


def _number_fields(f: list[str], n_ids: int) -> list[int]:
    return list(range(1 + n_ids, len(f)))


def _declares(lines, kinds) -> bool:
    return any(_kind(x)[0] in kinds for x in lines)


def mutations(base: str, lines: list[str], rng: random.Random) -> list[Case]:
    cases = []

    def add(mutation, new_lines, must_refuse, why=""):
        cases.append(Case(base, mutation, tuple(new_lines), must_refuse, why))

    def pick(pred):
        idx = [i for i, x in enumerate(lines) if pred(_kind(x))]
        return rng.choice(idx) if idx else None

    def with_line(i, fields):
        return lines[:i] + [" ".join(fields)] + lines[i + 1:]

    data = pick(lambda k: k[0] != "")
    edge = pick(lambda k: k[0] in EDGE_KINDS)
    vertex = pick(lambda k: k[0] in VERTEX_KINDS)
    between = pick(lambda k: k[0].startswith("between"))
    pose_vertices = _declares(lines, ("pose2", "pose3rpy", "pose3q"))
    point_vertices = _declares(lines, ("point2", "point3"))

    for i in {data, edge, vertex} - {None}:
        kind, n_ids, f = _kind(lines[i])
        j = rng.randrange(1, len(f))
        add(f"drop-field-L{i}", with_line(i, f[:j] + f[j + 1:]), True)
        if f[0] != "FIX":
            add(f"add-field-L{i}", with_line(i, f + [rng.choice(["0", "1.5", "7"])]), True)
        add(f"tag-lower-L{i}", with_line(i, [f[0].lower()] + f[1:]), True)
        add(f"tag-suffix-L{i}", with_line(i, [f[0] + "_X"] + f[1:]), True)
        if i + 1 < len(lines):
            add(f"join-L{i}", lines[:i] + [lines[i] + " " + lines[i + 1]] + lines[i + 2:], True)
        if len(f) > 2:
            s = rng.randrange(2, len(f))
            add(f"split-L{i}", lines[:i] + [" ".join(f[:s]), " ".join(f[s:])] + lines[i + 1:],
                True)
        for bad in ("{}.7", "-{}", str(10**30), str(2**56), "1e3", "+{}", "0x{}"):
            k = rng.randrange(1, 1 + n_ids)
            fields = list(f)
            fields[k] = bad.format(f[k])
            add(f"id-{bad.format('N')}-L{i}", with_line(i, fields), True)
        nums = _number_fields(f, n_ids)
        if nums:
            for bad in ("nan", "inf", "-inf", "NaN", "1e400", "abc", "0x10", "1_000", "1,5",
                        "٣"):
                fields = list(f)
                fields[rng.choice(nums)] = bad
                add(f"number-{bad}-L{i}", with_line(i, fields), True)
            for other in ("1e308", "-1e308", "1e-320", "2.5", "-0.0", "3e-5"):
                fields = list(f)
                k = rng.choice(nums)
                fields[k] = other
                add(f"number->{other}-L{i}", with_line(i, fields), False,
                    f"another valid number ({other}) as field {k} of a {f[0]} line, read as "
                    "written")
    if vertex is not None:
        add(f"duplicate-vertex-L{vertex}", lines + [lines[vertex]], True)
    if between is not None:
        kind, n_ids, f = _kind(lines[between])
        add(f"self-loop-L{between}", with_line(between, [f[0], f[1], f[1]] + f[3:]), True)
        fields = list(f)
        fields[2] = "99991"
        add(f"undeclared-pose-L{between}", with_line(between, fields), pose_vertices,
            "no pose vertices in the file: the new id is a pose declared by this edge")
        info = _number_fields(f, n_ids)[-21:] if "3" in kind else None
        fields = list(f)
        if info:  # a negative diagonal entry of the information matrix
            fields[info[rng.choice([0, 6, 11, 15, 18, 20])]] = "-5"
        else:
            fields[7] = "5"  # an off-diagonal term GTSAM's load2D layouts do not have
        add(f"indefinite-L{between}", with_line(between, fields), True)
        if not info:
            fields = list(f)
            fields[6] = "-" + fields[6]
            add(f"negative-variance-L{between}", with_line(between, fields), True)
    br = pick(lambda k: k[0] in ("br", "landmark"))
    if br is not None:
        kind, n_ids, f = _kind(lines[br])
        fields = list(f)
        fields[1] = "99992"
        add(f"undeclared-br-pose-L{br}", with_line(br, fields), True)
        fields = list(f)
        fields[2] = "99993"
        add(f"undeclared-landmark-L{br}", with_line(br, fields), point_vertices,
            "no landmark vertices in the file: GTSAM places the landmark by this measurement")
        fields = list(f)
        if kind == "br":
            fields[6] = rng.choice(["0", "-0.1", "1e-200", "1e200"])
            add(f"sigma-{fields[6]}-L{br}", with_line(br, fields), True)
            fields = list(f)
            fields[4] = "-1.135"
            add(f"negative-range-L{br}", with_line(br, fields), True)
        else:
            fields[5] = "-0.4"
            add(f"indefinite-covariance-L{br}", with_line(br, fields), True)
            for cov in ("0.4 0.1 0.4", "0.4 0 0.5"):  # GTSAM would replace these by σ = 1, 1
                fields = f[:5] + cov.split()
                add(f"landmark-covariance-{cov.replace(' ', '_')}-L{br}", with_line(br, fields),
                    True)
    if edge is not None:
        add(f"duplicate-edge-L{edge}", lines + [lines[edge]], False,
            "a repeated measurement: two factors, as GTSAM reads it")
    quat = pick(lambda k: k[0] in ("pose3q", "between3q"))
    if quat is not None:
        kind, n_ids, f = _kind(lines[quat])
        q0 = 1 + n_ids + 3
        for q in ("0 0 0 0", "1e308 0 0 1", "1e200 1e200 0 0", "1e-170 0 0 0", "0 0 0 2"):
            fields = f[:q0] + q.split() + f[q0 + 4:]
            add(f"quaternion-{q.replace(' ', '_')}-L{quat}", with_line(quat, fields),
                q != "0 0 0 2", "GTSAM normalises the quaternion (0, 0, 0, 2) to the identity")
    # whitespace and comments: the same file
    add("tabs", [x.replace(" ", "\t") for x in lines], False, "tabs are blanks")
    add("spaces", ["  " + x.replace(" ", "   ") + "  " for x in lines], False,
        "extra blanks, leading and trailing")
    add("crlf", [x + "\r" for x in lines], False, "CRLF line ends: '\\r' is a blank")
    add("vtab", [x.replace(" ", "\v", 1) for x in lines], False,
        "'\\v' is a blank to GTSAM's stream reader, and to fgc")
    add("comments", ["# a comment"] + [y for x in lines for y in (x, "")] + ["#"], False,
        "comment and blank lines")
    nb = pick(lambda k: k[0] != "")
    add(f"nbsp-L{nb}", lines[:nb] + [lines[nb].replace(" ", "\u00a0", 1)] + lines[nb + 1:], True)
    return cases


def all_cases() -> list[Case]:
    out = []
    for k, (base, lines) in enumerate(sorted(base_files().items())):
        out += mutations(base, lines, random.Random(1000 + k))
    return out


# --------------------------------------------------------------------------------------------
# the independent parse: what each accepted line means under GTSAM's conventions
# --------------------------------------------------------------------------------------------


def _rot2(theta):
    return [math.cos(theta), math.sin(theta)]


def _ypr(roll, pitch, yaw):
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch),
                              math.sin(pitch), math.cos(yaw), math.sin(yaw))
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def _quat(qx, qy, qz, qw):
    n = math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
    x, y, z, w = qx / n, qy / n, qz / n, qw / n
    return np.array([[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]])


def _sym(n, upper):
    m = np.zeros((n, n))
    k = 0
    for r in range(n):
        for c in range(r, n):
            m[r, c] = m[c, r] = upper[k]
            k += 1
    return m


def independent_parse(text: str):
    """(factors [(keys, {measurement: values}, information)], vertices {key: storage})."""
    factors, vertices = [], {}
    for raw in text.split("\n"):
        f = _split(raw)
        if not f or f[0].startswith("#") or TAGS[f[0]][0] == "skip":
            continue
        kind = TAGS[f[0]][0]
        if kind in VERTEX_KINDS:
            i, v = int(f[1]), [float(t) for t in f[2:]]
            if kind == "pose2":
                vertices[f"x{i}"] = v[:2] + _rot2(v[2])
            elif kind == "point2":
                vertices[f"l{i}"] = v
            elif kind == "pose3rpy":
                vertices[f"x{i}"] = list(_ypr(*v[3:6]).ravel()) + v[:3]
            elif kind == "pose3q":
                vertices[f"x{i}"] = list(_quat(*v[3:7]).ravel()) + v[:3]
            continue
        a, b, v = int(f[1]), int(f[2]), [float(t) for t in f[3:]]
        if kind == "between2":
            n = v[3:]
            cov = [n[0], n[2], n[3]] if n[2] != 0 else [n[0], n[3], n[5]]  # TORO / g2o order
            factors.append(((f"x{a}", f"x{b}"), {"measured": v[:2] + _rot2(v[2])},
                            np.diag([1 / c for c in cov])))
        elif kind in ("br", "landmark"):
            if kind == "br":
                bearing, rng_, sb, sr = v
            else:
                x, y, cxx, _, cyy = v
                bearing, rng_ = math.atan2(y, x), math.hypot(x, y)
                sb, sr = (math.sqrt(cxx / 10), math.sqrt(cxx)) if abs(cxx - cyy) < 1e-4 else (1, 1)
            factors.append(((f"x{a}", f"l{b}"), {"bearing": _rot2(bearing), "range": [rng_]},
                            np.diag([1 / sb**2, 1 / sr**2])))
        else:
            info = _sym(6, v[-21:])
            if kind == "between3rpy":
                rot = _ypr(*v[3:6])
            else:
                rot = _quat(*v[3:7])
                info = np.block([[info[3:, 3:], info[3:, :3]], [info[:3, 3:], info[:3, :3]]])
            factors.append(((f"x{a}", f"x{b}"), {"measured": list(rot.ravel()) + v[:3]}, info))
    return factors, vertices


def _close(got, want, tol=1e-9) -> bool:
    got, want = np.asarray(got, float), np.asarray(want, float)
    return got.shape == want.shape and bool(np.all(np.abs(got - want) <=
                                                   tol * np.maximum(1.0, np.abs(want))))


def compare(graph, text: str) -> str:
    """'' when the Graph is the independent parse of ``text``, else the first difference."""
    factors, vertices = independent_parse(text)
    if len(graph.factors) != len(factors):
        return f"{len(graph.factors)} factors, the file has {len(factors)}"
    for n, (f, (keys, measured, info)) in enumerate(zip(graph.factors, factors, strict=True)):
        if tuple(f.keys) != keys:
            return f"factor {n}: keys {f.keys} != {keys}"
        for name, want in measured.items():
            if not _close(f.measured[name], want):
                return f"factor {n}: {name} {f.measured[name]} != {want}"
        s = f.noise.sqrt_information
        if not _close(s.T @ s, info, 1e-9 * max(1.0, np.abs(info).max())):
            return f"factor {n}: information\n{s.T @ s}\n!= {info}"
    for key, var in graph.variables.items():
        if key in vertices and not _close(var.initial.to_storage(), vertices[key]):
            return f"vertex {key}: {var.initial.to_storage()} != {vertices[key]}"
    return ""


# --------------------------------------------------------------------------------------------
# classification
# --------------------------------------------------------------------------------------------

FILE_LEVEL = ("no edge",)
VALID = ("tabs", "spaces", "crlf", "vtab", "comments")  # must be accepted


def classify(case: Case, tmp: Path) -> tuple[str, str]:
    """('refused' | 'accepted' | 'FAILURE: …', detail) for one mutated file."""
    from fgc.interop.datasets import read_pose_graph

    path = tmp / f"fuzz{Path(case.base).suffix}"
    text = "\n".join(case.lines) + "\n"
    path.write_bytes(text.encode("utf-8"))
    with warnings.catch_warnings(record=True) as caught, np.errstate(divide="warn", over="warn",
                                                             invalid="warn", under="ignore"):
        warnings.simplefilter("always")
        try:
            graph = read_pose_graph(path)
        except FgcError as exc:
            msg = str(exc)
            if caught:
                return "FAILURE: warning", f"{caught[0].message} ({msg})"
            if case.mutation in VALID:
                return "FAILURE: refused a valid file", msg
            if re.match(rf"{re.escape(path.name)}:\d+: ", msg) or (
                    msg.startswith(str(path)) and any(s in msg for s in FILE_LEVEL)):
                return "refused", msg
            return "FAILURE: refusal without file and line", msg
        except Exception as exc:  # noqa: BLE001 - a traceback is what the fuzzing looks for
            return "FAILURE: traceback", f"{type(exc).__name__}: {exc}"
    if caught:
        return "FAILURE: warning", str(caught[0].message)
    if case.must_refuse:
        return "FAILURE: silent misread (accepted a file that must be refused)", ""
    diff = compare(graph, text)
    if diff:
        return "FAILURE: silent misread (accepted values differ from the file)", diff
    return "accepted", case.why


CASES = all_cases()


def _fast(cases: list[Case]) -> list[Case]:
    """Every mutation kind at least once where possible, then evenly spread, ``FAST`` in all."""
    kinds: dict[str, Case] = {}
    for c in cases:
        kinds.setdefault(re.sub(r"-L\d+$", "", c.mutation), c)
    chosen = list(kinds.values())[:FAST]
    rest = [c for c in cases if c not in chosen]
    step = max(1, len(rest) // max(1, FAST - len(chosen)))
    return (chosen + rest[::step])[:FAST]


def test_enough_cases_over_every_tag():
    from fgc.interop.datasets import _FORMATS

    assert set(TAGS) == set(_FORMATS)  # the fuzzing knows every tag the reader accepts
    assert len(CASES) >= 300
    tags = {_split(x)[0] for c in CASES for x in c.lines if _split(x)}
    assert set(TAGS) <= tags


def _check(case: Case, tmp_path: Path):
    outcome, detail = classify(case, tmp_path)
    assert not outcome.startswith("FAILURE"), f"{case.name}: {outcome}: {detail}\n" + \
        "\n".join(case.lines)


@pytest.mark.parametrize("case", _fast(CASES), ids=lambda c: c.name)
def test_fuzzed_file_fast(case, tmp_path):
    _check(case, tmp_path)


@pytest.mark.heavy
@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_fuzzed_file_all(case, tmp_path):
    _check(case, tmp_path)


def test_the_independent_parse_sees_a_changed_number(tmp_path):
    """The comparison can fail: a Graph read from one file against another file's text."""
    from fgc.interop.datasets import read_pose_graph

    lines = SMALL["small2d.g2o"]
    path = tmp_path / "a.g2o"
    path.write_text("\n".join(lines) + "\n")
    graph = read_pose_graph(path)
    assert compare(graph, "\n".join(lines)) == ""
    changed = [x.replace("BR 0 7 0.9", "BR 0 7 0.91") for x in lines]
    assert "bearing" in compare(graph, "\n".join(changed))


if __name__ == "__main__":  # counts per outcome over all cases
    import tempfile

    counts: Counter = Counter()
    why: Counter = Counter()
    with tempfile.TemporaryDirectory() as d:
        for c in CASES:
            outcome, detail = classify(c, Path(d))
            counts[outcome] += 1
            if outcome == "accepted":
                why[re.sub(r"-L\d+$", "", c.mutation) + ": " + detail] += 1
            elif outcome.startswith("FAILURE"):
                print(c.name, outcome, detail)
    print(f"{len(CASES)} files:", dict(counts))
    for w, n in sorted(why.items()):
        print(f"  accepted {n:3d}  {w}")
