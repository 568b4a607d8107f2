"""The root step in a wavefront behind its children (issue 33 item 2, ``HlsConfig.root_wave``):
paper A's window (two leaf steps, then the root) under the one-step policy runs the root inside
the linearisation's region ``lin_level`` with level 0: unit set 0 reflects step 0 and streams
its passed rows (``qr_pass``, a stream word as the root's banks take it) and its result
(``qr_commit``, to the process that writes COND and NF) as its collector writes them; unit set 1
reflects step 1, takes the root's own rows from their stream (``bank_root``, the datapaths
write it), stacks step 1's passed rows from its buffer and reflects the root, reading each of
step 0's rows before the root's first region that needs it (units/qr.py's ``wave_entries``).

- the on-chip incremental design (LIO N = 7, K = 3, one Gauss-Newton step an update, a sweep at
  keyframe 4; double) with the wave agrees with the simulator after every keyframe to 1e-8, as
  the level-by-level design does (tests/hls/test_hls_stream_sweep.py);
- the emitted lin_level region holds one producer and one consumer of ``qr_pass``,
  ``bank_root`` and ``qr_commit``, and the plan's channels name them; a kernel without the
  option has none of it;
- the plan hides the root's level, its stack and step 0's commit in lin_level's region
  (``qr_beside_linearize``) and saves cycles over the design without the wave, no DSP added;
- heavy: the counting C simulation equals the update model within 2 % on every update, and a
  row read one region too late breaks the agreement with the simulator.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from stream_cases import keyframe_distances, lio7_one_step

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls.config import DesignOptions, HlsConfig
from fgc_backends.hls.network import read_network
from fgc_backends.hls.plan import PlanOptions, build_plan
from fgc_backends.hls.plan.cost import phase_cycles
from fgc_backends.hls.plan.model import PlanError
from fgc_backends.hls.plan.stream import WindowUpdateModel
from fgc_backends.hls.streaming import OnChipIncrementalStream
from fgc_backends.hls.units.qr import wave_entries

SIM_TOL = 1e-8  # double design vs simulator, tangent-space distance per variable
WAVE = DesignOptions(root_wave=True)


def _distances(program, csim, sim_updates) -> list[float]:
    return keyframe_distances(program, csim.updates, sim_updates)


@pytest.fixture(scope="module")
def wave7(tmp_path_factory):
    return lio7_one_step(tmp_path_factory.mktemp("wave"), "lio_wave", WAVE)


def test_the_wave_agrees_with_the_simulator_after_every_keyframe(wave7):
    _, program, _, sim, _, csim = wave7
    assert [u["iterations"] for u in csim.updates] == [1] * 7
    dist = _distances(program, csim, sim)
    assert max(dist) <= SIM_TOL, dist
    assert max(dist[4:]) > 0.0  # the C simulation and the simulator, not one read twice


def test_the_wave_region_has_one_producer_and_one_consumer(wave7):
    _, _, _, _, stream, _ = wave7
    folder, name = stream.project.directory, stream.project.name
    text = (folder / f"{name}.cpp").read_text()
    regions = {r.function: r for r in read_network(text)}
    lin = regions["lin_level"]
    assert lin.processes == ("evaluate_all", "reduce_all", "qr_set0", "qr_set1", "qr_commit_wave")
    assert {"qr_pass", "bank_root", "qr_commit", "qr_commit1"} <= {s for s, _ in lin.streams}
    assert "qr_level" not in regions  # (the wave as its own region: designs without lin_level)
    model = WindowUpdateModel(stream.layout, HlsConfig(scalar="double", design=WAVE))
    ch = {c.name: c for c in model.plan.channels
          if c.name in ("qr_pass", "bank_root", "qr_commit", "qr_commit1")}
    assert (ch["qr_pass"].producer, ch["qr_pass"].consumer) == ("qr_set0", "qr_set1")
    assert (ch["bank_root"].producer, ch["bank_root"].consumer) == ("datapaths", "qr_set1")
    # the three steps' commits: each set's collector's words to the process that writes COND
    # and NF (set 0's step; set 1's step and the root, every pair held: set 1 never waits)
    assert (ch["qr_commit"].producer, ch["qr_commit"].consumer) == ("qr_set0", "qr_commit_wave")
    assert (ch["qr_commit1"].producer, ch["qr_commit1"].consumer) == ("qr_set1",
                                                                       "qr_commit_wave")
    t = stream.layout.template
    c0, _ = t.schedule.levels[-2]
    sc = sum(t.schedule.steps[c0].separator_dims)
    # every passed row, packed by the root's banks: each stream word 2 * n_u slots (two words
    # of a bank, its memory's two ports), word q in the slot of its root column's bank at that
    # column's local place; a row takes the fewest words its fullest bank allows
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.qr import pass_pack, wave_colmap

    units = model.plan.options.units
    root = t.schedule.levels[-1][0]
    tables = _tables(t)
    cols = wave_colmap(tables, c0, root)
    pack = pass_pack(tables, c0, root, units)
    assert len(cols) == sc + 1
    words, taken = 0, set()
    for t_col, pk in zip(cols, pack, strict=True):
        slot = pk & 255
        assert slot // 2 == t_col % units and (pk >> 8) & 255 == t_col // units
        assert slot not in taken
        taken.add(slot)
        if pk >> 16:
            words, taken = words + 1, set()
    assert not taken and pack[-1] >> 16
    fullest = max(sum(1 for c in cols if c % units == u) for u in range(units))
    assert words == -(-fullest // 2)
    assert ch["qr_pass"].depth == t.schedule.steps[c0].new_factor_rows * words
    # commit streams: a pair of one row's words a stream word
    assert ch["qr_commit"].width == ch["qr_commit1"].width
    assert ch["qr_pass"].width == 2 * units * (ch["qr_commit"].width // 2 + 8)
    _, c1 = t.schedule.levels[-2]
    pairs = sum(t.schedule.steps[s].frontal_dim * ((t.schedule.steps[s].frontal_dim
                                                     + sum(t.schedule.steps[s].separator_dims)
                                                     + 2) // 2) for s in (c1, root))
    assert ch["qr_commit1"].depth == pairs
    assert f"variable=qr_commit1 depth={pairs}" in text
    # the solve commits none of the wave's three steps after the region
    body = text[text.index("static void commit(int u, int s)"):]
    body = body[:body.index("\n    }\n")]
    assert "WAVE_DONE && (s == WAVE_FED || s == WAVE_SET1)) return;" in body
    assert f"variable=qr_pass depth={ch['qr_pass'].depth}" in text
    assert f"variable=bank_root depth={ch['bank_root'].depth}" in text


def test_the_datapaths_send_set_1_its_rows_before_set_0(wave7):
    """Set 1 reflects its step and then the root: the region's path. evaluate_all runs the
    loops that send set 1's step its rows first, then set 0's, then the root's own; reduce_all
    reads the stream in the same order, and the plan's datapath processes follow it."""
    import re

    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.datapath import (
        bank_ready_loops,
        datapath_loop_names,
        datapath_order,
    )
    from fgc_backends.hls.units.qr import rows_in_banks

    _, _, _, _, stream, _ = wave7
    t = stream.layout.template
    opts = WindowUpdateModel(stream.layout, HlsConfig(scalar="double", design=WAVE)).plan.options
    plain = WindowUpdateModel(stream.layout, HlsConfig(scalar="double")).plan.options
    names = datapath_loop_names(t, opts)
    assert datapath_loop_names(t, plain) == datapath_loop_names(t)  # no wave: the blocks' order
    assert datapath_order(t, plain) == sorted(datapath_order(t, plain))
    assert sorted(names) == sorted(datapath_loop_names(t)) and names != datapath_loop_names(t)
    ready = bank_ready_loops(t, rows_in_banks(t, opts, _tables(t), root=True), 3, opts)
    # set 1's step's last loop before set 0's, set 0's no later than the root's own rows' one
    assert names.index(ready[1]) < names.index(ready[0]) <= names.index(ready[2])
    model = WindowUpdateModel(stream.layout, HlsConfig(scalar="double", design=WAVE))
    lin = next(ph for ph in model.plan.phases if ph.name == "factor_jacobian")
    assert [p.name for p in lin.processes if p.name != "gradient"] == names
    text = (stream.project.directory / f"{stream.project.name}.cpp").read_text()
    for fn, call in (("evaluate_all", "evaluate"), ("reduce_all", "reduce")):
        body = text[text.index(f"void {fn}("):]
        body = body[:body.index("\n}\n")]
        called = re.findall(rf"\b{call}_(\d+|small)\(", body)
        assert [f"factor_{c}_jacobian" for c in called] == names, fn


