"""The C-family layer's error: a Program (or a configuration) it cannot print as C++."""

from fgc.errors import FgcError


class CodegenError(FgcError):
    """The Program cannot be printed as C++ by the shared layer (an unknown variable type, a
    structure table that disagrees with the Program); the HLS and native backends' configuration
    errors are subclasses."""
