"""``fgc report``: a compiled design at a glance — blocks, schedule, storage, cycles, resources.

    report = design_report(spec, params, graph, program, data, sim)    # a JSON-able dict
    print(format_text(report)); Path("r.html").write_text(render_html(report))

The report is built once as a plain dict (what ``--json`` writes); :func:`sections` turns it into
titled tables of display strings, which both the plain-text and the HTML renderings lay out, so
the two always show the same numbers. The HTML page is self-contained (inline CSS, figures as
data URIs) and rendered by jinja2 with autoescaping on: spec paths, parameters, block and factor
names are user strings.

The backend is passed in (never imported here), as in :mod:`fgc.app.run_report`.
"""

from __future__ import annotations

import base64
import dataclasses
import re
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from fgc.app.run_report import (
    final_error_text,
    fit_verdict,
    float64_error,
    plan_summary,
    require_finite_start,
)
from fgc.frontend.dsl import Graph

_TEMPLATE = "report.html.jinja"
_OP_MODES = (("unshared", "ops_unshared"), ("separate", "ops_before"), ("fused", "ops_after"),
             ("cost_mode", "ops_cost"))


@dataclass(frozen=True)
class Section:
    """One titled table of display strings (first column is a name), plus lines of notes."""

    title: str
    headers: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    notes: tuple[str, ...] = ()


# --------------------------------------------------------------------------------------------
# the report as data
# --------------------------------------------------------------------------------------------


def design_report(spec: str, params: dict, graph: Graph, program, data, sim,
                  iterations: int | None = None, plan_options=None) -> dict:
    """The report of ``program`` (compiled from ``graph``) as a JSON-able dict.

    The hardware figures are the accelerator plan's (:func:`fgc.app.run_report.plan_summary`) for
    ``iterations`` iterations; when that is None the simulator ``sim`` solves ``data`` first and
    its iteration count is used (and its outcome reported). ``plan_options`` are the priced
    design's (default: the Program's own, ``PlanOptions.of``).
    """
    solve = {"source": "--iterations", "iterations": iterations}
    if iterations is None:
        result = sim.run(program, data)
        require_finite_start(graph, result)
        solve = {"source": "simulator", "iterations": result.iterations,
                 "status": result.status, "reason": result.reason,
                 "initial_error": result.initial_error, "final_error": result.final_error,
                 "final_error_float64": float64_error(graph, result.values),
                 "precision": program.solver.precision}
        iterations = max(result.iterations, 1)
    cost = plan_summary(program, iterations, plan_options)
    return {
        "spec": spec, "params": {k: _plain_param(v) for k, v in params.items()},
        "program": program.name, "variables": len(program.variables),
        "factors": len(graph.factors), "block_instances": len(program.factors),
        "solver": dataclasses.asdict(program.solver), "blocks": block_table(program),
        "schedule": schedule_summary(program.schedule), "storage": storage_summary(program),
        "solve": solve, "cost": cost,
    }


def _plain_param(value: object) -> object:
    return value if isinstance(value, (bool, int, float, str)) or value is None else repr(value)


def block_table(program) -> list[dict]:
    """Per block type: variable types, member factors, instances, rows and op counts in the four
    modes (each ``{op: count, ..., "total": n}``)."""
    out = []
    for i, b in enumerate(program.blocks):
        ops = {mode: {**getattr(b, attr), "total": sum(getattr(b, attr).values())}
               for mode, attr in _OP_MODES}
        out.append({"name": b.name, "variable_types": list(b.variable_types),
                    "members": [m.factor_type for m in b.members],
                    "instances": sum(1 for f in program.factors if f.block == i),
                    "residual_dim": b.residual_dim, "ops": ops})
    return out


def schedule_summary(sched) -> dict:
    """Structure class, ordering, steps, sequential levels and fill of an elimination schedule."""
    return {"structure_class": sched.structure_class, "ordering": sched.ordering,
            "steps": len(sched.steps), "sequential_levels": sched.num_sequential_steps,
            "max_parallel_steps": max((len(level) for level in sched.levels), default=0),
            "fill_edges": sched.num_fill_edges, "r_nonzeros": sched.r_nonzeros,
            "dense_r_nonzeros": sched.dense_r_nonzeros,
            "order": list(sched.order)}


def storage_summary(program) -> dict:
    """Dense words and words after each storage step, with the ratio dense / words."""
    plan = program.storage
    steps = [{**dataclasses.asdict(s), "ratio": plan.ratio(i)}
             for i, s in enumerate(plan.steps, 1)]
    return {"solver": plan.solver, "dense_words": plan.dense_words, "steps": steps}


