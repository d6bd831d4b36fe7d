"""Design-space sweeps: the figures of many designs at once, with the reason each invalid one fails.

Beside ``spec``: it turns a :class:`~core.linkage.spec.Spec` plus arrays of varied
parameters into :class:`~core.linkage.designs.Designs` (the vectorized counterpart of
``Spec.design``, refusing each design by the rule a single design would fail)
and evaluates them with the same code as :func:`core.linkage.metrics.analyze` and
:func:`core.forces.flywheel.summarize`, so a design's row in a sweep equals its
single-design figures.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, replace

import numpy as np

from core.linkage.designs import Designs, dimensions_many, synthesize_many
from core.forces.masses import MassProperties
from core.forces.flywheel import cycle_summary
from core.base.errors import DesignError
from core.linkage.metrics import CyclePeaks, cycle_peaks, speed_figures
from core.linkage.kinematics import check_rpms, rpm_to_omega
from core.linkage.spec import GUIDE_RULES, MODES, ROD_INPUTS, ROD_SIDES, VARIANTS, Spec
from core.linkage.verdict import Verdict
from .names import PARAMETERS

SYNTHESIS_ONLY = ("time_ratio", "stroke")
DIMENSIONS_ONLY = ("frame", "lever")
MAX_DESIGNS = 1_000_000
MAX_COUNT = 100_000       # points per varied parameter
# Crank-angle intervals a sweep's loaded figures sample per cycle (a single design's summary
# takes 3600; the rod variant's sharp angles get crowded samples besides). The samples only
# bracket the torque and energy extrema, which are then polished on the closed form; the mean
# torque and the energy are closed-form: a design's row equals its single-design figures to
# 1e-9 on random designs and to 1e-8 (the polish's own rounding) at the domain's corners, K
# 1.0005 … 5 and rods a hair longer than their reach (tests/test_core/test_sweep_loaded.py).
# 45, 60 and 90 intervals agreed with 3600 to 1e-12 on some 1100 valid random designs (K 1.01 …
# 3, rod ratios 0.1 … 1.2) × 3 loads × 3 speeds, but 60 missed a minimum torque by 7e-5 at a
# K = 5 corner (where the grid fell: 45 did not), so 90, which passed 150 corner examples more.
# A loaded row at 1 speed then costs some 5 unloaded ones (issue 42: 10^6 loaded designs were
# projected at 2.6 hours).
SWEEP_INTERVALS = 90


@dataclass(frozen=True)
class Evaluation:
    """Figures of many designs (shape (n,) or (n, speeds)); NaN where a design is invalid."""

    designs: Designs
    verdict: Verdict
    rpm: np.ndarray                    # (m,) r/min
    peaks: CyclePeaks                  # speed-independent, over all n designs
    figures: dict[str, np.ndarray]     # per speed, (n, m), SI units (metrics.speed_figures)
    dynamics: dict[str, np.ndarray] | None   # (n, m) per speed, with loads only

    @property
    def valid(self) -> np.ndarray:
        return self.verdict.ok

    def error(self, index: int) -> DesignError | None:
        """Why design ``index`` is invalid (the single-design validation's error), or None."""
        return self.verdict.error(index)


def check_vary(name: str, spec: Spec) -> str:
    """The core name of a varied parameter, refusing one the design's mode cannot vary."""
    if name not in PARAMETERS:
        raise DesignError("vary", name, "must name one of " + ", ".join(PARAMETERS))
    core = PARAMETERS[name]
    if core in SYNTHESIS_ONLY and spec.mode != "synthesis":
        raise DesignError("vary", name, "can vary only for a design given by L1, K and H")
    if core in DIMENSIONS_ONLY and spec.mode != "dimensions":
        raise DesignError("vary", name, "can vary only for a design given by its dimensions")
    return core


def spec_designs(spec: Spec, values: dict[str, np.ndarray]) -> tuple[Designs, Verdict]:
    """``spec.design()`` for every combination in ``values`` (core names → equal-length arrays).

    A varied ``rod`` or ``rod_ratio`` makes the rod variant with that input; a
    varied ``guide`` is a height above O4 in mm.
    """
    for name, allowed in (("mode", MODES), ("variant", VARIANTS), ("guide_rule", GUIDE_RULES),
                          ("rod_input", ROD_INPUTS), ("rod_side", ROD_SIDES)):
        if getattr(spec, name) not in allowed:
            raise DesignError(name, getattr(spec, name), "must be one of " + ", ".join(allowed))
    if "rod" in values and "rod_ratio" in values:
        raise DesignError("rod", "vary", "vary either the rod length or its ratio L4/L3, not both")
    arrays = {k: np.asarray(v, dtype=float) for k, v in values.items()}
    get = lambda name, default: arrays.get(name, default)  # noqa: E731
    guide = get("guide", spec.guide_height if spec.guide_rule == "height" else spec.guide_rule)
    rod = ratio = None
    if "rod" in arrays:
        rod = arrays["rod"]
    elif "rod_ratio" in arrays:
        ratio = arrays["rod_ratio"]
    elif spec.variant == "rod":
        rod, ratio = (spec.rod_length, None) if spec.rod_input == "length" else (None, spec.rod_ratio)
    common = dict(guide=guide, rod=rod, rod_ratio=ratio, rod_side=spec.rod_side)
    if spec.mode == "synthesis":
        return synthesize_many(get("crank", spec.crank), get("time_ratio", spec.time_ratio),
                               get("stroke", spec.stroke), **common)
    return dimensions_many(get("crank", spec.crank), get("frame", spec.frame),
                           get("lever", spec.lever), **common)


def grid(ranges: dict[str, tuple[float, float, int]]) -> dict[str, np.ndarray]:
    """Every combination of the ranges (name → (low, high, count)), the first name varying
    slowest, as flat arrays."""
    axes = [np.linspace(lo, hi, int(count)) for lo, hi, count in ranges.values()]
    total = math.prod(a.size for a in axes) if axes else 0
    if total > MAX_DESIGNS:
        raise DesignError("vary", total, f"gives more than {MAX_DESIGNS} designs; use fewer points")
    mesh = np.meshgrid(*axes, indexing="ij")
    return {name: m.reshape(-1) for name, m in zip(ranges, mesh)}


def evaluate(spec: Spec, values: dict[str, np.ndarray], rpms,
             masses: MassProperties | None = None) -> Evaluation:
    """Validity, reasons and figures of every design in ``values`` (see :func:`spec_designs`).

    No Python loop runs per design: valid designs go through
    :func:`core.linkage.metrics.cycle_peaks` (and :func:`core.forces.flywheel.cycle_summary`
    with loads) as arrays, in chunks that bound memory.
    """
    rpm = check_rpms(rpms)
    omega = rpm_to_omega(rpm)
    designs, verdict = spec_designs(spec, values)
    size = int(np.prod(designs.shape)) if designs.shape else 1
    designs = designs.flat()
    ok = np.flatnonzero(verdict.ok.reshape(-1))
    good = designs.take(ok)
    sub = cycle_peaks(good)
    peaks = CyclePeaks(**{name: _spread(getattr(sub, name), ok, size)
                          for name in CyclePeaks.__dataclass_fields__})
    figures = {k: v for k, v in speed_figures(peaks, omega).items()}
    dynamics = None
    if masses is not None:
        if designs.rod is None and masses.rod_mass_kg > 0.0:
            raise DesignError("rod_mass_kg", masses.rod_mass_kg,
                              "must be 0 for the block variant, which has no rod")
        if ok.size:
            dyn = cycle_summary(good, omega, masses, intervals=SWEEP_INTERVALS)
            dynamics = {k: _spread(v, ok, size) for k, v in dyn.items()}
        else:
            dynamics = {k: np.full((size, rpm.size), np.nan) for k in
                        ("mean_torque_N_m", "max_torque_N_m", "min_torque_N_m",
                         "energy_fluctuation_J", "flywheel_inertia_kg_m2")}
    return Evaluation(designs=designs, verdict=verdict, rpm=rpm, peaks=peaks, figures=figures,
                      dynamics=dynamics)


def _spread(values: np.ndarray | None, index: np.ndarray, size: int) -> np.ndarray | None:
    if values is None:
        return None
    out = np.full((size,) + np.shape(values)[1:], np.nan)
    out[index] = values
    return out


def spec_changes(values: dict[str, float]) -> dict[str, object]:
    """The :class:`Spec` fields that set the varied core parameters ``values`` (one design),
    as :func:`spec_designs` reads them: e.g. a guide height switches the guide rule to
    ``height``, a rod ratio makes the rod variant with a ratio input."""
    fields = {"crank": "crank", "time_ratio": "time_ratio", "stroke": "stroke",
              "frame": "frame", "lever": "lever"}
    changes: dict[str, object] = {}
    for name, value in values.items():
        value = float(value)
        if name == "guide":
            changes.update(guide_rule="height", guide_height=value)
        elif name == "rod_ratio":
            changes.update(variant="rod", rod_input="ratio", rod_ratio=value)
        elif name == "rod":
            changes.update(variant="rod", rod_input="length", rod_length=value)
        elif name in fields:
            changes[fields[name]] = value
        else:
            raise DesignError("vary", name, "must name one of " + ", ".join(PARAMETERS.values()))
    return changes


def tidy_values(spec: Spec, values: dict[str, float], resolution: dict[str, float],
                bounds: dict[str, tuple[float, float]] | None = None) -> dict[str, float]:
    """``values`` as a person would read and type them: each rounded to a whole multiple of
    the power of ten at or below its ``resolution`` (52.564102564102564 at 0.01 → 52.56),
    rounded inward where it would leave its ``bounds``. Where the nearest multiples make a
    design that is not valid but the exact one is (a value on the edge of validity), the
    multiples on the valid side: K = 1.0019920563889833 beside the lever's 100 000 mm is
    1.001993, not the refused 1.001992 nor all its 17 digits. The exact ``values`` where no
    such rounding is valid; a design invalid either way gets the nearest multiples."""
    near: dict[str, float] = {}
    far: dict[str, float] = {}       # each value's multiple on its other side
    for name, value in values.items():
        value, step = float(value), resolution.get(name, 0.0)
        if not (math.isfinite(value) and math.isfinite(step) and step > 0.0):
            near[name] = far[name] = value
            continue
        step = 10.0 ** math.floor(math.log10(step))
        low, high = (bounds or {}).get(name, (-math.inf, math.inf))
        rounded = round(value / step) * step
        if rounded > high:
            rounded = math.floor(value / step) * step
        elif rounded < low:
            rounded = math.ceil(value / step) * step
        other = rounded - step if rounded > value else rounded + step
        near[name], far[name] = ((float(f"{v:.12g}") if low <= v <= high else value)
                                 for v in (rounded, other))
    exact = {name: float(value) for name, value in values.items()}
    names = list(values)
    for flips in sorted(itertools.product((False, True), repeat=len(names)), key=sum):
        candidate = {n: far[n] if flip else near[n] for n, flip in zip(names, flips)}
        if _valid(spec, candidate):
            return candidate
    return exact if _valid(spec, exact) else near


def _valid(spec: Spec, values: dict[str, float]) -> bool:
    """Whether ``spec`` with ``values`` of its core parameters is a valid design."""
    try:
        replace(spec, **spec_changes(values)).design()
        return True
    except DesignError:
        return False


def design_value(design, name: str) -> float | None:
    """The value of the core parameter ``name`` for one design (None where it has none)."""
    if name == "time_ratio":
        return float(design.time_ratio)
    if name == "rod_ratio":
        return None if design.rod is None else float(design.rod / design.lever)
    value = getattr(design, name)
    return None if value is None else float(value)


def varied_parameters(spec: Spec) -> list[str]:
    """The core parameters a design given as ``spec`` can vary in a sweep."""
    names = ["crank"] + (["time_ratio", "stroke"] if spec.mode == "synthesis" else ["frame", "lever"])
    names.append("guide")
    if spec.variant == "rod":
        names.append("rod_ratio" if spec.rod_input == "ratio" else "rod")
    return names


def default_range(design, name: str) -> tuple[float, float]:
    """A range of ``name`` around ``design`` that mostly holds valid designs."""
    if name == "time_ratio":
        return 1.05, 3.0
    if name == "rod_ratio":
        return 0.2, 1.2
    if name == "rod":
        return 0.2 * design.lever, 1.2 * design.lever
    if name == "guide":
        top = design.lever if design.rod is None else 1.2 * design.lever
        return (design.frame + design.crank) * 1.001, top
    value = design_value(design, name) or 1.0
    return 0.5 * value, 1.5 * value