def test_without_the_option_the_kernel_has_no_wave(wave7, tmp_path):
    import fgc_backends
    from fgc.app.streaming import stream_program

    graph, program, _, _, stream, _ = wave7
    plain = WindowUpdateModel(stream.layout, HlsConfig(scalar="double"))
    assert not any(c.name == "qr_pass" for c in plain.plan.channels)
    hls = fgc_backends.load("hls")
    hls.emit(stream_program(graph, program, None), tmp_path, HlsConfig(scalar="double"))
    texts = [p.read_text() for p in tmp_path.glob("*.cpp") if not p.name.startswith("tb_")]
    assert texts and not any("qr_pass" in t or "WAVE_ENTRY" in t for t in texts)


def test_the_wave_reads_a_row_before_the_region_that_first_needs_it(wave7):
    _, _, _, _, stream, _ = wave7
    t = stream.layout.template
    from fgc_backends.hls.plan.loops import _tables

    tables = _tables(t)
    c0, _ = t.schedule.levels[-2]
    root = t.schedule.levels[-1][0]
    entry = wave_entries(tables, c0, root)
    # LIO's separator columns are the root's first ones in order: row i (zero left of the
    # root's column i) is read before region i - 1, whose Evaluate takes column i
    assert entry == list(range(-1, len(entry) - 1))


