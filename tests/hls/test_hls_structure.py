"""The HLS backend's structure-aware code generation, checked in Python without a compiler.

- sparsity: the whitened pattern of each block and the Gram tiles that skip its structural zeros;
- steps: the specialised step patterns move exactly what the generic table-driven assembly moves,
  and a QR pattern's Householder plan lists every row a reflection can touch;
- printing for lanes (the native build's flags: ``test_native.py``).

Whether the emitted C++ computes the simulator's numbers is ``test_hls_csim.py``'s job.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph
from fgc.compiler.kernel import Kernel
from fgc.ir.codes import NOISE_CODES
from fgc.ir.program import SolverConfig
from fgc_backends.cfamily.blocks import block_contexts
from fgc_backends.cfamily.errors import CodegenError
from fgc_backends.cfamily.printer import print_kernel
from fgc_backends.cfamily.sparsity import TILE, ZERO, block_pattern
from fgc_backends.cfamily.steps import step_patterns
from fgc_backends.cfamily.tables import build_tables
from fgc_backends.hls import HlsConfig

lio = example("lio")
pose_graph = example("pose_graph")

ROOT = Path(__file__).resolve().parents[2]



@pytest.fixture(scope="module")
def programs() -> dict:
    out = {}
    for name, graph in (("lio", lio.build(N=8)), ("w100", pose_graph.build())):
        for linear in ("qr", "cholesky"):
            out[name, linear] = compile_graph(graph, SolverConfig(linear=linear), name=name)
    return out


def _kinds(block) -> tuple[int, ...]:
    return tuple(NOISE_CODES[m.noise_kind] for m in block.members)


# ---- sparsity --------------------------------------------------------------------------------


def test_full_noise_rows_are_the_union_of_the_rows_below(programs):
    program = programs["lio", "qr"]
    imu = next(b for b in program.blocks if b.name.startswith("CombinedImuFactor"))
    pattern = block_pattern(imu, _kinds(imu), "imu")
    first, rows, kind = pattern.members[0]
    assert kind == 2
    for i in range(first, first + rows):
        union = [any(pattern.raw[j][c] != ZERO for j in range(i, first + rows))
                 for c in range(pattern.stride)]
        assert list(pattern.whitened[i]) == union
    for first, rows, kind in pattern.members[1:]:  # LiDAR odometry: diagonal noise
        assert kind == 1
        for i in range(first, first + rows):
            assert list(pattern.whitened[i]) == [code != ZERO for code in pattern.raw[i]]
    assert sum(map(sum, pattern.whitened)) < pattern.m * pattern.stride  # zeros are left


@pytest.mark.parametrize("name", ["lio", "w100"])
def test_gram_tiles_cover_every_structural_entry(programs, name):
    for ctx in block_contexts(programs[name, "cholesky"]):
        pattern, tiles = ctx.pattern, ctx.tiles
        covered = {}
        for t in range(tiles.count):
            p0, q0, first, n, wide = tiles.table[5 * t:5 * t + 5]
            assert q0 + (wide - 1) * TILE <= p0 and p0 % TILE == 0 and q0 % TILE == 0
            assert wide in (1, 2)
            rows = set(tiles.rows[first:first + n])
            for p in range(p0, min(p0 + TILE, pattern.stride)):
                for q in range(q0, min(q0 + wide * TILE, p + 1)):
                    assert (p, q) not in covered  # each entry summed once
                    covered[p, q] = rows
        for p in range(pattern.stride):
            for q in range(p + 1):
                needed = set(pattern.gram_rows(p, q))
                assert needed <= covered.get((p, q), set()), (ctx.index, p, q)
        assert ctx.padded % TILE == 0 and ctx.padded >= pattern.stride


def test_structure_disagreeing_with_the_kernel_is_refused(programs):
    block = programs["w100", "qr"].blocks[0]
    codes = [list(map(list, k)) for k in block.structure]
    i, j = next((i, j) for i, row in enumerate(codes[0]) for j, c in enumerate(row) if c == "x")
    codes[0][i][j] = ZERO
    bad = dataclasses.replace(block, structure=tuple(tuple(map(tuple, k)) for k in codes))
    with pytest.raises(CodegenError, match="block type 7.*structure code '0'"):
        block_pattern(bad, _kinds(bad), "block type 7")


# ---- specialised steps -----------------------------------------------------------------------


def _generic_assembly(t: dict, s: int, operands: list, cholesky: bool, mu: float):
    """What the generic C++ step assembles (its table-driven loops, in NumPy)."""
    w, f = t["STEP_W"][s], t["STEP_F"][s]
    facs = t["STEP_FACTORS"][t["STEP_FACTOR_BEGIN"][s]:t["STEP_FACTOR_BEGIN"][s + 1]]
    kids = t["STEP_CHILDREN"][t["STEP_CHILD_BEGIN"][s]:t["STEP_CHILD_BEGIN"][s + 1]]
    out = np.zeros((w if cholesky else t["STEP_ROWS"][s], w + 1))
    row = 0
    for k, fac in enumerate(facs):
        cm = t["FACTOR_COLMAP"][t["FACTOR_COLMAP_BEGIN"][fac]:t["FACTOR_COLMAP_BEGIN"][fac + 1]]
        d, op = len(cm), operands[k]
        full = [*cm, w]
        if cholesky:
            for p in range(d + 1):
                for q in range(p + 1):
                    if (p, q) != (d, d):
                        a, b = sorted((full[p], full[q]))
                        out[a, b] += op[p * (p + 1) // 2 + q]
        else:
            for r in range(len(op) // (d + 1)):
                out[row, full] = op[r * (d + 1):(r + 1) * (d + 1)]
                row += 1
    for j, c in enumerate(kids):
        sc = t["STEP_W"][c] - t["STEP_F"][c]
        full = [*t["STEP_SEPMAP"][t["STEP_SEPMAP_BEGIN"][c]:t["STEP_SEPMAP_BEGIN"][c + 1]], w]
        op = operands[len(facs) + j]
        if cholesky:
            for a in range(sc):
                for b in range(a, sc + 1):
                    lo, hi = sorted((full[a], full[b]))
                    out[lo, hi] += op[a * (sc + 1) + b]
        else:
            for r in range(t["STEP_NF_ROWS"][c]):
                out[row, full] = op[r * (sc + 1):(r + 1) * (sc + 1)]
                row += 1
    if not cholesky:
        out[np.arange(row, row + f), np.arange(f)] = mu
    return out


@pytest.mark.parametrize("key", [("lio", "qr"), ("lio", "cholesky"), ("w100", "qr"),
                                 ("w100", "cholesky")])
def test_specialised_steps_assemble_what_the_tables_do(programs, key):
    program = programs[key]
    cholesky = key[1] == "cholesky"
    blocks = block_contexts(program)
    tables = build_tables(program, damped=True, cholesky=cholesky)
    t = {a.name: a.values for a in tables.arrays}
    patterns, of_step = step_patterns(tables, {b.index: b.pattern for b in blocks}, cholesky)
    assert patterns, "the examples repeat step shapes"
    rng = np.random.default_rng(1)
    for pat in patterns:
        for s in pat.steps:
            assert of_step[s] == pat.index
            operands = []
            for fac in t["STEP_FACTORS"][t["STEP_FACTOR_BEGIN"][s]:t["STEP_FACTOR_BEGIN"][s + 1]]:
                ctx = blocks[t["FACTOR_BLOCK"][fac]]
                pattern = ctx.pattern
                if cholesky:  # a Gram with the structural zeros of the block
                    op = np.zeros(pattern.stride * (pattern.stride + 1) // 2)
                    for p in range(pattern.stride):
                        for q in range(p + 1):
                            if pattern.gram_rows(p, q):
                                op[p * (p + 1) // 2 + q] = rng.standard_normal()
                else:
                    op = rng.standard_normal((pattern.m, pattern.stride)) * np.array(
                        pattern.whitened)
                operands.append(op.ravel())
            for c in t["STEP_CHILDREN"][t["STEP_CHILD_BEGIN"][s]:t["STEP_CHILD_BEGIN"][s + 1]]:
                sc = t["STEP_W"][c] - t["STEP_F"][c]
                rows = sc if cholesky else t["STEP_NF_ROWS"][c]
                operands.append(np.triu(rng.standard_normal((rows, sc + 1))).ravel())
            expected = _generic_assembly(t, s, operands, cholesky, mu=0.5)
            got = np.zeros_like(expected)
            for r, c, k, i in pat.moves:
                got[r, c] += operands[k][i]
            if not cholesky:
                got[np.arange(pat.rows - pat.f, pat.rows), np.arange(pat.f)] = 0.5
            np.testing.assert_array_equal(got, expected)


def test_householder_plan_lists_every_row_a_reflection_touches(programs):
    program = programs["lio", "qr"]
    blocks = block_contexts(program)
    tables = build_tables(program, damped=True, cholesky=False)
    patterns, _ = step_patterns(tables, {b.index: b.pattern for b in blocks}, cholesky=False)
    rng = np.random.default_rng(2)
    for pat in patterns:
        w = np.zeros((pat.rows, pat.w + 1))
        for r, c, _, _ in pat.moves:
            w[r, c] = rng.standard_normal()
        w[np.arange(pat.rows - pat.f, pat.rows), np.arange(pat.f)] = 0.3
        pos = 0
        for j in range(min(pat.rows, pat.w + 1)):
            n = pat.plan[pos]
            planned = list(pat.plan[pos + 1:pos + 1 + n])
            pos += n + 1
            touched = [i for i in range(j, pat.rows) if i == j or w[i, j] != 0]
            assert planned[0] == j and set(touched) <= set(planned), j
            x = w[planned, j].copy()  # the reflection, on the planned rows
            alpha = -np.copysign(np.linalg.norm(x), x[0])
            v = x.copy()
            v[0] -= alpha
            if v @ v > 0:
                w[planned] -= np.outer(2 * v / (v @ v), v @ w[planned])
                w[planned[1:], j] = 0
        assert pos == len(pat.plan)


def test_chain_steps_collapse_into_two_patterns(programs):
    program = programs["lio", "cholesky"]
    blocks = block_contexts(program)
    tables = build_tables(program, damped=True, cholesky=True)
    patterns, of_step = step_patterns(tables, {b.index: b.pattern for b in blocks}, True)
    assert len(patterns) == 2  # one per end of the two-ended chain
    assert sum(s == -1 for s in of_step) <= 4  # the ends meet priors and each other


# ---- printing and flags ----------------------------------------------------------------------


def test_kernels_print_for_lanes():
    x, y, t = sp.symbols("x y t", real=True)
    kernel = Kernel((x, y), ((t, x * y + sp.sqrt(x)),), (2 * t, x))
    scalar = print_kernel(kernel, ["in[0]", "in[1]"], "k")
    vector = print_kernel(kernel, ["in[0]", "in[1]"], "k", vector=True)
    assert scalar.intermediates == ("const T t0 = fgc_sqrt(in[0]) + in[0]*in[1];",)
    assert vector.intermediates == ("const V t0 = v_fgc_sqrt(in[0]) + in[0]*in[1];",)
    assert vector.outputs == scalar.outputs


# ---- the dataflow accelerator: the emitted network is the plan's ------------------------------


def _emit_accel(tmp_path, graph, name, backsub_lanes=None, **solver):
    """``backsub_lanes``: the design's (None: the automatic width, by columns on a chain)."""
    from fgc_backends.hls import HlsConfig, emit
    program = compile_graph(graph, SolverConfig(**solver), name=name)
    project = emit(program, tmp_path / f"{name}_{'_'.join(map(str, solver.values()))}",
                   HlsConfig(scalar="double", backsub_lanes=backsub_lanes))
    return program, project.directory


