"""The class's files beside the students' folders (issue 41): ``tasks.pdf`` (one task sheet
a student, A4), ``answer-key.json``, ``answer-key.csv`` and ``answer-key.pdf``.

The sheets are drawn by ``core.drawing.class_sheets`` and painted by the drawing sheets'
own painter; here they get their words in the UI's language. Each file is written
atomically.
"""
from __future__ import annotations

import json
import os
from typing import Any, Mapping, Sequence

from PySide6.QtCore import QCoreApplication

from core.files.atomic import atomic_write
from core.cli.answers import FIGURES, PER_SPEED, cell_text, failed_checks, key_csv, key_values
from core.course_design.plan import PARTS
from core.drawing.class_sheets import LAW_WORDS, answer_pages, failed_text, task_sheet

from shaperapp.drawing.render import pages_pdf
from shaperapp.report.design_data import law_name

translate = QCoreApplication.translate

TASKS_FILE = "tasks.pdf"
KEY_FILES = tuple(f"answer-key.{kind}" for kind in ("json", "csv", "pdf"))
"""The class's own files in DIR: the task sheets and the answer key."""


def task_labels() -> dict[str, str]:
    """The task sheet's and the answer key's words in the UI's language."""
    words = {
        "Course design task sheet": translate("ClassSheets", "Course design task sheet"),
        "Quick-return mechanism of a shaper": translate("ClassSheets", "Quick-return mechanism of a shaper"),
        "Student": translate("ClassSheets", "Student"),
        "Number": translate("ClassSheets", "Number"),
        "Class": translate("ClassSheets", "Class"),
        "Date": translate("ClassSheets", "Date"),
        "The mechanism (sketch to scale, crank at 60°)": translate("ClassSheets", "The mechanism (sketch to scale, crank at 60°)"),
        "Data set": translate("ClassSheets", "Data set"),
        "Quantity": translate("ClassSheets", "Quantity"),
        "Symbol": translate("ClassSheets", "Symbol"),
        "Value": translate("ClassSheets", "Value"),
        "Unit": translate("ClassSheets", "Unit"),
        "Crank speed": translate("ClassSheets", "Crank speed"),
        "Frame O_2O_4": translate("ClassSheets", "Frame O_2O_4"),
        "Crank O_2A": translate("ClassSheets", "Crank O_2A"),
        "Lever O_4B": translate("ClassSheets", "Lever O_4B"),
        "Rod BC": translate("ClassSheets", "Rod BC"),
        "Rod side: C ahead of B while cutting": translate("ClassSheets", "Rod side: C ahead of B while cutting"),
        "leading": translate("ClassSheets", "leading"),
        "Time ratio": translate("ClassSheets", "Time ratio"),
        "Stroke": translate("ClassSheets", "Stroke"),
        "Lever's centre of mass O_4S_4": translate("ClassSheets", "Lever's centre of mass O_4S_4"),
        "Lever weight": translate("ClassSheets", "Lever weight"),
        "Lever moment of inertia": translate("ClassSheets", "Lever moment of inertia"),
        "Ram weight": translate("ClassSheets", "Ram weight"),
        "Cutting force": translate("ClassSheets", "Cutting force"),
        "Height of the cutting force": translate("ClassSheets", "Height of the cutting force"),
        "Guide line": translate("ClassSheets", "Guide line"),
        "Follower arm": translate("ClassSheets", "Follower arm"),
        "Follower swing": translate("ClassSheets", "Follower swing"),
        "Allowed pressure angle": translate("ClassSheets", "Allowed pressure angle"),
        "Rise": translate("ClassSheets", "Rise"),
        "Outer dwell": translate("ClassSheets", "Outer dwell"),
        "Return": translate("ClassSheets", "Return"),
        "Pinion teeth": translate("ClassSheets", "Pinion teeth"),
        "Gear teeth": translate("ClassSheets", "Gear teeth"),
        "Module": translate("ClassSheets", "Module"),
        "Deliver": translate("ClassSheets", "Deliver"),
        "Answer key": translate("ClassSheets", "Answer key"),
        "page %1/%2": translate("ClassSheets", "page %1/%2"),
        "failed checks": translate("ClassSheets", "failed checks"),
        "speed": translate("ClassSheets", "speed"),
        "none": translate("ClassSheets", "none"),
        "No.": translate("ClassSheets", "No."),
        ", ": translate("ClassSheets", ", "),
        "cam pressure angle": translate("ClassSheets", "cam pressure angle"),
        "undercut 1": translate("ClassSheets", "undercut 1"),
        "undercut 2": translate("ClassSheets", "undercut 2"),
        "tip 1": translate("ClassSheets", "tip 1"),
        "tip 2": translate("ClassSheets", "tip 2"),
        "contact ratio": translate("ClassSheets", "contact ratio"),
        "interference 1": translate("ClassSheets", "interference 1"),
        "interference 2": translate("ClassSheets", "interference 2"),
        "Coefficient of speed fluctuation": translate("ClassSheets", "Coefficient of speed fluctuation"),
        "Idle margin at each end of the stroke": translate("Report", "Idle margin at each end of the stroke"),
        "Rod mass": translate("messages", "Rod mass"),
        "Block mass": translate("messages", "Block mass"),
        "Crank mass": translate("messages", "Crank mass"),
        "Gravity": translate("messages", "Gravity"),
        "not counted": translate("ClassSheets", "not counted"),
        "Other rotating parts": translate("ClassSheets", "Other rotating parts"),
        "Rise law": translate("messages", "Rise law"),
        "Return law": translate("messages", "Return law"),
        "Allowed pressure angle, return": translate("messages", "Allowed pressure angle, return"),
        "Roller radius": translate("messages", "Roller radius"),
        "Base radius": translate("ClassSheets", "Base radius"),
        "Centre distance of the cam": translate("ClassSheets", "Centre distance of the cam"),
        "Hub radius": translate("messages", "Hub radius"),
        "Pivot boss radius": translate("messages", "Pivot boss radius"),
        "Least clearance": translate("messages", "Least clearance"),
        "Shift factors": translate("ClassSheets", "Shift factors"),
        "Centre distance": translate("GearResults", "Centre distance"),
        "Pressure angle": translate("CamTab", "Pressure angle"),
        "Addendum": translate("ClassSheets", "Addendum"),
        "Clearance": translate("ClassSheets", "Clearance"),
        "Least tip thickness": translate("GearMessages", "Least tip thickness"),
        "Least contact ratio": translate("GearMessages", "Least contact ratio"),
    }
    words.update({word: law_name(law) for law, word in LAW_WORDS.items()})     # the report's words
    return words


