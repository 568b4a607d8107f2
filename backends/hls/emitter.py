"""emit: a Program → a Vitis HLS project (kernel, header, testbench, tcl, Makefile).

Everything a template places is computed here (tables, offsets, sizes) or printed by the backend's
printer (kernels, special functions, literals); the templates place them (loops over the
fields, conditionals on the configuration, offsets multiplied out in place). The only
user text that reaches the files goes through :mod:`fgc_backends.cfamily.names`. Limits are checked
first, so a Program the backend cannot build fails here with an :class:`HlsConfigError`, never in
g++.
"""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass
from pathlib import Path

from fgc.ir.program import Program
from fgc_backends.cfamily import limits, sources
from fgc_backends.cfamily.context import common_context
from fgc_backends.cfamily.names import comment, identifier, key_tokens
from fgc_backends.cfamily.results import ERROR_FLOOR_FACTOR, REFERENCE_MAGIC, RESULT_MAGIC
from fgc_backends.cfamily.scalars import (
    epsilon,
)
from fgc_backends.hls.config import HlsConfig, HlsConfigError
from fgc_backends.hls.lint import lint_project
from fgc_backends.hls.units.special_ops import printed_counts

# template → emitted file name ({name} is the project identifier): the dataflow accelerator the
# plan describes (docs/hls.md). The CPU program is the native backend's (fgc_backends.native).
FILES = (("accel.h.jinja", "{name}.h"), ("accel.cpp.jinja", "{name}.cpp"),
         ("tb.cpp.jinja", "tb_{name}.cpp"), ("run_hls.tcl.jinja", "run_hls.tcl"),
         ("Makefile.jinja", "Makefile"))
SYNTHESISED = ("accel.h.jinja", "accel.cpp.jinja")
INCLUDE = Path(__file__).resolve().parent / "include"  # copied into every project
# the testbench's comparison with the reference (see tb.cpp.jinja's header for the reasons)
TB_TOLERANCES = {"rel": "1e-9", "rot": "1e-3", "vec": "1e-2", "error": "1e-2"}
# the on-chip fixed-lag window's stream file and its result (tb.cpp.jinja's --stream mode)
STREAM_MAGIC = "FGC-STREAM 1"
STREAM_RESULT_MAGIC = "FGC-STREAM-RESULT 1"
# where a variable type stores its rotation: (kind, offset), kind 2 = cos-sin, 3 = 3x3 matrix
ROTATIONS = {"Rot2": (2, 0), "Pose2": (2, 2), "Rot3": (3, 0), "Pose3": (3, 0)}


@dataclass(frozen=True)
class HlsProject:
    """An emitted project: its folder, identifier and files (template order)."""

    directory: Path
    name: str
    files: tuple[Path, ...]
    config: HlsConfig
    # semantic lint issues (empty: the emitter lints strictly and raises on any)
    lint_issues: tuple = ()


_LITERAL = re.compile(r"\(?-?T\([-+0-9.eE]+\)\)?")


def is_constant_literal(expr: str) -> bool:
    """Whether a printed kernel output is a plain constant of T (``T(1)``, ``(-T(1))``): a
    scalar, not a V, so the kernel stores it as it is."""
    return _LITERAL.fullmatch(expr) is not None


def emit(program: Program, out_dir: str | Path, config: HlsConfig | None = None,
         name: str | None = None, stream=None, kernel_only: bool = False) -> HlsProject:
    """Write the HLS project of ``program`` into ``out_dir`` (created if needed).

    ``name`` (default: the Program's name) is sanitised into the project identifier used for
    file names and the top function ``<name>_top``. Emitting the same Program twice gives
    byte-identical files. Every synthesised file is linted (:func:`lint_project`).

    ``stream``: a :class:`fgc_backends.hls.window.WindowLayout` whose template ``program`` is:
    the design gets the on-chip fixed-lag window's top ``<name>_stream`` (the synthesis top) and
    the testbench its ``--stream`` mode; with a ``BatchLayout`` (and ``kernel_only``: the kernel
    and its header alone, no testbench, Makefile or script) the batch kernel of the on-chip
    incremental design, a second file of that design.
    """
    config = for_program(program, config or HlsConfig())
    config.check(program)  # the options, and those that depend on the Program (clock, lanes)
    if stream is not None and config.qr_unit != "householder":
        raise HlsConfigError(f"qr_unit {config.qr_unit!r}: the streaming designs (window, "
                             "incremental) are priced with the householder QR unit only")
    if stream is not None and config.backsub_lanes not in (None, 1):
        raise HlsConfigError(f"backsub_lanes {config.backsub_lanes}: the streaming designs "
                             "(window, incremental) are priced with one-lane back-substitution "
                             "only (plan/update.py)")
    if config.design.data_width != 32 and (stream is None or not _window(stream)
                                           or stream.batch is not None):
        raise HlsConfigError(f"data_width {config.design.data_width}: the streaming top's data "
                             "port (the on-chip window or incremental design, its update's "
                             "start); this design has " + (
                                 "no streaming top" if stream is None else
                                 "a batch kernel, whose entries read a word a beat"))
    # the automatic options decided for this Program (one lane in a streaming design): the
    # plan, the text and the project's config all carry the resolved width
    config = config.resolved(program, stream=stream is not None)
    check_accel(program, config)
    check_limits(program, config)
    project = identifier(name or program.name)
    context = _context(program, config, project, vector=False)
    context.update(accel_context(program, config, context))
    if stream is not None and stream.template is not program:
        raise HlsConfigError("internal error: the stream layout is not of the emitted Program")
    context["stream"] = None if stream is None else (
        stream.context(config.linear_cxx, config.part, config.data_words)
        if config.data_words > 1 else stream.context(config.linear_cxx, config.part))
    context["leaf_lin"] = bool(context["stream"] and context["stream"]["marginal"])
    # the on-chip window's one-step solve: level 0's unit sets reflect their steps inside the
    # linearisation's region (lin_level), as the datapaths fill their banks
    # (with the root step in a wavefront, units/qr.py's lin_wave: the root too, on unit set 1
    # after its own step; a design without lin_level runs the wave as qr_level with `wave`)
    context["lin_qr"] = bool(context["leaf_lin"] and context.get("banks")
                             and context["stream"]["role"] == "window")
    wave = context.get("wave")
    # the QR steps' keep rule by structure where lin_level runs them (fgc_qr.h's mask0)
    context["keep"] = (_keep_context(program, stream, context)
                       if context["lin_qr"] and wave and wave["lin"] else None)
    if wave and wave["lin"] != context["lin_qr"]:
        raise HlsConfigError("root_wave under the one-step policy runs the root inside "
                             "lin_level, the on-chip window's one-step design (an incremental "
                             "or fixed-lag window with its marginal); this design has none")
    # the leaving keyframe's tau and kept conditional beside the update's back-substitution
    # (the one-step policy, the slot design; fgc_stream.h's spec_tau_task, spec_keep_task)
    context["spec"] = bool(context["stream"] and context["stream"]["spec"]
                           and not context.get("mixed") and not context.get("bsc")
                           and not context.get("retire_test"))
    # the one-step solve's linearisation once keyframe 0 has left (lin_level's part 3): without
    # the instances that hold nothing from then on (units/datapath.py's solve_skip)
    context["solve_skip"] = frozenset()
    if context["lin_qr"]:
        from fgc_backends.hls.units.datapath import solve_skip
        context["solve_skip"] = solve_skip(stream.leaf_skipped(), {
            f for f, u in enumerate(context["banks"]["set"]) if u >= 0})
    if context["solve_skip"]:
        from fgc_backends.hls.plan.loops import _tables
        from fgc_backends.hls.units.datapath import bank_fill_words
        bk = context["banks"]
        bk["fill_live"] = bank_fill_words(program, _tables(program), {
            f: (u, 0, 0) for f, u in enumerate(bk["set"]) if u >= 0}, len(bk["step"]),
            context["solve_skip"])
    if context["leaf_lin"]:
        _leaf_context(context, stream.leaf_factors(), stream.leaf_gone(),
                      context["solve_skip"])
        context["leaf_skip"] = stream.leaf_skip()
    if context["stream"] is not None and context["stream"]["kept"]:
        context["stream"]["kept_hw"] = _kept_hw(context, config.scalar_cxx)
    context["stream_magic"], context["stream_result_magic"] = STREAM_MAGIC, STREAM_RESULT_MAGIC
    batch = getattr(stream, "batch", None)
    context["extra_sources"] = [f"{batch.project}.cpp"] if batch is not None else []
    env = sources.environment(config.template_dir())
    env.tests["constant_literal"] = is_constant_literal
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    texts = {}
    for template, pattern in FILES:
        if kernel_only and template not in SYNTHESISED:
            continue
        name_ = pattern.format(name=project)
        texts[name_] = env.get_template(template).render(**context, template=template,
                                                         file_name=name_)
    paths = []
    for name_, text in texts.items():
        path = out / name_
        path.write_text(text)
        paths.append(path)
    units = _copy_headers(out)
    result = HlsProject(out, project, tuple(paths), config)
    # the unit headers are synthesised with the kernel: the semantic rules read them together
    # (a batch kernel's file, emitted before this project, was linted on its own: its symbols
    # are its file's, the same names as this kernel's)
    synthesised = [out / FILES[i][1].format(name=project)
                   for i, (t, _) in enumerate(FILES) if t in SYNTHESISED]
    issues = lint_project(result, synthesised + units, strict=True)
    return dataclasses.replace(result, lint_issues=tuple(issues))