def _texts(directory, name, header):
    return (directory / f"{name}.cpp").read_text(), (directory / "include" / header).read_text()


def _backsub(directory):
    """The emitted back-substitution header (its driver's backsub_lane<p> regions)."""
    return (directory / "include" / "fgc_backsub.h").read_text()


# n_u = 4 (heavy) lies between the two ends the default run checks
@pytest.mark.parametrize("units", [1, pytest.param(4, marks=pytest.mark.heavy), 8])
def test_units_change_the_emitted_qr_network(tmp_path, units):
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.network import backsub_region, counts, read_network
    from fgc_backends.hls.plan import process_network
    # the slot driver (one lane; a chain's automatic width is by columns)
    program, out = _emit_accel(tmp_path, lio.build(N=8), "lio", backsub_lanes=1, linear="qr",
                               units=units)
    kernel, header = _texts(out, "lio", "fgc_qr.h")
    assert f"const int N_UNITS = {units};" in kernel
    level = next(r for r in read_network(kernel) if r.function == "qr_level")
    assert level.processes == ("qr_set0", "qr_set1")  # two-ended chain: two unit sets
    (reflection,) = [r for r in read_network(header) if r.streams]
    assert reflection.processes == ("qr_broadcast", "qr_finish", "qr_update_units::run",
                                    "qr_evaluate", "qr_collect")
    backsub = backsub_region(_backsub(out))
    assert backsub.processes == ("backsub_set0", "backsub_load1", "backsub_set1",
                                 "backsub_load0", "backsub_slots", "backsub_retire",
                                 "trial_cost")
    # per backsub_lane region the solve's x to the other lane's load (cond_load's part 3), the
    # solved words to the state update, its retired variables to the cost pass
    assert backsub.streams == (("xr", ""), ("xr", ""), ("dx", ""), ("tx", ""),
                               ("tx2", ""))  # tx2: a second cost process
    procs, streams = process_network(accel_plan(program, HlsConfig(backsub_lanes=1)))
    assert counts(kernel, header, _backsub(out)) == (len(procs), len(streams))
    # per unit set: 5 n_u + 4 streams (per unit its vector, v_0 / tau, row out and the next pivot
    # column as two streams by row parity, colq[N_UNITS][2]; the Evaluate's header, ...)
    # ... and back-substitution's: xr (a lane region each), dx, tx, tx2; the cost pass in two
    # processes here (the plan's slot_split_loops: trial_cost_b, and the feed of its data words)
    assert (len(procs), len(streams)) == ((units + 4) * 2 + 8, 2 * (5 * units + 4) + 6)
    assert tuple(p for p in procs if p.startswith(("backsub", "trial"))) == \
        backsub.processes + ("trial_cost_b",)
    for p in procs:  # the comment block lists the plan's network
        assert f"//   process {p}\n" in kernel


