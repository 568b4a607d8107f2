"""The C++ both C-family backends emit alike: the shared static headers (``include/``: LM control,
``fgc_lm.h``) and the shared Jinja macros (``templates/common.jinja``), and the Jinja environment
the backends render their templates in (their own folder first, then the shared one)."""

from __future__ import annotations

import functools
from pathlib import Path

import jinja2

HERE = Path(__file__).resolve().parent
INCLUDE = HERE / "include"  # copied into every emitted project's include/
TEMPLATES = HERE / "templates"


@functools.lru_cache(maxsize=8)
def environment(template_dir: Path) -> jinja2.Environment:
    """A backend's Jinja environment: its templates, then the shared macros; strict, no escaping.
    One per folder and process: the environment keeps its compiled templates (about 2.6 s of
    compiling a LIO stream design's templates again on every emit), and reloads a template
    whose file changed (jinja's ``auto_reload``)."""
    return jinja2.Environment(loader=jinja2.FileSystemLoader([str(template_dir), str(TEMPLATES)]),
                              undefined=jinja2.StrictUndefined, trim_blocks=True,
                              lstrip_blocks=True, keep_trailing_newline=True, autoescape=False)


def copy_headers(target: Path) -> list[Path]:
    """The shared headers into ``target`` (created if needed), in name order; returns the copies."""
    target.mkdir(parents=True, exist_ok=True)
    copies = []
    for header in sorted(INCLUDE.glob("*.h")):
        copy = target / header.name
        copy.write_bytes(header.read_bytes())
        copies.append(copy)
    return copies
