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

from core.atomic import atomic_write
from core.cli.answers import FIGURES, PER_SPEED, key_csv, key_values
from core.course import PARTS
from core.drawing.class_sheets import TASK_WORDS, answer_pages, task_sheet

from shaperapp.drawing.render import pages_pdf

translate = QCoreApplication.translate


def task_labels() -> dict[str, str]:
    """The task sheet's and the answer key's words in the UI's language."""
    words = {word: translate("ClassSheets", word) for word in TASK_WORDS}
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


# the answer key's PDF columns: (heading in the index notation, width in mm)
_PDF_FIGURES = {"theta": "θ (°)", "L1": "L_1", "L2": "L_2", "L3": "L_3", "L4": "L_4", "h": "h",
                "K": "K", "H": "H", "r0": "r_0", "a_cam": "a_cam", "r_roller": "r_r", "x1": "x_1",
                "x2": "x_2", "a'": "a′", "alpha'": "α′ (°)", "epsilon": "ε"}
_PDF_SPEED = {"v_work_max": "v_w,max", "v_return_max": "v_r,max", "a_max": "|a|_max", "M_max": "M_max",
              "M_mean": "M_m", "dW_max": "ΔW_max", "J_F": "J_F"}


def write_answer_key(folder: str, entries: Sequence[Mapping[str, Any]], groups: Sequence[str],
                     language: str) -> list[str]:
    """answer-key.json, .csv and .pdf in ``folder``; returns their paths."""
    paths = [os.path.join(folder, f"answer-key.{kind}") for kind in ("json", "csv", "pdf")]
    atomic_write(paths[0], json.dumps(list(entries), indent=1, ensure_ascii=False, allow_nan=False) + "\n")
    atomic_write(paths[1], "\ufeff" + key_csv(entries, groups))     # a BOM: Excel then reads UTF-8
    labels = task_labels()
    header = ["No.", labels["Student"], labels["Number"]]
    header += [_PDF_FIGURES[name] for name, _, _ in FIGURES if name not in ("h",)]
    header += ["n_2"] + [_PDF_SPEED[name] for name, _, _ in PER_SPEED] + [labels["failed checks"]]
    widths = [8, 22, 20] + [11] * (len(FIGURES) - 1) + [9] + [12] * len(PER_SPEED) + [30]
    rows = []
    for number, (entry, group) in enumerate(zip(entries, groups), start=1):
        rows += _pdf_rows(number, entry, group, labels)
    title = f"{labels['Answer key']}: {labels['Quick-return mechanism of a shaper']}"
    pages = answer_pages(rows, header, widths, title, labels, plain=(1, 2, len(header) - 1))
    atomic_write(paths[2], pages_pdf(pages, language, title))
    return paths


def _pdf_rows(number: int, entry: Mapping[str, Any], group: str, labels: Mapping[str, str]) -> list[list[str]]:
    """One row per speed of one student: who and the figures on the first, blank after."""
    speeds = len(entry["analyze"]["speeds"])
    values = key_values(entry, group, speeds)
    figures = [v for (name, _, _), v in zip(FIGURES, values[4:4 + len(FIGURES)]) if name != "h"]
    failed = values[-1] or labels["none"]
    rows = []
    for i in range(speeds):
        at = 4 + len(FIGURES) + i * (1 + len(PER_SPEED))
        per_speed = [_n(v) for v in values[at:at + 1 + len(PER_SPEED)]]
        head = [str(number), entry["student"], entry["student_number"]] + [_n(v) for v in figures] \
            if i == 0 else [""] * (3 + len(figures))
        rows.append(head + per_speed + ([failed] if i == 0 else [""]))
    return rows


def _n(value: Any) -> str:
    if value is None:
        return "—"
    if abs(value) >= 1e4:
        return f"{value:.0f}"
    return f"{value:.4g}" if abs(value) >= 1 else f"{value:.3f}"
