"""The accelerator plan's price of a stream's keyframe updates (issue 19:
``fgc_backends.hls.plan.update``, ``fgc stream --backend hls``).

The update model composes the plan's own loops: a window spanning the whole chain, eliminated
serially, must cost exactly what ``plan_cost`` says for the batch Program with the serial
ordering (that checks the window's stacked patterns against ``stacked_pattern``); a batch
keyframe costs ``plan_cost`` of the batch Program of its keyframes per iteration; more Update
units, a wider window, more iterations or a longer kept Bayes net are never cheaper; assumed
terms are labelled and kept out of the plan's latency. Pricing needs no simulator run: updates
are given by their keyframe, mode, first cluster and iterations. The command-line cases run
``--model-only`` (the simulator's updates, priced); the C simulation solving each update is
tests/hls/test_hls_stream_csim.py.
"""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import fgc
import fgc.frontend.factors
from fgc.app.cli import main
from fgc.app.specs import example  # noqa: E402
from fgc.app.streaming import (
    HW_REFUSAL,
    compile_stream,
    prefix_program,
    update_model,
)
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls.plan import PlanOptions, build_plan, phase_cycles, plan_cost
from fgc_backends.hls.plan.update import NOT_EMITTED, UpdateModel, UpdateModelError

lio = example("lio")

ROOT = Path(__file__).resolve().parents[2]
LIO = str(ROOT / "examples" / "lio.py")


N = 8


def update(keyframe, first, iterations=3, mode="incremental"):
    return SimpleNamespace(keyframe=keyframe, first=first, iterations=iterations, mode=mode)


@pytest.fixture(scope="module")
def graph():
    return lio.build(N=N)


@pytest.fixture(scope="module")
def stream(graph):
    """An incremental LIO stream's Program (K = 3, batch at 5) and its update model."""
    program = compile_stream(graph, SolverConfig(precision="float32"), incremental=3,
                             batch_every=(5,))
    return program, update_model(graph, program)


@pytest.mark.parametrize("linear, units", [("qr", 1), ("qr", 4), ("cholesky", 4)])
def test_a_whole_chain_window_costs_the_serial_batch_plan(graph, linear, units):
    program = compile_graph(graph, SolverConfig(precision="float32", ordering="serial",
                                                linear=linear), name="serial")
    model = UpdateModel(program, PlanOptions.of(program, units=units))
    phases = model.window_iteration_phases(0, N - 1)
    assert sum(phase_cycles(ph) for ph in phases) == plan_cost(model.plan).cycles
    # and a window of the newest clusters is cheaper than the whole chain
    assert (sum(phase_cycles(ph) for ph in model.window_iteration_phases(N - 3, N - 1))
            < plan_cost(model.plan).cycles)


