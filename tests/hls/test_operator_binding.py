"""The floating-point operators' binding as a design dimension (``DesignOptions.bind``): the
operator table's implementations (cost/operators.py), the plan's price of a bound design, the
emitted ``config_op`` lines, the second reader reading them back, and the design search taking
a binding when it is the only way to fit."""

from __future__ import annotations

import dataclasses

import pytest

from fgc.errors import FgcError
from fgc_backends.cost import operators
from fgc_backends.cost.operators import (
    DEFAULT_BIND,
    IMPLEMENTATIONS,
    TABLES,
    BindError,
    implementations,
    normalise_bind,
    parse_bind,
)
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.config import DesignOptions, HlsConfigError
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
from fgc_backends.hls.plan.model import PlanError
from fgc_backends.hls.target import Target
from tests.hls.hls_programs import chain

FABRIC_ADD = (("add", "fabric"),)
SMALL = (("add", "fabric"), ("mul", "meddsp"))


# -- the table ------------------------------------------------------------------------------

@pytest.mark.parametrize("key", sorted(TABLES, key=str))
def test_every_implementation_is_priced_with_a_source(key):
    table = TABLES[key]
    impls = implementations(table)
    assert set(impls) == set(IMPLEMENTATIONS)
    for kind, by_impl in impls.items():
        assert tuple(by_impl) == IMPLEMENTATIONS[kind]
        # the default implementation is the table's own entry: the default design's figures
        assert by_impl[DEFAULT_BIND[kind]] is table.op(kind)
        for o in by_impl.values():
            assert o.source and o.status in ("documented", "assumed")
            assert o.resource_status in ("documented", "assumed")
            # config_op pins the latency: a binding never changes a cycle
            assert (o.latency, o.ii) == (table.op(kind).latency, table.op(kind).ii)
            assert o.lut > 0 and o.ff > 0
        # fewer DSP from maxdsp to fabric, and the fabric ones take none
        dsp = [by_impl[i].dsp for i in IMPLEMENTATIONS[kind]]
        assert dsp == sorted(dsp, reverse=True) and by_impl["fabric"].dsp == 0
        assert by_impl["fabric"].lut > table.op(kind).lut


def test_fabric_adder_of_the_papers_table_is_documented():
    t = operators.table("float32", "7series", 143.0)
    add = implementations(t)["add"]["fabric"]
    assert (add.latency, add.dsp, add.lut, add.ff) == (4, 0, 338, 243)
    assert add.status == add.resource_status == "documented"
    assert "fadd_32ns_32ns_32_5_no_dsp" in add.source


def test_bound_table_replaces_add_and_mul_only():
    t = operators.table("float32")
    assert operators.bound(t, ()) is t
    b = operators.bound(t, SMALL)
    assert b.add.dsp == 0 and b.mul.dsp == implementations(t)["mul"]["meddsp"].dsp == 1
    for kind in operators.OPERATOR_KINDS:
        if kind not in ("add", "mul"):
            assert b.op(kind) is t.op(kind)
    assert Target(bind=SMALL).ops("float32") == b
    assert Target().ops("float32") is t


def test_binding_is_canonical_and_checked():
    assert normalise_bind((("mul", "meddsp"), ("add", "fabric"))) == SMALL
    assert normalise_bind((("add", "fulldsp"), ("mul", "maxdsp"))) == ()  # the defaults
    assert parse_bind("mul=meddsp, add=fabric") == SMALL
    assert parse_bind("default") == ()
    with pytest.raises(BindError, match="fulldsp, fabric"):
        normalise_bind((("add", "meddsp"),))
    assert issubclass(BindError, FgcError)
    with pytest.raises(BindError, match="kinds: add, mul"):
        parse_bind("div=fabric")
    with pytest.raises(BindError, match="twice"):
        normalise_bind((("add", "fabric"), ("add", "fulldsp")))
    with pytest.raises(HlsConfigError, match="implementations of mul: maxdsp, fulldsp, meddsp, "
                                             "fabric"):
        DesignOptions(bind=(("mul", "dsp"),))
    assert isinstance(HlsConfigError("x"), FgcError)
    assert HlsConfig(bind=(("mul", "meddsp"), ("add", "fabric"))).bind == SMALL
    assert HlsConfig(bind=(("add", "fulldsp"),)).design == DesignOptions()


# -- the plan -------------------------------------------------------------------------------

def _adds_and_muls(plan) -> tuple[int, int]:
    ops = [(k, u.instances * n) for u in plan.units for k, n in u.operators]
    return sum(n for k, n in ops if k == "add"), sum(n for k, n in ops if k == "mul")