def test_the_plan_hides_the_root_in_lin_level_and_saves_cycles(wave7):
    _, _, _, _, stream, csim = wave7
    plain = WindowUpdateModel(stream.layout, HlsConfig(scalar="double"))
    wave = WindowUpdateModel(stream.layout, HlsConfig(scalar="double", design=WAVE))
    # the solve's phases as without the wave (the eliminate_all a sweep runs); what the
    # one-step update no longer runs after lin_level is in its qr_beside_linearize term
    for g in ("qr", "qr_stack", "qr_commit"):
        assert wave.group[g] == plain.group[g], g
    phases = {ph.name: phase_cycles(ph) for ph in plain.plan.phases}
    u = csim.updates[6]
    w = wave.price(6, u["iterations"], status=u["status"])
    p = plain.price(6, u["iterations"], status=u["status"])
    wt = {t.name: t.each * t.times for t in w.terms}
    pt = {t.name: t.each * t.times for t in p.terms}
    assert set(wt) == set(pt)
    assert {k for k in wt if wt[k] != pt[k]} == {"qr_beside_linearize"}
    saved = p.cycles - w.cycles
    assert saved == pt["qr_beside_linearize"] - wt["qr_beside_linearize"]
    # the root's level, its stack and step 0's commit leave the path; the root's own time
    # (behind step 1 on set 1) stays on it: at least a tenth of them saved
    hidden = phases["qr_level1"] + phases["qr_stack_level1"] + phases["qr_commit_level0"] // 2
    assert saved > 0.1 * hidden, (saved, hidden)
    assert wave.resources()["dsp"] == plain.resources()["dsp"]  # no unit added


def test_a_schedule_without_a_root_over_two_steps_is_refused():
    program = compile_graph(example("lio").build(N=6), name="lio",
                            solver=SolverConfig(ordering="serial"))
    with pytest.raises(PlanError, match="root_wave"):
        build_plan(program, PlanOptions.of(program, root_wave=True))
    two = compile_graph(example("lio").build(N=6), name="lio")
    with pytest.raises(PlanError, match="two unit sets"):
        build_plan(two, PlanOptions.of(two, root_wave=True, unit_sets=1))


def test_without_lin_level_the_wave_is_its_own_region():
    # not the one-step policy (no lin_level): the last two levels one qr_level region with
    # `wave`, the root's level gone from the plan; no bank_root (the root stacks from AB)
    two = compile_graph(example("lio").build(N=6), name="lio")
    assert not two.solver.one_step and len(two.schedule.levels[-2]) == 2
    plain = build_plan(two, PlanOptions.of(two))
    wave = build_plan(two, PlanOptions.of(two, root_wave=True))
    last = len(two.schedule.levels) - 1
    names = {ph.name for ph in wave.phases}
    assert f"qr_level{last}" in {ph.name for ph in plain.phases}
    assert f"qr_level{last}" not in names and f"qr_level{last - 1}" in names
    channels = {c.name: c for c in wave.channels}
    assert "bank_root" not in channels
    assert (channels["qr_pass"].producer, channels["qr_pass"].consumer) == ("qr_set0", "qr_set1")