def test_per_call_and_per_rejection_terms_are_the_plans_phases(graph):
    """Over a whole stream the setup copies every variable's initial value and every factor's
    data in exactly once, as the batch plan's setup does once per call; a window spanning the
    chain prices the plan's rounding-noise pass; a record that counts its rejected steps is
    priced per rejection, one that does not has the pass assumed and counted zero times."""
    program = compile_graph(graph, SolverConfig(precision="float32", ordering="serial"),
                            name="serial")
    model = UpdateModel(program)
    plan = {ph.name: ph for ph in model.plan.phases}
    assert plan["setup"].per == "call" and plan["rounding_noise"].per == "rejection"
    whole = {lp.name: lp.trip for lp in plan["setup"].processes[0].loops}
    trips = {"x_in": 0, "data_in": 0}
    for j in range(N):
        loops = {lp.name: lp.trip for lp in model.setup_phase(max(0, j - 2), j,
                                                              "incremental").processes[0].loops}
        trips["x_in"] += loops["x_in"]
        trips["data_in"] += loops["data_in"]
        assert loops["x_out"] == sum(v.storage_dim for v in program.variables
                                     if v.key in {k for c in range(j + 1)
                                                  for k in model.clusters[c]})
    assert trips == {"x_in": whole["x_in"], "data_in": whole["data_in"]}
    fixed = {lp.name: lp.trip for lp in model.setup_phase(5, 7, "fixed-lag").processes[0].loops}
    assert fixed["x_out"] < whole["x_out"] == fixed["x_out"] + sum(
        v.storage_dim for v in program.variables
        if v.key in {k for c in range(5) for k in model.clusters[c]})
    assert (phase_cycles(model.rounding_noise_phase(0, N - 1))
            == phase_cycles(plan["rounding_noise"]))
    counted = model.price(SimpleNamespace(keyframe=6, first=4, iterations=3,
                                          mode="incremental", rejected=3, noise_passes=2))
    uncounted = model.price(update(6, 4))
    noise, trial = counted.term("rounding_noise"), counted.term("rejected_trial")
    assert not noise.assumed and noise.times == 2 and noise.each > 0
    assert noise.each == phase_cycles(model.rounding_noise_phase(4, 6))
    assert not trial.assumed and trial.times == 3
    # a rejected trial re-solves, retracts, costs and tests the step: an iteration without
    # the Jacobian and gradient passes (QR: one region, factor_jacobian) and without LM
    # control's other loops
    iteration = {ph.name: phase_cycles(ph) for ph in model.window_iteration_phases(4, 6)}
    assert "gradient" not in iteration
    assert trial.each == sum(iteration.values()) - sum(iteration[name] for name in (
        "factor_jacobian", "lm_iteration", "lm_accept"))
    assert iteration["lm_control"] > 0 and iteration["lm_iteration"] > 0
    for name in ("rounding_noise", "rejected_trial"):
        assert uncounted.term(name).assumed and uncounted.term(name).times == 0
    assert counted.cycles == uncounted.cycles + 2 * noise.each + 3 * trial.each
    assert counted.term("setup").cycles == phase_cycles(model.setup_phase(4, 6, "incremental"))
    for rejected, passes in ((-1, 0), (1, 2)):
        with pytest.raises(UpdateModelError, match=f"{rejected} rejected steps with {passes}"):
            model.price(SimpleNamespace(keyframe=6, first=4, iterations=3, mode="incremental",
                                        rejected=rejected, noise_passes=passes))


def test_a_batch_keyframe_costs_plan_cost_of_its_batch_program(graph, stream):
    program, model = stream
    price = model.price(update(5, 0, iterations=4, mode="batch"))
    batch = plan_cost(build_plan(prefix_program(graph, program, 6), model.options))
    assert price.term("batch_iteration").cycles == 4 * batch.cycles
    assert price.term("batch_iteration").each == batch.cycles
    assert price.cycles == (4 * batch.cycles + price.term("store").cycles
                            + price.term("setup").cycles)
    # at the last keyframe the batch Program is the stream's own
    last = model.price(update(N - 1, 0, iterations=2, mode="batch"))
    assert last.term("batch_iteration").each == plan_cost(build_plan(program,
                                                                     model.options)).cycles
    assert not any(t.name.startswith(("iteration:", "kept")) for t in price.terms)


def test_a_batch_keyframe_before_the_last_needs_its_program(stream):
    program, _ = stream
    model = UpdateModel(program)
    with pytest.raises(UpdateModelError, match="needs batch_program"):
        model.price(update(5, 0, mode="batch"))


def test_more_update_units_are_never_slower(graph, stream):
    program, _ = stream
    ups = [update(j, max(0, j - 2)) for j in range(N)] + [update(5, 0, mode="batch")]
    previous = None
    for units in (1, 8):  # two models (each compiles its batch prefixes): ~15 s, not 35
        model = update_model(graph, program, units=units)
        cycles = [model.price(u).cycles for u in ups]
        if previous is not None:
            assert all(c <= p for c, p in zip(cycles, previous, strict=True)), units
            assert sum(cycles) < sum(previous)
        previous = cycles


def test_the_price_grows_with_iterations_window_and_kept_conditionals(stream):
    _, model = stream
    one, three = model.price(update(6, 4, iterations=1)), model.price(update(6, 4))
    per = sum(t.each for t in one.terms if t.name.startswith("iteration:") and not t.assumed)
    assert per > 0 and three.cycles - one.cycles == 2 * per
    assert model.price(update(6, 3)).cycles > three.cycles  # a wider window
    # later keyframes back-substitute through more kept conditionals
    kept = [model.price(update(j, j - 2)).term("kept_backsub").cycles for j in (3, 5, 7)]
    assert kept[0] < kept[1] < kept[2]
    assert model.price(update(6, 4, iterations=0)).cycles < one.cycles


def test_float64_costs_more_than_float32(graph):
    prices = []
    for precision in ("float32", "float64"):
        program = compile_stream(graph, SolverConfig(precision=precision), incremental=3)
        prices.append(update_model(graph, program).price(update(6, 4)).cycles)
    assert prices[0] < prices[1]


