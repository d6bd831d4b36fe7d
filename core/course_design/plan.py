"""The course design from one design file: which files, in which order, named how, and
what of the design file each one needs (issue 35, item 6).

``shaper course`` and the GUI's File › Export course design… write the report and the
drawing sheets of one design into one folder. Everything that can refuse the job is
checked here, headless, BEFORE the first file is written: the parts of the design file
each file needs, the feed cam it designs, the folder and the names in it. So a refusal
writes nothing; the files themselves are painted and written by ``shaperapp.course``.

:data:`PARTS` is the one list of the files: a new sheet (the gear pair's) joins it by
one entry naming its drawing content, its file name, the design-file keys it needs and,
for a sheet that draws an object of the design file, how that object is read.
"""
from __future__ import annotations

import json
import os
import stat
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Collection, Mapping

from core.files.atomic import replace_refusal
from core.base.errors import DesignError, WriteError, os_reason

REPORT = "report"          # the content of the report (the other contents are drawing sheets)

# A design-file key → what it holds, in the words of the refusal.
KEY_NAMES = {"spec": "the linkage", "rpm": "the speeds", "forces": "the loads",
             "cam": "the feed cam", "gear": "the gear pair"}


def _designed_cam(data: Any, design, idle_fraction: float):
    """The file's cam synthesized and timed against the linkage, as the cam sheet draws it
    (DesignError naming a key of the cam)."""
    from core.cam import design_cam
    from core.cam.file import cam_from_dict
    inputs, phase = cam_from_dict(data)
    return design_cam(inputs, design, idle_fraction, phase)


def _designed_gear(data: Any, design, idle_fraction: float):
    """The file's gear pair designed (DesignError naming a key of the gear)."""
    from core.gear import design_pair
    from core.gear.file import gear_from_dict
    return design_pair(gear_from_dict(data))


@dataclass(frozen=True)
class Part:
    """One file of the course design (a PDF, and for a sheet a DXF beside it with --dxf)."""

    stem: str                 # the file's name after its number: "kinetostatic"
    content: str              # REPORT, or the drawing sheet registry's content: "forces"
    title: str                # what the refusal calls it: "the kinetostatic sheet"
    needs: tuple[str, ...]    # the design file's keys it needs besides "spec"
    drawn: str = ""           # the design-file object it draws (the sheet choice's field of that name)
    reader: Callable[[Any, Any, float], Any] | None = None   # (object, design, idle) → what is drawn


PARTS: tuple[Part, ...] = (
    Part("report", REPORT, "the report", ("rpm", "forces")),
    Part("motion", "motion", "the motion sheet", ("rpm",)),
    Part("kinetostatic", "forces", "the kinetostatic sheet", ("rpm", "forces")),
    Part("cam", "cam", "the cam sheet", ("rpm", "cam"), drawn="cam", reader=_designed_cam),
    Part("gear", "gear", "the gear sheet", ("gear",), drawn="gear", reader=_designed_gear),
)


class CourseError(ValueError):
    """The course design cannot be written; nothing was. ``option`` is what the message
    names ("--design", "--output"); ``missing`` the design-file keys that are not there,
    each with the titles of the files that need it, and ``cause`` the DesignError of a part
    that cannot be made (both for the GUI's own words)."""

    def __init__(self, option: str, message: str,
                 missing: tuple[tuple[str, tuple[str, ...]], ...] = (),
                 cause: DesignError | None = None) -> None:
        super().__init__(f"{option}: {message}")
        self.option, self.reason, self.missing, self.cause = option, message, missing, cause


@dataclass(frozen=True)
class CourseFile:
    part: Part
    path: str                 # the folder's path joined with "NN-stem.pdf" or ".dxf"


@dataclass(frozen=True)
class Course:
    """A checked course design: its inputs, what its sheets draw, and the files to write."""

    spec: Any                                  # core.linkage.spec.Spec
    rpms: tuple[float, ...]
    masses: Any                                # MassProperties (None only without the loads)
    files: tuple[CourseFile, ...]
    folder: str
    drawn: Mapping[str, Any] = field(default_factory=dict)   # Part.drawn → the object
    document: Mapping[str, Any] = field(default_factory=dict)  # the design file as read


def file_names(parts: tuple[Part, ...] = PARTS, dxf: bool = False) -> list[tuple[Part, str]]:
    """Each part's numbered file names in writing order: 00-report.pdf, 01-motion.pdf
    (01-motion.dxf with ``dxf``) …; the report has no DXF."""
    names = []
    for number, part in enumerate(parts):
        names.append((part, f"{number:02d}-{part.stem}.pdf"))
        if dxf and part.content != REPORT:
            names.append((part, f"{number:02d}-{part.stem}.dxf"))
    return names


