"""The report's feed-cam section: the figures ``shaper cam`` prints, under translated
labels and with their value texts translated (a Chinese report has no English), the
cam at a stated round scale, and the follower's ψ, ω, α and the pressure angle against
the cam angle as the Cam tab plots them (the cam sheet's curves)."""
from __future__ import annotations

import re
from typing import Callable

from PySide6.QtCore import QCoreApplication

from core.cam import CamInputs, design_cam
from core.cam.table import cam_summary, follower_peaks
from core.cli.cmd_cam import summary_rows as cam_rows
from core.base.errors import DesignError
from core.linkage.geometry import Design
from shaperapp.widgets.messages import describe

from . import figures
from .blocks import Figure, Heading, KeyValues, Paragraph

translate = QCoreApplication.translate   # lupdate extracts translate("Report", "…")

# The English words inside ``shaper cam``'s value texts, as patterns of their numbers.
_VALUE_WORDS = (
    (re.compile(r"\(allowed (\S+)° / (\S+)°\)"), lambda: translate("Report", "(allowed %1° / %2°)")),
    (re.compile(r"\(largest (\S+) mm\)"), lambda: translate("Report", "(largest %1 mm)")),
    (re.compile(r"\(cut ends at (\S+)°, the next starts (\S+)° later\)"),
     lambda: translate("Report", "(cut ends at %1°, the next starts %2° later)")),
    (re.compile(r"^EXCEEDED$"), lambda: translate("Report", "exceeded")),
    (re.compile(r"\(at least hub \+ clearance = (\S+) mm\)"),
     lambda: translate("Report", "(at least hub + clearance = %1 mm)")),
    (re.compile(r"\(at most a − boss − clearance = (\S+) mm\)"),
     lambda: translate("Report", "(at most a − boss − clearance = %1 mm)")),
    (re.compile(r"^base radius raised from (\S+) mm to take the roller and clear the hub and the pivot boss$"),
     lambda: translate("Report", "base radius raised from %1 mm to take the roller and clear the hub and the "
                                 "pivot boss")),
)


def value_text(text: str) -> str:
    """A ``shaper cam`` value with its words in the report's language, numbers unchanged."""
    for pattern, template in _VALUE_WORDS:
        def one(m: re.Match, template=template) -> str:
            out = template()
            for k, number in enumerate(m.groups(), 1):
                out = out.replace(f"%{k}", number)
            return out
        text = pattern.sub(one, text)
    return text


def _labels(rpm: float) -> dict[str, str]:
    return {
        "base radius r0 (pitch curve)": translate("Report", "Base radius r0 of the pitch curve"),
        "centre distance a": translate("Report", "Centre distance a"),
        "arm l": translate("Report", "Follower arm l"),
        "initial arm angle ψ0": translate("Report", "Initial arm angle ψ0"),
        "max pressure angle rise / return": translate("Report", "Max pressure angle, rise / return"),
        "min convex radius ρmin (pitch curve)": translate("Report", "Smallest convex radius ρmin of the pitch curve"),
        "roller r": translate("Report", "Roller radius r"),
        "profile base radius r0 − r": translate("Report", "Base radius of the profile r0 − r"),
        "profile's largest radius R1 − r": translate("Report", "Largest radius of the profile R1 − r"),
        "note": translate("Report", "Note"),
        f"follower max ω / α at {rpm:g} r/min":
            translate("Report", "Follower's largest ω / α at %1 r/min").replace("%1", f"{rpm:g}"),
        "allowance": translate("Report", "Pressure angle allowance"),
        "rise starts at crank angle": translate("Report", "Rise starts at crank angle")}


def cam_blocks(cam_inputs: tuple[CamInputs, float | None], design: Design, idle: float,
               rpm: float, number: int, views: figures.ReportViews,
               step: Callable[[], None] = lambda: None) -> list:
    """The feed cam: its figures as ``shaper cam`` prints them, the cam to scale and the
    follower's curves; ``step()`` after each of its three parts (the report's progress)."""
    blocks: list = [Heading(translate("Report", "%1 The feed cam").replace("%1", str(number)))]
    inputs, phase = cam_inputs
    try:
        cam = design_cam(inputs, design, idle, phase)
    except DesignError as exc:
        blocks.append(Paragraph(translate("Report", "The feed cam cannot be made for this design: %1")
                                .replace("%1", describe(exc))))      # in the report's language
        return blocks
    step()
    summary = cam_summary(cam)
    summary.update(follower_peaks(cam, rpm))
    labels = _labels(rpm)
    blocks.append(KeyValues([(labels[key], value_text(value)) for key, value in cam_rows(summary)
                             if key in labels]))
    blocks.append(Figure(translate("Report", "The feed cam at the start of the rise, with its "
                                   "follower and roller (the cam turns clockwise)"), 170.0, 100.0,
                         figures.cam_paint(cam)))
    step()
    blocks.append(Figure(translate("Report", "The follower's angle ψ, angular velocity ω and "
                                   "acceleration α (one curve per crank speed, in the colours of the "
                                   "ram's curves in section 4) and the pressure angle against the cam "
                                   "angle δ; dashed: the allowed pressure angles"),
                         170.0, 113.0, views.cam_curves(inputs, phase)))
    step()
    return blocks
