"""Plain-JSON round trip for the schedule stage's frozen dataclasses.

A later ``Program`` IR embeds the schedule, so every dataclass here converts to and from nested
``dict`` / ``list`` / ``int`` / ``str`` / ``None`` values that :func:`json.dumps` accepts unchanged.
The conversion is driven by the dataclass field annotations, so a new field needs no extra code.
"""

from __future__ import annotations

import dataclasses
import types
import typing
from collections.abc import Mapping
from typing import Any, TypeVar

_T = TypeVar("_T", bound="JsonDataclass")


class JsonDataclass:
    """Mixin giving a frozen dataclass ``to_dict()`` and ``from_dict()``.

    Supported field types: ``int``, ``str``, ``bool``, ``float``, ``Literal``, ``X | None``,
    ``tuple[X, ...]``, fixed-length ``tuple[X, Y]`` and nested ``JsonDataclass`` subclasses.
    Tuples become JSON lists; ``from_dict`` turns them back into tuples, so
    ``type(x).from_dict(x.to_dict()) == x``.
    """

    def to_dict(self) -> dict[str, Any]:
        """Return the fields as plain JSON values (tuples become lists)."""
        fields = dataclasses.fields(self)  # type: ignore[arg-type]
        return {field.name: _encode(getattr(self, field.name)) for field in fields}

    @classmethod
    def from_dict(cls: type[_T], data: Mapping[str, Any]) -> _T:
        """Rebuild an instance from :meth:`to_dict` output; unknown keys are an error."""
        fields = dataclasses.fields(cls)  # type: ignore[arg-type]
        unknown = sorted(set(data) - {field.name for field in fields})
        if unknown:
            raise ValueError(f"{cls.__name__}.from_dict: unknown keys {unknown}")
        hints = typing.get_type_hints(cls)
        return cls(**{f.name: _decode(hints[f.name], data[f.name]) for f in fields})


def _encode(value: Any) -> Any:
    if isinstance(value, JsonDataclass):
        return value.to_dict()
    if isinstance(value, tuple):
        return [_encode(item) for item in value]
    return value


def _decode(hint: Any, value: Any) -> Any:
    """Convert one JSON value back to the Python type named by ``hint``."""
    origin = typing.get_origin(hint)
    if origin in (typing.Union, types.UnionType):
        options = [arg for arg in typing.get_args(hint) if arg is not type(None)]
        if value is None:
            return None
        if len(options) != 1:
            raise TypeError(f"only 'X | None' unions are supported, not {hint}")
        return _decode(options[0], value)
    if origin is tuple:
        args = typing.get_args(hint)
        if len(args) == 2 and args[1] is Ellipsis:
            return tuple(_decode(args[0], item) for item in value)
        return tuple(_decode(arg, item) for arg, item in zip(args, value, strict=True))
    if isinstance(hint, type) and issubclass(hint, JsonDataclass):
        return hint.from_dict(value)
    return value
