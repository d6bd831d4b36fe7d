"""What the design report says: blocks of text, tables and figures, built once.

Every number comes from ``core``, and the figures the ``shaper`` CLI prints come
as the CLI's own rows (``synth``, ``analyze`` and ``dynamics`` ``*_rows`` and
``table``'s ``number_text``) under translated labels, so the report and the CLI
cannot drift apart (tested through the PDF text layer). Figures are drawn by the
app's own views (``figures``) and the polygon painter, never by drawing code of
their own. The blocks are defined in ``blocks``; the comparison section is
``comparison``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from PySide6.QtCore import QCoreApplication

from core.cli.cmd_analyze import cycle_rows
from core.cli.cmd_analyze import speed_rows as analyze_speed_rows
from core.cli.cmd_dynamics import speed_rows as dynamics_speed_rows
from core.cli.cmd_dynamics import summary_rows
from core.cli.cmd_synth import dimension_rows
from core.cam import CamInputs
from core.space.compare import Candidate
from core.forces.dynamics import DynamicsSummary
from core.forces.masses import MassProperties, masses_for_design
from core.base.figure_text import figure_text
from core.forces.flywheel import summarize
from core.gear import GearPairInputs
from core.linkage.geometry import Design
from core.linkage.margins import margins
from core.linkage.metrics import CycleMetrics, analyze
from core.course_design.positions import PositionTable, position_table, positions
from core.base.progress import Progress
from core.linkage.spec import Spec
from shaperapp.widgets.command_line import inputs_name
from shaperapp.widgets.i18n import join_sentences
from shaperapp.widgets.notation import typeset

from . import figures
from .blocks import (Cover, Figure, Heading, KeyValues, Paragraph, Report, Table,
                     numbered_figures)
from .cam import cam_blocks
from .comparison import comparison_blocks, report_comparison
from .design_data import cam_rows, flywheel_formula, gear_rows, load_rows
from .gear import gear_blocks
from .positions import position_tables, positions_note

translate = QCoreApplication.translate   # lupdate extracts translate("Report", "…")


@dataclass(frozen=True)
class Options:
    """What the user chooses: positions count and the crank angles of the vector diagrams."""

    count: int = 12
    diagram_deg: tuple[float, float] | None = None    # None: one in the working, one in the return stroke
    compare: tuple[Candidate, ...] = ()               # other designs for a comparison section
    cover: Cover = Cover()                            # student, class … for the cover block
    cam: tuple[CamInputs, float | None] | None = None  # the feed cam's inputs and phase, if any
    gear: GearPairInputs | None = None                 # the gear pair's inputs, if any


def default_diagram_angles(table: PositionTable, metrics: CycleMetrics) -> tuple[float, float]:
    """The numbered positions nearest the middle of the working and of the return stroke."""
    work_mid = metrics.work_angle_deg / 2.0
    back_mid = metrics.work_angle_deg + metrics.return_angle_deg / 2.0
    numbered = [d for d, n in zip(table.positions.crank_deg, table.positions.number) if n]
    pick = lambda target: float(min(numbered, key=lambda d: abs(d - target)))  # noqa: E731
    return pick(work_mid), pick(back_mid)


# the steps of :func:`build` that every report takes (a section or two, each ≲ 1.5 s with
# 16 speeds), and those of the sections a report may add
BUILD_STEPS = 9
CAM_STEPS = 3
BUILD_SHARE = 0.85     # of a report's progress: building it (views, sections); its pages the rest


def build(spec: Spec, rpms: Sequence[float], masses: MassProperties | None, name: str, date: str,
          language: str, options: Options = Options(), progress: Progress = Progress()) -> Report:
    """The whole report; ``masses`` None leaves out the force analysis (with a note).
    ``progress`` hears of every section or two as it is built (Cancelled when it says
    stop: the views are closed and nothing is returned)."""
    step = progress.steps(BUILD_STEPS + bool(options.compare) + CAM_STEPS * (options.cam is not None)
                          + (options.gear is not None))
    design = spec.design()
    metrics = analyze(design, rpms)
    used = masses_for_design(design, masses) if masses is not None else None
    idle = used.idle_fraction if used is not None else MassProperties().idle_fraction
    table = position_table(design, positions(design, options.count, (), idle), rpms, used)
    summary = summarize(design, rpms, used) if used is not None else None
    angles = options.diagram_deg or default_diagram_angles(table, metrics)
    report = Report(translate("Report", "Design report: quick-return mechanism of a shaper"),
                    name or inputs_name(spec), date, language, cover=options.cover)
    name = report.name
    add = report.blocks.append
    views = figures.ReportViews(spec, rpms, used, metrics)
    try:
        add(Heading(translate("Report", "1 Design inputs")))
        add(KeyValues(_inputs(spec, rpms, used) + (load_rows(used, design) if used is not None else [])
                      + (cam_rows(options.cam) if options.cam is not None else [])
                      + (gear_rows(options.gear) if options.gear is not None else [])))
        add(Heading(translate("Report", "2 Synthesized dimensions and validation margins")))
        add(KeyValues(_dimensions(design)))
        add(_margin_table(design))
        step()
        add(Heading(translate("Report", "3 The mechanism at its limit positions")))
        add(Figure(translate("Report", "Scheme to scale at the limit positions that start and end "
                             "the working stroke"), 170.0, 85.0, views.limit_schemes(step)))
        step()
        add(Heading(translate("Report", "4 Motion of the ram and cycle metrics")))
        add(KeyValues(_cycle(metrics)))
        add(Figure(translate("Report", "Ram displacement, velocity and acceleration over one "
                             "crank revolution, one curve per speed"), 170.0, 128.0, views.curves()))
        add(_speed_table(metrics))            # after the figure, which then fits on the page
        step()
        add(Heading(translate("Report", "5 Kinematic and force analysis at the crank positions")))
        add(Paragraph(join_sentences(translate("Report", "Positions 1 … N are equally spaced from the limit "
                                               "position that starts the working stroke (φ = 0). The shaded "
                                               "rows are the special positions, solved exactly. Forces are on "
                                               "the named body."), positions_note(table)), True))
        report.blocks.extend(position_tables(table))
        step()
        add(Heading(translate("Report", "6 Velocity, acceleration and force polygons")))
        add(Paragraph(translate("Report", "Drawn to scale from the exact solution at %1 r/min; "
                                "μ is the scale of each drawing (1 mm on the page).")
                      .replace("%1", f"{rpms[0]:g}"), True))
        for deg in angles:
            for kind in ("velocity", "acceleration", "force", "lever"):
                if kind in ("force", "lever") and used is None:
                    continue
                add(Figure(figures.polygon_caption(kind, deg), 170.0, 105.0 if kind != "velocity" else 85.0,
                           figures.polygon_paint(design, deg, rpms[0], used, kind, language)))
        step()
        if summary is not None:
            add(Heading(translate("Report", "7 Crank torque, energy and flywheel")))
            add(Paragraph(translate("Report", "<b>Flywheel.</b> On the crank shaft, %1; the loads "
                                    "are those of section 1.").replace("%1", flywheel_formula(used)),
                          True))            # it introduces the table: not alone at a page's foot
            add(_dynamics_table(summary, design))
            add(Figure(translate("Report", "Crank torque, input power, energy fluctuation ΔE and "
                                 "joint forces over one revolution"), 170.0, 170.0, views.forces()))
        else:
            add(Heading(translate("Report", "7 Crank torque, energy and flywheel")))
            add(Paragraph(translate("Report", "No loads were given, so the force analysis is left "
                                    "out. Give the masses and the cutting force (or a design file "
                                    "with loads) to include it.")))
        step()
        add(Heading(translate("Report", "8 Conventions and formulas")))
        report.blocks.extend(_conventions(spec))
        step()
        if options.compare:
            result = report_comparison(spec, masses, name, options.compare, rpms[0])
            report.blocks.extend(comparison_blocks(result, views.comparison_curves(result)))
            step()
        number = 10 if options.compare else 9     # the sections after the conventions
        if options.cam is not None:
            report.blocks.extend(cam_blocks(options.cam, design, idle, rpms[0], number, views, step))
            number += 1
        if options.gear is not None:        # the last section
            report.blocks.extend(gear_blocks(options.gear, number, language))
            step()
    finally:
        views.close()
    report.blocks = numbered_figures(report.blocks)
    return report


# ---- sections --------------------------------------------------------------
def _inputs(spec: Spec, rpms: Sequence[float], masses: MassProperties | None) -> list[tuple[str, str]]:
    rows = []
    if spec.mode == "synthesis":
        rows += [(translate("Report", "Crank length L1"), f"{spec.crank:g} mm"),
                 (translate("Report", "Time ratio K"), f"{spec.time_ratio:g}"),
                 (translate("Report", "Stroke H"), f"{spec.stroke:g} mm")]
    else:
        rows += [(translate("Report", "Crank length L1"), f"{spec.crank:g} mm"),
                 (translate("Report", "Frame O2O4 L2"), f"{spec.frame:g} mm"),
                 (translate("Report", "Lever O4B L3"), f"{spec.lever:g} mm")]
    variant = {"block": translate("Report", "block on the lever tip in a slot of the ram"),
               "rod": translate("Report", "connecting rod from the lever tip to the ram")}[spec.variant]
    rows.append((translate("Report", "Ram drive"), variant))
    guide = {"chord": translate("Report", "through the lever tip's extreme positions"),
             "sagitta": translate("Report", "midway along the tip arc's sagitta")}.get(
        spec.guide_rule, f"{spec.guide_height:g} mm")
    rows.append((translate("Report", "Ram guide line"), guide))
    if spec.variant == "rod":
        rod = f"{spec.rod_length:g} mm" if spec.rod_input == "length" else f"L4/L3 = {spec.rod_ratio:g}"
        side = {"trailing": translate("Report", "trailing the tip"),
                "leading": translate("Report", "leading the tip")}[spec.rod_side]
        rows.append((translate("Report", "Connecting rod"), f"{rod}, {side}"))
    rows.append((translate("Report", "Crank speeds"), ", ".join(f"{r:g}" for r in rpms) + " r/min"))
    if masses is None:
        rows.append((translate("Report", "Loads"), translate("Report", "none given")))
    return rows


def _labelled(rows: list[tuple[str, str]], labels: dict[str, str]) -> list[tuple[str, str]]:
    """The CLI's rows (its very value texts) under the report's translated labels; rows
    without a label here (shown elsewhere in the report) are left out."""
    return [(labels[key], value) for key, value in rows if key in labels]


def _dimensions(design: Design) -> list[tuple[str, str]]:
    """As ``shaper synth`` prints them."""
    words = {"trailing": translate("Report", "trailing"), "leading": translate("Report", "leading")}
    return _labelled(dimension_rows(design, words), {
        "extreme-position angle θ": translate("Report", "Extreme-position angle θ"),
        "frame O2O4 L2": translate("Report", "Frame O2O4 L2"),
        "lever O4B L3": translate("Report", "Lever O4B L3"),
        "guide above lever pivot": translate("Report", "Guide line above the lever pivot O4"),
        "guide above crank centre h": translate("Report", "Guide line above the crank centre O2, h"),
        "rod BC L4": translate("Report", "Connecting rod BC L4"),
        "time ratio K": translate("Report", "Time ratio K of the dimensions"),
        "stroke H": translate("Report", "Stroke H of the dimensions")})


def _margin_table(design: Design) -> Table:
    names = {"time_ratio": translate("Report", "time ratio K ≤ 5"),
             "lever_reach": translate("Report", "lever L3 ≥ L2 + L1 (crank pin stays on the lever)"),
             "guide_clears_crank": translate("Report", "guide above L2 + L1 (ram clears the crank)"),
             "guide_below_tip": translate("Report", "guide ≤ L3 (block reaches the guide)"),
             "rod_reach": translate("Report", "rod reaches the guide over the whole cycle"),
             "rod_dead_centre": translate("Report", "rod never in line with the lever (no dead centre)")}
    kind = {"mm": "length", "": "ratio"}          # one precision per kind, as the dimensions above
    rows = [[names[m.rule]] + [f"{figure_text(kind[m.unit], v)} {m.unit}".strip() for v in (m.value, m.limit, m.margin)]
            for m in margins(design)]
    return Table([translate("Report", "Rule"), translate("Report", "Value"),
                  translate("Report", "Limit"), translate("Report", "Margin")], rows,
                 translate("Report", "Validation margins"))


def _cycle(metrics: CycleMetrics) -> list[tuple[str, str]]:
    """As ``shaper analyze`` prints them (θ is among the dimensions)."""
    return _labelled(cycle_rows(metrics), {
        "measured K": translate("Report", "Measured time ratio K"),
        "measured stroke": translate("Report", "Measured stroke"),
        "working / return crank angle": translate("Report", "Working / return crank angle"),
        "max pressure angle": translate("Report", "Largest pressure angle")})


def _per_speed(rows: list[list[tuple[str, str]]], rpms: Sequence[float], labels: dict[str, str],
               caption: str) -> Table:
    """A table with one column per crank speed from each speed's CLI rows."""
    header = [translate("Report", "Crank speed")] + [f"{r:g} r/min" for r in rpms]
    columns = [dict(r) for r in rows]
    return Table(header, [[label] + [c[key] for c in columns] for key, label in labels.items()],
                 caption)