def _copy_headers(out: Path) -> list[Path]:
    """The csim stand-in for hls_stream.h into ``csim_include/`` and the unit headers (this
    backend's and the C-family ones it shares with the native solver, fgc_lm.h) into
    ``include/``: the project builds on its own (only the Makefile puts csim_include on the
    include path; Vitis has its own hls_stream.h). Returns the unit headers (synthesised, so
    linted with the kernel; the stand-in is host code, never synthesised)."""
    units = []
    for sub, pattern in (("csim_include", "csim/*.h"), ("include", "*.h")):
        (out / sub).mkdir(exist_ok=True)
        for header in sorted(INCLUDE.glob(pattern)):
            target = out / sub / header.name
            target.write_bytes(header.read_bytes())
            if sub == "include":
                units.append(target)
    return sorted(units + sources.copy_headers(out / "include"))


def check_accel(program: Program, config: HlsConfig) -> None:
    """Raise :class:`HlsConfigError` for what the dataflow design cannot be emitted for yet."""
    if config.is_fixed_point:
        raise HlsConfigError("the dataflow accelerator is emitted in float or double only: "
                             f"{config.scalar_cxx} has no range-checked fixed-point path yet")


_FUNCTIONS = re.compile(r"\b(fgc_(?:sin|cos|tan|atan2|atan|exp|log1p|log|asin|acos|tanh))\(")
TRIG = ("fgc_sin", "fgc_cos")


def _allocation(unit, scalar_cxx: str, text: str) -> tuple[tuple[str, int], ...]:
    """``#pragma HLS ALLOCATION`` arguments of a factor datapath: the plan's operator limits as
    Vitis operation names (f… float, d… double), trig and special as function instances."""
    prefix = "f" if scalar_cxx == "float" else "d"
    used = sorted(set(_FUNCTIONS.findall(text)))
    out = []
    for kind, limit in unit.operators:
        if kind in ("add", "mul", "div", "sqrt"):
            out.append((f"operation instances={prefix}{kind}", limit))
        elif kind == "trig":
            out += [(f"function instances={f}", limit) for f in used if f in TRIG]
        elif kind == "special":
            out += [(f"function instances={f}", limit) for f in used if f not in TRIG]
    return tuple(out)


