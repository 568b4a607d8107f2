"""The front end: what a user writes. The DSL (graphs, factor types as residual functions),
variables on Lie groups (``geometry``), built-in factors, noise models, IMU preintegration and
the functions a residual may call. Nothing here knows about schedules or backends."""
