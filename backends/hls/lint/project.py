"""An emitted project's lint: the per-file rules and the semantic rules together, raised as
:class:`HlsLintError` (a design over its part's DSP: an :class:`HlsFitWarning`)."""

from __future__ import annotations

import warnings
from collections.abc import Iterable
from pathlib import Path

from fgc.errors import FgcError
from fgc_backends.cfamily.lint import LintIssue, synthesis_view
from fgc_backends.hls.lint.semantic import semantic_issues
from fgc_backends.hls.lint.source import lint_files


class HlsLintError(FgcError):
    """Emitted C++ breaks a synthesisability rule (each issue names file, line and rule)."""


class HlsFitWarning(UserWarning):
    """An emitted design is well formed but does not fit its part (the ``dsp`` rule)."""


def lint_project(project, synthesised: Iterable[Path], strict: bool = True) -> list[LintIssue]:
    """Lint an emitted project: full rules on ``synthesised`` files, allocation/STL rules on the
    rest, and the semantic rules (:func:`semantic_issues`) on the synthesised files together;
    raise :class:`HlsLintError` listing every issue. With ``strict=False`` semantic issues do not
    raise; they are returned. The ``dsp`` rule (the ALLOCATION limits imply more DSP than the
    part has) never raises: such a design is still a correct program whose C simulation checks
    the numbers (a double LIO design, say), so it is emitted with an :class:`HlsFitWarning` and
    the issue is returned; synthesis would not fit it."""
    synthesised = [Path(p) for p in synthesised]
    host = [p for p in project.files if p.suffix in (".cpp", ".h") and p not in synthesised]
    issues = lint_files(synthesised) + lint_files(host, synthesis=False)
    config = getattr(project, "config", None)
    semantic = semantic_issues([(p.name, synthesis_view(p.read_text())) for p in synthesised],
                               part=getattr(config, "part", None),
                               scalar=getattr(config, "scalar_cxx", None),
                               bind=getattr(config, "bind", ()))
    fit = [i for i in semantic if i.rule == "dsp"]
    for i in fit:
        warnings.warn(f"{project.name}: {i.message}: the design does not fit its part",
                      HlsFitWarning, stacklevel=3)
    raised = issues + [i for i in semantic if i.rule != "dsp"] if strict else issues
    if raised:
        listing = "\n".join(str(i) for i in raised[:20])
        more = f"\n… and {len(raised) - 20} more" if len(raised) > 20 else ""
        raise HlsLintError(f"emitted project '{project.name}' is not synthesisable:\n{listing}"
                           f"{more}")
    return semantic
