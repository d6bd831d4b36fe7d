"""A package's public names imported on first use (PEP 562's module ``__getattr__``).

Why: a package's ``__init__`` that imports its public names from every submodule makes
importing one light submodule (a file's reader, the form's defaults) import them all;
the window's start-up paid for the cam's solver and the gear's checks that way before its
first paint (issue 43 item 5).
"""
from __future__ import annotations

from importlib import import_module
from typing import Any, Callable


def lazy_names(package: str, homes: dict[str, str]) -> Callable[[str], Any]:
    """The ``__getattr__`` of ``package`` that imports ``homes[name]`` (a submodule's
    name) when ``name`` is first asked for, and keeps the value in the package."""
    def __getattr__(name: str) -> Any:
        if name not in homes:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(import_module(f"{package}.{homes[name]}"), name)
        setattr(import_module(package), name, value)
        return value
    return __getattr__
