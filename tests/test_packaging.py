"""Packaging: every package directory is installed, under the name docs/design.md gives it."""

from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _declared() -> set[str]:
    with (ROOT / "pyproject.toml").open("rb") as fh:
        return set(tomllib.load(fh)["tool"]["setuptools"]["packages"])


def _on_disk() -> set[str]:
    found = set()
    for top, name in (("fgc", "fgc"), ("backends", "fgc_backends")):
        for init in (ROOT / top).rglob("__init__.py"):
            rel = init.parent.relative_to(ROOT / top).parts
            found.add(".".join((name, *rel)))
    return found


def test_every_package_directory_is_listed_in_pyproject():
    missing = _on_disk() - _declared()
    assert not missing, f"add to [tool.setuptools] packages in pyproject.toml: {sorted(missing)}"


def test_backends_import_as_fgc_backends():
    import fgc_backends

    assert Path(fgc_backends.__file__).resolve().parent == ROOT / "backends"


def test_every_template_and_header_is_package_data():
    """The emitters read templates/*.jinja and copy include/*.h (the shared C-family headers
    too) from the installed package: each must be matched by [tool.setuptools.package-data]."""
    import fnmatch

    with (ROOT / "pyproject.toml").open("rb") as fh:
        data = tomllib.load(fh)["tool"]["setuptools"]["package-data"]
    missing = []
    for folder in ("templates", "include"):
        for path in sorted((ROOT / "backends").rglob(f"{folder}/**/*")):
            if not path.is_file() or path.suffix not in (".jinja", ".h"):
                continue
            package = path.parent
            while package.name in ("templates", "include", "csim"):
                package = package.parent
            name = ".".join(("fgc_backends", *package.relative_to(ROOT / "backends").parts))
            rel = path.relative_to(package).as_posix()
            if not any(fnmatch.fnmatch(rel, pat) for pat in data.get(name, ())):
                missing.append(f"{name}: {rel}")
    assert not missing, f"add to [tool.setuptools.package-data]: {missing}"