def part_titles() -> list[str]:
    """The files a student delivers, as the task sheet lists them."""
    titles = {"report": translate("ClassSheets", "Design report (00-report.pdf)"),
              "motion": translate("ClassSheets", "Motion analysis sheet (01-motion)"),
              "kinetostatic": translate("ClassSheets", "Kinetostatic analysis sheet (02-kinetostatic)"),
              "cam": translate("ClassSheets", "Feed cam sheet (03-cam)"),
              "gear": translate("ClassSheets", "Gear meshing sheet (04-gear)")}
    return [titles.get(part.stem, part.title) for part in PARTS]


def write_tasks(path: str, students: Sequence[tuple[Mapping[str, Any], Mapping[str, str]]],
                language: str) -> None:
    """tasks.pdf: one A4 page per (design document, who) in ``students``."""
    labels, deliver = task_labels(), part_titles()
    sheets = [task_sheet(doc, who, deliver, labels) for doc, who in students]
    atomic_write(path, pages_pdf(sheets, language, labels["Course design task sheet"]))


# the answer key's PDF columns: (FIGURES' or PER_SPEED's name, heading in the index notation,
# unit, mm), in three tables, each column wide enough for its widest figure at 2.5 mm
# (figure_text's decimals: a length "1234.567", a shift factor "-0.123456"); wider where a
# text needs it (class_sheets.fitted_widths: a student's number, the failed checks' words)
_LINKAGE = (("theta", "θ", "°", 16), ("L1", "L_1", "mm", 18), ("L2", "L_2", "mm", 18), ("L3", "L_3", "mm", 18),
            ("L4", "L_4", "mm", 18), ("h", "h", "mm", 18), ("K", "K", "", 14), ("H", "H", "mm", 18),
            ("n", "n_2", "r/min", 13), ("v_work_max", "v_w,max", "m/s", 16),
            ("v_return_max", "v_r,max", "m/s", 16), ("a_max", "|a|_max", "m/s²", 17))
