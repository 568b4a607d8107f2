"""Tests of the schedule stage (fgc/schedule): classification, orderings, Bayes tree, checks, JSON.

Chains are checked against serial elimination and a brute-force search over all cluster orders;
general graphs against GTSAM's COLAMD with fill measured by GTSAM's own elimination (integer
counts, compared exactly or with the stated 1.1 factor).
"""

from __future__ import annotations

import importlib.util
import itertools
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from fgc.compiler.schedule import (
    FactorInfo,
    GraphStructure,
    IncrementalPlan,
    Schedule,
    VarInfo,
    check_schedule,
    schedule,
)
from fgc.errors import FgcError, StructureError

ROOT = Path(__file__).resolve().parents[2]


def _load_bench():
    """The GTSAM helpers live in bench/bench_ordering.py; load that file as a module."""
    path = ROOT / "bench" / "bench_ordering.py"
    spec = importlib.util.spec_from_file_location("bench_ordering", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules["bench_ordering"] = module
    spec.loader.exec_module(module)
    return module


bench = _load_bench()


# ---------------------------------------------------------------------------- graph builders


def pose_chain(n: int, closures: tuple[tuple[int, int], ...] = ()) -> GraphStructure:
    """Pose2 chain x0..x(n-1): prior on x0, odometry between neighbours, optional closures."""
    variables = [(f"x{i}", 3, "Pose2") for i in range(n)]
    factors = [("prior0", ("x0",), 3)]
    factors += [(f"odom{i}", (f"x{i}", f"x{i + 1}"), 3) for i in range(n - 1)]
    factors += [(f"loop{a}_{b}", (f"x{a}", f"x{b}"), 3) for a, b in closures]
    return GraphStructure.from_lists(variables, factors)


def lio_chain(n: int, combined: bool = True) -> GraphStructure:
    """LIO-like chain: keyframe j = pose x_j (6), velocity v_j (3), IMU bias b_j (6).

    Priors on x0, v0, b0 separately; GPS on every pose; LiDAR between consecutive poses; either a
    combined IMU factor on both keyframes (15 rows) or GTSAM's ImuFactor on (x, v, x', v', b) plus a
    bias-between factor.
    """
    variables = []
    for j in range(n):
        variables += [(f"x{j}", 6, "Pose3"), (f"v{j}", 3, "Vector3"), (f"b{j}", 6, "ImuBias")]
    factors = [("prior_x0", ("x0",), 6), ("prior_v0", ("v0",), 3), ("prior_b0", ("b0",), 6)]
    factors += [(f"gps{j}", (f"x{j}",), 3) for j in range(n)]
    for j in range(n - 1):
        a, b = (f"x{j}", f"v{j}", f"b{j}"), (f"x{j + 1}", f"v{j + 1}", f"b{j + 1}")
        if combined:
            factors.append((f"imu{j}", (a[0], a[1], b[0], b[1], a[2], b[2]), 15))
        else:
            factors.append((f"imu{j}", (a[0], a[1], b[0], b[1], a[2]), 9))
            factors.append((f"bias{j}", (a[2], b[2]), 6))
        factors.append((f"lidar{j}", (a[0], b[0]), 6))
    return GraphStructure.from_lists(variables, factors)


def cluster_fill(structure: GraphStructure, clusters: list[tuple[str, ...]], order) -> int:
    """Brute-force reference: scalar R non-zeros of eliminating whole clusters in ``order``.

    Independent of fgc's elimination code: a cluster-level elimination game where eliminating C
    with neighbour clusters N costs D_C(D_C+1)/2 + D_C·ΣD_N and connects N pairwise.
    """
    dim = {v.key: v.dim for v in structure.variables}
    size = [sum(dim[k] for k in cluster) for cluster in clusters]
    where = {k: c for c, cluster in enumerate(clusters) for k in cluster}
    adjacent = [set() for _ in clusters]
    for factor in structure.factors:
        touched = {where[k] for k in factor.keys}
        for c in touched:
            adjacent[c] |= touched - {c}
    total = 0
    for c in order:
        neighbours = adjacent[c]
        total += size[c] * (size[c] + 1) // 2 + size[c] * sum(size[n] for n in neighbours)
        for n in neighbours:
            adjacent[n] |= neighbours - {n}
            adjacent[n].discard(c)
    return total


# ---------------------------------------------------------------------------- classification


def test_pose_chain_is_chain_of_single_poses():
    result = schedule(pose_chain(6))
    assert result.structure_class == "chain"
    assert result.clusters == tuple((f"x{i}",) for i in range(6))


@pytest.mark.parametrize("combined", [True, False], ids=["combined-imu", "imu+bias-between"])
def test_lio_chain_clusters_are_keyframes(combined):
    result = schedule(lio_chain(8, combined))
    assert result.structure_class == "chain"
    assert result.clusters == tuple((f"x{j}", f"v{j}", f"b{j}") for j in range(8))


def test_pose_graph_with_loop_closures_is_general():
    structure = pose_chain(30, closures=((0, 12), (5, 20), (9, 29), (14, 27)))
    result = schedule(structure)
    assert result.structure_class == "general"
    assert result.clusters == ()
    assert result.ordering in ("min-degree", "nested-dissection")


def test_single_loop_is_general():
    result = schedule(pose_chain(12, closures=((0, 11),)))
    assert result.structure_class == "general"


def test_w100_is_general():
    structure = bench.structure_from_gtsam(bench.load_w100())
    assert schedule(structure, "min-degree").structure_class == "general"


def test_disconnected_graph_with_priors_is_general():
    first, second = pose_chain(3), pose_chain(3)
    factors = [
        FactorInfo(f.name + "b", tuple(k + "b" for k in f.keys), f.dim) for f in second.factors
    ]
    variables = [VarInfo(v.key + "b", v.dim, v.type_name) for v in second.variables]
    result = schedule(
        GraphStructure(first.variables + tuple(variables), first.factors + tuple(factors))
    )
    assert result.structure_class == "general"
    assert len(result.roots) == 2


def test_chain_orderings_rejected_on_general_graph():
    structure = pose_chain(10, closures=((0, 5), (2, 8), (1, 9)))
    with pytest.raises(StructureError, match="two-ended.*general"):
        schedule(structure, "two-ended")
    with pytest.raises(StructureError, match="incremental_k.*general"):
        schedule(structure, incremental_k=3)


# ---------------------------------------------------------------------------- chain orderings

CHAIN_SIZES = [4, 5, 6, 7, 10, 31, 100, 1000]


@pytest.mark.parametrize("n", CHAIN_SIZES)
@pytest.mark.parametrize("build", [lio_chain, pose_chain], ids=["lio", "pose"])
def test_two_ended_same_fill_as_serial_half_the_steps(build, n):
    structure = build(n)
    two_ended = schedule(structure, "two-ended")
    serial = schedule(structure, "serial")
    assert two_ended.ordering == "two-ended" and schedule(structure).ordering == "two-ended"
    assert two_ended.r_nonzeros == serial.r_nonzeros == two_ended.dense_r_nonzeros
    assert two_ended.num_fill_edges == serial.num_fill_edges == 0
    assert two_ended.num_sequential_steps == math.ceil(n / 2)
    assert serial.num_sequential_steps == n


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6, 7])
@pytest.mark.parametrize("build", [lio_chain, pose_chain], ids=["lio", "pose"])
def test_two_ended_attains_brute_force_minimum_fill(build, n):
    structure = build(n)
    result = schedule(structure, "two-ended")
    clusters = list(result.clusters)
    best = min(cluster_fill(structure, clusters, p) for p in itertools.permutations(range(n)))
    assert result.r_nonzeros == best