def test_cholesky_prices_the_cascade_with_its_cpe(graph):
    program = compile_stream(graph, SolverConfig(precision="float32", linear="cholesky"),
                             incremental=3)
    a = update_model(graph, program, cpe=5).price(update(6, 4))
    b = update_model(graph, program, cpe=20).price(update(6, 4))
    def cascade(price):  # the window's steps, each a cholesky_level<t> region
        levels = [t.cycles for t in price.terms if t.name.startswith("iteration:cholesky_level")]
        assert levels
        return sum(levels)

    assert cascade(a) != cascade(b)
    assert a.term("iteration:hgc").cycles == b.term("iteration:hgc").cycles > 0


def test_assumed_terms_are_labelled_and_kept_out_of_the_plan_latency(stream):
    _, model = stream
    price = model.price(update(6, 4))
    assumed = [t for t in price.terms if t.assumed]
    assert {t.name for t in assumed} >= {"iteration:prior_rows", "kept_reexpress",
                                         "transfer", "on_chip_state"}
    assert all(t.text.startswith("assumed") for t in assumed)
    assert not any(t.text.startswith("assumed") for t in price.terms if not t.assumed)
    assert price.cycles == sum(t.cycles for t in price.terms if not t.assumed)
    assert price.latency_with_assumed_ms > price.latency_ms > 0
    assert price.latency_ms == pytest.approx(price.cycles / (143.0 * 1e3))
    d = price.as_dict()
    assert "model estimate" in d["source"] and d["latency_ms"] == price.latency_ms
    # the oldest window (nothing kept, no τ) has only the host transfer, the state and the
    # uncounted rejections assumed
    first = model.price(update(2, 0))
    assert {t.name for t in first.terms if t.assumed} == {"transfer", "on_chip_state",
                                                          "rounding_noise", "rejected_trial"}


def test_a_fixed_lag_update_walks_no_kept_conditionals(graph):
    program = compile_stream(graph, window=3)
    price = update_model(graph, program).price(update(6, 3, mode="fixed-lag"))
    names = {t.name for t in price.terms}
    assert "iteration:prior_rows" in names and "store" in names
    assert not any(n.startswith("kept") for n in names)


@pytest.mark.parametrize("bad, message", [
    (update(3, 1, mode="sideways"), "update mode 'sideways'"),
    (update(N, 6), f"outside the stream's {N} keyframes"),
    (update(4, 5), "outside"),
    (update(5, 2, mode="batch"), "re-eliminates every keyframe"),
    (update(5, 3, iterations=-1), "-1 iterations"),
])
def test_bad_updates_are_refused(stream, bad, message):
    _, model = stream
    with pytest.raises(UpdateModelError, match=message):
        model.price(bad)


def test_a_graph_that_is_not_a_chain_has_no_update_model():
    graph = lio.build(N=5)
    graph.add(fgc.factors.BetweenFactor("x0", "x3", fgc.Pose3(), fgc.noise.isotropic(6, 1)))
    program = compile_graph(graph, SolverConfig(precision="float32"), name="loop")
    with pytest.raises(fgc.FgcError, match="needs a chain of keyframes"):
        UpdateModel(program)


# --------------------------------------------------------------------------------------------
# command line
# --------------------------------------------------------------------------------------------


@pytest.mark.heavy  # about 45 s on 2 cores; test_hls_window's CLI test streams the on-chip design
def test_cli_stream_hls_prints_the_model_beside_the_simulator(tmp_path, capsys):
    """``--model-only`` on a QR Program: the simulator's updates priced on the on-chip
    incremental design's plan (its window, kept net and batch kernel), every term the plan's."""
    out, tum = tmp_path / "stream.json", tmp_path / "stream.tum"
    rc = main(["stream", LIO, "-p", "N=6", "--incremental", "2", "--batch-every", "3,",
               "--backend", "hls", "--model-only", "--units", "2", "--precision", "float32",
               "--json", str(out), "--tum", str(tum)])
    text = capsys.readouterr().out
    assert rc == 0, text
    assert "kept Bayes net on chip" in text and "n_u = 2" in text
    assert "keyframe    3 (batch, from 0)" in text and "(model estimate, on chip)" in text
    assert "(simulator wall time)" in text and "BRAM36 (model estimate" in text
    assert len(tum.read_text().splitlines()) == 6
    report = json.loads(out.read_text())
    assert report["backend"] == "hls" and "not_emitted" not in report
    # each keyframe's figure is the on-chip design's price of the update the simulator ran
    graph = lio.build(N=6)
    program = compile_stream(graph, SolverConfig(precision="float32", units=2),
                             incremental=2, batch_every=(3,))
    from fgc.app.streaming import WindowPricer, stream_program

    model = WindowPricer(stream_program(graph, program))
    for u, priced in zip(report["updates"], report["model_estimate"], strict=True):
        again = model.price(SimpleNamespace(**{k: u[k] for k in ("keyframe", "mode", "first",
                                                                  "iterations", "status")}))
        assert priced["cycles"] == again.cycles and priced["keyframe"] == u["keyframe"]
        assert not any(t["assumed"] for t in priced["terms"])


