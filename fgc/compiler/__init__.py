"""The compiler stages between a Graph and a Program, in pipeline order: ``derive`` (sympy
residuals and tangent-space Jacobians, ``kernel``), ``fuse`` (factor blocks sharing one kernel,
``fuse_kernels``), ``schedule`` (elimination order, levels, incremental plan), ``storage`` (what
the memories hold) and ``lower`` (→ :class:`fgc.ir.program.Program`); ``cache`` keeps their
symbolic work on disk. :func:`fgc.compile.compile_graph` calls them in that order."""