@pytest.mark.heavy
def test_the_counted_csim_equals_the_model_on_every_update(wave7):
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
    from bench_stream_cycles import counted

    _, _, data, _, stream, _ = wave7
    model = WindowUpdateModel(stream.layout, HlsConfig(scalar="double", design=WAVE))
    result = stream.run(data)
    for u, (cycles, ev) in zip(result.updates, counted(stream), strict=True):
        ev = dict(ev)
        ev.setdefault("relinearize", 0)
        ev["linearize"] = ev.get("linearize", 0) - ev["relinearize"] - ev.get("sweep", 0)
        price = model.price(u["keyframe"], u["iterations"], ev, u["status"])
        assert abs(cycles / price.cycles - 1) <= 0.02, (u["keyframe"], cycles, price.cycles)


@pytest.mark.heavy
def test_a_row_read_too_late_breaks_the_agreement(wave7, tmp_path):
    graph, program, data, sim, _, _ = wave7
    bad = OnChipIncrementalStream(graph, program, "double", out_dir=tmp_path, design=WAVE)
    kernel = bad.project.directory / f"{bad.project.name}.cpp"
    text = kernel.read_text()
    # every row of step 0 read before the root's region 1 instead of each before its own
    patched = text.replace("const int WAVE_ENTRY[LesConfig::MAX_COLS] = {  // per passed row: "
                           "the root's region that first needs it\n    -1, 0,",
                           "const int WAVE_ENTRY[LesConfig::MAX_COLS] = {  // per passed row: "
                           "the root's region that first needs it\n    -1, 1,")
    assert patched != text
    kernel.write_text(patched)
    (bad.project.directory / f"{bad.project.name}.o").unlink(missing_ok=True)
    try:
        csim = bad.run(data)
    except Exception:  # noqa: BLE001 - a failure is as good as a disagreement here
        return
    assert max(_distances(program, csim, sim)) > 1e3 * SIM_TOL


def test_lin_levels_steps_keep_rows_by_the_plans_patterns(wave7):
    """The emitted kernel's QR_KEEP_MASK (fgc_qr.h's keep rule by structure, stop 49) holds, per
    update class of the window, each wave step's row patterns as the plan prices them
    (plan/stream.py's step_patterns on that keyframe's zero factors and unit priors), the class
    of each keyframe count jc, and sets 0 and 1 pass it to their QR step in lin_level."""
    import re

    from fgc_backends.hls.plan.stream import step_patterns

    _, _, _, _, stream, _ = wave7
    folder, name = stream.project.directory, stream.project.name
    text = (folder / f"{name}.cpp").read_text()
    assert "lin ? QR_KEEP_MASK[QR_KEEP_CLASS][0] : 0" in text
    assert "lin ? QR_KEEP_MASK[QR_KEEP_CLASS][root ? 2 : 1] : 0" in text
    lay = stream.layout
    t = lay.template
    table = re.search(r"QR_KEEP_CLASS_OF\[\d+\] = \{([^}]*)\}", text).group(1)
    of = [int(x) for x in re.findall(r"\b\d+\b", re.sub(r"//[^\n]*", "", table))]
    assert len(of) == lay.size + 1 and len(set(of)) > 1  # the filling window's own classes
    body = text[text.index("QR_KEEP_MASK["):text.index("int QR_KEEP_CLASS = 0")]
    rows = [int(x, 16) for x in re.findall(r"0x([0-9a-f]+)ULL", body)]
    c0, c1 = t.schedule.levels[-2]
    root = t.schedule.levels[-1][0]
    max_rows = len(rows) // (3 * (max(of) + 1))
    marginal = lay.context("double", "xc7z045ffg900-2")["marginal"]
    for jc, cls in enumerate(of):
        pats = step_patterns(t, lay.zero_factors(jc, marginal), True,
                             unit=lay.unit_factors(jc))
        for k, s in enumerate((c0, c1, root)):
            pattern, rhs = pats[s]
            w = pattern.shape[1]
            got = rows[(cls * 3 + k) * max_rows:(cls * 3 + k) * max_rows + len(pattern)]
            want = [sum(1 << c for c in range(w) if pattern[i, c]) | (int(rhs[i]) << w)
                    for i in range(len(pattern))]
            assert got == want, (jc, s)
