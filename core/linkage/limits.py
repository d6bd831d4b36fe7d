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
MAX_FILE_SAMPLES = 60_000
"""Largest design a design file holds, its crank angles × crank speeds: what the GUI
recomputes and redraws on every edit within about half a second (set when 60 000 samples
took 0.34–0.68 s on the shared 2-core machine under a load of 3.5; docs/performance.md). It is
the file's own limit, checked by its reader and by ``shaper design``, so every file the
CLI writes or the library keeps opens in the GUI; commands that write no design file
(``shaper curves --step``) go up to :data:`MAX_SAMPLES`."""