@pytest.mark.parametrize("cpe", [5, 20])
def test_cpe_changes_the_emitted_cascade(tmp_path, cpe):
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.network import counts, read_network
    from fgc_backends.hls.plan import process_network
    program, out = _emit_accel(tmp_path, pose_graph.build(), "w100", linear="cholesky", cpe=cpe)
    kernel, header = _texts(out, "w100", "fgc_cpe.h")
    assert f"const int N_CPE = {cpe};" in kernel
    (region,) = read_network(header)
    assert region.processes == ("cpe_feed", "cpe_cascade::run", "cpe_drain")
    procs, streams = process_network(accel_plan(program, HlsConfig()))
    # feed, per CPE its tap and itself, drain, the assembler beside the cascade (fgc_eliminate.h's
    # cholesky_overlap), back-substitution's lanes, its slot process and the state update it
    # feeds; links, tails (CPE K to the drain), tapped and recip, the assembler's stream,
    # back_substitute's, and per backsub_lane region the solve's x to the other lane's load
    # (the HGC beside the elimination: its Gram source a third process of the overlap region,
    # its Gram stream one more; the cost pass beside back-substitution: trial_cost and its
    # stream of retired variables)
    overlaps = {r.function: r for r in read_network(_texts(out, "w100", "fgc_eliminate.h")[1])}
    assert overlaps["cholesky_overlap"].processes == ("cholesky_assembler", "cholesky_cascade")
    assert overlaps["cholesky_overlap_beside"].processes == (
        "cholesky_gram_source", "cholesky_assembler", "cholesky_cascade")
    header += _texts(out, "w100", "fgc_eliminate.h")[1]
    assert counts(kernel, header, _backsub(out)) == (len(procs), len(streams)) == \
        (2 * cpe + 12, 4 * cpe + 7)
    assert procs[-7:] == ("backsub_set0", "backsub_load1", "backsub_set1", "backsub_load0",
                          "backsub_slots", "backsub_retire", "trial_cost")
    assert all(f"//   process {p}\n" in kernel for p in procs[-7:])
    assert f"//   stream cpe_tail{cpe - 1} " in kernel  # the last CPE's: to the drain
    assert f"//   stream cpe_link{cpe} " not in kernel


