"""Find the best design within bounds: the smallest pressure angle, acceleration, peak
torque or flywheel.

Beside ``sweep``, on which it is built. The search is global and bounded:
a dense vectorized sweep of the box, then scipy's differential evolution
(vectorized, seeded with the sweep's best point), then a bounded Nelder–Mead
polish. The result is the best design any stage found, so it is never worse
than the best point of the sweep. Invalid designs count as infinitely bad.

A result is a proposal only when it beats the design as given by more than
``GAIN_TOLERANCE`` of its objective (:func:`improves`): below that the gain is
round-off or the sweep's noise, and a changed design would be a change for nothing.
The dense sweep also tells which varied parameters the objective does not depend on
(``Optimum.insensitive``), so "no better design" can say why.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from core.forces.masses import MassProperties
from core.base.errors import DesignError
from core.linkage.spec import Spec
from .names import OBJECTIVES
from .sweep import Evaluation, evaluate, tidy_values

DENSE_POINTS = {False: 4096, True: 256}   # points of the first dense sweep (metrics / loads)
PENALTY = 1e30
GAIN_TOLERANCE = 1e-6
"""The objective's tolerance, relative: a design is better than another only when its
objective is lower by more than this share of the other's. It is the share within which
:func:`tidy_optimum` accepts a rounded design, and far above the objectives' round-off
(≈ 1e-13 relative: max |a| at L1 = 50 and 50.68 with K and H fixed differ by 5e-14)."""


@dataclass(frozen=True)
class Optimum:
    """The best design found and how good it is."""

    objective: str
    names: tuple[str, ...]             # varied core parameters
    x: np.ndarray                      # their optimal values
    value: float                       # objective at x (unit of OBJECTIVES)
    start_value: float | None          # objective of the design as given; None if it is invalid
    evaluations: int                   # designs evaluated
    evaluation: Evaluation             # the optimal design's figures (one design)
    insensitive: tuple[str, ...] = ()  # varied names the objective does not depend on here

    @property
    def improves(self) -> bool:
        """Is the optimum better than the design as given (see :func:`improves`)?"""
        return improves(self.value, self.start_value)


def improves(value: float, start: float | None) -> bool:
    """Whether an objective ``value`` beats the design as given (``start``, None when that
    design is invalid) by more than ``GAIN_TOLERANCE`` of it."""
    if start is None:
        return math.isfinite(value)
    return value < start - GAIN_TOLERANCE * abs(start)


def insensitive(dense: np.ndarray, shape: tuple[int, ...], names: tuple[str, ...]) -> tuple[str, ...]:
    """The varied parameters along which the dense sweep's objective (``dense``, on the
    "ij" grid of ``shape``) never changes by more than ``GAIN_TOLERANCE`` of its largest
    valid value, on any grid line with two valid points or more: the objective does not
    depend on them within the bounds (e.g. max |a| on L1 alone with K and H fixed)."""
    grid = np.where(np.isfinite(dense), dense, np.nan).reshape(shape)
    if not np.isfinite(grid).any():
        return ()
    scale = GAIN_TOLERANCE * float(np.nanmax(np.abs(grid)))
    out = []
    for axis, name in enumerate(names):
        counts = np.sum(np.isfinite(grid), axis=axis)
        if shape[axis] < 2 or not np.any(counts >= 2):
            continue
        with np.errstate(invalid="ignore"):
            high = np.fmax.reduce(grid, axis=axis)
            low = np.fmin.reduce(grid, axis=axis)
        if np.all(np.where(counts >= 2, high - low, 0.0) <= scale):
            out.append(name)
    return tuple(out)


def objective_of(evaluation: Evaluation, objective: str) -> np.ndarray:
    """The objective of every design in ``evaluation`` (inf where a design is invalid)."""
    if objective == "pressure-angle":
        if evaluation.peaks.pressure_max is None:
            raise DesignError("objective", objective, "needs the rod variant (give --rod or --rod-ratio)")
        value = np.degrees(evaluation.peaks.pressure_max)
    elif objective == "accel":
        value = np.max(evaluation.figures["a_max_m_s2"], axis=-1)
    elif objective in ("peak-torque", "flywheel"):
        if evaluation.dynamics is None:
            raise DesignError("objective", objective, "needs the loads (masses and cutting force)")
        key = "max_torque_N_m" if objective == "peak-torque" else "flywheel_inertia_kg_m2"
        value = np.max(evaluation.dynamics[key], axis=-1)
    else:
        raise DesignError("objective", objective, "must be one of " + ", ".join(OBJECTIVES))
    return np.where(evaluation.valid.reshape(-1) & np.isfinite(value), value, np.inf)


class Cancelled(Exception):
    """``should_stop`` asked the search to stop."""


def optimize(spec: Spec, bounds: dict[str, tuple[float, float]], objective: str, rpms,
             masses: MassProperties | None = None, seed: int = 1,
             should_stop: Callable[[], bool] | None = None) -> Optimum:
    """Minimize ``objective`` over the varied core parameters within ``bounds`` (low, high).

    ``should_stop`` is asked before every batch of evaluations; when it returns
    true the search raises :class:`Cancelled` (a GUI's Cancel button).
    """
    if objective not in OBJECTIVES:
        raise DesignError("objective", objective, "must be one of " + ", ".join(OBJECTIVES))
    if OBJECTIVES[objective][2] and masses is None:
        raise DesignError("objective", objective, "needs the loads (masses and cutting force)")
    use = masses if OBJECTIVES[objective][2] else None
    names = tuple(bounds)
    low = np.array([bounds[n][0] for n in names], dtype=float)
    high = np.array([bounds[n][1] for n in names], dtype=float)
    count = [0]

    def values(x: np.ndarray) -> np.ndarray:               # x: (dims, population)
        if should_stop is not None and should_stop():
            raise Cancelled()
        x = np.atleast_2d(np.asarray(x, dtype=float).T).T if np.ndim(x) == 1 else x
        count[0] += x.shape[1]
        ev = evaluate(spec, {n: x[i] for i, n in enumerate(names)}, rpms, use)
        return objective_of(ev, objective)

    start = objective_of(evaluate(spec, {}, rpms, use), objective)[0]
    # 1. A dense sweep of the box.
    per_axis = max(2, int(round(DENSE_POINTS[use is not None] ** (1.0 / len(names)))))
    axes = [np.linspace(lo, hi, per_axis) for lo, hi in zip(low, high)]
    points = np.stack([m.reshape(-1) for m in np.meshgrid(*axes, indexing="ij")])
    dense = values(points)
    best_i = int(np.argmin(dense))
    best_x, best = points[:, best_i], float(dense[best_i])
    if len(names) and np.any(high > low):
        best_x, best = _refine(values, low, high, best_x, best, seed)
    final = evaluate(spec, {n: np.array([best_x[i]]) for i, n in enumerate(names)}, rpms, masses)
    flat = insensitive(dense, tuple(a.size for a in axes), names)
    return Optimum(objective=objective, names=names, x=best_x, value=best,
                   start_value=float(start) if math.isfinite(start) else None,
                   evaluations=count[0], evaluation=final, insensitive=flat)


def _refine(values, low, high, best_x, best, seed):
    """Differential evolution seeded with the sweep's best, then a Nelder–Mead polish."""
    from scipy.optimize import differential_evolution, minimize

    free = high > low
    if not math.isfinite(best):
        return best_x, best

    def penalized(x):
        full = np.repeat(best_x[:, None], np.shape(x)[-1] if np.ndim(x) > 1 else 1, axis=1)
        full[free] = np.reshape(x, (int(free.sum()), -1))
        out = values(full)
        return np.where(np.isfinite(out), out, PENALTY)

    box = list(zip(low[free], high[free]))
    # SciPy scales x0 into [0, 1] about the box's middle, and one rounding step can put a
    # start on an end of the box outside it ("x0 lay outside the specified bounds", a
    # ValueError): the start is drawn a relative 1e-12 of the way toward the middle.
    middle = 0.5 * (low[free] + high[free])
    x0 = middle + (best_x[free] - middle) * (1.0 - 1e-12)
    result = differential_evolution(penalized, box, x0=x0, seed=seed, maxiter=40,
                                    popsize=8, tol=1e-8, polish=False, vectorized=True,
                                    updating="deferred")
    candidates = [(best, best_x[free])]
    if result.fun < PENALTY:
        # Differential evolution maps [0, 1] onto the box and can land one rounding step
        # past an end: outside the user's bounds, and a start Nelder–Mead warns about.
        candidates.append((float(result.fun), np.clip(result.x, low[free], high[free])))
    start = min(candidates, key=lambda c: c[0])[1]
    local = minimize(lambda x: float(penalized(x)[0]), start, method="Nelder-Mead",
                     bounds=box, options={"xatol": 1e-9 * float(np.max(high - low)), "fatol": 1e-12,
                                          "maxiter": 400})
    if local.fun < PENALTY:
        candidates.append((float(local.fun), np.clip(local.x, low[free], high[free])))
    value, x = min(candidates, key=lambda c: c[0])
    out = best_x.copy()
    out[free] = x
    return out, value


def tidy_optimum(spec: Spec, best: Optimum, bounds: dict[str, tuple[float, float]], rpms,
                 masses: MassProperties | None = None) -> tuple[dict[str, float], float]:
    """The optimum as a person would type it, with its objective: each value rounded to a
    millionth of its range, inside the bounds (142.06349206349205 → 142.0635 in 100 mm), or
    where that design is worse by more than 1e-6 of the value (a minimax objective rises
    steeply from its optimum), to a hundred-millionth; else the exact optimum. A rounded
    design that is invalid is never returned, nor one whose rounding loses an optimum's
    gain over the design as given (:func:`improves`)."""
    exact = dict(zip(best.names, (float(v) for v in best.x)))
    use = masses if OBJECTIVES[best.objective][2] else None
    for share in (1e-6, 1e-8):
        resolution = {n: share * (bounds[n][1] - bounds[n][0]) for n in best.names}
        tidy = tidy_values(spec, exact, resolution, bounds)
        if tidy == exact:
            break
        value = float(objective_of(evaluate(spec, {n: np.array([v]) for n, v in tidy.items()},
                                            rpms, use), best.objective)[0])
        keeps_gain = improves(value, best.start_value) or not best.improves
        if math.isfinite(value) and value <= best.value + GAIN_TOLERANCE * abs(best.value) \
                and keeps_gain:
            return tidy, value
    return exact, best.value


def tolerance_text() -> str:
    """GAIN_TOLERANCE as a person writes it: "1e-6", not Python's "1e-06"."""
    mantissa, exponent = f"{GAIN_TOLERANCE:.0e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def no_gain_text(best: Optimum, unit_names: dict[str, str] | None = None) -> str:
    """Why the optimum is no proposal (English, for the CLI; the GUI has its own
    translated text): the objective does not depend on the varied parameters, or the
    best found is not better than the design as given by more than GAIN_TOLERANCE."""
    names = unit_names or {}
    unit = OBJECTIVES[best.objective][1]
    text = "no better design within these bounds: "
    if best.insensitive:
        flat = ", ".join(names.get(n, n) for n in best.insensitive)
        text += (f"{best.objective} does not depend on {flat} (it changes by less than "
                 f"{tolerance_text()} of its value over the range)")
        if set(best.insensitive) == set(best.names):
            return text
        text += "; "
    return text + (f"the best found, {best.value:.6g} {unit}, is not lower than the design's own "
                   f"{best.start_value:.6g} {unit} by more than {tolerance_text()} of it")


def on_bounds(best: Optimum, bounds: dict[str, tuple[float, float]],
              share: float = 1e-4) -> dict[str, str]:
    """The varied parameters whose optimum lies on an end of its range (within ``share``
    of the range): name → "lower" or "upper". There the objective still falls toward the
    bound, so the best design may lie beyond it: the user should hear of it."""
    ends: dict[str, str] = {}
    for name, value in zip(best.names, (float(v) for v in best.x)):
        lo, hi = bounds[name]
        tolerance = share * (hi - lo)
        if value <= lo + tolerance:
            ends[name] = "lower"
        elif value >= hi - tolerance:
            ends[name] = "upper"
    return ends
