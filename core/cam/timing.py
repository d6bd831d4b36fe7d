"""When the cam feeds: on the crank's shaft, outside the linkage's cutting interval.

The cam is keyed to the crank, so the cam angle is δ = φ − φ0 with φ0 the crank angle at
which the rise begins (the phase). The table may only move while the tool is clear of the
work, i.e. outside the closed cut window of ``core.linkage.cut``. The rise, the outer dwell and the
return together must fit in the rest of the turn; by default they are centred in it, so the
feed has the same margin before and after the cut.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

from core.linkage.cut import cut_window
from core.linkage.designs import Designs
from core.base.errors import DesignError, require_range
from core.linkage.verdict import round_text
from .laws import Program


@dataclass(frozen=True)
class Timing:
    """The phase φ0 (crank angle of the rise's start) and the non-cutting span, degrees."""

    phase_deg: float
    clear_from_deg: float      # the crank angle at which the cut ends
    clear_span_deg: float      # how far the crank turns before the next cut starts

    def cam_angle(self, phi):
        """Cam angle δ (rad) at crank angles ``phi`` (rad)."""
        return phi - math.radians(self.phase_deg)


MAX_PHASE_DEG = 36000.0
"""A phase is an angle taken modulo 360°, but within ±36000° (as every crank angle the
program takes): 1e308° is no angle to the 1e-13° a float can still resolve there."""


def check_phase(phase_deg: object) -> float:
    """The phase as a float, DesignError naming ``phase`` for one outside ±MAX_PHASE_DEG."""
    return require_range("phase", phase_deg, -MAX_PHASE_DEG, MAX_PHASE_DEG, "°", low_open=False)


@lru_cache(maxsize=8)
def _clear_window(design, idle_fraction: float) -> tuple[float, float]:
    """The crank angles (°) where the cut of ``design`` starts and ends. Kept for the last
    designs (a frozen value): every edit of the Cam tab times the cam against the same
    linkage, and the window's root search was ~3 ms of the cam's ~40."""
    on, off = (math.degrees(float(v[0])) for v in cut_window(Designs.of(design), idle_fraction))
    return on, off


def timing(program: Program, design, idle_fraction: float, phase_deg: float | None = None) -> Timing:
    """Place the feed outside the cut of ``design`` (a ``core.linkage.geometry.Design``), centred in
    the non-cutting span, or check the given ``phase_deg``; DesignError names ``rise`` when
    the feed cannot fit, ``phase`` when the given phase would feed during the cut."""
    on, off = _clear_window(design, idle_fraction)
    span = 360.0 - (off - on)
    feed = program.feed_deg
    if feed > span:
        raise DesignError("rise", program.rise_deg,
                          f"rise + outer dwell + return ({feed:g}°) must fit in the {round_text(span, 4, down=True)}° "
                          "the crank turns outside the cut")
    if phase_deg is None:
        return Timing(math.fmod(off + (span - feed) / 2.0, 360.0), off, span)
    phase_deg = check_phase(phase_deg)
    since = (phase_deg - off) % 360.0
    if since + feed > span + 1e-9:
        raise DesignError("phase", phase_deg,
                          f"feeds during the cut: the rise must start between {round_text(off, 4)}° and "
                          f"{round_text(math.fmod(off + span - feed, 360.0), 4, down=True)}° of crank angle")
    return Timing(phase_deg % 360.0, off, span)
