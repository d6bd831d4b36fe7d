"""The Explore tab's names of figures and parameters, translated (context "ExploreView",
the tab's own, so the catalogue keeps its entries)."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from core.space.optimize import OBJECTIVES, Optimum, tolerance_text

translate = QCoreApplication.translate   # lupdate extracts translate("Context", "text")


def figure_names() -> dict[str, str]:
    return {"pressure-angle": translate("ExploreView", "Max pressure angle (°)"),
            "accel": translate("ExploreView", "Max |acceleration|, fastest speed (m/s²)"),
            "v-work": translate("ExploreView", "Max cutting speed, fastest speed (m/s)"),
            "v-return": translate("ExploreView", "Max return speed, fastest speed (m/s)"),
            "peak-torque": translate("ExploreView", "Peak crank torque, worst speed (N·m)"),
            "flywheel": translate("ExploreView", "Flywheel J_F, slowest speed (kg·m²)")}


def map_caption(key: str, rpms) -> str:
    """The line over an exported map: the figure's whole name (which speed it takes: the
    colour bar has the short title) and the speeds the map was computed at."""
    return (translate("ExploreView", "%1 — speeds %2 r/min").replace("%1", figure_names()[key])
            .replace("%2", ", ".join(f"{float(r):g}" for r in rpms)))


def figure_titles() -> dict[str, str]:
    """Short titles of the figures, for the colour bar beside the map."""
    return {"pressure-angle": translate("ExploreView", "pressure angle (°)"),
            "accel": translate("ExploreView", "max |a| (m/s²)"),
            "v-work": translate("ExploreView", "cutting speed (m/s)"),
            "v-return": translate("ExploreView", "return speed (m/s)"),
            "peak-torque": translate("ExploreView", "peak torque (N·m)"),
            "flywheel": translate("ExploreView", "J_F (kg·m²)")}


def parameter_names() -> dict[str, str]:
    return {"crank": translate("ExploreView", "Crank L1 (mm)"),
            "time_ratio": translate("ExploreView", "Time ratio K"),
            "stroke": translate("ExploreView", "Stroke H (mm)"),
            "frame": translate("ExploreView", "Frame L2 (mm)"),
            "lever": translate("ExploreView", "Lever L3 (mm)"),
            "guide": translate("ExploreView", "Guide above O4 (mm)"),
            "rod_ratio": translate("ExploreView", "Rod ratio L4/L3"),
            "rod": translate("ExploreView", "Rod L4 (mm)")}


def proposal_text(values: dict[str, float], value: float, best: Optimum, ends: dict[str, str]) -> str:
    """The message for a loaded optimum: a proposal, with the design before, and a red
    line for each parameter whose optimum is an end of its range (``ends``)."""
    unit = OBJECTIVES[best.objective][1]
    start = "—" if best.start_value is None else f"{best.start_value:.5g} {unit}"
    names = parameter_names()
    where = ", ".join(f"{names[n]} = {v:.7g}" for n, v in values.items())
    text = (translate("ExploreView", "Proposal: %1 %2 at %3 (the design before: %4), loaded into the "
                      "form; Undo proposal goes back.").replace("%1", f"{value:.5g}")
            .replace("%2", unit).replace("%3", where).replace("%4", start))
    return text + end_warnings(ends)


def end_warnings(ends: dict[str, str]) -> str:
    """A red line for each parameter whose optimum is an end of its range (``ends``)."""
    names = parameter_names()
    text = ""
    for name, end in ends.items():
        warning = (translate("ExploreView", "%1 is at the lower end of its range: the best design may "
                             "lie below it; widen the range.") if end == "lower" else
                   translate("ExploreView", "%1 is at the upper end of its range: the best design may "
                             "lie above it; widen the range."))
        text += f"<br><span style='color:#b71c1c'>{warning.replace('%1', names[name])}</span>"
    return text


def no_gain_text(best: Optimum, ends: dict[str, str]) -> str:
    """Why Optimize loads nothing: the objective does not depend on the free parameters
    (``best.insensitive``), or the best found does not beat the design before by more
    than the objective's tolerance (core.space.optimize.GAIN_TOLERANCE); then the red lines of
    the parameters whose best is an end of its range (``ends``: none the objective
    ignores), where a better design may lie beyond."""
    unit = OBJECTIVES[best.objective][1]
    names = parameter_names()
    share = tolerance_text()
    parts = []
    if best.insensitive:
        parts.append(translate("ExploreView", "The objective, %1, does not depend on %2: it changes by less "
                               "than %3 of its value over the range.")
                     .replace("%1", figure_titles()[best.objective])
                     .replace("%2", ", ".join(names[n] for n in best.insensitive)).replace("%3", share))
    if set(best.insensitive) != set(best.names):
        parts.append(translate("ExploreView", "The best design found, %1 %2, is not better than the design "
                               "before, %3 %2, by more than %4 of its value.")
                     .replace("%1", f"{best.value:.5g}").replace("%2", unit)
                     .replace("%3", f"{best.start_value:.5g}").replace("%4", share))
    head = translate("ExploreView", "No better design within these bounds; the design is kept.")
    return "<br>".join([head] + parts) + end_warnings(
        {n: e for n, e in ends.items() if n not in best.insensitive})