# --------------------------------------------------------------------------------------------
# display: sections of strings, text and HTML
# --------------------------------------------------------------------------------------------


def headline(r: dict) -> list[str]:
    """Title and solver lines shared by the text and HTML renderings."""
    s = r["solver"]
    params = " ".join(f"-p {k}={v!r}" for k, v in r["params"].items())
    return [f"fgc report {r['spec']} {params}".rstrip(),
            f"{r['program']}: {r['variables']} variables, {r['factors']} factors in "
            f"{r['block_instances']} block instances",
            f"solver: {s['method']} / {s['linear']}, {s['precision']}, ordering "
            f"{s['ordering']}, n_u {s['units']}, #CPE {s['cpe']}, {s['clock_mhz']:g} MHz"]


def sections(r: dict) -> list[Section]:
    """The report as titled tables of display strings."""
    return [_blocks_section(r), _schedule_section(r), _storage_section(r), _cycles_section(r),
            _resources_section(r)]


def _blocks_section(r: dict) -> Section:
    rows = tuple((b["name"], ", ".join(b["members"]), str(b["instances"]),
                  str(b["residual_dim"]),
                  *(f"{b['ops'][mode]['total']:,}" for mode, _ in _OP_MODES))
                 for b in r["blocks"])
    return Section("Factor blocks (operations per evaluation)",
                   ("block", "members", "instances", "rows", "unshared (r+J)",
                    "separate CSE (r+J)", "fused (r+J)", "fused (cost)"), rows,
                   ("unshared: every output its own expression tree; separate: member factors "
                    "CSE'd one by one; fused: one kernel with a shared General Calculation.",))


def _schedule_section(r: dict) -> Section:
    s = r["schedule"]
    rows = (("structure class", s["structure_class"]), ("ordering", s["ordering"]),
            ("elimination steps", f"{s['steps']:,}"),
            ("sequential levels", f"{s['sequential_levels']:,}"),
            ("widest level (parallel steps)", f"{s['max_parallel_steps']:,}"),
            ("fill edges", f"{s['fill_edges']:,}"),
            ("R non-zeros (dense blocks)", f"{s['r_nonzeros']:,} ({s['dense_r_nonzeros']:,})"))
    return Section("Schedule", ("", "value"), rows)


def _storage_section(r: dict) -> Section:
    st = r["storage"]
    rows = [("dense", f"{st['dense_words']:,}", "1.00×")]
    rows += [(f"{i}. {s['name']}", f"{s['words']:,}", f"{s['ratio']:.2f}×")
             for i, s in enumerate(st["steps"], 1)]
    return Section(f"Storage of the linear system ({st['solver']})",
                   ("step", "words", "dense / words"), tuple(rows))


def _cycles_section(r: dict) -> Section:
    c, solve = r["cost"], r["solve"]
    total = c["cycles"]
    rows = [(unit, f"{cycles:,}", f"{cycles / total:.1%}" if total else "-")
            for unit, cycles in c["cycles_by_unit"].items()]
    rows.append(("total", f"{total:,}", f"{c['latency_ms']:.3f} ms"))
    if solve["source"] == "simulator":
        note = (f"{c['iterations']} iterations from the simulator ({solve['status']}, final "
                f"error {final_error_text(solve)}) at {c['clock_mhz']:g} MHz")
    else:
        note = f"{c['iterations']} iterations (--iterations) at {c['clock_mhz']:g} MHz"
    notes = [note, f"{c['iteration_cycles']:,} cycles per iteration; source: " + c["source"]]
    if c.get("backsub_lanes") in BACKSUB_TEXT:  # the priced design's width, resolved
        notes.append(f"back-substitution {BACKSUB_TEXT[c['backsub_lanes']]} (backsub_lanes "
                     f"{c['backsub_lanes']}; --backsub-lanes, auto by default)")
    return Section("Modelled cycles by phase (whole solve; model estimate, accelerator plan)",
                   ("phase", "cycles", "share"), tuple(rows), tuple(notes))


BACKSUB_TEXT = {1: "one lane, a step's conditional two words a cycle",
                2: "two lanes wide, COND in two banks",
                4: "by columns, a process per end of the chain"}


