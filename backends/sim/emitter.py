"""emit: a Program → the simulator's files (a problem module plus its NumPy run-time).

Two files are generated: the problem module ``<name>_sim.py`` (block kernels, each variable
type's retraction and local coordinates printed from :mod:`fgc.frontend.geometry`, tables,
schedule) and ``fgc_sim_constants.py`` (fgc's Lie series). Everything their templates place is
computed here or printed by :class:`SimPrinter`. The run-time modules of
:mod:`fgc_backends.sim.runtime` are copied beside them byte for byte. User-given names (problem,
factor types) reach the emitted code only sanitised, in comments; variables, blocks and factors
are referred to by index. The variables' keys, which the result file names its values by, are
data: JSON text (hex-coded unless plain) in string literals (:meth:`SimPrinter.json_text`),
decoded at run time.
"""

from __future__ import annotations

from pathlib import Path

import jinja2

from fgc.errors import FgcError
from fgc.frontend.geometry import special
from fgc.ir.codes import NOISE_CODES, NOISE_KINDS, ROBUST_CODES, noise_param_count
from fgc.ir.datafile import MAGIC
from fgc.ir.program import BlockSpec, Program
from fgc.version import __version__

from .config import SimConfig, comment
from .printer import PrintedKernel, SimPrinter
from .runtime import fgc_sim_runtime
from .runtime.fgc_sim_optimizer import RESULT_FORMAT
from .types import VariableType, variable_types

__all__ = ["RESULT_FORMAT", "EmitError", "emit"]


class EmitError(FgcError):
    """The Program cannot be emitted as a simulator (unsupported type, inconsistent tables)."""


def emit(program: Program, out_dir: str | Path, config: SimConfig | None = None) -> list[Path]:
    """Write the simulator of ``program`` into ``out_dir`` (created if needed).

    Returns the written paths, the problem module ``<name>_sim.py`` first. Emitting the same
    Program twice gives byte-identical files.
    """
    config = config or SimConfig()
    _check_runtime()
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(config.template_dir()),
                             undefined=jinja2.StrictUndefined, trim_blocks=True,
                             lstrip_blocks=True, keep_trailing_newline=True, autoescape=False)
    context = _context(program, config)
    paths = []
    for template, file_name in config.files(program.name):
        text = env.get_template(template).render(**context, file_name=file_name)
        path = out / file_name
        path.write_text(text)
        paths.append(path)
    for source in config.runtime_files():
        path = out / source.name
        path.write_bytes(source.read_bytes())
        paths.append(path)
    return paths


def _check_runtime() -> None:
    """The run-time reads fgc's data files standalone (no fgc import): its format words and
    codes must be fgc's (fgc.ir.datafile, fgc.ir.codes)."""
    robust = {None: fgc_sim_runtime.ROBUST_NONE, "huber": fgc_sim_runtime.ROBUST_HUBER,
              "cauchy": fgc_sim_runtime.ROBUST_CAUCHY}
    if (fgc_sim_runtime.DATA_MAGIC != MAGIC or robust != ROBUST_CODES
            or fgc_sim_runtime.NOISE_KINDS != NOISE_KINDS):
        raise EmitError("the simulator run-time (fgc_sim_runtime.py) disagrees with "
                        "fgc.ir.datafile / fgc.ir.codes on the data file's magic, noise kinds "
                        "or robust loss codes")


def _context(program: Program, config: SimConfig) -> dict:
    printer = config.printer()
    lit = printer.literal
    sched = program.schedule
    types = variable_types(program, EmitError)  # checks the type names
    return {
        "fgc_version": __version__,
        "structure_fingerprint": program.structure_fingerprint,
        "problem_comment": comment(program.name),
        "series_below": repr(float(special.SERIES_BELOW)),
        "series": [(name, ", ".join(repr(float(c)) for c in reversed(coeffs)))
                   for name, coeffs in sorted(special.SERIES.items())],
        "coefficient_names": sorted(special.COEFFICIENT_FUNCTIONS),
        "num_variables": len(program.variables),
        "num_factors": len(program.factors),
        "num_steps": len(sched.steps),
        "num_levels": len(sched.levels),
        "structure_class": sched.structure_class,
        "solver_comment": comment(f"{program.solver.method}-{program.solver.linear}-"
                                  f"{program.solver.ordering}-{program.solver.precision}"),
        "solver": [(k, lit(v)) for k, v in _solver_options(program, config)],
        "variable_dims": lit([v.dim for v in program.variables]),
        "variable_storage": lit([v.storage_dim for v in program.variables]),
        "types": [_type(vt, printer) for vt in types],
        "retract_groups": lit([(vt.kind, list(vt.variables)) for vt in types]),
        "variables": [(printer.json_text(v.user_key), lit(v.type_name))
                      for v in program.variables],
        "blocks": _blocks(program, printer),
        "steps": [lit(s) for s in _steps(program)],
        "back_substitution": lit(sched.back_substitution),
        "clusters": lit(_clusters(program)),
        "incremental": lit(_incremental(program)),
    }


def _clusters(program: Program) -> list[list[int]] | None:
    """Variable indices per chain cluster (keyframe), None on a general graph."""
    if program.schedule.structure_class != "chain":
        return None
    index = {v.key: i for i, v in enumerate(program.variables)}
    return [[index[k] for k in cluster] for cluster in program.schedule.clusters]


def _incremental(program: Program) -> list[tuple] | None:
    plan = program.schedule.incremental
    if plan is None:
        return None
    return [(u.keyframe, u.mode == "batch", list(u.clusters), u.kept) for u in plan.updates]