def _speed_table(metrics: CycleMetrics) -> Table:
    """As ``shaper analyze`` prints it."""
    return _per_speed([analyze_speed_rows(s) for s in metrics.speeds],
                      [s.rpm for s in metrics.speeds], {
        "working / return time": translate("Report", "Working / return time"),
        "max cutting speed": translate("Report", "Max cutting speed"),
        "mean cutting speed": translate("Report", "Mean cutting speed"),
        "max return speed": translate("Report", "Max return speed"),
        "max |acceleration|": translate("Report", "Max |acceleration|")},
        translate("Report", "Cycle metrics per crank speed"))


def _dynamics_table(summary: DynamicsSummary, design: Design) -> Table:
    """As ``shaper dynamics`` prints it (J_e and J_c, the same at every speed, in each column)."""
    shared = dict(summary_rows(design, summary.masses, summary))
    rotors = summary.rotor_inertia_kg_m2 if summary.masses.rotors else None
    rows = []
    for s in summary.speeds:
        row = dynamics_speed_rows(s, rotors) + [("J_e", shared["mean reduced inertia J_e"])]
        if rotors is not None:
            row.append(("J_c", f"{figure_text('inertia', rotors)} kg·m²"))
            if not s.flywheel_needed:          # the CLI's words, in the report's language
                row.append(("flywheel needed J_F − J_c", translate("Report", "none needed (J_c ≥ J_F)")))
        rows.append(row)
    labels = {
        "mean / max crank torque": translate("Report", "Mean / max crank torque"),
        "mean power": translate("Report", "Mean power (motor, before efficiency)"),
        "energy fluctuation ΔW_max": translate("Report", "Energy fluctuation ΔW_max"),
        "flywheel J_F": translate("Report", "Flywheel J_F on the crank shaft")}
    if rotors is None:
        labels["flywheel J_F − J_e (net)"] = translate("Report", "Flywheel J_F − J_e (net)")
    else:
        labels.update({"J_c": translate("Report", "Rotating parts at the crank J_c"),
                       "flywheel needed J_F − J_c": translate("Report", "Flywheel needed J_F − J_c"),
                       "flywheel J_F − J_c − J_e (net)": translate("Report", "Flywheel J_F − J_c − J_e (net)")})
    labels["J_e"] = translate("Report", "Mean reduced inertia J_e")
    return _per_speed(rows, [s.rpm for s in summary.speeds], labels,
                      translate("Report", "Torque, power and flywheel per crank speed"))