def test_two_ended_levels_take_one_cluster_from_each_end():
    result = schedule(lio_chain(7), "two-ended")
    levels = [[result.steps[s].clusters for s in level] for level in result.levels]
    assert levels == [[(0,), (6,)], [(1,), (5,)], [(2,), (4,)], [(3,)]]
    root = result.steps[result.roots[0]]
    assert root.frontals == ("x3", "v3", "b3") and root.separator == ()
    assert result.back_substitution[0] == result.levels[-1]  # from the middle outwards
    assert result.steps[result.levels[0][0]].separator == ("x1", "v1", "b1")


def test_two_ended_even_chain_merges_the_middle_pair_into_the_root():
    result = schedule(lio_chain(6), "two-ended")
    root = result.steps[result.roots[0]]
    assert root.clusters == (2, 3)
    assert result.num_sequential_steps == 3


def test_imu_plus_bias_between_chain_two_ended_fill_no_worse_than_serial():
    structure = lio_chain(12, combined=False)
    two_ended, serial = schedule(structure, "two-ended"), schedule(structure, "serial")
    assert two_ended.r_nonzeros <= serial.r_nonzeros
    assert two_ended.r_nonzeros <= schedule(structure, "min-degree").r_nonzeros
    assert two_ended.num_sequential_steps == 6


def test_natural_ordering_on_pose_chain_is_serial():
    result = schedule(pose_chain(9), "natural")
    assert result.order == tuple(f"x{i}" for i in range(9))
    assert result.r_nonzeros == schedule(pose_chain(9), "serial").r_nonzeros


def test_describe_lists_every_level():
    text = schedule(pose_chain(5)).describe()
    assert "two-ended ordering: 5 steps in 3 levels" in text
    assert "level 2: [x2 | -]" in text


