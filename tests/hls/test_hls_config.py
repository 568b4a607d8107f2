"""The HLS backend's configuration (backends/hls/config.py): the design options an HlsConfig
carries, the one place they are validated, and the plan options built from them."""

from __future__ import annotations

import dataclasses

import pytest
from hls_programs import chain

from fgc.errors import FgcError
from fgc_backends.hls.config import DesignOptions, HlsConfig, HlsConfigError
from fgc_backends.hls.plan import DEFAULT_ALLOCATION, PlanOptions, build_plan
from fgc_backends.hls.target import DEFAULT_PART, Target

ZU9 = "xczu9eg-ffvb1156-2-e"


def test_the_old_keywords_are_the_design_options():
    old = HlsConfig(scalar="double", part=ZU9, clock_ns=5.0, unit_sets=2,
                    allocation=(("mul", 48),))
    new = HlsConfig(scalar="double", design=DesignOptions(part=ZU9, clock_ns=5.0, unit_sets=2,
                                                          allocation=(("mul", 48),)))
    assert old == new and hash(old) == hash(new)
    assert (old.part, old.clock_ns, old.unit_sets, old.allocation) == (
        ZU9, 5.0, 2, (("mul", 48),))
    # a keyword given beside ``design`` overrides that one option
    assert HlsConfig(design=new.design, unit_sets=3).design == dataclasses.replace(
        new.design, unit_sets=3)
    # dataclasses.replace (cfamily.limits.for_program widens the linear solver) keeps the design
    wide = dataclasses.replace(old, linear_scalar="double")
    assert wide.design == old.design and wide.linear_scalar == "double"
    assert HlsConfig().design == DesignOptions() and HlsConfig().part == DEFAULT_PART
    with pytest.raises(AttributeError):
        old.part = DEFAULT_PART  # frozen: read through, never set
    with pytest.raises(HlsConfigError, match="DesignOptions, got dict"):
        HlsConfig(design={"part": ZU9})


@pytest.mark.parametrize("options, message", [
    ({"part": "xc7z045;rm"}, "is not a plain part name"),
    ({"part": "xc9z999"}, "fgc knows no capacities for its device"),
    ({"clock_ns": 0.1}, r"clock period 0.1 ns is outside 0.5 … 1000 ns"),
    ({"unit_sets": 9}, r"unit_sets must be 1 … 8, got 9"),
    ({"allocation": (("fma", 4),)}, r"allocation entry \('fma', 4\)"),
    ({"allocation": (("mul", 0),)}, r"allocation limit of mul must be 1 … 4096, got 0"),
    ({"allocation": (("mul", 4), ("mul", 8))}, "names a kind twice"),
    ({"retire_special": 4}, r"retire_special must be 1, 2 or 3"),
])
def test_one_check_names_the_bad_option(options, message):
    design = DesignOptions(**options)
    for check in (design.check, HlsConfig(design=design).check):
        with pytest.raises(HlsConfigError, match=message) as err:
            check()
        assert isinstance(err.value, FgcError)  # one line at the command line, exit 2


def test_the_clock_agrees_with_the_programs():
    program = chain(4, linear="qr", clock_mhz=200.0)
    DesignOptions(clock_ns=5.0).check(program)
    DesignOptions().check(program)  # no period: the Program's clock
    with pytest.raises(HlsConfigError, match=r"clock mismatch: .* 200 MHz .*clock_ns=7"):
        HlsConfig(clock_ns=7.0).check(program)
    HlsConfig(clock_ns=7.0).check()  # without a Program there is nothing to agree with
    assert DesignOptions(part=ZU9).target(program) == Target(ZU9, 200.0)


@pytest.mark.parametrize("linear", ["qr", "cholesky"])
def test_the_plan_options_are_built_from_the_design(linear):
    program = chain(5, linear=linear)  # float32
    config = HlsConfig(scalar="double", part=ZU9, unit_sets=1, allocation=(("mul", 48),))
    options = config.plan_options(program)
    assert options == PlanOptions.for_config(config, program)
    assert (options.units, options.cpe) == (program.solver.units, program.solver.cpe)
    assert (options.part, options.unit_sets) == (ZU9, 1)
    assert dict(options.allocation) == {**dict(DEFAULT_ALLOCATION), "mul": 48}
    # priced in the scalar the design emits (double), not the Program's float32
    assert options.precision == options.les_precision == "float64"
    plan = build_plan(program, options)
    assert plan.target == DesignOptions(part=ZU9).target(program)
    assert HlsConfig().plan_options(program, cpe=3).cpe == 3  # a what-if change on top