_FORCES = (("n", "n_2", "r/min", 13), ("M_max", "M_max", "N·m", 16), ("M_mean", "M_m", "N·m", 16),
           ("dW_max", "ΔW_max", "J", 16), ("J_F", "J_F", "kg·m²", 16), ("J_F_needed", "J_F − J_c", "kg·m²", 18),
           ("r0", "r_0", "mm", 18),
           ("a_cam", "a_cam", "mm", 18), ("r_roller", "r_r", "mm", 18))
_GEAR = (("x1", "x_1", "", 20), ("x2", "x_2", "", 20), ("a'", "a′", "mm", 19), ("alpha'", "α′", "°", 20),
         ("epsilon", "ε", "", 19), ("failed", "", "", 30))


def write_answer_key(folder: str, entries: Sequence[Mapping[str, Any]], groups: Sequence[str],
                     language: str) -> list[str]:
    """answer-key.json, .csv and .pdf in ``folder``; returns their paths."""
    paths = [os.path.join(folder, name) for name in KEY_FILES]
    atomic_write(paths[0], json.dumps(list(entries), indent=1, ensure_ascii=False, allow_nan=False) + "\n")
    atomic_write(paths[1], "\ufeff" + key_csv(entries, groups))     # a BOM: Excel then reads UTF-8
    labels = task_labels()
    who = [(labels["No."], 9), (labels["Student"], 24), (labels["Number"], 20)]
    rows = [_pdf_row(number, entry, group, i, labels)
            for number, (entry, group) in enumerate(zip(entries, groups), start=1)
            for i in range(len(entry["analyze"]["speeds"]))]
    tables = []
    for columns in (_LINKAGE, _FORCES, _GEAR):
        header = [h for h, _ in who] + [heading or labels["failed checks"] for _, heading, _, _ in columns]
        units = ["" for _ in who] + [unit for _, _, unit, _ in columns]
        widths = [w for _, w in who] + [w for _, _, _, w in columns]
        body = [[row[0], row[1], row[2]] + [row[3][name] for name, _, _, _ in columns] for row in rows]
        tables.append(((header, units), widths, body))
    title = f"{labels['Answer key']}: {labels['Quick-return mechanism of a shaper']}"
    pages = answer_pages(tables, title, labels, plain=(1, 2))     # the failed checks are words, as wide as they need
    atomic_write(paths[2], pages_pdf(pages, language, title))
    return paths


def _pdf_row(number: int, entry: Mapping[str, Any], group: str, speed: int,
             labels: Mapping[str, str]) -> tuple[str, str, str, dict[str, str]]:
    """(No., student, number, name → text) of one speed of one student; the figures that
    do not depend on the speed on its first speed's row only."""
    speeds = len(entry["analyze"]["speeds"])
    values = key_values(entry, group, speeds)
    figures = dict(zip((name for name, _, _ in FIGURES), values[4:4 + len(FIGURES)]))
    at = 4 + len(FIGURES) + speed * (1 + len(PER_SPEED))
    texts = {"n": cell_text("n", values[at])}
    texts.update({name: cell_text(name, v)
                  for (name, _, _), v in zip(PER_SPEED, values[at + 1:at + 1 + len(PER_SPEED)])})
    first = speed == 0
    texts.update({name: cell_text(name, v) if first else "" for name, v in figures.items()})
    texts["failed"] = failed_text(failed_checks(entry), labels) if first else ""
    if not first:
        return "", "", "", texts
    return str(number), entry["student"], entry["student_number"], texts

