"""Where the ram bears on its guide: one resultant inside the guide, or two forces at
its ends when the resultant's line of action falls outside it.

The guide's normal forces on the ram reduce to a resultant N (up +) and a moment M
about the ram joint C (:mod:`core.forces.dynamics`). Their line of action is x = M/N from C.
A guide has a length, though: the column's ways, of length L_g, fixed in the frame and
centred on the mid-travel of C. Where M/N lies on the ways, the ram bears there.
Where it does not (a small N, such as the ram's weight alone, against a large moment
of the cutting or inertia forces, puts it metres away), no single contact can carry
the load: the ram tilts in its clearance until it bears on the two ends of the ways,
one end on the upper way and the other on the lower (two forces of opposite sign).
Those two end forces, statically determinate, replace the impossible point:

    N_rear + N_front = N,   x_rear·N_rear + x_front·N_front = M,

with x_rear and x_front the ends relative to C. A pure couple (N = 0, M ≠ 0) is
carried the same way.

Level: beside ``dynamics`` (which calls it); imports kinematics only.
"""
from __future__ import annotations

import numpy as np

from core.linkage.kinematics import ram_origin

MM = 1e-3
ROUND_OFF = 1e-9
"""A resultant this close to an end (relative to the guide's length) is on the guide."""


def guide_ends(design, ram_x_mm: np.ndarray, length_mm: float) -> tuple[np.ndarray, np.ndarray]:
    """x of the guide's rear and front end relative to the ram joint C at ``ram_x_mm``
    (C's x in the frame, (n,) mm), mm each: the guide of ``length_mm`` is fixed in the
    frame, centred on C's mid-travel ``ram_origin + H/2``."""
    centre = ram_origin(design) + design.stroke / 2.0
    x = np.asarray(ram_x_mm, dtype=float)
    return centre - length_mm / 2.0 - x, centre + length_mm / 2.0 - x


def end_forces(normal: np.ndarray, moment: np.ndarray, offset_mm: np.ndarray, rear_mm: np.ndarray,
               front_mm: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(rear, front, tilted): the normal forces at the guide's two ends, N (up +), that
    carry the resultant ``normal`` (N) and its ``moment`` about C (N·m), and whether the
    ram tilts onto them: where the resultant's line ``offset_mm`` (NaN for a pure couple)
    falls outside [rear, front]. Where it falls inside, the ram bears at ``offset_mm`` and
    the two end forces are only its statically equivalent split (both of its sign).

    ``normal`` and ``moment`` broadcast together, (m, n); the ends are (n,) mm."""
    normal, moment, offset = np.broadcast_arrays(normal, moment, offset_mm)
    rear, front = rear_mm * MM, front_mm * MM
    span = front - rear
    slack = ROUND_OFF * (front_mm - rear_mm)     # a resultant at an end (C there) is on the guide
    inside = np.isfinite(offset) & (offset >= rear_mm - slack) & (offset <= front_mm + slack)
    return (front * normal - moment) / span, (moment - rear * normal) / span, ~inside
