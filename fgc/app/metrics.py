"""Trajectory metrics: TUM export, absolute trajectory error (ATE) and relative pose error (RPE).

The definitions are evo's (``evo`` 1.38, Grupp 2017), so numbers can be quoted side by side with
``evo_ape`` / ``evo_rpe``; ``tests/app/test_metrics.py`` compares against evo itself (a test
dependency, ``fgc[test]``; not a runtime dependency of fgc):

- **TUM format**: one line per pose, ``timestamp tx ty tz qx qy qz qw`` (Hamilton unit quaternion,
  scalar last; written with qw ≥ 0, floats in shortest round-trip form).
- **Alignment** (``evo_ape --align`` / ``--align --correct_scale``): Umeyama's least-squares
  similarity (1991, eqs. 34–43) from the estimated positions x_i onto the reference positions
  y_i, y ≈ s·R·x + t (s = 1 for "se3"); applied to every estimated pose as evo's
  ``PosePath3D.align`` does: translations scaled by s, then left-multiplied by [R | t].
- **ATE** (``evo_ape``, ``PoseRelation.translation_part``): e_i = ‖t(P_i) − t(Q_i)‖ for the
  aligned estimate P and the reference Q.
- **RPE** (``evo_rpe``, translation part, ``delta`` in frames):
  E_i = (Q_i⁻¹ Q_{i+Δ})⁻¹ (P_i⁻¹ P_{i+Δ}), e_i = ‖t(E_i)‖, over evo's pairs: consecutive
  (0, Δ), (Δ, 2Δ), … by default, every (i, i + Δ) with ``all_pairs`` (``--all_pairs``); the two
  coincide for Δ = 1. A rigid alignment leaves the RPE unchanged; a Sim(3) one rescales it.
- **Rotation errors** (``relation="rotation"``, evo's ``PoseRelation.rotation_angle_deg``,
  ``-r angle_deg``): the angle in degrees of the rotation of Q_i⁻¹ P_i (ATE) or of E_i (RPE),
  computed as atan2(‖vee(R − Rᵀ)‖ / 2, (tr R − 1) / 2), accurate near 0 and π.
- **Statistics** (evo's ``get_all_statistics``): rmse = √mean(e²), mean, median, population std,
  min, max, sse = Σe².

Poses are paired by index; evo's ``sync.associate_trajectories`` pairing by time is not
reimplemented, so the two trajectories must have the same length and timestamps that agree to
``max_time_diff`` (evo's default ``max_diff``, 0.01 s).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Union

import numpy as np

from fgc.errors import DataError, FgcError
from fgc.frontend.geometry import LieGroup, Point2, Point3, Pose2, Pose3

ALIGNMENTS = ("none", "se3", "sim3")
RELATIONS = ("translation", "rotation")  # evo's trans_part and angle_deg
MAX_TIME_DIFF = 0.01  # evo's default max_diff for associating timestamps (seconds)


@dataclass(frozen=True, eq=False)
class Trajectory:
    """Timestamped SE(3) poses: ``times`` (N,) in seconds, ``poses`` (N, 4, 4) homogeneous."""

    times: np.ndarray
    poses: np.ndarray

    def __post_init__(self):
        if self.poses.ndim != 3 or self.poses.shape[1:] != (4, 4):
            raise DataError(f"trajectory poses must have shape (N, 4, 4), got {self.poses.shape}")
        if self.times.shape != (len(self.poses),):
            raise DataError(f"trajectory has {len(self.poses)} poses but {self.times.size} "
                            "timestamps")
        if not (np.all(np.isfinite(self.times)) and np.all(np.isfinite(self.poses))):
            raise DataError("trajectory contains a non-finite time or pose")

    def __len__(self) -> int:
        return len(self.poses)

    @property
    def positions(self) -> np.ndarray:
        """(N, 3) translations."""
        return self.poses[:, :3, 3]


TrajectoryLike = Union[Trajectory, Sequence, Mapping]  # noqa: UP007 - a runtime alias


def pose_matrix(value) -> np.ndarray:
    """4×4 homogeneous matrix of a Pose3, Pose2 (z = 0) or point (identity rotation)."""
    m = np.eye(4)
    if isinstance(value, Pose3):
        m[:3, :3], m[:3, 3] = value.r.R, value.t
    elif isinstance(value, Pose2):
        c, s = float(value.r.c), float(value.r.s)
        m[:2, :2], m[:2, 3] = [[c, -s], [s, c]], [float(value.x()), float(value.y())]
    elif isinstance(value, (Point3, Point2)):
        m[: value.dim, 3] = value.v
    else:
        raise DataError(f"a trajectory needs Pose3, Pose2 or point values, got "
                        f"{type(value).__name__}")
    return m


def as_trajectory(poses: TrajectoryLike, times=None) -> Trajectory:
    """Normalise the accepted trajectory inputs to a :class:`Trajectory`.

    In: a Trajectory; a sequence of ``(time, pose)`` pairs; or a dict of values (e.g.
    ``Solution.values``) with ``times`` either a dict {key: time} (those keys, in time order), a
    sequence of times (matched in order to the dict's pose-valued entries: Pose3, else Pose2) or
    None (frame index 0, 1, …). Out: the Trajectory.
    """
    if isinstance(poses, Trajectory):
        return poses
    if isinstance(poses, Mapping):
        pairs = _pairs_from_values(poses, times)
    else:
        if times is not None:
            raise FgcError("times are given by the (time, pose) pairs; pass times=None")
        pairs = list(poses)
    if not pairs:
        raise DataError("the trajectory is empty")
    return Trajectory(np.array([float(t) for t, _ in pairs]),
                      np.stack([pose_matrix(p) for _, p in pairs]))


def _pairs_from_values(values: Mapping, times) -> list[tuple[float, LieGroup]]:
    if isinstance(times, Mapping):
        missing = [k for k in times if k not in values]
        if missing:
            raise FgcError(f"times given for keys {missing} that have no value")
        return sorted(((float(t), values[k]) for k, t in times.items()), key=lambda p: p[0])
    kind = Pose3 if any(isinstance(v, Pose3) for v in values.values()) else Pose2
    keys = [k for k, v in values.items() if isinstance(v, kind)]
    if times is None:
        times = range(len(keys))
    times = list(times)
    if len(times) != len(keys):
        raise FgcError(f"{len(times)} times for the {len(keys)} {kind.__name__} values")
    return [(float(t), values[k]) for t, k in zip(times, keys, strict=True)]


# --------------------------------------------------------------------------------------------
# TUM files
# --------------------------------------------------------------------------------------------


def quaternion_xyzw(rotation: np.ndarray) -> np.ndarray:
    """Unit quaternion [qx, qy, qz, qw] (qw ≥ 0) of a rotation matrix; Shepperd's method picks
    the largest of the four squared components, so it is accurate for every rotation."""
    r = np.asarray(rotation, float)
    tr = np.trace(r)
    k = int(np.argmax([tr, r[0, 0], r[1, 1], r[2, 2]]))
    if k == 0:
        q = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1], 1.0 + tr])
    else:
        i, j, m = k - 1, k % 3, (k + 1) % 3
        q = np.empty(4)
        q[i] = 1.0 + 2.0 * r[i, i] - tr
        q[j], q[m] = r[j, i] + r[i, j], r[m, i] + r[i, m]
        q[3] = r[m, j] - r[j, m]
    q /= np.linalg.norm(q)
    return -q if q[3] < 0 else q


def rotation_from_quaternion(q_xyzw) -> np.ndarray:
    """Rotation matrix of a (normalised here) quaternion [qx, qy, qz, qw]."""
    x, y, z, w = np.asarray(q_xyzw, float) / np.linalg.norm(q_xyzw)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def format_tum(poses: TrajectoryLike, times=None) -> str:
    """The TUM text of a trajectory (inputs as :func:`as_trajectory`), one line per pose."""
    traj = as_trajectory(poses, times)
    lines = []
    for t, m in zip(traj.times, traj.poses, strict=True):
        nums = [t, *m[:3, 3], *quaternion_xyzw(m[:3, :3])]
        lines.append(" ".join(repr(float(x)) for x in nums))
    return "\n".join(lines) + "\n"


def write_tum(path: str | Path, poses: TrajectoryLike, times=None) -> Path:
    """Write a trajectory (inputs as :func:`as_trajectory`) as a TUM file; returns the path."""
    path = Path(path)
    path.write_text(format_tum(poses, times))
    return path


def read_tum(path: str | Path) -> Trajectory:
    """Read a TUM file (``#`` comments and blank lines skipped); errors name file and line."""
    path = Path(path)
    times, mats = [], []
    for lineno, line in enumerate(path.read_text().splitlines(), start=1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        try:
            nums = [float(f) for f in line.split()]
        except ValueError:
            raise DataError(f"{path.name}:{lineno}: not a number in a TUM line") from None
        if len(nums) != 8:
            raise DataError(f"{path.name}:{lineno}: a TUM line has 8 numbers, got {len(nums)}")
        m = np.eye(4)
        m[:3, 3], m[:3, :3] = nums[1:4], rotation_from_quaternion(nums[4:8])
        times.append(nums[0])
        mats.append(m)
    if not mats:
        raise DataError(f"{path}: no poses")
    return Trajectory(np.array(times), np.stack(mats))


# --------------------------------------------------------------------------------------------
# alignment and errors
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Alignment:
    """Similarity y = scale·rotation·x + translation mapping estimate onto reference."""

    rotation: np.ndarray
    translation: np.ndarray
    scale: float = 1.0

    @classmethod
    def identity(cls) -> Alignment:
        return cls(np.eye(3), np.zeros(3), 1.0)

    def apply(self, poses: np.ndarray) -> np.ndarray:
        """Aligned copies of (N, 4, 4) poses (evo: scale translations, then left-multiply)."""
        out = poses.copy()
        out[:, :3, :3] = self.rotation @ poses[:, :3, :3]
        out[:, :3, 3] = (self.scale * poses[:, :3, 3]) @ self.rotation.T + self.translation
        return out


def umeyama(x: np.ndarray, y: np.ndarray, with_scale: bool = False) -> Alignment:
    """Least-squares similarity from points x (N, 3) onto y (N, 3) (Umeyama 1991, as evo)."""
    n = len(x)
    mx, my = x.mean(axis=0), y.mean(axis=0)
    var_x = np.sum((x - mx) ** 2) / n
    cov = (y - my).T @ (x - mx) / n
    u, d, vt = np.linalg.svd(cov)
    if np.count_nonzero(d > np.finfo(float).eps) < 2:
        raise FgcError("degenerate point set (collinear or too few poses): Umeyama alignment is "
                       "not possible")
    s = np.eye(3)
    if np.linalg.det(u) * np.linalg.det(vt) < 0:
        s[2, 2] = -1.0  # a proper rotation, not a reflection
    rot = u @ s @ vt
    scale = float(np.trace(np.diag(d) @ s) / var_x) if with_scale else 1.0
    return Alignment(rot, my - scale * rot @ mx, scale)


@dataclass(frozen=True, eq=False)
class TrajectoryError:
    """Per-pose (ATE) or per-pair (RPE) errors — translation in metres, or rotation in degrees
    (``relation``) — their statistics, and the alignment that was applied to the estimate."""

    errors: np.ndarray
    rmse: float
    mean: float
    median: float
    std: float
    min: float
    max: float
    sse: float
    alignment: Alignment
    relation: str = "translation"

    @property
    def unit(self) -> str:
        """``"m"`` for translation errors, ``"deg"`` for rotation errors."""
        return "m" if self.relation == "translation" else "deg"

    def statistics(self) -> dict[str, float]:
        """rmse, mean, median, std, min, max, sse as a dict (evo's ``get_all_statistics``)."""
        return {k: getattr(self, k) for k in ("rmse", "mean", "median", "std", "min", "max",
                                                "sse")}

    @classmethod
    def of(cls, errors: np.ndarray, alignment: Alignment,
           relation: str = "translation") -> TrajectoryError:
        e = np.asarray(errors, float)
        return cls(e, float(np.sqrt(np.mean(e * e))), float(np.mean(e)), float(np.median(e)),
                   float(np.std(e)), float(e.min()), float(e.max()), float(np.sum(e * e)),
                   alignment, relation)


def rotation_angles_deg(poses: np.ndarray) -> np.ndarray:
    """Rotation angle in degrees of each (N, 4, 4) pose (or (N, 3, 3) rotation)."""
    r = poses[:, :3, :3]
    vee = np.stack([r[:, 2, 1] - r[:, 1, 2], r[:, 0, 2] - r[:, 2, 0], r[:, 1, 0] - r[:, 0, 1]],
                   axis=1)
    cos = (np.trace(r, axis1=1, axis2=2) - 1.0) / 2.0
    return np.degrees(np.arctan2(np.linalg.norm(vee, axis=1) / 2.0, cos))


def _errors(delta_poses: np.ndarray, relation: str) -> np.ndarray:
    if relation not in RELATIONS:
        raise FgcError(f"relation must be one of {RELATIONS}, got {relation!r}")
    if relation == "rotation":
        return rotation_angles_deg(delta_poses)
    return np.linalg.norm(delta_poses[:, :3, 3], axis=1)


def _inverse(poses: np.ndarray) -> np.ndarray:
    """SE(3) inverses [Rᵀ | −Rᵀt] of (N, 4, 4) poses."""
    out = np.zeros_like(poses)
    rt = np.transpose(poses[:, :3, :3], (0, 2, 1))
    out[:, :3, :3] = rt
    out[:, :3, 3] = -np.einsum("nij,nj->ni", rt, poses[:, :3, 3])
    out[:, 3, 3] = 1.0
    return out


def _paired(estimate, reference, max_time_diff: float) -> tuple[Trajectory, Trajectory]:
    est, ref = as_trajectory(estimate), as_trajectory(reference)
    if len(est) != len(ref):
        raise FgcError(f"the estimate has {len(est)} poses and the reference {len(ref)}; poses "
                       "are paired by index")
    gap = np.abs(est.times - ref.times)
    if gap.max() > max_time_diff:
        i = int(np.argmax(gap))
        raise FgcError(f"pose {i}: estimate time {est.times[i]} and reference time "
                       f"{ref.times[i]} differ by more than {max_time_diff} s")
    return est, ref


def _aligned(est: Trajectory, ref: Trajectory, align: str) -> tuple[np.ndarray, Alignment]:
    if align not in ALIGNMENTS:
        raise FgcError(f"align must be one of {ALIGNMENTS}, got {align!r}")
    if align == "none":
        return est.poses, Alignment.identity()
    al = umeyama(est.positions, ref.positions, with_scale=align == "sim3")
    return al.apply(est.poses), al


def ate(estimate: TrajectoryLike, reference: TrajectoryLike, align: str = "none",
        max_time_diff: float = MAX_TIME_DIFF, relation: str = "translation") -> TrajectoryError:
    """Absolute trajectory error (evo ``ape``, translation part or rotation angle).

    In: estimate and reference (inputs as :func:`as_trajectory`, paired by index), ``align``
    "none", "se3" (``--align``) or "sim3" (``--align --correct_scale``), ``relation``
    "translation" or "rotation". Out: the errors ‖t(P_i) − t(Q_i)‖ (m) or the angles of
    Q_i⁻¹ P_i (degrees) of the aligned estimate, and their statistics.
    """
    if relation not in RELATIONS:
        raise FgcError(f"relation must be one of {RELATIONS}, got {relation!r}")
    est, ref = _paired(estimate, reference, max_time_diff)
    poses, al = _aligned(est, ref, align)
    if relation == "translation":  # the difference directly, as evo's translation_part
        return TrajectoryError.of(np.linalg.norm(poses[:, :3, 3] - ref.positions, axis=1), al)
    return TrajectoryError.of(_errors(_inverse(ref.poses) @ poses, relation), al, relation)


def rpe(estimate: TrajectoryLike, reference: TrajectoryLike, delta: int = 1,
        align: str = "none", all_pairs: bool = False,
        max_time_diff: float = MAX_TIME_DIFF, relation: str = "translation") -> TrajectoryError:
    """Relative pose error (evo ``rpe``, translation part or rotation angle, ``delta`` in
    frames).

    In: as :func:`ate`, plus ``delta`` ≥ 1 and ``all_pairs``. Out: e_i = ‖t(E_i)‖ (m), or the
    angle of E_i's rotation (degrees) for ``relation="rotation"``, with
    E_i = (Q_i⁻¹ Q_j)⁻¹ (P_i⁻¹ P_j) for the pairs (i, j) = (0, Δ), (Δ, 2Δ), … (evo's default)
    or, with ``all_pairs``, (i, i + Δ) for i = 0 … N−1−Δ; and their statistics.
    """
    if int(delta) != delta or delta < 1:
        raise FgcError(f"delta must be a positive whole number of frames, got {delta}")
    est, ref = _paired(estimate, reference, max_time_diff)
    if len(est) <= delta:
        raise FgcError(f"RPE with delta={delta} needs more than {delta} poses, got {len(est)}")
    p, al = _aligned(est, ref, align)
    q = ref.poses
    d = int(delta)
    ids = np.arange(len(p)) if all_pairs else np.arange(0, len(p), d)
    i = ids[ids + d < len(p)] if all_pairs else ids[:-1]
    j = i + d
    e = _inverse(_inverse(q[i]) @ q[j]) @ (_inverse(p[i]) @ p[j])
    return TrajectoryError.of(_errors(e, relation), al, relation)
