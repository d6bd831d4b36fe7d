"""The cam form's default hub, boss, clearance and return allowance, and the motion laws'
names, without the cam's code.

Why a module of its own: the window's cam model (its form's defaults) needs these four
numbers at start-up, ``shaper cam --help`` prints them and the laws' names, and the cam's
solver, synthesis and timing (with scipy on first use) are imported only when a cam is
first computed (issue 43 item 5).
"""
from __future__ import annotations

HUB_MM, BOSS_MM, CLEARANCE_MM = 12.5, 12.5, 3.0
"""Defaults: a feed cam's shaft of Ø16 mm keyed in a hub of Ø25 mm; the follower's pivot pin
of Ø12 mm in a boss of Ø25 mm; 3 mm between the profile and either (a rough casting's and
the assembly's tolerance). The form's default cam (arm 120 mm) clears the hub by 13.2 mm
and the boss by 30.7 mm, and the course data sheet's (cosine/parabolic) by 2.4 and
44.8 mm, so both are unchanged; the issue's rise-100° cam (profile base radius 6.6 mm)
is not."""

MIN_ARM_MM, MAX_ARM_MM = 1.0, 5000.0
"""The follower arm's range (mm); the longest arm a refusal's search tries is the most."""

RETURN_PRESSURE_DEG = 70.0
"""Default allowed pressure angle on the return, °. The follower comes back unloaded,
closed by its spring (or the groove), so the return can take a much larger pressure angle
than the working rise: the textbooks allow [α′] = 70°–80° there against 30°–45° on the
rise of an oscillating follower; 70° is the cautious end."""

LAWS = ("parabolic", "cosine", "sine", "poly345")
"""The motion laws of a rise or a return, by the names a design file and ``--law`` use."""
