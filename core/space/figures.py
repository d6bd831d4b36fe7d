"""The key figures of a design: what a library sorts by and a comparison puts side by side.

Beside ``io`` at the last level of core: it only gathers numbers that
``metrics.analyze`` and ``flywheel.summarize`` compute, under the JSON keys
``shaper analyze`` and ``shaper dynamics`` use, so a figure in the library or
a comparison is by construction the figure those commands print.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Iterable

if TYPE_CHECKING:
    from core.forces.masses import MassProperties
    from core.linkage.spec import Spec

# The computation's modules are imported by ``figures``: the tables of names below are read by
# the library's filter syntax, which ``shaper library list --help`` prints (issue 43 item 5).

# Which computation of the figures this program does. Raise it whenever a figure below
# comes out differently (a corrected formula, a finer peak search): a library keeps each
# entry's figures with the version that computed them, so entries from an older version
# are found and recomputed from their stored designs (``Library.refresh_figures``).
FIGURES_VERSION = 1

# Speed-independent figures: (key, unit, short alias, better) — better is "lower",
# "higher" or None when no value is better in itself (a requirement such as K or H).
DESIGN_FIGURES = (
    ("K", "", "K", None),
    ("stroke_mm", "mm", "H", None),
    ("theta_deg", "°", "theta", None),
    ("crank_mm", "mm", "L1", None),
    ("frame_mm", "mm", "L2", None),
    ("lever_mm", "mm", "L3", None),
    ("rod_mm", "mm", "L4", None),
    ("guide_mm", "mm", "guide", None),
    ("pressure_angle_max_deg", "°", "pressure_angle_max", "lower"),
)
# Per-speed figures; the torques and J_F need loads and are None without them.
SPEED_FIGURES = (
    ("v_work_max_m_s", "m/s", "v_work_max", None),
    ("v_work_mean_m_s", "m/s", "v_work_mean", None),
    ("v_return_max_m_s", "m/s", "v_return_max", None),
    ("a_max_m_s2", "m/s²", "a_max", "lower"),
    ("mean_torque_N_m", "N·m", "mean_torque", "lower"),
    ("max_torque_N_m", "N·m", "max_torque", "lower"),
    ("flywheel_inertia_kg_m2", "kg·m²", "J_F", "lower"),
)
DESIGN_KEYS = tuple(key for key, *_ in DESIGN_FIGURES)
SPEED_KEYS = tuple(key for key, *_ in SPEED_FIGURES)
TEXT_FIGURES = ("variant", "rod_side")


@dataclass(frozen=True)
class SpeedFigures:
    """Figures at one crank speed. Speeds m/s, acceleration m/s², torque N·m, J_F kg·m²."""

    rpm: float
    v_work_max_m_s: float
    v_work_mean_m_s: float
    v_return_max_m_s: float
    a_max_m_s2: float
    mean_torque_N_m: float | None
    max_torque_N_m: float | None
    flywheel_inertia_kg_m2: float | None


@dataclass(frozen=True)
class Figures:
    """Figures of one design: measured K and stroke, dimensions in mm, angles in degrees."""

    variant: str
    rod_side: str | None          # None for the block variant
    K: float                      # measured, as ``shaper analyze`` reports it
    stroke_mm: float              # measured
    theta_deg: float
    crank_mm: float               # L1
    frame_mm: float               # L2
    lever_mm: float               # L3
    rod_mm: float | None          # L4, rod variant only
    guide_mm: float               # guide line above the lever pivot O4
    pressure_angle_max_deg: float | None   # rod variant only; independent of speed
    speeds: tuple[SpeedFigures, ...]

    def design_values(self) -> dict[str, Any]:
        return {key: getattr(self, key) for key in TEXT_FIGURES + DESIGN_KEYS}

    def speed(self, rpm: float) -> SpeedFigures | None:
        """The figures at ``rpm`` (to 1e-9 r/min), or None if not computed there."""
        for s in self.speeds:
            if math.isclose(s.rpm, rpm, rel_tol=1e-12, abs_tol=1e-9):
                return s
        return None


def figures(spec: Spec, rpms: Iterable[float], masses: MassProperties | None) -> Figures:
    """All key figures of ``spec`` at ``rpms``; loads ``masses`` (None: no torque figures).

    Raises DesignError for an invalid spec, speeds or loads.
    """
    from core.files.io import finite_or_none
    from core.forces.flywheel import summarize
    from core.forces.masses import masses_for_design
    from core.linkage.metrics import analyze
    design = spec.design()
    rpms = list(rpms)
    metrics = analyze(design, rpms)
    summary = summarize(design, rpms, masses_for_design(design, masses)) if masses is not None else None
    speeds = []
    for i, s in enumerate(metrics.speeds):
        d = summary.speeds[i] if summary is not None else None
        speeds.append(SpeedFigures(
            rpm=s.rpm, v_work_max_m_s=s.v_work_max_m_s, v_work_mean_m_s=s.v_work_mean_m_s,
            v_return_max_m_s=s.v_return_max_m_s, a_max_m_s2=s.a_max_m_s2,
            mean_torque_N_m=finite_or_none(d.mean_torque_N_m) if d else None,
            max_torque_N_m=finite_or_none(d.max_torque_N_m) if d else None,
            flywheel_inertia_kg_m2=finite_or_none(d.flywheel_inertia_kg_m2) if d else None))
    return Figures(
        variant=design.variant, rod_side=design.rod_side if design.rod is not None else None,
        K=metrics.time_ratio, stroke_mm=metrics.stroke_mm, theta_deg=math.degrees(design.theta),
        crank_mm=design.crank, frame_mm=design.frame, lever_mm=design.lever, rod_mm=design.rod,
        guide_mm=design.guide, pressure_angle_max_deg=finite_or_none(metrics.pressure_angle_max_deg),
        speeds=tuple(speeds))

