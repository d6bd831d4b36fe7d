"""A sheet's text laid out by the width a renderer draws it at, not the sheet's estimate.

The sheet (``core.drawing.sheet``) places every text by an estimate of its width that is
never narrower than the fonts draw it, so no two texts meet on paper. A text with an index
is drawn as runs (``Text.runs``), each after the previous run's *estimated* width; where the
font is narrower than the estimate, a subscript after a long run stood apart from its
letter. Each renderer (the PDF's Qt font, the DXF's outline font) measures its own runs and
closes them up here, so both set a subscript right after its letter.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Callable

import numpy as np

from .sheet import Text


def closed_up(item: Text, drawn_width: Callable[[Text], float]) -> list[Text]:
    """The runs of ``item``, each one after the previous run's ``drawn_width`` (paper mm)
    instead of its estimated width, the whole aligned by its drawn width within the
    estimated one (a centred text stays centred on its anchor)."""
    runs = item.runs()
    if len(runs) < 2:
        return runs
    drawn = [drawn_width(run) for run in runs]
    spare = item.width - sum(drawn)
    at = {"l": 0.0, "c": spare / 2.0, "r": spare}[item.align[0]]
    u = np.array([math.cos(math.radians(item.rotation)), math.sin(math.radians(item.rotation))])
    closed, estimated = [], 0.0
    for run, width in zip(runs, drawn):
        x, y = np.asarray(run.position) + u * (at - estimated)
        closed.append(replace(run, position=(float(x), float(y))))
        estimated += run.width
        at += width
    return closed
