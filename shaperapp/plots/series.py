"""What a view tells its plot stack: the plots (``Series``) and the questions the stack
asks it (``StackSource``), kept apart from the stack's widget code so that the views
and the stack share one vocabulary."""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from shaperapp.design.model import DesignModel

from .curves import Band, Curve
from .legend import LegendKey


@dataclass(frozen=True)
class Series:
    """One plot of the stack: ``curves(model)`` gives what it draws."""

    key: str
    unit: str
    name: Callable[[], str]          # full translated name, for the read-out
    title: Callable[[], str]         # short translated axis title
    curves: Callable[[DesignModel], list[Curve]]
    group: str = "main"              # plots of one group share a legend


class StackSource(Protocol):
    """What a view tells the stack besides its series."""

    def bands(self) -> list[Band]: ...                        # shaded x spans, all plots
    def legend_keys(self) -> dict[str, list[LegendKey]]: ...  # per group, after the curves
    def group_titles(self) -> dict[str, str]: ...             # per group, over its legend
    def legend_units(self) -> dict[str, str]: ...             # per group, left of the entries
    def x_axis(self) -> tuple[str, float, float, bool]: ...   # title, range, degree ticks
    def x_text(self, x: float) -> str: ...                    # "φ = 12.0°" for the read-out
    def cursor_x(self, index: int) -> float | dict[str, float]: ...   # per curve label

