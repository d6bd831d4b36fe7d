"""The parts of a design file that other models keep (the cam's inputs, the gear pair's).

The design model holds the linkage, speeds and loads; each other part of the file belongs
to a model of its own, which registers how Save gets it and how an opened file's value is
checked. Opening stays all or nothing: every registered part of the new state is checked
before anything changes (:meth:`FileParts.check`), and a part no model edits is kept as it
was read, so opening and saving a file never drops it.
"""
from __future__ import annotations

from typing import Any, Callable


class FileParts:
    """Registered savers and checkers, and what the state last loaded held for each part."""

    def __init__(self) -> None:
        self._loaded: dict[str, Any] = {}
        self._savers: dict[str, Callable[[], Any]] = {}
        self._checks: dict[str, Callable[[Any], Any]] = {}

    def register(self, name: str, save: Callable[[], Any],
                 check: Callable[[Any], Any] | None = None) -> None:
        """``save()`` gives the JSON value Save writes under ``name``; ``check(value)``
        raises DesignError for a value an opened file holds that the part's model cannot
        show (the file is then refused, nothing changed)."""
        self._savers[name] = save
        if check is not None:
            self._checks[name] = check

    def saved(self) -> dict[str, Any]:
        """Every part Save writes: each registered one as its model gives it, and a part
        the last loaded state held that no model edits as it was read."""
        kept = {name: value for name, value in self._loaded.items()
                if value is not None and name not in self._savers}
        return {**kept, **{name: save() for name, save in self._savers.items()}}

    def loaded(self, name: str) -> Any:
        """What the state last loaded held under ``name`` (None: nothing, the defaults)."""
        return self._loaded.get(name)

    def check(self, parts: dict[str, Any]) -> None:
        """DesignError if a registered part of ``parts`` cannot be shown."""
        for name, check in self._checks.items():
            if parts.get(name) is not None:
                check(parts[name])

    def set_loaded(self, parts: dict[str, Any]) -> None:
        self._loaded = dict(parts)
