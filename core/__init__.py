"""Headless engine of the shaper designer: synthesis, kinematics, metrics, files.

Levels, each importing only those before it: ``geometry`` (lengths, synthesis)
→ ``kinematics`` (closed-form motion) → ``metrics`` (measured cycle values) →
``spec``/``io`` (what the user states, files) → ``cli``. Never imports Qt.

The names below are imported when first used (``core.analyze``), not with the
package: every ``shaper`` command imports ``core`` first, and ``shaper curves``
needs neither the metrics nor their root search (issue 24).
"""
from __future__ import annotations

from importlib import import_module

_HOMES = {"DesignError": "errors", "FileFormatError": "errors", "Design": "geometry",
          "from_dimensions": "geometry", "synthesize": "geometry", "Motion": "kinematics",
          "crank_angles": "kinematics", "solve": "kinematics", "CycleMetrics": "metrics",
          "analyze": "metrics", "Spec": "spec"}

__all__ = ["Design", "DesignError", "FileFormatError", "Motion", "CycleMetrics", "Spec",
           "analyze", "crank_angles", "from_dimensions", "solve", "synthesize"]


def __getattr__(name: str) -> object:
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module 'core' has no attribute {name!r}")
    value = getattr(import_module(f".{home}", __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
