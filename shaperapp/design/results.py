"""What the model computes from the inputs: the design, its motion, metrics and forces.

Pure functions (no Qt): the model calls them and keeps the last valid results. Core
computations can fail in ways other than DesignError on extreme input; the GUI reports
those as "cannot be computed" and keeps the last valid design.
"""
from __future__ import annotations

from collections.abc import Callable

import numpy as np

from core.forces.dynamics import ENERGY_INTERVALS, Dynamics, DynamicsSummary, SpeedSummary, solve_dynamics
from core.forces.masses import MassProperties, masses_for_design
from core.base.errors import DesignError
from core.linkage.geometry import Design
from core.linkage.kinematics import Motion, check_file_samples, check_rpms, crank_angles, rpm_to_omega, solve
from core.linkage.metrics import CycleMetrics, analyze

from .inputs import Inputs

COMPUTE_ERRORS = (ArithmeticError, ValueError, RuntimeError, MemoryError)


def compute_motion(inputs: Inputs) -> tuple[Design, Motion, CycleMetrics]:
    """Design, motion and metrics of ``inputs``; DesignError names the bad input."""
    design = inputs.spec.design()
    rpms = tuple(float(v) for v in check_rpms(list(inputs.rpms)))
    if not isinstance(inputs.step, (int, float)) or isinstance(inputs.step, bool):
        raise DesignError("step", inputs.step, "must be a number")
    step = float(inputs.step)
    check_file_samples(step, len(rpms))     # a design file's limit: what is shown can be saved
    angles = crank_angles(step)
    return design, solve(design, angles, rpms), analyze(design, rpms)


def summarize(design: Design, rpm, masses: MassProperties, peaks: bool = True) -> DynamicsSummary:
    """``core.forces.flywheel.summarize``, imported when first called: the first screen shows
    no summary (the forces table is below the Results pane's fold), and the flywheel's
    solver and peak search cost every start their imports (issue 43 item 5)."""
    from core.forces.flywheel import summarize as solve_summary
    return solve_summary(design, rpm, masses, peaks=peaks)


class SummaryOnDemand:
    """The cycle summary (mean and peak torque, energy, flywheel) of the forces on
    screen, solved the first time something asks for it, then kept.

    It is the largest part of an edit's computation, the exact torque peaks most of
    it, and most edits show no view of it: the forces table sits below the fold of the
    Results pane and the Forces tab is usually behind; the Forces tab's plots need the
    energy and the means but not the peaks (``peaks=False``). Its inputs are those of
    the forces solved with it, so a late answer is never another design's.
    """

    def __init__(self, design: Design, rpm, masses: MassProperties) -> None:
        self.design, self.rpm, self.masses = design, rpm, masses
        self._full: DynamicsSummary | None = None
        self._cycle: DynamicsSummary | None = None

    def get(self, peaks: bool = True) -> DynamicsSummary:
        """The summary (``peaks=False``: max/min torque and peak power NaN); raises what
        summarize raises, once (then the undefined one)."""
        if self._full is not None:
            return self._full
        if not peaks and self._cycle is not None:
            return self._cycle
        try:
            value = summarize(self.design, self.rpm, self.masses, peaks=peaks)
        except (DesignError, *COMPUTE_ERRORS):
            self._full = self.undefined()
            raise
        if peaks:
            self._full = value
        else:
            self._cycle = value
        return value

    def solved(self) -> bool:
        return self._full is not None or self._cycle is not None

    def undefined(self) -> DynamicsSummary:
        """Every value NaN (shown as such), for a summary that cannot be computed."""
        phi = np.linspace(0.0, 2.0 * np.pi, ENERGY_INTERVALS + 1)
        nan = float("nan")
        speeds = tuple(SpeedSummary(float(r), float(w), *([nan] * 8), flywheel_needed=False,
                                    flywheel_inertia_net_kg_m2=nan)
                       for r, w in zip(self.rpm, rpm_to_omega(np.asarray(self.rpm, dtype=float))))
        return DynamicsSummary(masses=self.masses, crank_angle=phi,
                               energy=np.full((len(speeds), phi.size), nan),
                               equivalent_inertia=np.full(phi.size, nan),
                               equivalent_inertia_mean_kg_m2=nan, rotor_inertia_kg_m2=nan,
                               speeds=speeds)


def solve_forces(design: Design, motion: Motion,
                 masses: MassProperties) -> tuple[Dynamics, SummaryOnDemand]:
    used = masses_for_design(design, masses)
    return (solve_dynamics(design, motion.crank_angle, motion.rpm, used),
            SummaryOnDemand(design, motion.rpm, used))


def compute(inputs: Inputs, masses: MassProperties):
    """Everything at once: (design, motion, metrics, dynamics, summary)."""
    design, motion, metrics = compute_motion(inputs)
    return (design, motion, metrics) + solve_forces(design, motion, masses)


def compute_whole(inputs: Inputs, masses: MassProperties, check: Callable[[], None]):
    """``compute``, all or nothing (the cycle summary too), after ``check`` (the fields, the
    file's parts): a whole state put in at once. Any failure is raised as a DesignError."""
    try:
        check()
        results = compute(inputs, masses)
        results[-1].get()
    except DesignError:
        raise
    except COMPUTE_ERRORS as exc:
        raise compute_error(exc) from None
    return results


def compute_error(exc: BaseException) -> DesignError:
    return DesignError("design", type(exc).__name__, "cannot be computed for these inputs")


def as_design_error(exc: BaseException) -> DesignError:
    """A DesignError as it is, any other failure of a computation as "cannot be computed"."""
    return exc if isinstance(exc, DesignError) else compute_error(exc)
