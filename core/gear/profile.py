"""The teeth as the rack cuts them: true involute flanks and the generated root fillet.

The gear is cut by its basic rack (GB/T 1356) rolling on the reference circle, the rack's
mean line shifted out by x m. The rack's tooth has straight flanks down to h*a m below its
mean line and a tip rounded with the largest circle that fits the clearance,
ρ = c* m / (1 − sin α) (0.38 m for c* = 0.25, the standard's ρf); with c* = 0 a sharp corner.
Each part of the rack leaves its envelope on the gear: the straight flank the involute (and,
past the limit point N, the undercut), the tip circle the fillet (an offset of the trochoid
its centre traces), the tip line the root circle. The flank at each radius is the nearest of
these to the tooth's axis. Points are exact envelope points of the rack, not arcs.

Frame of one tooth: its axis along +x, the gear's centre at the origin; ``flank`` gives the
upper (counter-clockwise) flank, the lower is its mirror.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .inputs import GearPairInputs
from .pair import Gear

FLANK_POINTS = 80
FILLET_POINTS = 48


@dataclass(frozen=True)
class Flank:
    """The upper flank of a tooth from the root circle to the tip, in the tooth's frame:
    ``radius`` (n,) mm, increasing; ``angle`` (n,) rad from the tooth's axis; ``involute``
    (n,) bool, True where the point is on the straight flank's envelope before N (the true
    involute of the base circle)."""
    radius: np.ndarray
    angle: np.ndarray
    involute: np.ndarray

    def points(self) -> np.ndarray:
        """(n, 2) mm in the tooth's frame."""
        return np.column_stack([self.radius * np.cos(self.angle), self.radius * np.sin(self.angle)])


def rack_tip_radius(p: GearPairInputs) -> float:
    """ρ = c* m / (1 − sin α): the rack's tip rounding, tangent to its flank at h*a m."""
    return p.clearance * p.module_mm / (1.0 - math.sin(p.alpha))


def _polar(x: np.ndarray, y: np.ndarray, phi: np.ndarray, half_pitch: float):
    """Fixed-frame points (x, y) with the gear turned by φ: radius and the angle from the axis
    of the tooth right of the space (the space centred on +y at φ = 0)."""
    angle = np.arctan2(y, x) - phi - (math.pi / 2.0 - half_pitch)
    return np.hypot(x, y), angle


def _straight(p: GearPairInputs, gear: Gear, half_pitch: float):
    """The straight flank's envelope, split at N: (before N, past N), each (radius, angle).
    A flank point at depth h below the rolling line touches when the rack has moved
    r φ = u(h) − h cot α; it is then at (h cot α, r − h) in the fixed frame."""
    m, alpha, r = p.module_mm, p.alpha, gear.r
    s2 = math.sin(alpha) ** 2
    low = (p.addendum - gear.shift) * m                 # where the straight flank ends
    tip = s2 * (r - math.sqrt(r * r - (r * r - gear.ra ** 2) / s2))    # depth at the tip radius
    depth_n = r * s2                                     # depth of the limit point N
    k = math.pi * m / 4.0 - gear.shift * m * math.tan(alpha)
    out = []
    for a, b in ((tip, min(low, depth_n)), (depth_n, low)):
        if b <= a:
            out.append((np.zeros(0), np.zeros(0)))
            continue
        h = np.linspace(a, b, FLANK_POINTS)
        phi = (k - h * math.tan(alpha) - h / math.tan(alpha)) / r
        out.append(_polar(h / math.tan(alpha), r - h, phi, half_pitch))
    return out


def _fillet(p: GearPairInputs, gear: Gear, half_pitch: float):
    """The tip circle's envelope from the root circle to where it meets the straight flank.
    Its centre C is at depth h_c, u_c in the rack; the touching point lies on the line from
    the pitch point I through C, ρ from C on the gear's side."""
    m, alpha, r = p.module_mm, p.alpha, gear.r
    rho = rack_tip_radius(p)
    h_c = (p.addendum + p.clearance - gear.shift) * m - rho
    u_c = math.pi * m / 4.0 - gear.shift * m * math.tan(alpha) - h_c * math.tan(alpha) \
        - rho / math.cos(alpha)
    start = u_c / r                                      # C straight below I: the root
    end = (u_c - h_c * math.cos(alpha) / math.sin(alpha)) / r     # C − I along the flank's normal
    phi = np.linspace(start, end, FILLET_POINTS)
    cx, cy = u_c - r * phi, r - h_c
    side = 1.0 if h_c >= 0.0 else -1.0                  # C above the rolling line: towards I
    dx, dy = side * cx, side * (cy - r)
    norm = np.hypot(dx, dy)
    norm = np.where(norm > 0.0, norm, 1.0)
    return _polar(cx + rho * dx / norm, cy + rho * dy / norm, phi, half_pitch)


def flank(p: GearPairInputs, gear: Gear) -> Flank:
    """The upper flank of one of ``gear``'s teeth (see the module's note)."""
    half_pitch = math.pi / gear.teeth
    pieces = [*_straight(p, gear, half_pitch), _fillet(p, gear, half_pitch)]
    kinds = [True, False, False]
    radius, angle, involute = [], [], []
    for i, (rad, ang) in enumerate(pieces):
        if not rad.size:
            continue
        bound = np.full(rad.shape, np.inf)
        for j, (r2, a2) in enumerate(pieces):
            if j == i or r2.size < 2:
                continue
            order = np.argsort(r2)
            inside = (rad >= r2[order[0]]) & (rad <= r2[order[-1]])
            bound = np.where(inside, np.minimum(bound, np.interp(rad, r2[order], a2[order])), bound)
        # within the blank: past N the undercut branch runs on above the tip circle
        blank = (rad <= gear.ra * (1.0 + 1e-12)) & (rad >= gear.rf * (1.0 - 1e-12))
        keep = (ang <= bound + 1e-12) & blank
        radius.append(rad[keep])
        angle.append(ang[keep])
        involute.append(np.full(int(keep.sum()), kinds[i]))
    radius_all, angle_all = np.concatenate(radius), np.concatenate(angle)
    order = np.argsort(radius_all, kind="stable")
    return Flank(radius_all[order], angle_all[order], np.concatenate(involute)[order])


def tooth_outline(p: GearPairInputs, gear: Gear, arc_points: int = 8) -> np.ndarray:
    """One tooth from the root circle at half a pitch below its axis to half a pitch above,
    counter-clockwise, in the tooth's frame: lower root, lower flank up, tip, upper flank
    down, upper root. (n, 2) mm."""
    f = flank(p, gear)
    half_pitch = math.pi / gear.teeth

    def arc(radius, a, b):
        t = np.linspace(a, b, arc_points)
        return np.column_stack([radius * np.cos(t), radius * np.sin(t)])
    upper = f.points()                      # root to tip
    lower = upper * (1.0, -1.0)             # its mirror, also root to tip
    root_lower = arc(gear.rf, -half_pitch, -f.angle[0])
    tip = arc(gear.ra, -f.angle[-1], f.angle[-1])
    root_upper = arc(gear.rf, f.angle[0], half_pitch)
    return np.vstack([root_lower, lower, tip, upper[::-1], root_upper])