def test_plan_prices_the_bound_operators_and_keeps_the_cycles():
    program = chain(5, units=4)
    plans = {bind: build_plan(program, PlanOptions.for_config(HlsConfig(bind=bind), program))
             for bind in ((), FABRIC_ADD, SMALL)}
    costs = {bind: plan_cost(p) for bind, p in plans.items()}
    adds, muls = _adds_and_muls(plans[()])
    assert adds > 0 and muls > 0
    t = operators.table("float32")
    full, fabric = t.add, implementations(t)["add"]["fabric"]
    med = implementations(t)["mul"]["meddsp"]
    d, f, s = costs[()], costs[FABRIC_ADD], costs[SMALL]
    assert d.cycles == f.cycles == s.cycles
    assert d.phase_cycles == f.phase_cycles == s.phase_cycles
    assert d.dsp - f.dsp == adds * full.dsp
    assert f.lut - d.lut == adds * (fabric.lut - full.lut)
    assert f.ff - d.ff == adds * (fabric.ff - full.ff)
    assert f.dsp - s.dsp == muls * (t.mul.dsp - med.dsp)
    assert plans[SMALL].target.bind == SMALL


@pytest.mark.parametrize("scalar", ["float", "double"])
def test_rebind_is_the_plan_built_with_the_binding(scalar):
    """The search prices a design's bindings by rebinding one plan: exactly the plan built
    with each (no unit reads an operator's DSP/LUT/FF while it is built)."""
    from fgc_backends.hls.emitter import for_program
    from fgc_backends.hls.plan.cost import rebind

    # float: the mixed design (a double linear solver, its own table); double: all double
    program = chain(5, units=4, linear_precision="float64") if scalar == "float" else chain(5)

    def plan(bind):
        config = for_program(program, HlsConfig(scalar=scalar, bind=bind))
        return build_plan(program, PlanOptions.for_config(config, program))

    base = plan(())
    assert rebind(base, ()) is base
    assert scalar == "double" or base.options.les_precision == "float64"
    for bind in (FABRIC_ADD, SMALL, (("mul", "fabric"),)):
        built = plan(bind)
        again = rebind(base, bind)
        assert again.options == built.options and again.ops == built.ops
        assert plan_cost(again) == plan_cost(built)
        assert plan_cost(rebind(again, ())) == plan_cost(base)


def test_plan_refuses_a_bad_binding():
    program = chain(5)
    with pytest.raises(PlanError, match="implementations of add"):
        build_plan(program, PlanOptions.of(program, bind=(("add", "maxdsp"),)))
    with pytest.raises(PlanError, match="not canonical"):
        build_plan(program, PlanOptions.of(program, bind=(("mul", "fabric"), ("add", "fabric"))))


def test_fit_counts_lut_and_ff():
    """A design bound to fabric cannot fit by its DSP alone: the part's LUTs decide."""
    program = chain(5, units=4)
    bind = (("add", "fabric"), ("mul", "fabric"))
    cost = plan_cost(build_plan(program, PlanOptions.for_config(
        HlsConfig(part="xc7z020clg484-1", bind=bind), program)))
    assert cost.dsp <= 220  # the xc7z020's DSP
    assert not cost.fits and "LUT" in cost.over


# -- the emitted text and the second reader ---------------------------------------------------

def test_emitted_config_op_lines(tmp_path):
    from fgc_backends.hls.reader import emitted_ops, tcl_binding

    program = chain(5)
    emit(program, tmp_path / "d", HlsConfig())
    assert "config_op" not in (tmp_path / "d" / "run_hls.tcl").read_text()
    for out in ("a", "b"):
        emit(program, tmp_path / out, HlsConfig(bind=SMALL))
    tcl = (tmp_path / "a" / "run_hls.tcl").read_text()
    assert tcl == (tmp_path / "b" / "run_hls.tcl").read_text()  # deterministic
    lines = [ln for ln in tcl.splitlines() if ln.startswith("config_op")]
    assert lines == ["config_op fadd -impl fabric -latency 4",
                     "config_op fsub -impl fabric -latency 4",
                     "config_op fmul -impl meddsp -latency 3"]
    assert tcl.index("create_clock") < tcl.index("config_op") < tcl.index("csim_design")
    assert tcl_binding(tcl) == {"float32": SMALL}
    # the binding is the script's alone: the C++ (and so the C simulation, the counting
    # csim's cycles) is the default design's, byte for byte
    names = sorted(p.relative_to(tmp_path / "d") for p in (tmp_path / "d").rglob("*")
                   if p.is_file())
    assert names == sorted(p.relative_to(tmp_path / "a") for p in (tmp_path / "a").rglob("*")
                           if p.is_file())
    for name in names:
        if name.name != "run_hls.tcl":
            assert (tmp_path / "d" / name).read_bytes() == (tmp_path / "a" / name).read_bytes()
    assert emitted_ops(tmp_path / "a")("float32") == Target(bind=SMALL).ops("float32")
    assert emitted_ops(tmp_path / "d")("float32") is operators.table("float32")


def test_double_design_binds_the_double_operators(tmp_path):
    program = chain(5)
    emit(program, tmp_path, HlsConfig(scalar="double", bind=FABRIC_ADD))
    tcl = (tmp_path / "run_hls.tcl").read_text()
    lines = [ln for ln in tcl.splitlines() if ln.startswith("config_op")]
    lat = operators.table("float64").add.latency
    assert lines == [f"config_op dadd -impl fabric -latency {lat}",
                     f"config_op dsub -impl fabric -latency {lat}"]


