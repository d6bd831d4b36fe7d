"""The report's comparison section: the report's design beside others at its first speed.

The numbers are :mod:`core.space.compare`'s, written as ``shaper library compare``
writes them (``value_text`` and ``difference_text``), under the figure names the
Library pane and the Compare tab use (``figure_labels``); the curves are drawn by
the Compare tab's own component (``compare_plots``), through the report's views.
"""
from __future__ import annotations

import html
from typing import Sequence

from PySide6.QtCore import QCoreApplication

from core.space.compare import Candidate, Comparison, compare, difference_text, value_text
from core.forces.masses import MassProperties
from core.library.names import unique_name
from core.linkage.spec import Spec
from shaperapp.widgets.figure_labels import figure_label, variant_label
from shaperapp.widgets.notation import typeset

from .blocks import Figure, Heading, Paragraph, Table

translate = QCoreApplication.translate


def report_comparison(spec: Spec, masses: MassProperties | None, name: str,
                      others: Sequence[Candidate], rpm: float) -> Comparison:
    """The report's design (labelled ``name``, the reference) and ``others`` at ``rpm``;
    another design called ``name`` is renamed "name (2)"."""
    rest = [Candidate(unique_name(c.label, [name]), c.spec, c.masses) for c in others]
    return compare([Candidate(name, spec, masses)] + rest, rpm)


def comparison_table(result: Comparison) -> Table:
    """One row per figure, one column per design: the value, its difference from the
    reference in brackets, ★ before the best value of a row."""
    rows = []
    for row in result.rows:
        cells = []
        for k, value in enumerate(row.values):
            text = variant_label(value) if isinstance(value, str) else value_text(value, row.key)
            cells.append(("★ " if k in row.best else "") + text + difference_text(row, k))
        rows.append([figure_label(row.key)] + cells)
    return Table([translate("Report", "Figure")] + list(result.labels), rows,
                 translate("Report", "Figures at %1 r/min").replace("%1", f"{result.rpm:g}"),
                 [bool(row.best) for row in result.rows], plain_header=True)


def comparison_blocks(result: Comparison, curves) -> list:
    """Heading, introduction, overlay curves (``curves``: a figure paint) and the table.
    The introduction is rich text (PDF and HTML): the designs' names go in escaped."""
    labels = [html.escape(label) for label in result.labels]
    others = translate("Report", ", ").join(f"“{label}”" for label in labels[1:])
    intro = translate(
        "Report", "The design of this report, “%1”, beside %2 at %3 r/min, the report's first "
        "speed. Each value is followed by its difference from “%1” in brackets ((=): the same); "
        "★ marks the best value of a row: the lowest max |a|, pressure angle, torques and "
        "flywheel J_F. Torques and J_F need loads; a design without them has none (—). The "
        "numbers are those of shaper library compare.")
    intro = typeset(intro).replace("%1", labels[0]).replace("%2", others) \
        .replace("%3", f"{result.rpm:g}")
    return [Heading(translate("Report", "9 Comparison with other designs")),
            Paragraph(intro, True),
            Figure(translate("Report", "Ram displacement, velocity, acceleration and crank torque "
                             "of the compared designs over one crank revolution"), 170.0, 165.0,
                   curves),
            comparison_table(result)]