def _kept_hw(context: dict, scalar_cxx: str) -> dict:
    """The kept net's datapath module (accel.cpp.jinja's keyframe_pass, the on-chip stream's
    Log and retraction of a keyframe): the Log kernels and the retractions of a keyframe's
    variables that are not vectors printed again with the special functions' ``kept_`` copies
    (INLINE, so their operators are the module's), which coefficients they call and whether
    so3_log, and its ALLOCATION: plan/stream.py's KEPT_LIMITS per arithmetic kind (Vitis
    operation names), one instance of every special function the module reaches."""
    from fgc_backends.hls.plan.stream import KEPT_LIMITS

    stream = context["stream"]
    kinds = {v["kind"] for v in stream["kf_vars"] if not v["flat"]}

    def kept(lines):
        return [re.sub(r"\bso3_log\(", "kept_so3_log(",
                       re.sub(r"\blie_(\w+)\(", r"kept_lie_\1(", line)) for line in lines]

    def printed(k):
        return {"kind": k.kind, "storage_dim": k.storage_dim, "dim": k.dim,
                "intermediates": kept(k.printed.intermediates),
                "outputs": kept(k.printed.outputs)}

    locals_ = [printed(k) for k in stream["locals"] if not k.flat and k.kind in kinds]
    retracts = [printed(k) for k in context["retracts"] if k.kind in kinds]
    text = "\n".join(line for k in locals_ + retracts
                     for line in (*k["intermediates"], *k["outputs"]))
    if re.search(r"\bso3_log_[xyz]\(", text):
        raise HlsConfigError("internal error: the kept net's Log calls so3_log by component")
    helpers = sorted(set(re.findall(r"\bkept_lie_(\w+)\(", text)))
    so3_log = "kept_so3_log(" in text
    reached = text + "".join(line for f in context["coefficients"] if f.name in helpers
                             for line in f.closed_lines)
    if so3_log:
        reached += " fgc_atan2("
    prefix = "f" if scalar_cxx == "float" else "d"
    allocation = [(f"operation instances={prefix}{kind}", n) for kind, n in KEPT_LIMITS]
    functions = set(_FUNCTIONS.findall(reached))
    if so3_log or "fgc_sqrt(" in reached:
        functions.add("fgc_sqrt")
    allocation += [(f"function instances={f}", 1) for f in sorted(functions)]
    return {"locals": locals_, "retracts": retracts, "helpers": helpers, "so3_log": so3_log,
            "allocation": allocation}


def _bound(limits, counts: dict, ii: int, table) -> tuple[tuple[str, int], ...]:
    """One mode's ALLOCATION limits of a factor datapath: per kind of ``limits`` (the options'
    share, units/datapath.py's mode_allocation) the instances its loop binds at ``ii``
    (plan/binding.py's rule, at most that limit), in the limits' order."""
    from fgc_backends.hls.plan.binding import loop_operators
    from fgc_backends.hls.units.datapath import mode_allocation
    allocated = mode_allocation(limits, counts)
    bound = loop_operators({k: counts.get(k, 0) for k, _ in allocated}, ii, dict(allocated),
                           1, table)
    return tuple((k, bound[k]) for k, _ in allocated if bound.get(k))


class _AccelBlock:
    """A block's template context plus what the plan says about its datapath."""

    def __init__(self, block, allocation, jacobian, cost, noise_rows):
        self._block = block
        self.allocation, self.allocation_cost = allocation  # factor_<b>, factor_cost_<b>
        self.ii_jacobian, self.depth_jacobian = jacobian.ii, jacobian.depth
        self.ii_cost, self.depth_cost = cost.ii, cost.depth
        self.noise_row_ii, self.noise_row_depth = noise_rows.ii, noise_rows.depth

    def __getattr__(self, name):
        return getattr(self._block, name)


def accel_plan(program: Program, config: HlsConfig):
    """The accelerator plan the emitted design prints (the Program's n_u / #CPE, the config's
    unit sets and scalar types: :meth:`PlanOptions.for_config`)."""
    from fgc_backends.hls.plan import PlanOptions, build_plan
    return build_plan(program, PlanOptions.for_config(for_program(program, config), program))


def _leaf_context(context: dict, leaf: frozenset, gone: frozenset,
                  skip: frozenset = frozenset()) -> None:
    """The marginal's linearisation (``linearize_all(X, part)``): per block type the instances
    whose rows slot 0's step stacks (``leaf``, part 1) and those of them left once keyframe 0 has
    gone (``live``, part 2), in the block's instance order; a part's table (``*_index``) only
    where its instances are not the first of the block's (then the loop only stops early). The
    small block types' shared loop the same, by its entries. ``skip`` (lin_level's part 3, the
    one-step solve's once keyframe 0 has left): every instance but those (``solve``)."""
    for b in context["blocks"]:
        insts = list(b.instances)
        for part, keep in (("leaf", leaf), ("live", leaf - gone),
                           ("solve", frozenset(insts) - skip)):
            chosen = [f for f in insts if f in keep]
            setattr(b, part, chosen)
            setattr(b, f"{part}_index", chosen)
            setattr(b, f"{part}_table", chosen != insts[:len(chosen)])
    small = context["small"]
    if small:
        for part, keep in (("leaf", leaf), ("live", leaf - gone),
                           ("solve", frozenset(small["instances"]) - skip)):
            chosen = [k for k, f in enumerate(small["instances"]) if f in keep]
            small[part] = chosen
            small[f"{part}_index"] = chosen
            small[f"{part}_table"] = chosen != list(range(len(chosen)))


def _lin_blocks(program, options, blocks: list) -> list:
    """The block types in the order evaluate_all and reduce_all emit their datapath loops
    (units/datapath.py's datapath_order; the small ones where the first of them stands)."""
    from fgc_backends.hls.units.datapath import datapath_order, small_blocks

    small = small_blocks(program)
    at = {b: k for k, b in enumerate(datapath_order(program, options))}
    return sorted(blocks, key=lambda b: at[small[0] if b.index in small else b.index])