def test_reader_takes_the_binding_from_the_text(tmp_path):
    """The reader prices a fabric design's adders at 0 DSP because run_hls.tcl says so: the
    same text without the config_op lines reads at the default binding's DSP; plan >= reader
    holds for the bound design."""
    from fgc_backends.hls.reader import (
        check_dsp,
        dsp_table,
        emitted_files,
        emitted_ops,
        read_design,
    )

    program = chain(5, units=4)
    config = HlsConfig(bind=FABRIC_ADD)
    emit(program, tmp_path, config)
    files, top = emitted_files(tmp_path)
    design = read_design(files, top, 4)
    bound = design.dsp(dsp_table(emitted_ops(tmp_path), "float32"))
    cost = plan_cost(build_plan(program, PlanOptions.for_config(config, program)))
    assert bound <= cost.dsp and check_dsp(design, cost.dsp,
                                           dsp_table(emitted_ops(tmp_path), "float32")) == []
    tcl = tmp_path / "run_hls.tcl"
    tcl.write_text("\n".join(ln for ln in tcl.read_text().splitlines()
                             if not ln.startswith("config_op")))
    unbound = design.dsp(dsp_table(emitted_ops(tmp_path), "float32"))
    adds = dict(design.operators).get("add", 0)
    assert adds > 0 and unbound - bound == adds * operators.table("float32").add.dsp


def test_reader_refuses_an_unknown_implementation():
    from fgc_backends.hls.reader import tcl_binding

    with pytest.raises(ValueError, match="fulldsp, fabric"):
        tcl_binding("config_op fadd -impl maxdsp -latency 4\n")
    # the tool's own choice, and operators the table does not bind, are the default binding
    assert tcl_binding("config_op fadd -impl all\nconfig_op fdiv -impl fabric\n") == {}
    # fadd and fsub bound apart: the one of fewer DSP (a lower bound)
    assert tcl_binding("config_op fadd -impl fabric -latency 4\n"
                       "config_op fsub -impl fulldsp -latency 4\n") == {"float32": FABRIC_ADD}


# -- the search -----------------------------------------------------------------------------

def test_search_takes_the_binding_when_only_it_fits():
    """On a part whose DSP the default binding exceeds, the search's best design is the bound
    one; with the binding ignored (every candidate priced at the default) none would fit."""
    from fgc.app.search import Space, search

    program = chain(5, units=16)
    part = "xc7z035ffg676-2"  # 900 DSP, 171,900 LUT
    default, bound = (plan_cost(build_plan(program, PlanOptions.for_config(
        HlsConfig(part=part, bind=b), program))) for b in ((), FABRIC_ADD))
    assert bound.dsp <= 900 < default.dsp and bound.fits
    reads = []

    def reader(p, config):  # the plan's DSP as the reader's (the real reader: test above)
        reads.append(config.bind)
        return {"dsp": plan_cost(build_plan(p, PlanOptions.for_config(config, p))).dsp}, False

    space = Space(linears=("qr",), units=(16,), part=part, binds=((), FABRIC_ADD),
                  extra=(("qr_unit", ("householder",)),))
    result = search({"qr": program}, space, reader_fn=reader)
    assert result.best is not None and result.best.candidate.bind == FABRIC_ADD
    assert "bind add=fabric" in result.best.label
    over = [r for r in result.rows if r.candidate.bind == ()]
    assert over and all(r.verdict == "over" for r in over)
    assert reads == [FABRIC_ADD]  # the default one is over by its plan: never read
    # among designs of equal speed the space's order decides: the default first when it fits
    roomy = dataclasses.replace(space, part="xczu9eg-ffvb1156-2-e")
    reads.clear()
    best = search({"qr": program}, roomy, reader_fn=reader).best
    assert best.candidate.bind == () and reads == [()]


def test_sweep_fit_binds_option():
    """``fgc sweep --fit-bind add=fabric``: the fit search may take that binding too (the
    default first); a bad binding is a usage error naming the implementations."""
    import argparse

    from fgc.app import sweep

    parser = argparse.ArgumentParser()
    sweep.add_fit_arguments(parser)
    args = parser.parse_args(["--fit-bind", "add=fabric", "--fit-bind", "mul=meddsp,add=fabric"])
    assert sweep.fit_options(args, False)["fit_binds"] == ((), FABRIC_ADD, SMALL)
    assert sweep.fit_options(parser.parse_args([]), False)["fit_binds"] == ((),)
    with pytest.raises(SystemExit):
        parser.parse_args(["--fit-bind", "add=meddsp"])


def test_cli_bind_reaches_the_design():
    from fgc.app.cli import build_parser
    from fgc.app.commands.steps import hls_config

    args = build_parser().parse_args(["compile", "x.py", "--backend", "hls", "--out", "o",
                                      "--bind", "add=fabric,mul=meddsp"])
    assert hls_config(args, chain(3)).bind == SMALL
