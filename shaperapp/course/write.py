"""Paint and write the files of a checked course design (``core.course_design.plan``), one by one.

Shared by ``shaper course`` and File › Export course design…, so both write the same
files. Each file is written atomically (``core.files.atomic``): at any moment every file in
the folder is a complete old or a complete new one. A sheet is built once for its PDF
and its DXF.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Callable, Iterator

import numpy as np

from core.cam.file import cam_from_dict
from core.course_design.plan import REPORT, Course, CourseFile, make_folder
from core.gear.file import gear_from_dict
from core.course_design.positions import DEFAULT_COUNT
from core.base.progress import Progress

from shaperapp.drawing.content import SheetChoice, build_sheet
from shaperapp.drawing.render import write_sheet
from shaperapp.report.blocks import Cover
from shaperapp.report.command import write_report
from shaperapp.report.content import BUILD_SHARE, Options, build


@dataclass(frozen=True)
class Covering:
    """What the user adds to every file: the paper of the sheets, the design's name, the
    date, the cover fields (student, number, group, school, supervisor) and which of the
    design's speeds the sheets are drawn at (0: the first; the report shows them all)."""

    paper: str = "A1"
    title: str = ""
    date: str = ""
    cover: dict[str, str] = field(default_factory=dict)
    cad_font: str = "gb"              # how the DXFs write their texts (core.drawing.CAD_FONTS)
    speed: int = 0


# How long each file takes, about, relative to a sheet's PDF (``shaper course`` of a design
# of 16 speeds with --dxf: the report 8 s, a sheet's PDF ~1 s, its DXF ~0.7 s): the share of
# the progress each file stands for.
WEIGHTS = {"report": 8.0, "pdf": 1.0, "dxf": 0.7}


def file_shares(files: tuple[CourseFile, ...]) -> list[tuple[float, float]]:
    """Each file's slice (start, end) of the whole run's progress, by :data:`WEIGHTS`."""
    weights = [WEIGHTS["report"] if f.part.content == REPORT else WEIGHTS[f.path.rsplit(".", 1)[-1]]
               for f in files]
    edges = np.concatenate(([0.0], np.cumsum(weights))) / max(sum(weights), 1e-9)
    return [(float(a), float(b)) for a, b in zip(edges[:-1], edges[1:])]


def write_course(course: Course, language: str, covering: Covering,
                 progress: Progress = Progress()) -> Iterator[CourseFile]:
    """Write the files in order, yielding each one once it is complete. The folder is made
    first if it is not there. OSError (a WriteError naming the file) stops the run; the
    files already yielded stay complete. ``progress`` hears of every file and of the
    report's sections and pages; when it says stop (at the start of a file, or within the
    report) the run ends with Cancelled and the file being made is not written."""
    make_folder(course.folder)
    sheets: dict[str, object] = {}
    for file, (start, end) in zip(course.files, file_shares(course.files)):
        part, share = file.part, progress.part(start, end)
        share.done(0.0)
        if part.content == REPORT:
            write_report(_report(course, language, covering, share.part(0.0, BUILD_SHARE)), file.path,
                         share.part(BUILD_SHARE, 1.0))
        else:
            if part.stem not in sheets:
                sheets[part.stem] = _sheet(course, part, covering)
            write_sheet(sheets[part.stem], file.path, language, covering.title, covering.cad_font)
        share.note(1.0)
        yield file


def write_course_of(progress: Progress, file_done: Callable[[str], None], course: Course, language: str,
                    covering: Covering) -> None:
    """:func:`write_course`, telling ``file_done`` of each file once it is complete: the job
    of the export's child process (``widgets.export_child``)."""
    for file in write_course(course, language, covering, progress):
        file_done(file.path)


def _report(course: Course, language: str, covering: Covering, progress: Progress = Progress()):
    cam, gear = course.document.get("cam"), course.document.get("gear")
    options = Options(DEFAULT_COUNT, None, (), Cover(**covering.cover),
                      cam_from_dict(cam) if cam is not None else None,
                      gear_from_dict(gear) if gear is not None else None)
    return build(course.spec, list(course.rpms), course.masses, covering.title, covering.date,
                 language, options, progress)


def _sheet(course: Course, part, covering: Covering):
    cover = covering.cover
    choice = SheetChoice(part.content, covering.paper, DEFAULT_COUNT, None, covering.title,
                         cover.get("student", ""), covering.date, cover.get("school", ""),
                         number=cover.get("number", ""), group=cover.get("group", ""),
                         supervisor=cover.get("supervisor", ""), speed=covering.speed)
    if part.drawn:
        choice = replace(choice, **{part.drawn: course.drawn[part.drawn]})
    return build_sheet(course.spec, course.rpms, course.masses, choice)
