"""fgc backends (import package ``fgc_backends``): one sub-package per target."""
