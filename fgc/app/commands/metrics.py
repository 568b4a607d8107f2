"""``fgc metrics EST.tum REF.tum``: ATE and RPE (translation m, rotation degrees)."""

from __future__ import annotations

from fgc.app import metrics
from fgc.app.commands.options import Formatter, positive_int, verbosity_args
from fgc.app.commands.outputs import print_lines, write_json
from fgc.app.commands.steps import EXIT_OK

NAME = "metrics"


def cmd_metrics(args) -> int:
    est, ref = metrics.read_tum(args.estimate), metrics.read_tum(args.reference)
    results, lines = {}, [f"fgc metrics {args.estimate} vs {args.reference}: {len(est)} poses, "
                          f"alignment {args.align}, RPE delta {args.delta} frames"
                          + (" (all pairs)" if args.all_pairs else "")]
    for name, func, kw in (("ate", metrics.ate, {}),
                           ("rpe", metrics.rpe, {"delta": args.delta,
                                                 "all_pairs": args.all_pairs})):
        for relation in metrics.RELATIONS:
            res = func(est, ref, align=args.align, relation=relation,
                       max_time_diff=args.max_time_diff, **kw)
            stats = res.statistics()
            results[f"{name}_{relation}"] = {"unit": res.unit, **stats}
            lines.append(f"  {name.upper()} {relation:<11} [{res.unit:>3}]  " + "  ".join(
                f"{k} {v:.6g}" for k, v in stats.items() if k != "sse"))
        if name == "ate" and args.align != "none":
            results["alignment"] = {"rotation": res.alignment.rotation.tolist(),
                                    "translation": res.alignment.translation.tolist(),
                                    "scale": res.alignment.scale}
    print_lines(args, lines, lines[1].strip())
    write_json(args.json, results)
    return EXIT_OK


def add_parser(sub):
    p = sub.add_parser(NAME, help="ATE and RPE of a TUM trajectory against a reference "
                       "(translation in m, rotation in degrees; evo's definitions)",
                       description="fgc metrics: absolute trajectory error (ATE) and relative "
                       "pose error (RPE) of EST against REF, both TUM files (timestamp tx ty tz "
                       "qx qy qz qw) paired by index; translation (m) and rotation angle "
                       "(degrees), as evo_ape / evo_rpe compute them",
                       epilog="exit status: 0 success, 2 bad input (one line on stderr)",
                       formatter_class=Formatter)
    p.add_argument("estimate", metavar="EST", help="estimated trajectory (TUM)")
    p.add_argument("reference", metavar="REF", help="reference trajectory (TUM)")
    p.add_argument("--align", choices=("none", "se3", "sim3"), default="none",
                   help="Umeyama alignment of EST onto REF: se3 = evo's --align, sim3 = "
                        "--align --correct_scale")
    p.add_argument("--delta", type=positive_int, default=1, metavar="N",
                   help="RPE frame distance")
    p.add_argument("--all-pairs", action="store_true",
                   help="RPE over every pair (i, i+delta), not (0, delta), (delta, 2 delta), …")
    p.add_argument("--max-time-diff", type=float, default=0.01, metavar="S",
                   help="largest timestamp difference between paired poses")
    p.add_argument("--json", metavar="FILE", help="also write the statistics as JSON")
    verbosity_args(p, suppress=True)
    return p
