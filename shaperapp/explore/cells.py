"""What the Explore map says of one cell and what a click on it loads: the cell's parameters
and every figure of its design (to weigh one against another), or why it is invalid; the
clicked design's values, tidied. Pure functions of a map's result, apart from the view."""
from __future__ import annotations

import math
from typing import Any

import numpy as np
from PySide6.QtCore import QCoreApplication

from core.linkage.spec import Spec
from core.space.sweep import spec_changes, tidy_values
from shaperapp.widgets.messages import describe

from . import names as explore_names
from .jobs import MapResult


def cell_text(result: MapResult, row: int, column: int) -> str:
    """The read-out of the cell (``row``, ``column``) in the UI's language."""
    names = explore_names.parameter_names()
    where = f"{names[result.x_name]} = {result.x[column]:.5g}, {names[result.y_name]} = {result.y[row]:.5g}"
    error = result.errors[row * result.x.size + column]
    if error is not None:
        return QCoreApplication.translate("ExploreView", "%1 — invalid: %2").replace(
            "%1", where).replace("%2", describe(error))
    labels = explore_names.figure_names()
    shown = [f"{labels[key]}: {values[row, column]:.5g}" for key, values in
             result.figures.items() if math.isfinite(values[row, column])]
    return where + "\n" + ";  ".join(shown)


def clicked_changes(result: MapResult, row: int, column: int, spec: Spec) -> dict[str, Any]:
    """The spec changes that load the clicked cell's design, its values rounded to a
    hundredth of the cell (52.56, not 52.564102564102564)."""
    cell = {result.x_name: (result.x, column), result.y_name: (result.y, row)}
    values = {n: float(axis[i]) for n, (axis, i) in cell.items()}
    resolution = {n: float(np.ptp(axis)) / max(axis.size - 1, 1) / 100 for n, (axis, _) in cell.items()}
    return spec_changes(tidy_values(spec, values, resolution))