def accel_context(program: Program, config: HlsConfig, context: dict) -> dict:
    """What accel.cpp.jinja needs beyond the shared context: the plan's units, IIs and network."""
    from fgc_backends.hls.plan import kernel_timing, process_network, unit_sets
    from fgc_backends.hls.plan.loops import _sizes, _tables
    from fgc_backends.hls.plan.model import Unit
    from fgc_backends.hls.units.backsub import retire_solved
    from fgc_backends.hls.units.cholesky import (
        gram_config,
        gram_ii,
        jacobian_cycles,
        jacobian_ii,
    )
    from fgc_backends.hls.units.datapath import (
        cost_in_linearization,
        factor_allocation,
        small_allocation,
        small_blocks,
    )
    from fgc_backends.hls.units.state_update import retire_order, retire_timing
    plan = accel_plan(program, config)
    phase = {ph.name: ph for ph in plan.phases}
    # each datapath's instance loop (Cholesky: its Jacobian pass in its linearize_<b> region)
    loops = {p.name: p.loops[0] for ph in plan.phases for p in ph.processes
             if re.fullmatch(r"factor_(\d+|small)_(jacobian|cost)", p.name)}
    noise = {p.name: p.loops[2] for p in phase["rounding_noise"].processes
             if p.name.startswith("noise_")}
    hgc = {p.name: p for ph in plan.phases if ph.name.startswith("hgc") for p in ph.processes
           if p.name.startswith("reduce_")}
    jac_ii = jacobian_ii(p for ph in plan.phases for p in ph.processes)
    jac_cycles = jacobian_cycles([p for ph in plan.phases for p in ph.processes])
    blocks = []
    # factor_<b>'s ALLOCATION limits (the plan's unit is what Vitis binds around them)
    allocations = factor_allocation(program, plan.options)
    small = small_blocks(program)
    shared = None
    if small:  # the small block types' one datapath per mode (units/datapath.py)
        texts = "\n".join(line for i in small for b in (context["blocks"][i],)
                          for line in (*b.jacobian.intermediates, *b.jacobian.outputs,
                                       *b.cost.intermediates, *b.cost.outputs))
        small_jac, small_cost = (loops[f"factor_small_{mode}"] for mode in ("jacobian", "cost"))
        shared = {"first": small[0], "count": small_jac.trip,
                  "blocks": [i for i in small for _ in context["blocks"][i].instances],
                  "instances": [f for i in small for f in context["blocks"][i].instances],
                  "names": ", ".join(context["blocks"][i].comment for i in small),
                  **{key: _allocation(Unit("factor_small", "ALLOCATION", 1, small_allocation(
                      program, context["blocks"], plan.options, mode, plan.ops)[0]),
                      config.scalar_cxx, texts)
                     for key, mode in (("allocation", "jacobian"), ("allocation_cost", "cost"))},
                  "ii_jacobian": small_jac.ii, "depth_jacobian": small_jac.depth,
                  "ii_cost": small_cost.ii, "depth_cost": small_cost.depth}
    for b in context["blocks"]:
        block = program.blocks[b.index]
        if b.index in small:  # printed inline into the shared datapath's branch
            blocks.append(_AccelBlock(b, ((), ()), small_jac, small_cost,
                                      noise[f"noise_{b.index}"]))
            blocks[-1].small = True
        else:
            # each mode's ALLOCATION: the instances the plan binds at its loop's II (at most
            # the options' limits), so the text holds Vitis to the plan's operators
            # (the counts as printed: the special functions' bodies in)
            jac = Unit(f"factor_{b.index}", "ALLOCATION", 1, _bound(
                allocations[b.index], printed_counts(block, "jacobian"),
                loops[f"factor_{b.index}_jacobian"].ii, plan.ops))
            cost = Unit(f"factor_cost_{b.index}", "ALLOCATION", 1, _bound(
                allocations[b.index], printed_counts(block, "cost"),
                loops[f"factor_{b.index}_cost"].ii, plan.ops))
            jac_text = "\n".join((*b.jacobian.intermediates, *b.jacobian.outputs))
            cost_text = "\n".join((*b.cost.intermediates, *b.cost.outputs))
            blocks.append(_AccelBlock(b, (_allocation(jac, config.scalar_cxx, jac_text),
                                          _allocation(cost, config.scalar_cxx, cost_text)),
                                      loops[f"factor_{b.index}_jacobian"],
                                      loops[f"factor_{b.index}_cost"],
                                      noise[f"noise_{b.index}"]))
            blocks[-1].small = False
        # Cholesky's HGC: the II of the block's Gram entries (its multipliers) and the entries
        blocks[-1].gram_ii = gram_ii(program, b.index, plan.options.hgc_lanes)
        lane_a, lane_b, k, paired = (
            gram_config(program, b.index, plan.options.hgc_lanes, jac_ii, jac_cycles)
            if program.solver.linear == "cholesky" else ((), (), 0, False))
        blocks[-1].gram_pair = paired  # gram_entries_pair: II 2, two lane-A entries
        blocks[-1].gram_p = [p for p, _ in lane_a]
        blocks[-1].gram_q = [q for _, q in lane_a]
        blocks[-1].gram_pb = [p for p, _ in lane_b]  # lane B: the first gram_k rows only
        blocks[-1].gram_qb = [q for _, q in lane_b]
        blocks[-1].gram_k = k
        blocks[-1].gram_pc, blocks[-1].gram_qc = [], []  # lane C (_beside_context: gram_third)
        blocks[-1].gram_kc = blocks[-1].gram_c0 = 0
        # its HGC loop's iterations an instance and depth: the plan's (units/cholesky.py)
        gram = hgc.get(f"reduce_{b.index}")
        count = len(b.instances)
        blocks[-1].gram_steps = gram.loops[1].trip // count if gram and count else 0
        blocks[-1].gram_depth = gram.loops[1].depth if gram else 0
        # per column of A: its variable (k-th of the factor's keys) and offset (the gradient)
        cols = sorted((v.col + j, v.k, j) for v in b.variables for j in range(v.dim))
        blocks[-1].gram_col_var = [k for _, k, _ in cols]
        blocks[-1].gram_col_off = [j for _, _, j in cols]
    beside = _beside_context(program, plan, blocks)
    # the state update's datapath per variable type: the plan's operators
    retract = {}
    for k in context["retracts"]:
        text = "\n".join((*k.printed.intermediates, *k.printed.outputs))
        retract[k.kind] = {"allocation": _allocation(plan.unit(f"state_update_{k.kind}"),
                                                     config.scalar_cxx, text)}
    # back_substitute's state update (fgc_backsub.h's backsub_retire): its loop's tables and
    # (II, depth), the plan's
    kinds = [0] * len(program.variables)
    for k in context["retracts"]:
        for v in k.variables:
            kinds[v] = k.kind
    variables, steps = retire_order(program, retire_solved(_tables(program)))
    from fgc_backends.hls.units.lm_control import (
        fused_step_test,
        retire_solved_test,
        retire_step_test,
    )
    ii, depth = retire_timing(program.variables, plan.ops, _sizes(program)["MAX_F"],
                              plan.options.state_allocation,
                              retire_step_test(program, plan.options))
    retire = {"kinds": kinds, "variables": variables, "steps": steps, "ii": ii, "depth": depth}
    # back_substitute's trial_cost (units/datapath.py): its loops' tables, II and depth
    from fgc_backends.hls.units.datapath import trial_banked, trial_span
    split = retire_step_test(program, plan.options)
    var_end = None if split else _trial_var_end(program, plan)
    trial = _trial_context(program, context["blocks"], blocks, phase, split, var_end)
    two = any(lp["proc"] == 1 for lp in trial)  # (the slot design's too: slot_split_loops)
    if split or two:  # per variable the trial-cost processes it goes to (bit q: process q)
        send = [0] * len(program.variables)
        offsets = {sum(v.storage_dim for v in program.variables[:i]): i
                   for i in range(len(program.variables))}
        for lp in trial:
            for x0, x1 in zip(lp["x0"], lp["x1"], strict=True):
                if x0 < x1:
                    send[offsets[x0]] |= 1 << lp["proc"]
        retire["send"] = send
    # trial_cost_b's copy of its instances' data lines (units/datapath.py's trial_b_data)
    trial_b, trial_feed = None, None
    if two:
        from fgc_backends.hls.plan.loops import _tables
        from fgc_backends.hls.units.datapath import cost_loops, trial_b_data, trial_plan
        procs = [p for p in phase["factor_cost"].processes
                 if re.fullmatch(r"factor_(\d+|small)_cost", p.name)]
        tables = _tables(program)
        loops = trial_plan(program, context["blocks"], cost_loops(procs), tables, split,
                           var_end)
        lo, words = trial_b_data(program, loops, tables)
        trial_b = {"lo": lo, "words": words}
        # the slot design's feed of DATA_B (units/datapath.py's slot_split_loops): the cycles
        # each process spends on it, the plan's
        feeds = [next((lp.feed for lp in loops if lp.proc == q and lp.feed), 0) for q in (0, 1)]
        trial_feed = feeds if any(feeds) else None
    # the column design: trial_cost's gathers from DATA_BUF's two banks (units/datapath.py)
    trial_spans = [trial_span(bc) for bc in context["blocks"]] \
        if trial_banked(program, plan.options) else None
    # the factors whose rows the datapaths write straight into a unit set's banks (units/qr.py's
    # rows_in_banks): per factor its set (-1: none), first row and its step's right-hand side
    # column; per set the step they make up
    from fgc_backends.hls.units.qr import rows_in_banks
    tables = _tables(program)
    in_banks = rows_in_banks(program, plan.options, tables, root=True)
    banks = None
    if in_banks:
        n = len(program.factors)
        # (the root's own factors, the root step in a wavefront: set `sets`, its own stream)
        steps = sorted({(u, s) for u, s, _ in in_banks.values() if u < unit_sets(plan)})
        banks = {"set": [in_banks[f][0] if f in in_banks else -1 for f in range(n)],
                 "row": [in_banks[f][2] if f in in_banks else 0 for f in range(n)],
                 "w": [tables["STEP_W"][in_banks[f][1]] if f in in_banks else 0
                       for f in range(n)],
                 "step": [s for _, s in steps]}
    for b in blocks:
        b.banked = any(f in in_banks for f in b.instances)
    if banks:
        # the words each set takes from the datapaths (PORTS a stream word, a factor's rows
        # [A | b] whole words) and the datapath loop (the emitted order) that sends its last
        # ones: under the window's one-step solve the set reflects its step beside the
        # linearisation (lin_level) once that loop has ended (units/datapath.py's sets_beside)
        from fgc_backends.hls.units.datapath import bank_fill_words, bank_ready_loops
        banks["fill"] = bank_fill_words(program, tables, in_banks, len(banks["step"]))
        banks["wait"] = bank_ready_loops(program, in_banks, len(banks["step"]), plan.options)
    procs, streams = process_network(plan)
    units = max(1, int(program.solver.units))
    sets = unit_sets(plan)
    option = f"n_u={units}, {sets} unit set(s)" + (
        f", {plan.options.qr_rows} rows a cycle" if plan.options.qr_rows > 1 else "") \
        if sets else f"cpe={plan.options.cpe}" + (
        ", 2 cascades" if any(u.name == "cpe_set1" for u in plan.units) else "") + (
        f", {plan.options.cascade_lanes} lanes" if plan.options.cascade_lanes > 1 else "")
    network = [f"{len(procs)} processes, {len(streams)} streams ({option})"]
    network += [f"process {p}" for p in procs]
    network += [f"stream {ch.name} depth={ch.depth}: {ch.producer} -> {ch.consumer}"
                for ch in streams]
    les = plan.target.ops("float32" if config.linear_cxx == "float" else "float64")
    # the kernel's loops around the units, priced as the plan prices them (its FGC_CYCLES)
    timing = {"kt": kernel_timing(plan.ops), "klt": kernel_timing(les)}
    return {**timing,
            "les": {"partials": les.add.latency, "add": les.add.latency,
                    "mul": les.mul.latency, "div": les.div.latency, "sqrt": les.sqrt.latency,
                    "singular_eps": repr(10 * epsilon(config.linear_cxx))},
            "blocks": blocks, "lin_blocks": _lin_blocks(program, plan.options, blocks),
            "beside": beside, "network": network, "retract_hw": retract,
            "retire": retire, "trial": trial, "trial_spans": trial_spans, "trial_b": trial_b,
            "trial_feed": trial_feed,
            # the block types trial_cost_b's fused loops cost (their gather_b_<b>)
            "trial_b_fused": sorted({b.index for lp in trial if lp["proc"] == 1
                                     for b in lp["fused"]}),
            # reweight / robust_loss are printed only for a design with a robust member
            "robust_any": any(m.robust for b in blocks for m in b.members),
            # the gradient pass gives LM the cost at X (fgc_lm.h's FGC_LM_COST_IN_LINEARIZE)
            "cost_in_lin": cost_in_linearization(program),
            # the one-step policy: the gradient's maximum, |X| and the step test in one loop after
            # the solve (units/lm_control.py's fused_step_test)
            "fused_test": fused_step_test(program, plan.options),
            # LM's step test summed by back_substitute's state update, |X| and G's zeroing in
            # the copies into X (units/lm_control.py's retire_step_test)
            "retire_test": retire_step_test(program, plan.options),
            # the one-step policy's sums in the slot design's state update instead of that loop
            # (units/lm_control.py's retire_solved_test; fgc_backsub.h's FGC_BS_STEP_TEST)
            "retire_solved": retire_solved_test(program, plan.options),
            "small": shared, "banks": banks, "wave": _wave_context(program, plan),
            "unit_sets": max(1, sets), "units": units, "qr_unit": plan.options.qr_unit,
            "qr_rows": plan.options.qr_rows,  # fgc_qr.h's FGC_QR_TWO_ROWS (2)
            # back_substitute's schedule: (solve step, load step, solving lane) per slot
            "bs_slots": [sl[:3] for sl in _backsub_schedule(program, plan)],
            # per slot: the loaded separator's offset in the loading lane's last solution (-1:
            # from DELTA)
            "bs_xoff": [sl[4] for sl in _backsub_schedule(program, plan)],
            # per slot: what its load moves (0 all, 1 R and d of the next slot's step, 2 S, 3 R,
            # d and S as the solve's x arrives: units/backsub.py's backsub_schedule)
            "bs_parts": [sl[3] for sl in _backsub_schedule(program, plan)],
            # the root's conditional into back-substitution's lane 0 by its commit (slot 0 not
            # run: units/backsub.py's root_in_commit), and the root step
            "bs_root_commit": _root_in_commit(program, plan),
            "bs_lanes": plan.options.backsub_lanes,  # fgc_backsub.h's FGC_BS_LANES (> 1)
            "bsc": _backsub_columns(program, plan),  # backsub_lanes 4: the BSC_* tables
            "cpe": plan.options.cpe, "cascade_lanes": plan.options.cascade_lanes,
            # one cascade: each step's pivot check beside the next step's cascade (the plan's
            # choice, units/cholesky.py's check_beside: its last pass is a process "check")
            "check_beside": any(p.name == "check" for ph in plan.phases
                                for p in ph.processes),
            "plan": plan, **_cascade_context(program, plan),
            "tables": [t for t in context["tables"] if t.name != "STEP_PATTERN"]}


