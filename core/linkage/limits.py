"""The bounds of a request (speeds, crank-angle step, samples), without the kinematics.

Why a module of its own: every ``shaper`` command's ``--help`` prints these numbers, and
``core.linkage.kinematics`` (which checks requests against them) imports numpy, about
0.3 s of a help that prints text only (issue 43 item 5).
"""
from __future__ import annotations

MIN_RPM = 0.01
"""Slowest crank speed, r/min (one turn in 100 minutes): every time and rate stays finite."""
MAX_RPM = 1000.0
MAX_SPEEDS = 16
MIN_STEP_DEG = 0.0002
"""Finest crank-angle step, degrees (1 800 001 angles per cycle)."""
MAX_STEP_DEG = 90.0
MAX_SAMPLES = 2_000_000
"""Largest request, crank angles × crank speeds: what one computation may hold in memory."""
MAX_ANGLES = MAX_SAMPLES
