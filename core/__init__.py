"""Headless engine of the shaper designer: synthesis, kinematics, metrics, files.

Levels, each importing only those before it: ``geometry`` (lengths, synthesis)
→ ``kinematics`` (closed-form motion) → ``metrics`` (measured cycle values) →
``spec``/``io`` (what the user states, files) → ``cli``. Never imports Qt.
"""
from .errors import DesignError, FileFormatError
from .geometry import Design, from_dimensions, synthesize
from .kinematics import Motion, crank_angles, solve
from .metrics import CycleMetrics, analyze
from .spec import Spec

__all__ = ["Design", "DesignError", "FileFormatError", "Motion", "CycleMetrics", "Spec",
           "analyze", "crank_angles", "from_dimensions", "solve", "synthesize"]
