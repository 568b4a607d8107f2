"""The special functions' arithmetic the plan adds to a datapath's counts
(backends/hls/units/special_ops.py): the emitted helpers' bodies (a Lie coefficient's Horner
series and closed form, so3_log once per rotation) run inside the caller's pipelined loop, so
the plan prices them with the kernel's own operations; imu_window's IMU datapath read 16 DSP
above its plan without them."""

from __future__ import annotations

import re

import pytest

from fgc.frontend.geometry import special
from fgc_backends.hls.units.special_ops import SO3_LOG_OPS, coefficient_ops, helper_ops


@pytest.fixture(scope="module")
def imu():
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig

    return compile_graph(example("imu_window").build(N=3), name="imu",
                         solver=SolverConfig(linear="cholesky", cpe=5))


def test_a_coefficient_is_its_series_and_its_closed_form():
    for name, series in special.SERIES.items():
        ops = dict(coefficient_ops(name))
        terms = len(series) - 1
        assert ops["add"] >= terms and ops["mul"] >= terms and ops["sqrt"] == 1
        assert "trig" not in ops  # the sines and cosines are what `special` prices
        # one call issues the larger branch of each kind: the series' terms or the closed form's
        issued = dict(coefficient_ops(name, exclusive=True))
        assert issued["add"] == max(terms, ops["add"] - terms)
        assert issued["mul"] == max(terms, ops["mul"] - terms) < ops["mul"] or name == "A"
        assert issued["sqrt"] == 1 and issued["div"] == ops["div"]  # the series has neither


def test_helper_ops_count_each_call_and_one_log_per_rotation(imu):
    block = next(b for b in imu.blocks if b.name == "CombinedImuFactor")
    text = block.cost_kernel
    printed = " ".join(e for _, e in text.assignments) + " ".join(text.outputs)
    calls = re.findall(r"\blie_(A1|B1|C1|D1|A|B|C|D)\(", printed)
    logs = len(set(re.findall(r"so3_log_[xyz]\((.*?)\)\)", printed))) or 1
    assert calls, "the IMU cost kernel calls Lie coefficients"
    want = {k: 0 for k in ("add", "mul", "div", "sqrt")}
    for name in calls:
        for k, n in coefficient_ops(name):
            want[k] += n
    for k, n in SO3_LOG_OPS.items():
        want[k] += n * logs
    assert dict(helper_ops(text)) == {k: n for k, n in want.items() if n}
    # a kernel without special functions adds nothing
    prior = next(b for b in imu.blocks if b.name == "PriorFactorVector3")
    assert helper_ops(prior.kernel) == ()


@pytest.mark.heavy  # ~25 s: imu_window N=10 emitted and read
def test_the_imu_datapath_is_priced_at_least_as_read(tmp_path):
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls import HlsConfig, emit
    from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
    from fgc_backends.hls.reader import emitted_files, read_design

    program = compile_graph(example("imu_window").build(N=10), name="imu",
                            solver=SolverConfig(linear="cholesky", cpe=20))
    emit(program, tmp_path, HlsConfig())
    plan = build_plan(program, PlanOptions.for_config(HlsConfig(), program))
    units = dict(plan_cost(plan).dsp_by_unit)
    tab = plan.target.ops(plan.precision)
    dsp = {k: tab.op(k).dsp for k in ("add", "mul", "div", "sqrt", "special")}
    files, top = emitted_files(tmp_path)
    design = read_design(files, top, tab.add.latency)
    modules = dict(design.modules)
    for b in range(len(program.blocks)):
        loops = [r for r in design.loops if re.fullmatch(rf"(?:evaluate|cost_of)_{b}", r.function)]
        read = sum(r.dsp(dsp) * modules.get(r.function, 0) for r in loops)
        assert read <= units[f"factor_{b}"], (program.blocks[b].name, read, units)


def test_sign_flips_are_no_multiplies(imu):
    """The compiler counts a - b as a + (-1)·b and s**2/2 as a multiply and a divide; the
    printed kernel holds a subtraction and (T(0.5))*(s*s). The datapath's counts are the
    printer's: each multiply and divide of the printed cost kernel, no more."""
    import sympy as sp

    from fgc_backends.cfamily.blocks import block_contexts
    from fgc_backends.hls.units.special_ops import printed_counts

    b = next(i for i, blk in enumerate(imu.blocks) if blk.name == "PriorFactorVector3")
    prior = imu.blocks[b]
    kernel = prior.cost_kernel.kernel()
    flips = sum(1 for e in [e for _, e in kernel.assignments] + list(kernel.outputs)
                for node in sp.preorder_traversal(sp.sympify(e))
                if node.is_Mul and node.as_coeff_Mul()[0] == -1)
    assert flips > 0
    printed = block_contexts(imu, vector=False)[b].cost
    text = "\n".join((*printed.intermediates, *printed.outputs))
    counts = printed_counts(prior, "cost")
    assert "(T(0.5))*" in text  # ½‖W r‖²: a multiply by 0.5, counted as a divide there
    assert counts.get("mul", 0) == text.count("*") < prior.ops_cost["mul"]
    assert counts.get("div", 0) == text.count("/") < prior.ops_cost["div"]