def test_step_rows_and_factors_on_lio_chain():
    structure = lio_chain(5)
    result = schedule(structure, "serial")
    first = result.steps[0]
    names = [structure.factors[f].name for f in first.factors]
    assert sorted(names) == ["gps0", "imu0", "lidar0", "prior_b0", "prior_v0", "prior_x0"]
    assert first.rows == 6 + 3 + 6 + 3 + 15 + 6
    assert first.new_factor_rows == 15  # min(rows - 15 frontal columns, 15 separator columns)
    assert result.steps[1].children == (0,) and result.steps[1].rows == 3 + 15 + 6 + 15


# ---------------------------------------------------------------------------- general graphs


def test_min_degree_on_loop_closure_graph_is_valid_and_fills():
    structure = pose_chain(40, closures=((0, 20), (5, 35), (10, 30), (15, 39)))
    result = schedule(structure, "min-degree")
    check_schedule(structure, result)
    assert result.num_fill_edges > 0
    assert sorted(result.order) == sorted(v.key for v in structure.variables)


def test_nested_dissection_is_shallower_on_w100():
    structure = bench.structure_from_gtsam(bench.load_w100())
    by_degree = schedule(structure, "min-degree")
    by_dissection = schedule(structure, "nested-dissection")
    assert by_dissection.num_sequential_steps < by_degree.num_sequential_steps


@pytest.mark.parametrize(
    "load",
    [bench.load_w100, bench.load_pose3example, bench.random_pose_graph],
    ids=["w100", "pose3example", "random400"],
)
def test_fill_against_gtsam_colamd(load):
    """Our ordering's fill <= 1.1 × COLAMD's, both measured by GTSAM's eliminateSequential."""
    problem = load()
    structure = bench.structure_from_gtsam(problem)
    ours = schedule(structure)
    ours_fill = bench.gtsam_fill(problem, list(ours.order))
    colamd_fill = bench.gtsam_fill(problem, bench.colamd_keys(problem))
    assert ours_fill <= 1.1 * colamd_fill
    # fgc's own structural count is exactly what GTSAM stores
    assert ours.r_nonzeros == ours_fill
    assert schedule(structure, bench.colamd_keys(problem)).r_nonzeros == colamd_fill


# ---------------------------------------------------------------------------- incremental plans


def test_incremental_plan_with_explicit_batch_steps():
    result = schedule(lio_chain(30), incremental_k=3, batch_every=[5, 15, 25])
    plan = result.incremental
    assert plan.window == 3 and plan.batch_keyframes == (5, 15, 25)
    updates = plan.updates
    assert [u.keyframe for u in updates] == list(range(30))
    assert updates[0].clusters == (0,) and updates[1].clusters == (0, 1)
    assert updates[4].mode == "incremental" and updates[4].clusters == (2, 3, 4)
    assert updates[4].kept == 2
    assert updates[5].mode == "batch" and updates[5].clusters == tuple(range(6))
    assert updates[6].clusters == (4, 5, 6)
    assert sum(u.mode == "batch" for u in updates) == 3


def test_incremental_plan_with_batch_period():
    plan = schedule(pose_chain(25), incremental_k=2, batch_every=10).incremental
    assert plan.batch_keyframes == (10, 20)
    assert plan.updates[11].clusters == (10, 11)


def test_incremental_arguments_checked():
    with pytest.raises(ValueError, match="incremental_k"):
        schedule(pose_chain(5), incremental_k=0)
    with pytest.raises(ValueError, match="batch_every needs incremental_k"):
        schedule(pose_chain(5), batch_every=2)
    with pytest.raises(ValueError, match="outside"):
        schedule(pose_chain(5), incremental_k=2, batch_every=[7])


# ---------------------------------------------------------------------------- JSON round trip


@pytest.mark.parametrize(
    "make",
    [
        lambda: schedule(lio_chain(9), incremental_k=3, batch_every=[5]),
        lambda: schedule(pose_chain(12, closures=((0, 6), (3, 11), (2, 9)))),
    ],
    ids=["chain-incremental", "general"],
)
def test_schedule_round_trips_through_json(make):
    result = make()
    text = json.dumps(result.to_dict())
    back = Schedule.from_dict(json.loads(text))
    assert back == result
    assert isinstance(back.steps[0].frontals, tuple)


def test_structure_and_plan_round_trip_through_json():
    structure = lio_chain(4, combined=False)
    assert GraphStructure.from_dict(json.loads(json.dumps(structure.to_dict()))) == structure
    plan = schedule(structure, incremental_k=2).incremental
    assert IncrementalPlan.from_dict(json.loads(json.dumps(plan.to_dict()))) == plan


