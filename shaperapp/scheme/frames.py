"""The scheme's per-frame arrays: every crank angle's joints, rotations, label spots and
tool tip, computed once per design from core's arrays (vectorized over the angles).

Split from mechanism.py (the layer that draws them) so that the per-design arithmetic
stands apart from the Qt items: an animation frame only indexes these arrays, and
nothing here touches a graphics item.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from core.base.arrays import sorted_unique
from core.linkage.geometry import Design
from core.linkage.kinematics import Motion
from core.linkage.metrics import CycleMetrics

RETURN_LIFT = 0.35         # the return stroke of the tool path is drawn this many u higher
LIMIT_TOL_DEG = 1e-6       # a grid angle this close to a limit position counts as on it


@dataclass(frozen=True)
class Frames:
    """Everything one animation frame needs, one row per crank-angle index."""

    joints: np.ndarray          # (n, k, 2) moving joints A, B[, C], mm
    crank_deg: np.ndarray       # (n,) rotation of the crank body about O2
    lever_deg: np.ndarray       # (n,) rotation of the lever body about O4
    rod_deg: np.ndarray | None  # (n,) rotation of the rod body about B
    ram_x: np.ndarray           # (n,) x of the ram's reference point C
    labels: np.ndarray          # (n, k, 2) where the labels A, B[, C] go
    away: np.ndarray            # (n, 2, 2) unit directions of A's and O2's labels from their joints
    u: float                    # the drawing's unit, mm
    tip: np.ndarray             # (n, 2) tool tip; the return stroke lifted by RETURN_LIFT·u
    corners: np.ndarray         # indices where the tool path turns (stroke ends), ascending


def build_frames(design: Design, motion: Motion, metrics: CycleMetrics, u: float,
                 tip_local: tuple[float, float]) -> Frames:
    """Per-index transforms and points, all from core's arrays."""
    sh = motion.shape
    a, b, c = sh.crank_pin.T, sh.lever_tip.T, sh.ram_joint.T
    rod = design.rod is not None
    o2 = np.array([0.0, design.frame])
    along = b / design.lever
    normal = np.stack([along[:, 1], -along[:, 0]], axis=1)        # across the lever
    side = -1.0 if rod and design.rod_side == "leading" else 1.0   # B's label away from the rod
    across = side * normal
    # O2 lies on one side of the lever, the crank runs from it to A on the lever: A's
    # label goes across the lever to the other side, O2's away from the lever (they sat
    # on the lever at φ = 100° and under it at 120°, when placed along the crank).
    o2_side = np.sign(np.einsum("ij,ij->i", normal, o2 - a))
    o2_side[o2_side == 0.0] = 1.0
    toward_o2 = normal * o2_side[:, None]
    labels = [a - 1.0 * u * toward_o2, b + 2.0 * u * across]   # A: moved on in show()
    if rod:
        labels.append(c + np.array([0.0, -2.4 * u]))
    tip = np.stack([c[:, 0] + tip_local[0], np.full(len(c), design.guide + tip_local[1])], axis=1)
    # Return stroke: strictly between the limits (a limit on the grid counts as cutting).
    phase = (np.degrees(motion.crank_angle) - metrics.work_start_deg) % 360.0
    returning = (phase > metrics.work_angle_deg + LIMIT_TOL_DEG) & (phase < 360.0 - LIMIT_TOL_DEG)
    tip[returning, 1] += RETURN_LIFT * u
    turns = np.flatnonzero(returning[1:] != returning[:-1])
    return Frames(
        joints=np.stack([a, b, c] if rod else [a, b], axis=1),
        crank_deg=np.degrees(np.arctan2(a[:, 1] - o2[1], a[:, 0] - o2[0])),
        lever_deg=90.0 - np.degrees(sh.lever),
        rod_deg=np.degrees(sh.rod) if rod else None, ram_x=c[:, 0],
        labels=np.stack(labels, axis=1), away=np.stack([-toward_o2, toward_o2], axis=1), u=u, tip=tip,
        corners=sorted_unique(np.concatenate([turns, turns + 1])))