def _method(spec: Spec) -> str:
    """The synthesis (or dimensions) paragraph with the guide rule this design uses: a
    sagitta design was described by the chord rule."""
    if spec.mode == "synthesis":
        return {
            "chord": translate("Report", "<b>Synthesis.</b> θ = 180°·(K − 1)/(K + 1); L2 = L1/sin(θ/2); "
                               "L3 = H/(2·sin(θ/2)); guide through the tip's extreme positions at L3·cos(θ/2) "
                               "above O4 (h = H/(2·tan(θ/2)) − L2 above O2)."),
            "sagitta": translate("Report", "<b>Synthesis.</b> θ = 180°·(K − 1)/(K + 1); L2 = L1/sin(θ/2); "
                                 "L3 = H/(2·sin(θ/2)); guide midway along the sagitta of the tip's arc, at "
                                 "L3·(1 + cos(θ/2))/2 above O4."),
            "height": translate("Report", "<b>Synthesis.</b> θ = 180°·(K − 1)/(K + 1); L2 = L1/sin(θ/2); "
                                "L3 = H/(2·sin(θ/2)); guide at the height given above O4."),
        }[spec.guide_rule]
    return {
        "chord": translate("Report", "<b>Dimensions.</b> L1, L2 and L3 as given; θ = 2·arcsin(L1/L2), "
                           "K = (180° + θ)/(180° − θ), H = 2·L3·sin(θ/2); guide through the tip's extreme "
                           "positions at L3·cos(θ/2) above O4."),
        "sagitta": translate("Report", "<b>Dimensions.</b> L1, L2 and L3 as given; θ = 2·arcsin(L1/L2), "
                             "K = (180° + θ)/(180° − θ), H = 2·L3·sin(θ/2); guide midway along the sagitta "
                             "of the tip's arc, at L3·(1 + cos(θ/2))/2 above O4."),
        "height": translate("Report", "<b>Dimensions.</b> L1, L2 and L3 as given; θ = 2·arcsin(L1/L2), "
                            "K = (180° + θ)/(180° − θ), H = 2·L3·sin(θ/2); guide at the height given above O4."),
    }[spec.guide_rule]


