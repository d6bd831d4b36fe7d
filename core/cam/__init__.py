"""The feed cam: a disc cam with an oscillating roller follower on the crank's shaft.

``laws`` the motion laws and the program; ``follower`` the pitch curve, profile, pressure
angle and curvature; ``extremes`` the largest pressure angles and the smallest convex
radius, solved; ``synthesis`` the smallest base radius and the largest roller;
``timing`` the feed placed outside the linkage's cut; ``cam`` one cam from its inputs;
``build`` whether it clears its hub and the follower pivot's boss; ``advice`` the values a
refusal names and ``advised`` its sentences; ``pending`` a refusal whose advice is searched
later; ``table`` its rows per cam angle and its figures; ``file`` its inputs in a design file.

Level: its own, just above the analysis level (it times the feed against ``core.linkage.cut``);
it imports the analysis and mechanism levels only. Its DXF is ``core.drawing.cam_dxf``.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from core.base.lazy import lazy_names

if TYPE_CHECKING:
    from .cam import Cam, CamInputs, design_cam
    from .follower import Follower
    from .laws import LAWS, Program
    from .synthesis import Allowance

__all__ = ["Allowance", "Cam", "CamInputs", "Follower", "LAWS", "Program", "design_cam"]

# Imported on first use: ``core.cam.defaults`` (the form's defaults, read at the window's
# start-up) must not bring in the solver, the synthesis and the timing.
__getattr__ = lazy_names(__name__, {"Allowance": "synthesis", "Cam": "cam", "CamInputs": "cam",
                                    "Follower": "follower", "LAWS": "laws", "Program": "laws",
                                    "design_cam": "cam"})
