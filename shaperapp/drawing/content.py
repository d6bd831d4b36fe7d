"""Which sheet to build, from the user's choices: shared by ``shaper drawing`` and the dialog."""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, Sequence

from core.drawing.paper import paper

from shaperapp.widgets.command_line import inputs_name

from .labels import motion_labels

if TYPE_CHECKING:
    from core.cam import Cam
    from core.drawing.sheet import Sheet
    from core.drawing.title_block import TitleBlock
    from core.forces.masses import MassProperties
    from core.gear import GearPair
    from core.linkage.spec import Spec

# The sheets' modules (numpy, the engine) are imported by the builders: ``shaper drawing
# --help`` prints the contents' names only (issue 43 item 5).

CONTENTS = ("motion", "forces", "cam", "gear")
SHEET_NUMBER = {"motion": "1/4", "forces": "2/4", "cam": "3/4", "gear": "4/4"}   # the course design's sheets
ALONE = "1/1"       # a sheet printed on its own, outside the course design's set (the Gear tab's, shaper gear's)
DEFAULT_PAPER = {"gear": "A2"}      # the meshing drawing's usual paper; the others A1
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
    cam: "Cam | None" = None        # the cam sheet's cam (the Cam tab's, or the options')
    number: str = ""                # the student's number
    group: str = ""                 # the class
    supervisor: str = ""
    gear: "GearPair | None" = None  # the meshing sheet's pair (shaper gear's options)
    speed: int = 0                  # which of the design's speeds the sheet is drawn at (0: the first)
    sheet_number: str = ""          # "n/m" of the title block; "": the course design's (SHEET_NUMBER)

    def title_block(self, title: str, design_name: str, rpm: float | None = None) -> TitleBlock:
        """The title block's fields of this choice (its scale is the sheet's to fill in), with
        the crank speed ``rpm`` the sheet is drawn at (None for a sheet of no speed)."""
        from core.drawing.title_block import TitleBlock
        return TitleBlock(title, design_name, "", self.sheet_number or SHEET_NUMBER[self.content], self.drawn, self.date,
                          self.school, number=self.number, group=self.group,
                          supervisor=self.supervisor, speed="" if rpm is None else speed_text(rpm))


def speed_text(rpm: float) -> str:
    """The title block's speed, in the sheets' index notation: "n_2 = 60 r/min"."""
    from core.drawing.sheet import number_text
    return f"n_2 = {number_text(rpm)} r/min"


def sheet_rpm(rpms: Sequence[float], choice: SheetChoice) -> float:
    """The speed the sheet is drawn at: the choice's of the design's speeds."""
    return float(rpms[choice.speed])


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
    """The motion sheet at the choice's speed."""
    from core.drawing.motion import motion_sheet
    from core.forces.masses import MassProperties
    design = spec.design()
    idle = masses.idle_fraction if masses is not None else MassProperties().idle_fraction
    labels = motion_labels()
    rpm = sheet_rpm(rpms, choice)
    block = choice.title_block(labels["title"], choice.design_name or inputs_name(spec), rpm)
    return motion_sheet(design, rpm, paper(choice.paper), count=choice.count,
                        diagram_deg=choice.diagram_deg, idle_fraction=idle, labels=labels,
                        block=block).sheet


def forces(spec: Spec, rpms: Sequence[float], masses: MassProperties | None,
           choice: SheetChoice) -> Sheet:
    """The kinetostatic sheet at the choice's speed; the loads are needed (UsageError naming
    the cutting force without them: only the command line can leave them out)."""
    from core.drawing.forces import forces_sheet
    from core.forces.masses import masses_for_design
    from core.cli.common import UsageError
    from .forces_labels import forces_labels
    if masses is None:
        raise UsageError("--cut-force: the forces sheet needs the loads: give the masses and the "
                         "cutting force, or a design file with loads")
    design = spec.design()
    labels = forces_labels()
    rpm = sheet_rpm(rpms, choice)
    block = choice.title_block(labels["title"], choice.design_name or inputs_name(spec), rpm)
    return forces_sheet(design, rpm, masses_for_design(design, masses), paper(choice.paper),
                        diagram_deg=choice.diagram_deg, labels=labels, block=block).sheet


def cam(spec: Spec, rpms: Sequence[float], masses: MassProperties | None,
        choice: SheetChoice) -> Sheet:
    """The feed cam's sheet at the choice's speed (the cam turns with the crank);
    ContentUnavailable without a cam in the choice."""
    from core.drawing.cam_sheet import cam_sheet
    from .cam_labels import cam_labels
    if choice.cam is None:
        raise ContentUnavailable("the cam sheet needs a cam")
    labels = cam_labels()
    rpm = sheet_rpm(rpms, choice)
    block = choice.title_block(labels["title"], choice.design_name or inputs_name(spec), rpm)
    return cam_sheet(choice.cam, rpm, paper(choice.paper), labels=labels, block=block).sheet


def gear(spec: Spec | None, rpms: Sequence[float], masses: MassProperties | None,
         choice: SheetChoice) -> Sheet:
    """The gear pair's meshing sheet (the linkage is not needed); ContentUnavailable without
    a pair in the choice."""
    from core.drawing.gear_sheet import gear_sheet
    from .gear_labels import gear_labels
    if choice.gear is None:
        raise ContentUnavailable("the gear sheet needs a gear pair")
    labels = gear_labels()
    block = choice.title_block(labels["title"], choice.design_name or gear_name(choice.gear))
    return gear_sheet(choice.gear, paper(choice.paper), labels=labels, block=block).sheet


def gear_name(pair: "GearPair") -> str:
    """The pair's inputs as a design name: z1/z2, m."""
    return f"z {pair.inputs.z1}/{pair.inputs.z2}, m {pair.inputs.module_mm:g}"


# content → its builder (spec, speeds, loads or None, choice) → Sheet; the forces sheet joins here
BUILDERS: dict[str, Callable[[Spec, Sequence[float], MassProperties | None, SheetChoice], Sheet]] = {
    "motion": motion,
    "forces": forces,
    "cam": cam,
    "gear": gear,
}
