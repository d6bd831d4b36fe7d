"""Which sheet to build, from the user's choices: shared by ``shaper drawing`` and the dialog."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

from core.drawing.motion import motion_sheet
from core.drawing.sheet import Sheet, TitleBlock, paper
from core.dynamics import MassProperties
from core.spec import Spec

from shaperapp.widgets.command_line import inputs_name

from .labels import motion_labels

CONTENTS = ("motion", "forces")
SHEET_NUMBER = {"motion": "1/2", "forces": "2/2"}     # the course design's two sheets
SHEET_SUFFIXES = (".pdf", ".svg", ".dxf")


class ContentUnavailable(ValueError):
    """A content this build cannot draw yet (the message says which)."""


@dataclass(frozen=True)
class SheetChoice:
    content: str = "motion"
    paper: str = "A1"
    count: int = 12
    diagram_deg: tuple[float, float] | None = None
    design_name: str = ""
    drawn: str = ""
    date: str = ""
    school: str = ""


def build_sheet(spec: Spec, rpms: Sequence[float], masses: MassProperties | None,
                choice: SheetChoice) -> Sheet:
    """The sheet in the current language (Qt's translator must be installed).
    ContentUnavailable for a content without a builder in BUILDERS."""
    builder = BUILDERS.get(choice.content)
    if builder is None:
        raise ContentUnavailable(f"the {choice.content} sheet is not available in this version")
    return builder(spec, rpms, masses, choice)


def motion(spec: Spec, rpms: Sequence[float], masses: MassProperties | None,
           choice: SheetChoice) -> Sheet:
    """The motion sheet at the first speed."""
    design = spec.design()
    idle = masses.idle_fraction if masses is not None else MassProperties().idle_fraction
    labels = motion_labels()
    block = TitleBlock(labels["title"], choice.design_name or inputs_name(spec), "",
                       SHEET_NUMBER[choice.content],
                       choice.drawn, choice.date, choice.school)
    return motion_sheet(design, float(rpms[0]), paper(choice.paper), count=choice.count,
                        diagram_deg=choice.diagram_deg, idle_fraction=idle, labels=labels,
                        block=block).sheet


# content → its builder (spec, speeds, loads or None, choice) → Sheet; the forces sheet joins here
BUILDERS: dict[str, Callable[[Spec, Sequence[float], MassProperties | None, SheetChoice], Sheet]] = {
    "motion": motion,
}