def _conventions(spec: Spec) -> list:
    p = lambda text: Paragraph(typeset(text))  # noqa: E731
    return [
        p(translate("Report", "<b>Frame and signs.</b> Lever pivot O4 at the origin, crank centre O2 at "
                    "(0, L2) above it, ram guide the line y = guide height; the ram cuts toward +x and the "
                    "crank turns clockwise. Crank angle φ = 0 at the limit position that starts the working "
                    "stroke, increasing with rotation; 0 … 180° + θ is the working stroke. Ram x, v and a are "
                    "positive in the cutting direction, x measured from the position at φ = 0. The lever "
                    "angle ψ is measured from O4→O2, positive toward the cut. Links as in the task book: "
                    "1 frame, 2 crank O2A, 3 block at A, 4 lever O4B, 5 rod BC (in the block variant the "
                    "block at B), 6 ram; S4 and S6 are the lever's and the ram's centres of mass. Forces are those on the named body, torque positive in the "
                    "direction of rotation.")),
        p(_method(spec)),
        p(translate("Report", "<b>Senses.</b> The lever's ω4 and α4 are positive clockwise (as ψ and the "
                    "crank), the rod's ω5 and α5 counter-clockwise. The block's sliding speed is positive "
                    "away from O4 and its Coriolis acceleration 2·ω4·v_slide is the component along the "
                    "direction of increasing ψ; the polygons' v_A4A3 and a^k_A4A3 are their negatives. The "
                    "cutting force acts from the start to the end of the cut, both included: the rows at "
                    "those angles show it acting.")),
        p(translate("Report", "<b>Velocities.</b> v_A4 = v_A3 + v_A4A3 with v_A3 = v_A2 = ω2·L1 ⟂ O2A, "
                    "v_A4 = ω4·O4A ⟂ O4A, v_A4A3 ∥ O4A; v_B = ω4·L3; block variant v_C = v_B + v_CB "
                    "(v_CB vertical), rod variant v_C = v_B + v_CB with v_CB = ω5·L4 ⟂ BC.")),
        p(translate("Report", "<b>Accelerations.</b> a_A4 = a^n_A4 + a^t_A4 = a_A3 + a^k_A4A3 + a^r_A4A3, "
                    "a^n_A4 = ω4²·O4A toward O4, a^t_A4 = α4·O4A, Coriolis a^k_A4A3 = 2·ω4·v_A4A3 "
                    "(v_A4A3 turned 90° in the sense of ω4); a_C = a_B + a^n_CB + a^t_CB (rod) with "
                    "a^n_CB = ω5²·L4, a^t_CB = α5·L4.")),
        p(translate("Report", "<b>Forces.</b> Kinetostatics at constant crank speed (d'Alembert): "
                    "inertia forces F_I = −m·a_S and moments −J·α are applied and each link is in "
                    "equilibrium; joints are frictionless. The cutting force P acts against the cut between "
                    "idle·H and (1 − idle)·H of the working stroke.")),
        p(translate("Report", "<b>Flywheel.</b> M_m = (1/2π)∮M dφ; P_m = M_m·ω; "
                    "ΔW_max = max − min of ∫(M − M_m) dφ; J_F = ΔW_max/(ω²·δ) on the crank shaft "
                    "(on a shaft turning i times faster: J_F/i²).")),
        p(translate("Report", "<b>Method.</b> All values are computed in closed form from the exact "
                    "position solution and its derivatives (no numerical differentiation); special "
                    "positions are exact roots. Every number equals the output of the shaper command "
                    "line for the same inputs.")),
    ]