def test_lm_control_runs_at_ii_1_in_interleaved_partials(tmp_path):
    """Issue 18: LM control's sums (|x|², found beside the gradient's maximum, the step test's
    ‖δ‖² and δᵀg) go two terms a cycle (PIPELINE II=1, issue 33: the memories' two ports) into
    two lanes of as many interleaved partial sums as the adder's latency, the gradient's
    largest entry into as many partial maxima as the compare's, the partial arrays completely
    partitioned; the plan prices those loops at II 1 (one accumulator each, as before, runs at
    II = the adder's latency)."""
    from fgc_backends.hls import HlsConfig
    from fgc_backends.hls.emitter import accel_plan
    program, out = _emit_accel(tmp_path, lio.build(N=8), "lio", linear="qr")
    kernel, units = _texts(out, "lio", "fgc_lm_units.h")  # the reductions: LmConfig's hooks
    plan = accel_plan(program, HlsConfig(scalar="double"))
    # at 143 MHz the compare core is one stage (fcmp_..._1_2_no_dsp): one partial maximum
    assert plan.ops.add.latency > 1 and plan.ops.compare.latency >= 1
    assert f"T_ADD_LAT = {plan.ops.add.latency}," in kernel and "T_PARTIALS = T_ADD_LAT;" in kernel
    assert f"T_CMP_LAT = {plan.ops.compare.latency}," in kernel
    assert "T_MAXIMA = T_CMP_LAT;" in kernel
    assert "PARTIALS = T_PARTIALS," in kernel and "MAXIMA = T_MAXIMA," in kernel
    for array, update in (("xp", "xp[k] += x[i] * x[i];"), ("dp", "dp[k] += d * d;"),
                          ("pp", "pp[k] += d * g[i];"),
                          ("gp", "gp[k] = a > gp[k] ? a : gp[k];")):
        at = units.index(update)
        loop = units[units.rindex("for (int e = 0;", 0, at):at]
        assert "#pragma HLS PIPELINE II=1\n" in loop, array
        # each partial comes back PARTIALS iterations later (lm_iterate's maxima as many as its
        # sums): the true distance
        assert (f"#pragma HLS DEPENDENCE variable={array} inter true distance=CFG::PARTIALS"
                in loop), array
        assert f"#pragma HLS ARRAY_PARTITION variable={array} complete" in units, array
    loops = {lp.name: lp for ph in plan.phases if ph.name.startswith("lm_")
             for pr in ph.processes for lp in pr.loops}
    n_t = sum(v.dim for v in program.variables)
    assert n_t >= plan.ops.add.latency
    assert all(loops[n].ii == 1 for n in ("gradient_x_norm", "step_test"))


