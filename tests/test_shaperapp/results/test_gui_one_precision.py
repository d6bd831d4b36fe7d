"""One figure, one precision (issue 40 item 3): θ read 33.6529° in the CLI and the
report and 33.653° on the Results pane and the sheet; K 1.45991, 1.4599 and 1.459905;
lengths 345.398 beside 345.40; the torque 300.8 beside 300.8 and 300.80. Each figure is
now written by ``core.base.figure_text`` wherever a table shows it: the CLI's rows (which the
report prints), the Results pane, the library's and Compare's tables, and the motion and
forces sheets' tables. The reference below is the rule itself, written out: lengths and
angles to 3 decimals, K, times, speeds and accelerations to 4, loads to 4 significant
digits."""
from __future__ import annotations

import math
import re

from core.cli.cmd_analyze import cycle_rows, speed_rows
from core.cli.cmd_dynamics import speed_rows as load_rows
from core.cli.cmd_synth import dimension_rows
from core.drawing.forces import ENGLISH as FORCE_LABELS
from core.drawing.forces import flywheel_rows
from core.drawing.motion import ENGLISH as MOTION_LABELS
from core.drawing.motion import _dimension_rows
from core.forces.masses import MassProperties
from core.forces.flywheel import summarize
from core.linkage.geometry import synthesize
from core.linkage.metrics import analyze
from shaperapp.results.panel import MetricsPanel
from shaperapp.widgets.figure_labels import format_figure

DESIGN = dict(crank=100.0, time_ratio=1.46, stroke=300.0)
LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                       cut_height_mm=80)


def fixed(value: float, decimals: int) -> str:
    return f"{value:.{decimals}f}"


def significant(value: float, digits: int) -> str:
    return f"{value:.{max(digits - 1 - math.floor(math.log10(abs(value))), 0)}f}"


def numbers(text: str) -> list[str]:
    return re.findall(r"-?\d+(?:\.\d+)?", text)


def shown(rows, label: str) -> list[str]:
    return numbers(dict(rows)[label])


def test_a_figure_reads_the_same_in_every_table(qtbot, model):
    design = synthesize(**DESIGN)
    metrics = analyze(design, [40.0])
    summary = summarize(design, [40.0], LOADS)
    theta = math.degrees(design.theta)
    torque = summary.speeds[0].max_torque_N_m
    expect = {"theta": fixed(theta, 3), "frame": fixed(design.frame, 3), "K": fixed(design.time_ratio, 4),
              "v": fixed(metrics.speeds[0].v_work_max_m_s, 4), "torque": significant(torque, 4),
              "J_F": significant(summary.speeds[0].flywheel_inertia_kg_m2, 4)}
    assert expect["theta"] == "33.659" and expect["K"] == "1.4600"      # the rule, by hand

    # the CLI (and the report, which prints these rows)
    dims = dimension_rows(design)
    assert shown(dims, "extreme-position angle θ") == [expect["theta"]]
    assert shown(dims, "frame O2O4 L2") == [expect["frame"]]
    assert shown(dims, "time ratio K") == [expect["K"]]
    assert shown(cycle_rows(metrics), "θ") == [expect["theta"]]
    assert shown(speed_rows(metrics.speeds[0]), "max cutting speed") == [expect["v"]]
    assert shown(load_rows(summary.speeds[0]), "mean / max crank torque")[1] == expect["torque"]
    assert shown(load_rows(summary.speeds[0]), "flywheel J_F") == [expect["J_F"]]

    # the report's validation margins, beside its dimensions: L3 read 518.0975 mm there and
    # 518.098 mm in the table above it, K 1.4600 in both
    from shaperapp.report.content import _margin_table
    margins = {row[0]: row[1:] for row in _margin_table(design).rows}
    lever = next(cells for rule, cells in margins.items() if rule.startswith("lever L3"))
    assert numbers(lever[0]) == [fixed(design.lever, 3)]
    assert numbers(margins["time ratio K ≤ 5"][0]) == [expect["K"]]

    # the sheets
    sheet = _dimension_rows(design, 40.0, MOTION_LABELS)
    assert shown(sheet, MOTION_LABELS["theta"]) == [expect["theta"]]
    assert shown(sheet, MOTION_LABELS["L2"])[-1] == expect["frame"]
    assert shown(sheet, MOTION_LABELS["K"]) == [expect["K"]]
    fly = flywheel_rows(summary, LOADS, FORCE_LABELS)
    assert shown(fly, FORCE_LABELS["M_max"]) == [expect["torque"]]
    assert numbers(dict(fly)[FORCE_LABELS["J_F"]])[-1] == expect["J_F"]

    # the library's and Compare's tables
    assert format_figure("theta_deg", theta) == expect["theta"]
    assert format_figure("frame_mm", design.frame) == expect["frame"]
    assert format_figure("K", design.time_ratio) == expect["K"]
    assert format_figure("max_torque_N_m", torque) == expect["torque"]
    assert format_figure("flywheel_inertia_kg_m2", summary.speeds[0].flywheel_inertia_kg_m2) == expect["J_F"]

    # the Results pane, on the same design
    model.set_spec(crank=100.0, time_ratio=1.46, stroke=300.0)
    model.set_masses(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0, cut_force_N=7000.0,
                     cut_height_mm=80.0)
    model.set_rpms([40.0])
    panel = MetricsPanel(model)
    qtbot.addWidget(panel)
    assert panel.value_text("theta") == expect["theta"]
    assert panel.value_text("frame") == expect["frame"]
    assert panel.value_text("K_nominal") == expect["K"]
    forces = panel.tables()[3]
    assert forces.text(1, 0) == expect["torque"]
    assert forces.text(5, 0) == expect["J_F"]
    assert panel.tables()[2].text(3, 0) == expect["v"]

