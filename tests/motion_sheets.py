"""The motion sheets several test modules read, each built once per process.

``test_motion_complete.py`` and ``test_sheet.py`` look at the same sheets (the default block
and rod designs at 40 r/min on every paper, and at 60 r/min with 24 positions on A1 and A3),
and ``test_sheet.py`` alone at the default block's A1 sheet five times; a sheet takes
0.3–2.7 s to build. The tests only read what they are given.
"""
from __future__ import annotations

import functools

from core.drawing.motion import MotionSheet, motion_sheet
from core.drawing.sheet import paper
from core.linkage.geometry import Design


def motion_drawn(design: Design, rpm: float, size: str, count: int = 12) -> MotionSheet:
    """``motion_sheet(design, rpm, paper(size), count=count)``, shared: read it, never change it."""
    return _drawn(design, float(rpm), size.upper(), int(count))


@functools.lru_cache(maxsize=None)
def _drawn(design: Design, rpm: float, size: str, count: int) -> MotionSheet:
    return motion_sheet(design, rpm, paper(size), count=count)
