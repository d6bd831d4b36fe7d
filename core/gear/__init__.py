"""The gear pair that drives the crank: an external involute spur pair on the GB/T 1356 rack.

``involute`` the involute function and its inverse (Newton) and the tooth-thickness forms;
``inputs`` the checked inputs; ``shift`` which shift factors (given, from a′, or the rule);
``pair`` every length of the pair; ``margins`` each check's verdict; ``advice`` and
``amounts`` what to change and by how much; ``checks`` undercut, tip, ε and interference, each
with what to change; ``table`` the results as rows and JSON; ``file`` the design file's "gear";
``profile`` the teeth as drawn (true involutes and the rack-generated fillet).

Level: its own, beside the cam; it imports ``core.base.errors`` only.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from core.base.lazy import lazy_names

if TYPE_CHECKING:
    from .checks import Check, pair_checks
    from .inputs import GearPairInputs
    from .pair import Gear, GearPair, design_pair

__all__ = ["Check", "Gear", "GearPair", "GearPairInputs", "design_pair", "pair_checks"]

# Imported on first use: the window's gear model (its pair and its file) must not bring in
# the checks and their advice at start-up.
__getattr__ = lazy_names(__name__, {"Check": "checks", "pair_checks": "checks", "GearPairInputs": "inputs",
                                    "Gear": "pair", "GearPair": "pair", "design_pair": "pair"})
