"""The product around the compiler: the ``fgc`` command line, the reports behind ``simulate`` /
``verify`` (``run_report``) and ``report`` (``design_report``), the design-space sweep, plots,
trajectory metrics, the one-call ``fgc.solve`` / ``fgc.verify``, marginals and streaming."""
