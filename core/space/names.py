"""What a sweep may vary and what an optimization may minimize, by the names a user types.

Why a module of its own: ``shaper sweep --help`` and ``shaper optimize --help`` list these
names, and ``core.space.sweep`` and ``core.space.optimize`` (which evaluate them) import
numpy, scipy and the whole engine, most of a help's time (issue 43 item 5).
"""
from __future__ import annotations

# Sweepable parameters: the name a user types (as the design options) → the core name.
PARAMETERS = {"crank": "crank", "K": "time_ratio", "stroke": "stroke", "rod": "rod",
              "rod-ratio": "rod_ratio", "guide": "guide", "frame": "frame", "lever": "lever"}
UNITLESS = ("K", "rod-ratio")       # the others are lengths in mm

# objective → (what it minimizes, unit, needs loads)
OBJECTIVES = {
    "pressure-angle": ("largest pressure angle between the rod and the guide", "°", False),
    "accel": ("largest ram acceleration |a| at the highest speed", "m/s²", False),
    "peak-torque": ("largest crank driving torque over the speeds", "N·m", True),
    "flywheel": ("flywheel inertia J_F at the slowest speed", "kg·m²", True),
}
