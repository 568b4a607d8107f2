"""Error types raised by fgc.

Every error a user can trigger is an :class:`FgcError`; its message names the factor, variable,
argument or file that is wrong and says what is wrong with it.
"""

from __future__ import annotations


class FgcError(Exception):
    """Base class of all errors fgc reports to its users."""


class DslError(FgcError):
    """A factor definition or graph built with the DSL is malformed."""


class DerivationError(FgcError):
    """A factor's residual could not be derived symbolically."""


class StructureError(FgcError):
    """A graph's structure cannot be scheduled (gauge freedom, unconstrained variable, ...)."""


class DataError(FgcError):
    """A measurement, initial value or data file is malformed or non-finite."""