def missing_parts(keys: Collection[str], parts: tuple[Part, ...] = PARTS
                  ) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """The keys some part needs that ``keys`` (the design file's own) lack, in the order of
    the parts, each with the titles of the parts that need it."""
    found: dict[str, list[str]] = {}
    for part in parts:
        for key in part.needs:
            if key not in keys:
                found.setdefault(key, []).append(part.title)
    return tuple((key, tuple(titles)) for key, titles in found.items())


def missing_text(name: str, missing: tuple[tuple[str, tuple[str, ...]], ...]) -> str:
    """One sentence: 'd.json has no "forces" (the loads): the report and the kinetostatic
    sheet need it; no "cam" (the feed cam): the cam sheet needs it'."""
    pieces = []
    for key, titles in missing:
        who = titles[0] if len(titles) == 1 else ", ".join(titles[:-1]) + " and " + titles[-1]
        verb = "needs" if len(titles) == 1 else "need"
        pieces.append(f'"{key}" ({KEY_NAMES.get(key, key)}): {who} {verb} it')
    return f"{name} has no " + "; no ".join(pieces)


def read_document(path: str | os.PathLike) -> tuple[dict[str, Any], frozenset[str]]:
    """The design file read all or nothing (``parse_design``: FileFormatError), and the keys
    the file itself holds: the reader fills in speeds a file leaves out, a course design
    must not print speeds the student never chose."""
    name = os.fsdecode(path)
    from core.files.design_file import parse_design, read_limited   # its bounded, non-blocking read
    raw = read_limited(name)
    doc = parse_design(raw, name)
    return doc, frozenset(json.loads(raw.decode("utf-8-sig")))


def plan_course(doc: Mapping[str, Any], keys: Collection[str], name: str, folder: str,
                dxf: bool = False, parts: tuple[Part, ...] = PARTS) -> Course:
    """The course design of a read design file (``doc`` as ``parse_design`` returns it,
    ``keys`` the file's own keys, ``name`` how messages call it) to be written into
    ``folder``; CourseError naming --design or --output for anything that would stop it,
    found before anything is written."""
    missing = missing_parts(keys, parts)
    if missing:
        raise CourseError("--design", missing_text(name, missing), missing)
    spec = doc["spec"]
    design = spec.design()
    masses = doc.get("masses")
    if masses is not None:
        from core.forces.masses import masses_for_design
        masses = masses_for_design(design, masses)
    idle = masses.idle_fraction if masses is not None else 0.05
    drawn = {}
    for part in parts:
        if part.reader is not None and part.drawn not in drawn:
            try:
                drawn[part.drawn] = part.reader(doc[part.drawn], design, idle)
            except DesignError as exc:
                raise CourseError("--design", f"{name}: {part.title}: {exc}", cause=exc) from None
    files = tuple(CourseFile(part, os.path.join(folder, file)) for part, file in file_names(parts, dxf))
    check_folder(folder, [f.path for f in files])
    return Course(spec, tuple(float(r) for r in doc["rpm"]), masses, files, folder, drawn, dict(doc))


def check_folder(folder: str, paths: list[str]) -> None:
    """CourseError naming --output unless ``folder`` is (or can be made as) a folder this
    process may write in and every one of ``paths`` a name it can write there."""
    where = Path(folder)
    home = where if _status(folder, where) is not None else (where.parent if str(where.parent) else Path("."))
    if home is where and not where.is_dir():
        raise CourseError("--output", f"cannot write into {folder}: it is not a folder")
    if home is not where and not home.is_dir():
        why = f"{home} is not a folder" if _status(folder, home) is not None else f"there is no folder {home}"
        raise CourseError("--output", f"cannot make {folder}: {why}")
    if not os.access(home, os.W_OK | os.X_OK):
        raise CourseError("--output", f"cannot write into {home}: permission denied")
    for path in paths:
        status = _status(folder, Path(path))
        if status is not None and stat.S_ISDIR(status.st_mode):
            raise CourseError("--output", f"cannot write {path}: it is a folder")
        refusal = replace_refusal(path) if status is not None and stat.S_ISREG(status.st_mode) else None
        if refusal:
            raise CourseError("--output", f"cannot replace {path}: {refusal}; nothing was written")


def _status(folder: str, path: Path) -> os.stat_result | None:
    """``path``'s status, None when it is not there; CourseError naming --output for a name
    the system refuses (too long, a part that is not a folder …)."""
    try:
        return path.stat()
    except FileNotFoundError:
        return None
    except OSError as exc:
        raise CourseError("--output", f"cannot write {path}: {os_reason(exc)}") from None


def make_folder(folder: str) -> None:
    """The output folder, made (one level) if it is not there: the first thing written."""
    try:
        os.mkdir(folder)
    except FileExistsError:
        pass
    except OSError as exc:
        raise WriteError(folder, exc) from None