def test_cli_stream_hls_cholesky_prices_the_host_kept_path(capsys):
    """A Cholesky Program has no on-chip design: the update model of the host-kept path, its
    assumed terms and the reason printed."""
    rc = main(["stream", LIO, "-p", "N=5", "--incremental", "2", "--backend", "hls",
               "--model-only", "--linear", "cholesky", "--cpe", "5"])
    text = capsys.readouterr().out
    assert rc == 0, text
    assert "ms assumed (model estimate" in text and NOT_EMITTED in text


@pytest.mark.heavy  # the host-kept Cholesky CLI stream above keeps the CLI path in the default run
def test_cli_stream_hls_fixed_lag_cholesky(capsys):
    rc = main(["stream", LIO, "-p", "N=5", "--window", "2", "--backend", "hls", "--model-only",
               "--linear", "cholesky", "--cpe", "5"])
    text = capsys.readouterr().out
    assert rc == 0, text
    assert "CHOLESKY, #CPE = 5" in text and "keyframe    4 (fixed-lag, from 2)" in text


@pytest.mark.parametrize("argv, refusal", [
    (["stream", LIO, "-p", "N=4", "--backend", "native", "--incremental", "2", "--model-only"],
     "--model-only prices the simulator's updates on the HLS plan: it needs --backend hls"),
    (["run", LIO, "-p", "N=4", "--backend", "hls", "--incremental", "2"], HW_REFUSAL),
    (["run", LIO, "-p", "N=4", "--backend", "hls", "--window", "2"], HW_REFUSAL),
])
def test_cli_refuses_streaming_where_no_model_or_solver_runs_it(argv, refusal, capsys):
    rc = main(argv)
    err = capsys.readouterr().err
    assert rc == 2 and refusal in err and "--backend" in err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_cli_stream_hls_needs_a_mode(capsys):
    assert main(["stream", LIO, "-p", "N=4", "--backend", "hls"]) == 2
    assert "--incremental K or --window W" in capsys.readouterr().err


def test_the_simulator_counts_rejected_trial_steps():
    """The simulator's LM counts each trial step it retracts, costs and rejects, and each
    iteration that works out the rounding-noise band for one (the update model prices both):
    on f(x) = x⁴ with a Hessian a hundred times too small, every iteration's first trials
    overshoot and μ grows until a step lowers the cost."""
    from fgc_backends.sim.runtime import fgc_sim_optimizer

    class SingularError(Exception):
        pass

    class Quartic:
        dtype = np.dtype(np.float64)
        x0 = np.array([2.0])
        lib = SimpleNamespace(linear=SimpleNamespace(SingularError=SingularError))

        def cost(self, x):
            return float(x[0] ** 4)

        def linearize(self, x):
            return [np.zeros((1, 2))], np.array([4 * x[0] ** 3]), 0.0

        def solve(self, abs_, mu):
            return np.array([-self.g / (0.01 * self.h + mu)])

        def retract(self, x, delta):
            return x + delta

    problem = Quartic()
    opts = {"eps_step": 1e-12, "lambda_initial": 1e-5, "method": "lm", "max_iterations": 3,
            "eps_gradient": 1e-12, "lambda_factor": 10.0, "mu_min": 1e-12,
            "lambda_upper_bound": 1e10, "absolute_error_tol": 0.0, "relative_error_tol": 0.0}
    tried = []

    trials = []  # per iteration, the points costed

    def linearize(x):
        problem.g, problem.h = 4 * x[0] ** 3, 12 * x[0] ** 2
        trials.append([])
        return Quartic.linearize(problem, x)

    def cost(x):
        tried.append(float(x[0]))
        if trials:
            trials[-1].append(float(x[0]))
        return Quartic.cost(problem, x)

    problem.linearize, problem.cost = linearize, cost
    x, final, iterations, *_ = fgc_sim_optimizer.optimize(problem, opts)
    assert iterations == 3 and final < 16.0
    # every costed point but the start and the three accepted ones was a rejected trial
    assert problem.rejected == len(tried) - 1 - 3 > 3
    # the band is worked out once in each iteration that rejected a trial at a finite cost
    assert problem.noise_passes == sum(len(t) > 1 for t in trials) >= 1


