"""Headless engine of the shaper designer: one package per concern, never Qt.

Floors, each importing only those below it (the layers contract in pyproject.toml):
``base`` (errors, small helpers) → ``linkage`` (synthesis, kinematics, the measured
cycle) → ``forces`` (kinetostatics, flywheel) | ``cam`` | ``gear`` → ``files`` (design
files, CSV/JSON, safe writes) → ``space`` (sweep, optimum, comparison) | ``course_design``
(positions table, export plan) → ``drawing`` | ``library`` → ``cli``.

The names below are imported when first used (``core.analyze``), not with the
package: every ``shaper`` command imports ``core`` first, and ``shaper curves``
needs neither the metrics nor their root search (issue 24).
"""
from __future__ import annotations

from importlib import import_module

_HOMES = {"DesignError": "base.errors", "FileFormatError": "base.errors",
          "Design": "linkage.geometry", "from_dimensions": "linkage.geometry",
          "synthesize": "linkage.geometry", "Motion": "linkage.kinematics",
          "crank_angles": "linkage.kinematics", "solve": "linkage.kinematics",
          "CycleMetrics": "linkage.metrics", "analyze": "linkage.metrics", "Spec": "linkage.spec"}

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
