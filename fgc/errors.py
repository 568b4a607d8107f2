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


def caused_by_interrupt(exc: BaseException | None) -> bool:
    """Whether ``exc`` is, or was raised because of, a KeyboardInterrupt (Ctrl-C): an extension
    module interrupted while it initialises reports an ImportError whose cause is the interrupt,
    and an error raised while unwinding from one carries it as its context. Such an error is an
    interrupt, not a missing package or a bug."""
    seen: set[int] = set()
    todo = [exc]
    while todo:
        exc = todo.pop()
        if exc is None or id(exc) in seen:
            continue
        if isinstance(exc, KeyboardInterrupt):
            return True
        seen.add(id(exc))
        todo += [exc.__cause__, exc.__context__]
    return False