def _stream_parts(files, top, model):
    """Per part of the on-chip stream design (window kernel, batch kernel, stream section) the
    plan's DSP and the second reader's: the window kernel as its own top reads, the batch
    kernel what the stream top reaches in its translation unit, the stream section the rest
    (bench_second_reader.measure_stream's split)."""
    from fgc_backends.hls.reader.design import _design, _Reader

    tab = model.plan.ops
    dsp_of = {"add": tab.add.dsp, "mul": tab.mul.dsp, "div": tab.div.dsp,
              "sqrt": tab.sqrt.dsp, "special": tab.special.dsp}
    reader = _Reader(files, tab.add.latency)
    design = _design(reader, top)
    name = top.removesuffix("_stream")
    batch_cpp = next(k for k, _ in files if k.endswith(".cpp") and k != f"{name}.cpp")
    batch = design.unit_dsp(dsp_of, batch_cpp)
    window = _design(reader, f"{name}_top").dsp(dsp_of)
    read = {"window kernel": window, "batch kernel": batch,
            "stream section": design.dsp(dsp_of) - batch - window}
    plan = {k: d for k, (d, _) in model.resources()["parts"].items()}
    return {k: (plan[k], read[k]) for k in read}, dict(design.modules)


@pytest.fixture(scope="module")
def emitted_stream(graph, stream, tmp_path_factory):
    """Paper A's on-chip design (the incremental K = 3 stream with a batch step), emitted."""
    import fgc_backends
    from fgc.app.streaming import WindowPricer, stream_program
    from fgc_backends.hls.reader import emitted_files

    program = stream[0]
    model = WindowPricer(stream_program(graph, program)).model
    out = tmp_path_factory.mktemp("stream_design")
    hls = fgc_backends.load("hls")
    hls.emit(stream_program(graph, program, None), out, hls.Config(scalar="float"))
    files, top = emitted_files(out)
    return files, top, model


def test_the_plan_prices_every_copy_of_the_stream_design(emitted_stream):
    """Issue 32: every RTL copy the emitted stream design holds (each call site its own unless
    an ALLOCATION shares it) has a price: the plan's DSP is at least the second reader's on each
    part (the window kernel, the batch kernel, the stream section's own code), and the copies
    that run one after the other are one instance (LM's linearisation and elimination and the
    stream's after it; the kept net's Log / retraction passes)."""
    files, top, model = emitted_stream
    parts, modules = _stream_parts(files, top, model)
    assert set(parts) == {"window kernel", "batch kernel", "stream section"}
    for part, (plan, read) in parts.items():
        assert plan >= read > 0, (part, plan, read)
    # one per kernel (the window's, the batch kernel's); one each in the kept net
    assert modules["linearize_all"] == modules["eliminate_all"] == 2
    assert modules["back_substitute_at"] == 2  # the cost pass with it (trial_cost)
    assert modules["keyframe_pass"] == 1  # the kept net's Log and retraction: one module
    assert "keyframe_local" not in modules and "keyframe_retract" not in modules  # INLINE


@pytest.mark.heavy
def test_a_call_site_without_a_price_fails_the_stream_check(emitted_stream):
    """The check above can fail: a second call of the window / kept region planted in the
    stream top is a second copy of LM's units and the kept net's datapaths that the plan does
    not price, and the stream section then reads above its plan."""
    files, top, model = emitted_stream
    call = "window_and_kept<CFG>(mode, mc, live, lin01, errors, info, result, reexp, walk, x0);"
    planted = [(k, t.replace(call, call + "\n        " + call)) if k == "fgc_stream.h" else (k, t)
               for k, t in files]
    assert planted != files
    plan, read = _stream_parts(planted, top, model)[0]["stream section"]
    assert read > plan