def test_schedule_is_independent_of_hash_seed():
    """Same JSON under different string-hash seeds (sets of keys never decide the order)."""
    code = (
        "import json, sys; sys.path.insert(0, 'tests/compiler'); import test_schedule as t;"
        "from fgc.compiler.schedule import schedule;"
        "s = t.pose_chain(40, closures=((0, 20), (5, 35), (10, 30), (15, 39)));"
        "print(json.dumps([schedule(s).to_dict(), schedule(t.lio_chain(6, False)).to_dict()]))"
    )
    outputs = set()
    for seed in ("1", "2"):
        env = {**os.environ, "PYTHONHASHSEED": seed}
        env["PYTHONPATH"] = os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")])
        done = subprocess.run(
            [sys.executable, "-c", code],
            cwd=ROOT,
            env=env,
            capture_output=True,
            text=True,
            check=True,
        )
        outputs.add(done.stdout)
    assert len(outputs) == 1


# ---------------------------------------------------------------------------- structure errors


def test_unconstrained_variable_is_named():
    structure = GraphStructure.from_lists(
        [("x6", 3, "Pose2"), ("x7", 3, "Pose2")], [("prior", ("x6",), 3)]
    )
    with pytest.raises(StructureError, match="variable 'x7' is not constrained by any factor"):
        schedule(structure)


def test_component_without_prior_is_gauge_freedom():
    base = pose_chain(5)
    variables = base.variables + (VarInfo("x5", 3, "Pose2"), VarInfo("x6", 3, "Pose2"))
    factors = base.factors + (FactorInfo("odom56", ("x5", "x6"), 3),)
    with pytest.raises(StructureError, match=r"component \{x5, x6\} has no prior: gauge freedom"):
        schedule(GraphStructure(variables, factors))


def test_too_many_variables():
    with pytest.raises(StructureError, match="12 variables, more than max_variables=10"):
        schedule(pose_chain(12), max_variables=10)


def test_structurally_rank_deficient_step_is_named():
    # a Pose3 chain anchored only by a 3-row GPS factor: rotation about it is unobservable
    structure = GraphStructure.from_lists(
        [("x0", 6, "Pose3"), ("x1", 6, "Pose3")],
        [("gps0", ("x0",), 3), ("between01", ("x0", "x1"), 6)],
    )
    with pytest.raises(StructureError, match=r"eliminating \{x0, x1\} receives 9 rows for 12"):
        schedule(structure)


@pytest.mark.parametrize(
    ("variables", "factors", "message"),
    [
        ([("x0", 3, "Pose2"), ("x0", 3, "Pose2")], [], "variable 'x0' is declared twice"),
        ([("x0", 0, "Pose2")], [], "variable 'x0' has dimension 0"),
        ([("x0", 3, "Pose2")], [("gps", ("x9",), 3)], "factor 'gps' refers to undeclared .* 'x9'"),
        ([("x0", 3, "Pose2")], [("p", ("x0",), 0)], "factor 'p' has 0 rows"),
        ([("x0", 3, "Pose2")], [("p", ("x0", "x0"), 3)], "factor 'p' lists a variable twice"),
    ],
)
def test_malformed_structures_name_the_item(variables, factors, message):
    with pytest.raises(StructureError, match=message):
        GraphStructure.from_lists(variables, factors)


def test_bad_ordering_arguments():
    with pytest.raises(ValueError, match="unknown ordering 'colamd'"):
        schedule(pose_chain(4), "colamd")
    with pytest.raises(ValueError, match="misses variable 'x3'"):
        schedule(pose_chain(4), ["x0", "x1", "x2"])
    assert issubclass(StructureError, FgcError)


# ---------------------------------------------------------------------------- check_schedule


def _tamper(result: Schedule, index: int, **changes) -> Schedule:
    data = result.to_dict()
    data["steps"][index].update(changes)
    return Schedule.from_dict(data)


def test_check_schedule_catches_inconsistencies():
    structure = lio_chain(5)
    result = schedule(structure)
    check_schedule(structure, result)
    with pytest.raises(StructureError, match="separator"):
        check_schedule(structure, _tamper(result, 0, separator=["x1", "v1"]))
    with pytest.raises(StructureError, match="variable 'x0' is never eliminated"):
        check_schedule(structure, _tamper(result, 0, frontals=["v0", "b0"]))
    with pytest.raises(StructureError, match="'x1' is eliminated 2 times"):
        check_schedule(structure, _tamper(result, 0, frontals=["x0", "v0", "b0", "x1"]))
    with pytest.raises(StructureError, match="levels"):
        check_schedule(structure, Schedule.from_dict({**result.to_dict(), "levels": [[0, 1]]}))
