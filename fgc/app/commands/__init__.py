"""The ``fgc`` commands, one module each (fgc/app/cli.py builds the parser from them).

A solver command's module (compile, simulate, verify, run, report, stream, sweep) gives its
``NAME``, ``HELP`` (one line), ``FAILS`` (what exit status 1 means, or None), ``JSON_HELP``,
``HARDWARE`` (which hardware options it takes: None, ``"emitted"`` or ``"priced"``),
``add_arguments(p)`` (its own options, between the solver and the hardware groups) and its
handler ``cmd_NAME(args) -> exit status``. ``metrics`` and ``cache`` build their own parser
(``add_parser(sub)``). Shared pieces: ``options`` (argparse types and option groups), ``steps``
(load, compile, backend configurations, progress, exit codes), ``outputs`` (stdout and the
files the user named).
"""