def _resources_section(r: dict) -> Section:
    c = r["cost"]
    res, util = c["resources"], c["utilization"]
    names = (("dsp", "DSP48E1"), ("bram", "BRAM36"), ("lut", "LUT"), ("ff", "FF"))
    rows = tuple((label, f"{res[key]:,}" if isinstance(res[key], int) else f"{res[key]:,g}",
                  f"{util[key]:.1%}") for key, label in names)
    return Section(f"Resources on {c['device']} (model estimate)",
                   ("resource", "used (model estimate)", "of device"), rows,
                   (f"{fit_verdict(c)} (model estimate); power {c['power_w']:.2f} W, energy "
                    f"{c['energy_mj']:.3f} mJ per solve (model estimate: the plan has no power "
                    "model; the sim model's power fit applied to the plan's resources)",
                    f"memories of the plan: {c['memory_words']:,} words (model estimate)"))


def format_table(headers: Sequence[str], rows: Sequence[Sequence[str]],
                 indent: str = "  ") -> list[str]:
    """Aligned plain-text lines: the first column left-aligned, the others right-aligned."""
    table = [tuple(headers), *(tuple(row) for row in rows)]
    widths = [max(len(row[j]) for row in table) for j in range(len(headers))]

    def line(row: tuple[str, ...]) -> str:
        cells = [row[0].ljust(widths[0])] + [c.rjust(w) for c, w in zip(row[1:], widths[1:],
                                                                        strict=True)]
        return (indent + "  ".join(cells)).rstrip()

    return [line(row) for row in table]


def format_text(r: dict) -> str:
    """The plain-text report: headline, then each section as an aligned table."""
    lines = headline(r)
    for s in sections(r):
        lines += ["", s.title, *format_table(s.headers, s.rows)]
        lines += [f"  {note}" for note in s.notes]
    return "\n".join(lines) + "\n"


def figures(r: dict) -> dict[str, str]:
    """Latency-breakdown and storage figures as PNG data URIs (FgcError with the install hint
    without matplotlib)."""
    from fgc.app import plots
    st = r["storage"]
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        lat, sto = Path(tmp) / "latency.png", Path(tmp) / "storage.png"
        plots.plot_latency_breakdown(r["cost"]["cycles_by_unit"], path=lat)
        plots.plot_storage_steps(st["dense_words"], [(s["name"], s["words"]) for s in st["steps"]],
                                 path=sto)
        for name, path in (("Latency breakdown (model estimate)", lat), ("Storage", sto)):
            out[name] = "data:image/png;base64," + base64.b64encode(path.read_bytes()).decode()
    return out


def render_html(r: dict, figure_uris: dict[str, str] | None = None) -> str:
    """A self-contained HTML page of the report (autoescaped: user strings are never markup)."""
    import jinja2

    env = jinja2.Environment(loader=jinja2.PackageLoader("fgc.app", "templates"),
                             autoescape=True, undefined=jinja2.StrictUndefined,
                             trim_blocks=True, lstrip_blocks=True)
    env.filters["breakable"] = breakable
    laid_out = [{"title": s.title, "headers": s.headers, "rows": s.rows, "notes": s.notes,
                 "kinds": column_kinds(s)} for s in sections(r)]
    return env.get_template(_TEMPLATE).render(
        headline=headline(r), sections=laid_out, figures=figure_uris or {},
        template=_TEMPLATE)


_NUMBER = re.compile(r"[-+]?[\d,.]+(e[-+]?\d+)?\s*(×|%|[a-zA-Zµ/]{1,4})?(\s*\(.*\))?|[—-]?")


def breakable(text: str):
    """``text`` HTML-escaped, with a line-break opportunity (``<wbr>``) after ``+``, ``,``,
    ``_`` and ``/`` and between the words of a CamelCase name, so that a long block name wraps
    at a word ("CombinedImu|Factor+|Lidar|Odometry|Factor") rather than overflow the page."""
    import markupsafe

    escaped = str(markupsafe.escape(text))
    return markupsafe.Markup(re.sub(r"(?<=[+,_/])|(?<=[a-z0-9])(?=[A-Z])", "<wbr>", escaped))


def column_kinds(section: Section) -> list[str]:
    """"num" (right-aligned, never wrapped) or "text" (left-aligned, wrapped) per column: the
    first column is the row's name; a column is a number column if every cell reads as a
    number, optionally with a unit and a parenthesised remark."""
    return ["text" if j == 0 or not all(_NUMBER.fullmatch(row[j].strip())
                                        for row in section.rows) else "num"
            for j in range(len(section.headers))]
