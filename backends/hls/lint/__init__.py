"""A synthesisability lint for emitted C++ (a conservative subset of what Vitis HLS accepts).

Rules, checked on code with comments and string literals blanked out:

- ``alloc``: no dynamic allocation (``new``, ``delete``, ``malloc``, ``calloc``, ``realloc``,
  ``free``);
- ``stl``: no STL containers or strings (``std::vector``, ``<map>``, …);
- ``recursion``: no function that can reach itself through calls within the file;
- ``unbounded``: no ``while``/``do``/``goto`` and no ``for`` without a condition;
- ``tripcount``: every ``for`` loop compares its variable with a compile-time bound (integer
  literals and ALL_CAPS constants) or opens its body with ``#pragma HLS LOOP_TRIPCOUNT``.

The testbench and the native backend's files run only on the host, so they are checked for
``alloc`` and ``stl`` only (``synthesis=False``).

**Semantic rules** (:func:`semantic_issues`, on the synthesised files of a project together; a
deliberately small C-like parser: function definitions and their parameters, calls, pragmas,
``for`` loops, ``constexpr``/``#define`` integer constants):

- ``dataflow``: the block holding ``#pragma HLS DATAFLOW`` (a function body or a loop body) holds
  only declarations of local channels (no initialiser), HLS pragmas, unconditional calls of
  ``void`` functions defined in the project, and fully unrolled (``#pragma HLS UNROLL`` without a
  factor) constant-bound loops of such calls: no ``if``/``return``/assignment, no used return
  value;
- ``channel``: each array, pointer, reference or ``hls::stream`` passed to the calls of a
  DATAFLOW block is written by at most one call and read by at most one; the direction comes
  from the callee's parameter (streams: ``.write(``/``.read(`` in its body; ``const``: a read;
  others: assigned → written, used otherwise → read; passed on → the inner callee's use). One
  that is both written and read in the block (by two or more calls) must be written by one call
  and read by a *different, later* one: a channel read before it is written (a feedback through
  it between invocations of the region) or read and written by the same call is an issue. A
  memory that a single call alone reads and writes (an Update unit's bank) is that process's
  own, not a channel;
- ``pointer``: no pointer variable or parameter is reassigned (``=``, ``+=``, ``++``…) after its
  initialisation, and no function returns a pointer;
- ``function_pointer``: no function pointer (declarator ``(*f)(…)``), and no function defined in
  the project passed as a template argument;
- ``partition``: an ``ARRAY_PARTITION`` factor is at most the partitioned dimension (sizes from
  the files' integer constants; an array whose size cannot be resolved, a template parameter,
  is not judged);
- ``pipeline``: a ``PIPELINE`` loop (or function) holds only loops with constant bounds (start
  and end), which HLS unrolls completely;
- ``dsp``: Σ over ``#pragma HLS ALLOCATION operation instances=<op> limit=<n>`` of n × the DSP of
  one ``<op>`` (:mod:`fgc_backends.cost.operators`, by precision: ``f…``/``d…`` names, else the
  project's scalar) is at most the part's DSP count (``hls/target.py``; each function is counted
  as one hardware instance);
- ``synthesis_macro``: no ``__SYNTHESIS__`` in a synthesised file (C simulation must compile the
  code that is synthesised).

Modules: ``cxx`` (the C-like reading the rules and the second reader share), ``source``
(the per-file rules), ``semantic`` (the semantic rules), ``project`` (an emitted project's
lint).
"""

from fgc_backends.cfamily.lint import (
    LintIssue,
    line_of,
    strip_comments_and_strings,
    synthesis_view,
)
from fgc_backends.hls.lint.cxx import statement_end
from fgc_backends.hls.lint.project import HlsFitWarning, HlsLintError, lint_project
from fgc_backends.hls.lint.semantic import ALLOCATION_OPS, SEMANTIC_RULES, semantic_issues
from fgc_backends.hls.lint.source import lint_files, lint_source

__all__ = ["ALLOCATION_OPS", "SEMANTIC_RULES", "HlsFitWarning", "HlsLintError", "LintIssue",
           "line_of", "lint_files", "lint_project", "lint_source", "semantic_issues",
           "statement_end", "strip_comments_and_strings", "synthesis_view"]