def test_network_read_back_sees_a_missing_back_substitution_unit(tmp_path):
    """The read-back counts what the text holds: a back-substitution header whose backsub_lane
    region lost a unit's call (or gained a stream) no longer equals the plan's network."""
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.network import counts
    from fgc_backends.hls.plan import process_network
    program, out = _emit_accel(tmp_path, lio.build(N=8), "lio", backsub_lanes=1, linear="qr",
                               units=2)
    kernel, header = _texts(out, "lio", "fgc_qr.h")
    # (the emitted design's own configuration: whether its cost pass is split in two is the plan's)
    procs, streams = process_network(accel_plan(program, HlsConfig(scalar="double",
                                                                   backsub_lanes=1)))
    backsub = _backsub(out)
    assert counts(kernel, header, backsub) == (len(procs), len(streams))
    call = "    backsub_set1<CFG>(cond1, f1, s1, part1, x1, cb1, dx, split, xr, nx);\n"
    assert backsub.count(call) == 1
    assert counts(kernel, header, backsub.replace(call, "")) == (len(procs) - 1, len(streams))
    extra = "#pragma HLS DATAFLOW\n    hls::stream<L> spare;\n"
    widened = backsub.replace("#pragma HLS DATAFLOW\n    hls::stream<L> xr;",
                              extra + "    hls::stream<L> xr;", 1)
    assert counts(kernel, header, widened) == (len(procs), len(streams) + 1)