def test_back_substitutions_width_is_decided_for_the_program():
    """``DesignOptions.backsub_lanes = None`` (the default): by columns (4) where the elimination
    tree is a chain (one end or two, the rule the column design is built or refused by), one
    lane on a tree and in the streaming designs; explicit widths are kept and checked; the plan
    options carry the resolved width."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls.config import auto_backsub_lanes
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.plan.model import PlanError
    from fgc_backends.hls.units.backsub import column_chain

    assert DesignOptions().backsub_lanes is None and HlsConfig().backsub_lanes is None
    HlsConfig().check()
    two_ended, one_ended = chain(6, linear="cholesky"), chain(6, ordering="natural")
    tree = compile_graph(example("pose_graph").build(), SolverConfig(linear="cholesky"),
                         name="w100")
    assert column_chain(_tables(one_ended))[1] == ()  # one end: the root's chain alone
    assert [auto_backsub_lanes(p) for p in (two_ended, one_ended, tree)] == [4, 4, 1]
    assert auto_backsub_lanes(two_ended, stream=True) == 1
    for program, lanes in ((two_ended, 4), (one_ended, 4), (tree, 1)):
        config = HlsConfig()
        assert config.resolved(program).backsub_lanes == lanes
        assert config.plan_options(program).backsub_lanes == lanes
        assert config.resolved(program).plan_options(program) == config.plan_options(program)
    assert HlsConfig().resolved(two_ended, stream=True).backsub_lanes == 1
    # explicit widths are the design's, resolved or not; a what-if change wins
    for lanes in (1, 2, 4):
        config = HlsConfig(backsub_lanes=lanes)
        assert config.resolved(two_ended) is config
        assert config.plan_options(two_ended).backsub_lanes == lanes
    assert HlsConfig().plan_options(two_ended, backsub_lanes=2).backsub_lanes == 2
    # columns are a frontal design's: a what-if dense Hessian stays one lane
    assert HlsConfig().plan_options(two_ended, hessian_storage="dense").backsub_lanes == 1
    with pytest.raises(PlanError, match="backsub_lanes 4.*w100.*not a chain"):
        build_plan(tree, HlsConfig(backsub_lanes=4).plan_options(tree))
    for bad in (0, 3, True, "auto"):
        with pytest.raises(HlsConfigError, match="backsub_lanes must be one of 1, 2, 4 or None"):
            HlsConfig(backsub_lanes=bad).check()


def test_the_emitted_design_and_its_project_carry_the_resolved_width(tmp_path):
    """``emit`` with the default config: a chain gets back-substitution by columns (the kernel
    defines FGC_BS_COLUMNS; the project's config says 4, so the plan of ``project.config`` is
    the design's); an explicit width of one is the slot design."""
    from fgc_backends.hls import emit
    from fgc_backends.hls.emitter import accel_plan

    program = chain(4, linear="cholesky")
    project = emit(program, tmp_path / "chain", HlsConfig(scalar="float"))
    text = (tmp_path / "chain" / f"{project.name}.cpp").read_text()
    assert "#define FGC_BS_COLUMNS 1" in text and project.config.backsub_lanes == 4
    assert accel_plan(program, project.config) == accel_plan(program, HlsConfig(scalar="float"))
    one = emit(program, tmp_path / "one", HlsConfig(scalar="float", backsub_lanes=1))
    assert "FGC_BS_COLUMNS" not in (tmp_path / "one" / f"{one.name}.cpp").read_text()


def test_the_streaming_designs_back_substitute_one_lane():
    """The on-chip window's template is a chain, yet its design and its price keep one lane
    (plan/update.py prices one): the default config resolves to 1 there, and an explicit wider
    width is refused by name."""
    from fgc import Graph, Pose2
    from fgc.app.streaming import compile_stream
    from fgc.compiler.stream import stream_program
    from fgc.frontend import noise
    from fgc.frontend.factors import BetweenFactor, PriorFactor
    from fgc_backends.hls.config import auto_backsub_lanes
    from fgc_backends.hls.emitter import emit
    from fgc_backends.hls.plan.stream import WindowUpdateModel
    from fgc_backends.hls.streaming import layout_of

    graph = Graph()
    for i in range(6):
        graph.add_variable(i, Pose2(float(i), 0.0, 0.0))
    graph.add(PriorFactor(0, Pose2(0.0, 0.0, 0.0), noise.isotropic(3, 0.1)))
    for i in range(5):
        graph.add(BetweenFactor(i, i + 1, Pose2(1.0, 0.0, 0.0), noise.isotropic(3, 0.2)))
    layout = layout_of(stream_program(graph, compile_stream(graph, window=3), 3))
    assert auto_backsub_lanes(layout.template) == 4  # a batch design of it would take columns
    model = WindowUpdateModel(layout, HlsConfig(scalar="float"))
    assert model.plan.options.backsub_lanes == 1
    for lanes in (2, 4):
        with pytest.raises(HlsConfigError, match=f"backsub_lanes {lanes}: the streaming"):
            emit(layout.template, "/nonexistent", HlsConfig(backsub_lanes=lanes), stream=layout)


def test_the_retires_special_function_instances_set_its_ii():
    """``retire_special``: retract_<k>'s special-function instances (PlanOptions.state_limits);
    a Pose3 retraction's 3 special functions (II 12) on 1 instance a variable every 36 cycles,
    on 2 every 22 (its 88 adds on 4 adders), a special-function instance more in the plan."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls.units.state_update import retire_timing
    program = compile_graph(example("lio").build(N=3),
                            SolverConfig(method="gn", linear="qr", precision="float32"))
    iis = {}
    for n in (None, 2):
        options = HlsConfig(scalar="float", backsub_lanes=1,  # (by columns: 2 already)
                            retire_special=n).plan_options(program)
        assert dict(options.state_allocation)["special"] == (n or 1)
        iis[n] = retire_timing(program.variables, build_plan(program, options).ops, 15,
                               options.state_allocation)[0]
        pose = dict(build_plan(program, options).unit("state_update_0").operators)
        assert pose["special"] == (n or 1)
    assert iis == {None: 36, 2: 22}