def _keep_context(program: Program, stream, context) -> dict | None:
    """The table of the QR steps' keep rule by structure (fgc_qr.h's qr_rowmask: a row's
    pattern, bit c its column c, the right-hand side's bit w) for the steps lin_level reflects
    with the root in a wavefront (set 0's step c0, set 1's step c1, the root): per update class
    of the window the patterns the plan prices (plan/stream.py's ``step_patterns`` on the
    update's zero factors and unit priors, WindowLayout.zero_factors / unit_factors), a class
    per distinct set of patterns, and the class of each keyframe count j = 0 ... STREAM_SLOTS
    (fgc_stream.h's jc, saturating at STREAM_SLOTS). None (the value rule) if the stream's
    keyframes past the window's fill do not all have the full window's patterns."""
    from fgc_backends.hls.plan.loops import _sizes
    from fgc_backends.hls.plan.stream import step_patterns

    wave = context["wave"]
    steps = (wave["c0"], wave["c1"], wave["root"])
    sizes = _sizes(program)
    max_rows, cols = sizes["MAX_ROWS"], sizes["MAX_W"] + 1
    words = -(-cols // 64)
    marginal = context["stream"]["marginal"]
    slots = stream.size

    def patterns(j: int) -> tuple:
        pats = step_patterns(program, stream.zero_factors(j, marginal), True,
                             unit=stream.unit_factors(j))
        out = []
        for s in steps:
            pattern, rhs = pats[s]
            w = pattern.shape[1]
            rows = []
            for i in range(max_rows):
                bits = 0
                if i < len(pattern):
                    for c in range(w):
                        if pattern[i, c]:
                            bits |= 1 << c
                    if rhs[i]:
                        bits |= 1 << w
                rows.append(tuple((bits >> (64 * q)) & (2 ** 64 - 1) for q in range(words)))
            out.append(tuple(rows))
        return tuple(out)

    by_j: dict = {}
    for k in range(len(stream.program.schedule.clusters)):  # the stream's keyframes
        p = patterns(k)
        if by_j.setdefault(min(k, slots), p) != p:
            return None  # a later keyframe's patterns not the full window's: the value rule
    classes = list(dict.fromkeys(by_j.values()))
    return {"slots": slots, "words": words,
            "class_of": [classes.index(by_j[j]) if j in by_j else 0 for j in range(slots + 1)],
            "masks": [[[", ".join(f"0x{x:x}ULL" for x in row) for row in step]
                       for step in cls] for cls in classes]}


def _wave_context(program: Program, plan) -> dict | None:
    """The root step in a wavefront's constants (``HlsConfig.root_wave``, units/qr.py's
    ``wave_steps``), None without it: the root, the fed child c0 (unit set 0's step), its
    passed rows' place in the root's rows, their words, each row's region
    (``wave_entries``), each word's slot in a ``qr_pass`` stream word (``pass_pack``) and the
    stream words a row, and the stream's depth (every passed row: unit set 1 reads them behind
    set 0)."""
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.qr import (
        _own_rows,
        commit_pair_words,
        lin_wave,
        pass_pack,
        pass_words,
        root_bank_parity_words,
        rows_in_banks,
        wave_entries,
        wave_steps,
    )

    steps = wave_steps(program, plan.options)
    if steps is None:
        return None
    c0, c1, root = steps
    tables = _tables(program)
    lin = lin_wave(program, plan.options) is not None
    root_fill = root_wait = root_even = root_odd = None
    if lin:  # the root's own rows by their stream (set 1 reads them after its own step)
        from fgc_backends.hls.units.datapath import bank_ready_loops

        in_banks = rows_in_banks(program, plan.options, tables, root=True)
        # (its words by row parity, one of each a cycle: units/qr.py's root_bank_parity_words)
        root_even, root_odd = root_bank_parity_words(tables, root)
        root_fill = max(root_even, root_odd)
        root_wait = bank_ready_loops(program, in_banks, 3, plan.options)[2]
    first = {}  # per child of the root, its passed rows' first row in the root
    row = _own_rows(tables, root)
    for e in range(tables["STEP_CHILD_BEGIN"][root], tables["STEP_CHILD_BEGIN"][root + 1]):
        first[tables["STEP_CHILDREN"][e]] = row
        row += tables["STEP_NF_ROWS"][tables["STEP_CHILDREN"][e]]
    row0 = first[c0]
    sc = tables["STEP_W"][c0] - tables["STEP_F"][c0]
    nf = tables["STEP_NF_ROWS"][c0]
    units = plan.options.units
    return {"c0": c0, "c1": c1, "root": root, "row0": row0, "nfed": nf, "words": sc + 1,
            "entry": wave_entries(tables, c0, root),
            "pack": pass_pack(tables, c0, root, units),
            "pass_words": pass_words(tables, c0, root, units),
            "depth": nf * pass_words(tables, c0, root, units), "lin": lin,
            "root_fill": root_fill, "root_even": root_even, "root_odd": root_odd,
            "root_wait": root_wait, "row1": first[c1],
            # (set 1's own passed rows packed alike by its collector, read after its step)
            "nf1": tables["STEP_NF_ROWS"][c1], "pack1": pass_pack(tables, c1, root, units),
            "pass_words1": pass_words(tables, c1, root, units),
            "own_depth": tables["STEP_NF_ROWS"][c1] * pass_words(tables, c1, root, units),
            "commit1": commit_pair_words(tables, c1, root) if lin else None}


def _beside_context(program: Program, plan, blocks) -> dict | None:
    """The HGC beside the elimination's tables and constants (units/cholesky.py's _beside:
    the plan's phase hgc_beside names the streamed block type), None without it."""
    name = next((p.name for ph in plan.phases if ph.name == "hgc_beside" for p in ph.processes),
                None)
    if name is None:
        return None
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.cholesky import (
        beside_layout,
        beside_region_layout,
        cascade_regions,
        cascades_of,
        gram_third,
        jacobian_cycles,
        jacobian_ii,
    )
    big = int(name.rsplit("_", 1)[1])
    tables = _tables(program)
    order = [tables["LEVEL_STEPS"][i] for i in range(len(program.schedule.steps))]
    # two cascades: the stream and the stage lanes by region (fgc_cascades.h), else by step
    regions = cascades_of(program, plan.options) == 2
    lay = (beside_region_layout(program, tables, cascade_regions(tables, order), big) if regions
           else beside_layout(program, tables, order, big))
    b = blocks[big]
    reduce = next(p for ph in plan.phases if ph.name == "hgc_producer" for p in ph.processes
                  if p.name == f"reduce_{big}")
    third = None
    if regions and any(m.name == "stage_c" for m in plan.memories):  # the plan's third lane
        procs = [p for ph in plan.phases for p in ph.processes]
        third = gram_third(program, big, plan.options.hgc_lanes, jacobian_ii(procs),
                           jacobian_cycles(procs))
        if third is None:
            raise RuntimeError(f"internal error: block {big}'s third Gram lane not found")
        lane_a, lane_b, lane_c, b.gram_k, b.gram_kc, b.gram_c0 = third
        b.gram_p, b.gram_q = [p for p, _ in lane_a], [q for _, q in lane_a]
        b.gram_pb, b.gram_qb = [p for p, _ in lane_b], [q for _, q in lane_b]
        b.gram_pc, b.gram_qc = [p for p, _ in lane_c], [q for _, q in lane_c]
        if [p * (p + 1) // 2 + q for p, q in lane_c] != list(
                range(b.gram_c0, b.gram_c0 + len(lane_c))):
            raise RuntimeError(f"internal error: block {big}'s lane C is not a run")
    nc, nb = len(b.gram_pc), lay["nb"]
    ha = 2 if b.gram_pair else 1
    if any(p * (p + 1) // 2 + q >= lay["nb"] for p, q in zip(b.gram_p + b.gram_pb,
                                                            b.gram_q + b.gram_qb, strict=True)):
        raise RuntimeError(f"internal error: block {big}'s Gram entries outside its packed Gram")
    slots = ha + (1 if b.gram_pb else 0) + (1 if nc else 0)
    return {**lay, "block": big, "ha": ha, "unit": "REGION" if regions else "STEP",
            "nc": nc, "c0": b.gram_c0, "n_stage_c": lay["n_stage"] // nb * nc if nc else 1,
            "factor_stage_c": [fs // nb * nc if fs >= 0 else -1 for fs in lay["factor_stage"]],
            "slots": slots, "gii": reduce.loops[1].ii,
            "steps": b.gram_steps, "count": len(lay["order"]),
            "depth": lay["max_per_step"] * b.gram_steps, "rows_cycles": reduce.loops[0].cycles,
            "pos_a": [p * (p + 1) // 2 + q for p, q in zip(b.gram_p, b.gram_q, strict=True)],
            "pos_b": [p * (p + 1) // 2 + q for p, q in zip(b.gram_pb, b.gram_qb, strict=True)]}


def _cascade_context(program: Program, plan) -> dict:
    """The two-cascade Cholesky design's tables (units/cholesky.py's cascade_regions and
    cascade_children): ``cascades`` (1 or 2) and, for 2, REGION_STEP (flat, two a region),
    STEP_REGION, STEP_CASCADE and STEP_STREAMED."""
    if program.solver.linear != "cholesky":
        return {"cascades": 1}
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.cholesky import cascade_children, cascade_regions, cascades_of
    sets = cascades_of(program, plan.options)
    if sets == 1:
        return {"cascades": 1}
    tables = _tables(program)
    n = len(program.schedule.steps)
    regions = cascade_regions(tables, [tables["LEVEL_STEPS"][i] for i in range(n)])
    kids = cascade_children(tables, regions)
    where = {s: (r, k) for r, reg in enumerate(regions) for k, s in enumerate(reg) if s >= 0}
    return {"cascades": 2, "regions": [s for reg in regions for s in reg],
            "step_region": [where[s][0] for s in range(n)],
            "step_cascade": [where[s][1] for s in range(n)],
            "step_streamed": [kids[s][0] for s in range(n)]}


def _trial_var_end(program: Program, plan):
    """units/datapath.py's trial_var_end for the plan's options (the order of trial_cost's
    loops is the plan's)."""
    from fgc_backends.hls.plan.assemble import PlanBuild
    from fgc_backends.hls.units.datapath import trial_var_end
    return trial_var_end(PlanBuild(program, plan.options, plan.ops,
                                   plan.target.ops(plan.options.precisions(program)[1])))


def _trial_context(program: Program, contexts, blocks, phase: dict,
                   split: bool = False, var_end: list[int] | None = None) -> list[dict]:
    """trial_cost's loops as accel.cpp.jinja prints them (units/datapath.py's trial_plan on
    the plan's cost-mode loops): per loop its entries' instance (and block type, for the
    shared small datapath), the storage words of the variables each takes ([x0, x1) in x, k
    a row, x0 = x1 none), II and depth; ``split`` (units/datapath.py's split_trial_loops): its
    process (0: trial_cost, 1: trial_cost_b) and the retire position of each variable it takes
    (p, -1 none: the counting build's keyed marks)."""
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.datapath import cost_loops, trial_plan, trial_positions
    procs = [p for p in phase["factor_cost"].processes
             if re.fullmatch(r"factor_(\d+|small)_cost", p.name)]
    offsets = [0]
    for v in program.variables:
        offsets.append(offsets[-1] + v.storage_dim)
    out = []
    tables = _tables(program)
    pos = trial_positions(program, tables)
    for lp in trial_plan(program, contexts, cost_loops(procs), tables, split, var_end):
        x0, x1, at = [], [], []
        for _, taking in lp.entries:
            row = [(offsets[v], offsets[v + 1]) for v in taking]
            row += [(0, 0)] * (lp.k - len(row))
            x0 += [a for a, _ in row]
            x1 += [b for _, b in row]
            at += [pos[v] for v in taking] + [-1] * (lp.k - len(taking))
        small = lp.key == "small"
        names = sorted({contexts[program.factors[f].block].comment  # sanitised
                        for f, _ in lp.entries if f >= 0})
        # a fused loop (units/datapath.py's slot_split_loops): its blocks' datapaths, an
        # entry's by its block type (TRIAL_B_<key>)
        fused = [blocks[c] for c in lp.fused]
        out.append({"key": lp.key, "name": lp.name, "small": small, "k": lp.k, "ii": lp.ii,
                    "depth": lp.depth, "count": len(lp.entries),
                    "block": None if small or fused else blocks[lp.key], "fused": fused,
                    "f": [f for f, _ in lp.entries],
                    "b": [program.factors[f].block if f >= 0 else -1 for f, _ in lp.entries],
                    "x0": x0, "x1": x1, "proc": lp.proc, "at": at,
                    "comment": ("the small datapath" if small else
                                "blocks " + ", ".join(str(c) for c in lp.fused) + " fused"
                                if fused else f"block {lp.key}")
                    + " (" + ", ".join(names) + ")"})
    return out


def _backsub_slots(program: Program) -> tuple[tuple[int, int, int], ...]:
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.backsub import backsub_slots
    return backsub_slots(_tables(program))


def _root_in_commit(program: Program, plan) -> int | None:
    """The root step when qr_commit writes its conditional into back-substitution's lane 0
    (units/backsub.py's root_in_commit), else None."""
    from fgc_backends.hls.units.backsub import root_in_commit
    if not root_in_commit(program, plan.options):
        return None
    return _backsub_slots(program)[0][1]


def _backsub_schedule(program: Program, plan) -> tuple[tuple[int, int, int, int, int], ...]:
    """back_substitute's slots as the plan prices them (units/backsub.py's backsub_schedule,
    on the linear solver's operator table: CHAIN decides where S loads as x arrives)."""
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.backsub import backsub_schedule
    les = plan.target.ops(plan.options.precisions(program)[1])
    return backsub_schedule(_tables(program), les, plan.options.backsub_lanes)


def _backsub_columns(program: Program, plan) -> dict | None:
    if plan.options.backsub_lanes != 4:
        return None
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.backsub import column_tables
    out = column_tables(_tables(program), plan.ops)
    depth = {c.name: c.depth for c in plan.channels}  # priced with the linear solver's table
    out["fifo"] = [depth[f"backsub_groups{e}"] for e in range(2)]
    out["dx"] = [depth[f"backsub_dx{e}"] for e in range(2)]
    return out


def for_program(program: Program, config: HlsConfig) -> HlsConfig:
    """``config`` with the linear solver's scalar the Program asks for (the mixed design)."""
    return limits.for_program(program, config)


def check_limits(program: Program, config: HlsConfig) -> None:
    """Raise :class:`HlsConfigError` if ``program`` exceeds what ``config`` can build."""
    limits.check_limits(program, config, HlsConfigError, "the HLS backend", "HlsConfig")


def tcl_clock(clock_mhz: float) -> dict:
    """``run_hls.tcl``'s clock: the period of the cost model's clock (SolverConfig.clock_mhz;
    ``HlsConfig.check`` has checked HlsConfig.clock_ns against it), so model and synthesis
    describe one clock."""
    mhz = float(clock_mhz)
    return {"clock_mhz": f"{mhz:g}", "clock_ns": f"{1000.0 / mhz:.6g}"}





def tcl_config_ops(program: Program, config: HlsConfig) -> list[tuple[str, str, int]]:
    """``run_hls.tcl``'s ``config_op`` lines of the design's operator binding
    (``DesignOptions.bind``): (Vitis operator, implementation, latency) per Vitis operator of
    each bound kind in every scalar the design computes in (T, and L when wider), the latency
    the plan's (the bound table's: Vitis schedules what config_op pins). None for the default
    binding."""
    from fgc_backends.cost.operators import VITIS_OPS

    if not config.bind:
        return []
    target = config.design.target(program)
    out = []
    for cxx in dict.fromkeys((config.scalar_cxx, config.linear_cxx)):
        precision = "float32" if cxx == "float" else "float64"
        table = target.ops(precision)
        for kind, impl in config.bind:
            out += [(op, impl, table.op(kind).latency) for op in VITIS_OPS[kind, precision]]
    return out


def _window(stream) -> bool:
    """Whether ``stream`` is the on-chip window's layout (its top takes the call's words)."""
    from fgc_backends.hls.window import WindowLayout

    return isinstance(stream, WindowLayout)


def _context(program: Program, config: HlsConfig, project: str, vector: bool = True) -> dict:
    from fgc_backends.hls.plan import PlanOptions
    from fgc_backends.hls.plan.assemble import factor_ops
    from fgc_backends.hls.plan.loops import tree_latencies

    two_ended = program.schedule.ordering == "two-ended"
    # the kernels' sums and products as the reduction trees the plan prices (its operator
    # table: accel_plan's options; cfamily.trees)
    latencies = tree_latencies(factor_ops(program, PlanOptions.for_config(
        for_program(program, config), program)))
    context = common_context(program, config, project, HlsConfigError,
                             unit_sets=config.unit_sets or (2 if two_ended else 1), vector=vector,
                             latencies=latencies)
    return context | {
        "part": config.part, **tcl_clock(program.solver.clock_mhz),
        "config_ops": tcl_config_ops(program, config) if config.scalar_cxx in ("float", "double")
        else [],
        "key_tokens": key_tokens(v.key for v in program.variables),
        "rotations": [ROTATIONS.get(v.type_name, (0, 0)) for v in program.variables],
        "tb_double": config.scalar_cxx == "double", "tol": TB_TOLERANCES,
        "error_floor_factor": repr(ERROR_FLOOR_FACTOR),
        "tolerance_comment": comment(f"T = {config.scalar_cxx}, linear solver "
                                     f"{config.linear_cxx}"),
        "reference_magic": REFERENCE_MAGIC, "result_magic": RESULT_MAGIC,
    }