def test_accelerator_kernel_has_no_host_only_code(tmp_path):
    for linear in ("qr", "cholesky"):
        _, out = _emit_accel(tmp_path, lio.build(N=8), "lio", linear=linear)
        text = (out / "lio.cpp").read_text()
        assert "__SYNTHESIS__" not in text and "LANES" not in text
        assert "__attribute__" not in text and "nullptr" not in text
        assert (out / "csim_include" / "hls_stream.h").exists()
        assert "csim_include" in (out / "Makefile").read_text()
        assert "csim_include" not in (out / "run_hls.tcl").read_text()


def test_allocation_limits_are_the_plans(tmp_path):
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.network import allocations
    program, out = _emit_accel(tmp_path, lio.build(N=8), "lio", linear="qr")
    plan = accel_plan(program, HlsConfig(scalar="double"))  # the design _emit_accel emits
    from fgc_backends.hls.units.datapath import factor_allocation, mode_allocation
    found = allocations((out / "lio.cpp").read_text())
    # the gradient's and the rounding noise's one module for every block type (issue 33 item 5;
    # the gradient's in reduce_all, beside the datapaths in linearize_rows' region)
    assert found.pop("reduce_all") == (("function", "accumulate", 1),)
    assert found.pop("rounding_noise_all") == (("function", "rounding_noise", 1),)
    # the factor datapaths per mode (factor_<b>: the Jacobian's, factor_cost_<b>: the cost's
    # operations under the block's limits) and the state update's per variable type
    # (retract_<k>: its unit's operators)
    from fgc_backends.cfamily.blocks import block_contexts
    from fgc_backends.hls.units.datapath import small_allocation, small_blocks
    from fgc_backends.hls.units.special_ops import printed_counts
    shared = factor_allocation(program, plan.options)
    small = small_blocks(program)  # LIO's priors and GPS: one shared datapath per mode
    assert small
    limits_of = {}
    # each mode's limits: the instances its loop binds at the plan's II (ceil(n x op II / II)),
    # at most the block's share of the options' limits
    ii = {p.name: p.loops[0].ii for ph in plan.phases for p in ph.processes if p.loops}
    for b, block in enumerate(program.blocks):
        if b in small:
            continue
        # (the counts as printed: the printer's count, units/special_ops.py's helpers' bodies in)
        for function, mode, counts in (
                (f"factor_{b}", "jacobian", printed_counts(block, "jacobian")),
                (f"factor_cost_{b}", "cost", printed_counts(block, "cost"))):
            limits_of[function] = {
                k: min(lim, -(-counts[k] * plan.ops.op(k).ii // ii[f"factor_{b}_{mode}"]))
                for k, lim in mode_allocation(shared[b], counts)}
    contexts = block_contexts(program, vector=False)
    for function, mode in (("evaluate_small_one", "jacobian"), ("cost_small_one", "cost")):
        limits_of[function] = dict(small_allocation(program, contexts, plan.options, mode,
                                                    plan.ops)[0])
    pairs = [(name, None) for name in limits_of]
    pairs += [(f"retract_{u.name.rsplit('_', 1)[1]}", u.name) for u in plan.units
              if u.name.startswith("state_update_")]
    assert len(pairs) > 2 * (len(program.blocks) - len(small)) + 2
    assert set(found) == {function for function, _ in pairs}
    for function, unit in pairs:
        limits = limits_of[function] if unit is None else dict(plan.unit(unit).operators)
        ops = {n[1:]: lim for kind, n, lim in found[function] if kind == "operation"}
        assert ops == {k: v for k, v in limits.items() if k in ("add", "mul", "div", "sqrt")}
        assert all(n.startswith("d") for kind, n, _ in found[function]
                   if kind == "operation")  # double: dadd, dmul, ...
