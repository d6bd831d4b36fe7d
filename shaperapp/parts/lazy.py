"""A part's model made when first used, its place in the design file held from the start.

Why: the window's first screen shows neither the cam nor the gear pair, yet making their
models imported ``core.gear`` (and designed the default pair) and ``core.cam``'s defaults
before the first paint, some 5 ms of every start (issue 43 item 5). Save and Open need the
part from the start, so :class:`LazyPart` registers with the design model's file parts at
once: Save asks the model (made then, if no tab or export made it before), Open checks an
opened file's part through ``check`` without making it. A model made after a file was opened
starts from that file's part (each model reads ``parts.loaded`` when it is made), so it holds
what it would have held had it been made at start.
"""
from __future__ import annotations

from typing import Any, Callable, Generic, TypeVar

from shaperapp.design.model import DesignModel

Part = TypeVar("Part")


class LazyPart(Generic[Part]):
    """``model``: the part's model, made by ``make()`` at the first ask."""

    def __init__(self, design: DesignModel, name: str, make: Callable[[], Part],
                 check: Callable[[Any], Any] | None = None) -> None:
        self._make = make
        self._model: Part | None = None
        design.parts.register(name, lambda: self.model.document(), check)

    @property
    def model(self) -> Part:
        if self._model is None:
            self._model = self._make()
        return self._model

    def made(self) -> bool:
        return self._model is not None
