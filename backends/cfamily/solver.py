"""The LM / GN constants both C++ backends print (``const T LAMBDA_UPPER_BOUND = …`` and the
rest of the solver block of ``accel.cpp.jinja`` / ``kernel.cpp.jinja``): one context from the
Program's :class:`fgc.ir.program.SolverConfig` (the one home of LM's limits, the simulator reads
the same fields) and the emitted scalar's epsilon."""

from __future__ import annotations

from fgc.ir.program import Program
from fgc_backends.cfamily.names import comment
from fgc_backends.cfamily.printer import HlsCodePrinter
from fgc_backends.cfamily.scalars import epsilon, lsb_floor


def solver_context(program: Program, config, printer: HlsCodePrinter) -> dict:
    """The solver constants as C++ literals of ``config``'s scalar (``scalar_cxx``,
    ``linear_cxx``, ``is_fixed_point``: an HlsConfig or a NativeConfig). For fixed point a floor
    or tolerance below one LSB would round to 0, so it is raised to one LSB."""
    s, eps = program.solver, epsilon(config.scalar_cxx)
    lit = printer.literal
    if config.is_fixed_point:
        def lit(value, _literal=printer.literal):
            return _literal(lsb_floor(value, config.scalar_cxx))
    lm = s.method == "lm"
    tries = 1
    if lm:  # μ grows from at least mu_min by lambda_factor until it passes the upper bound
        mu = s.mu_min
        while mu <= s.lambda_upper_bound:
            mu, tries = mu * s.lambda_factor, tries + 1
    return {
        "lm": lm, "cholesky": s.linear == "cholesky", "max_iterations": int(s.max_iterations),
        "max_tries": tries, "lambda_initial": lit(s.lambda_initial if lm else 0.0),
        "lambda_factor": lit(s.lambda_factor), "lambda_upper_bound": lit(s.lambda_upper_bound),
        "mu_min": lit(s.mu_min), "eps_gradient": lit(s.eps_gradient),
        "eps_step": lit(max(s.eps_step, 10 * eps)), "tol": lit(s.relative_error_tol),
        "epsilon": lit(eps), "resolution": lit(16 * eps),
        "absolute_error_tol": lit(s.absolute_error_tol), "singular_eps": lit(10 * eps),
        "linear_singular_eps": lit(10 * epsilon(config.linear_cxx)),
        "comment": comment(f"{s.method} {s.linear} {s.ordering} n_u={s.units} cpe={s.cpe}"),
    }