def _solver_options(program: Program, config: SimConfig) -> list[tuple[str, object]]:
    s = program.solver
    return [("method", s.method), ("linear", s.linear), ("precision", s.precision),
            ("linear_precision", s.linear_precision),
            ("max_iterations", int(s.max_iterations)),
            ("lambda_initial", float(s.lambda_initial)),
            ("lambda_factor", float(s.lambda_factor)),
            ("lambda_upper_bound", float(s.lambda_upper_bound)), ("mu_min", float(s.mu_min)),
            ("eps_gradient", float(s.eps_gradient)), ("eps_step", float(s.eps_step)),
            ("relative_error_tol", float(s.relative_error_tol)),
            ("absolute_error_tol", float(s.absolute_error_tol)),
            ("diagnose", bool(config.diagnose)),
            ("condition_iterations", int(config.condition_iterations)),
            ("singular_lm_fails", bool(config.singular_lm_fails)),
            ("pivot_tolerance_float64", float(config.pivot_tolerance_float64)),
            ("pivot_tolerance_float32", float(config.pivot_tolerance_float32))]


def _type(vt: VariableType, printer: SimPrinter) -> dict:
    """A variable type's printed retraction and local coordinates."""
    return {"kind": vt.kind, "comment": comment(vt.type_name), "storage_dim": vt.storage_dim,
            "dim": vt.dim, "retract": printer.kernel(vt.retract, f"retract_{vt.kind}"),
            "local": printer.kernel(vt.local, f"local_{vt.kind}")}


# --------------------------------------------------------------------------------------------
# blocks
# --------------------------------------------------------------------------------------------


def _blocks(program: Program, printer: SimPrinter) -> list[dict]:
    index = {v.key: i for i, v in enumerate(program.variables)}
    storage = [v.storage_dim for v in program.variables]
    lit = printer.literal
    out = []
    for b, block in enumerate(program.blocks):
        ids = [j for j, f in enumerate(program.factors) if f.block == b]
        instances = [[index[k] for k in program.factors[j].keys] for j in ids]
        jac, cost = _kernels(b, block, printer)
        out.append({
            "number": b, "comment": comment(block.name), "jacobian": jac, "cost": cost,
            "residual_dim": block.residual_dim,
            "variable_dims": lit(block.variable_dims),
            "variable_storage": lit([storage[i] for i in instances[0]]),
            "members": lit(_members(block)),
            "instances": lit(instances), "factor_ids": lit(ids),
        })
    return out


def _kernels(b: int, block: BlockSpec, printer: SimPrinter
             ) -> tuple[PrintedKernel, PrintedKernel]:
    kernel, cost = block.kernel.kernel(), block.cost_kernel.kernel()
    n_out = block.residual_dim * (1 + sum(block.variable_dims))
    if len(kernel.outputs) != n_out:
        raise EmitError(f"block type {b}: kernel has {len(kernel.outputs)} outputs, expected "
                        f"{n_out}")
    m, members = block.residual_dim, len(block.members)
    n_params = sum(mem.noise_params for mem in block.members)
    if len(cost.inputs) != len(kernel.inputs) + n_params or len(cost.outputs) != m + members + 1:
        raise EmitError(f"block type {b}: cost kernel does not match the block's layout")
    return (printer.kernel(kernel, f"jacobian_{b}"),
            printer.kernel(cost, f"cost_{b}", outputs=range(m, m + members)))


def _members(block: BlockSpec) -> list[tuple]:
    """(first row, last row, noise kind, #noise params, #measurement numbers, touched block
    variables) per member; a member touches a variable where its Jacobian is not fixed zero."""
    out = []
    for number, mem in enumerate(block.members):
        first, last = mem.rows
        rows = last - first
        expected = {kind: noise_param_count(kind, rows) for kind in NOISE_KINDS}
        if expected.get(mem.noise_kind) != mem.noise_params:
            raise EmitError(f"block '{comment(block.name)}' member {number}: noise kind "
                            f"{comment(mem.noise_kind)} with {mem.noise_params} parameters")
        touches = [k for k, s in enumerate(block.structure)
                   if any(e != "0" for row in s[first:last] for e in row)]
        out.append((first, last, NOISE_CODES[mem.noise_kind], mem.noise_params,
                    sum(size for _, size in mem.measurements), touches))
    return out


# --------------------------------------------------------------------------------------------
# schedule
# --------------------------------------------------------------------------------------------


def _steps(program: Program) -> list[tuple]:
    """Per elimination step: frontals, separator, entering (block type, instance, member),
    children, parent."""
    index = {v.key: i for i, v in enumerate(program.variables)}
    member_of = _member_of(program)
    out = []
    for step in program.schedule.steps:
        entering = []
        for f in step.factors:
            if f not in member_of:
                raise EmitError(f"elimination step {step.index}: graph factor {f} is in no block")
            entering.append(member_of[f])
        parent = -1 if step.parent is None else step.parent
        out.append(([index[k] for k in step.frontals], [index[k] for k in step.separator],
                    entering, list(step.children), parent))
    return out


def _member_of(program: Program) -> dict[int, tuple[int, int, int]]:
    """Graph factor index → (block type, instance within the type, member)."""
    seen = [0] * len(program.blocks)
    out = {}
    for spec in program.factors:
        for member, f in enumerate(spec.factors):
            out[f] = (spec.block, seen[spec.block], member)
        seen[spec.block] += 1
    return out
