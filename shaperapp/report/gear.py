"""The report's gear-pair section (issue 35, item 5): the inputs, which shifts and why, the
results with their formulas, the checks with what to change, and the pair in mesh to scale.

Every number comes from ``core.gear``: the pair's figures are ``shaper gear``'s own rows
(``core.gear.table.summary_rows``) under translated labels, the per-gear table the lengths
of :class:`core.gear.Gear`, the checks :func:`core.gear.pair_checks`. The words are the
report's (no English in a Chinese report): core's English advice is not printed, each check
is said again here, in the report's language, with core's numbers.
"""
from __future__ import annotations

import html
import math

from PySide6.QtCore import QCoreApplication

from core.drawing.cam_sheet import ratio_text
from core.drawing.scales import number_text
from core.base.errors import DesignError
from core.base.figure_text import figure_text
from core.gear import Check, GearPair, GearPairInputs, design_pair, pair_checks
from core.gear.involute import least_teeth
from core.gear.shift import centre_step, mesh_of_sum
from core.gear.table import summary_rows, tip_limit_text
from shaperapp.widgets.gear_messages import check_advice, describe_gear_error
from shaperapp.widgets.i18n import join_sentences
from shaperapp.widgets.notation import typeset

from .blocks import Figure, Heading, KeyValues, Paragraph, Table
from .gear_figure import gear_figure

translate = QCoreApplication.translate   # lupdate extracts translate("Report", "…")

# The formulas (docs/methods.md, "The gear pair"), typeset; the same in every language.
FORMULAS = (
    ("meshing", "inv α = tan α − α;&nbsp; inv α′ = 2 tan α (x<sub>1</sub> + x<sub>2</sub>)/(z<sub>1</sub> + "
                "z<sub>2</sub>) + inv α;&nbsp; a = m (z<sub>1</sub> + z<sub>2</sub>)/2;&nbsp; a′ cos α′ = "
                "a cos α;&nbsp; y = (a′ − a)/m;&nbsp; Δy = x<sub>1</sub> + x<sub>2</sub> − y"),
    ("undercut", "x<sub>min</sub> = h<sub>a</sub><sup>*</sup> (z<sub>min</sub> − z)/z<sub>min</sub>,&nbsp; "
                 "z<sub>min</sub> = 2 h<sub>a</sub><sup>*</sup>/sin²α"),
    ("gear", "r = m z/2;&nbsp; r<sub>b</sub> = r cos α;&nbsp; r<sub>a</sub> = r + (h<sub>a</sub><sup>*</sup> + "
             "x − Δy) m;&nbsp; r<sub>f</sub> = r − (h<sub>a</sub><sup>*</sup> + c<sup>*</sup> − x) m;&nbsp; "
             "r′ = r<sub>b</sub>/cos α′;&nbsp; s = m (π/2 + 2 x tan α);&nbsp; e = π m − s;&nbsp; "
             "s<sub>a</sub> = s r<sub>a</sub>/r − 2 r<sub>a</sub> (inv α<sub>a</sub> − inv α),&nbsp; "
             "cos α<sub>a</sub> = r<sub>b</sub>/r<sub>a</sub>"),
    ("line", "N<sub>1</sub>N<sub>2</sub> = a′ sin α′;&nbsp; B<sub>1</sub>B<sub>2</sub> = "
             "√(r<sub>a1</sub>² − r<sub>b1</sub>²) + √(r<sub>a2</sub>² − r<sub>b2</sub>²) − a′ sin α′;&nbsp; "
             "p<sub>b</sub> = π m cos α;&nbsp; ε = [z<sub>1</sub> (tan α<sub>a1</sub> − tan α′) + "
             "z<sub>2</sub> (tan α<sub>a2</sub> − tan α′)]/2π = B<sub>1</sub>B<sub>2</sub>/p<sub>b</sub>"),
)


def _formula_names() -> dict[str, str]:
    return {"meshing": translate("Report", "Meshing without backlash."),
            "undercut": translate("Report", "Least shift without undercut."),
            "gear": translate("Report", "Each gear."),
            "line": translate("Report", "Line of action and contact ratio.")}


def gear_blocks(inputs: GearPairInputs, number: int, language: str) -> list:
    """The gear section numbered ``number``; a pair core refuses is one paragraph saying why."""
    blocks: list = [Heading(translate("Report", "%1 The gear pair").replace("%1", str(number)))]
    try:
        pair = design_pair(inputs)
    except DesignError as exc:
        blocks.append(Paragraph(translate("Report", "The gear pair cannot be made: %1")
                                .replace("%1", describe_gear_error(exc))))
        return blocks
    blocks.append(KeyValues(_inputs(pair)))
    blocks.append(Paragraph(shift_reason(pair)))
    blocks.append(KeyValues(_pair_rows(pair)))
    blocks.append(_gear_table(pair))
    names = _formula_names()
    blocks += [Paragraph(f"<b>{names[key]}</b>{'' if names[key].endswith('。') else ' '}{text}")
               for key, text in FORMULAS]
    blocks += _checks(pair)
    figure = gear_figure(pair, language)
    blocks.append(Figure(translate("Report", "The pair in mesh at a′ = %1 mm, to scale %2 (μl = %3 m/mm), "
                                   "the teeth as the rack cuts them; the pinion 1 drives "
                                   "counter-clockwise. N1N2 the line of action, B1B2 the actual one, "
                                   "P the pitch point")
                         .replace("%1", f"{pair.centre_mm:.4f}").replace("%2", ratio_text(figure.scale))
                         .replace("%3", number_text(figure.scale / 1000.0)),     # as the sheets write μl
                         figure.width_mm, figure.height_mm, figure.paint, to_scale=True))
    return blocks


def _inputs(pair: GearPair) -> list[tuple[str, str]]:
    p = pair.inputs
    rows = [(translate("Report", "Teeth z_1 / z_2"), f"{p.z1} / {p.z2}"),
            (translate("Report", "Module m"), f"{p.module_mm:g} mm")]
    if p.module_note:
        rows.append((translate("Report", "Note"),
                     translate("Report", "m = %1 mm is not a module of GB/T 1357's first series")
                     .replace("%1", f"{p.module_mm:g}")))
    rows += [(translate("Report", "Basic rack α, h_a*, c*"),
              f"{p.pressure_angle_deg:g}°, {p.addendum:g}, {p.clearance:g}")]
    if p.x1 is not None:
        given = f"x_1 = {p.x1:g}, x_2 = {p.x2:g}"
    elif p.centre_mm is not None:
        given = f"a′ = {p.centre_mm:g} mm"
    else:
        given = translate("Report", "neither shifts nor a centre distance (the rule)")
    rows += [(translate("Report", "Given"), given),
             (translate("Report", "Least tip thickness s_a"), tip_limit_text(p)),
             (translate("Report", "Least contact ratio ε"), f"{p.contact_limit:g}")]
    return rows


def shift_reason(pair: GearPair) -> str:
    """Which rule of ``core.gear.shift`` gave the shifts, and why it applied, with core's numbers."""
    p, g1, g2 = pair.inputs, pair.gear1, pair.gear2
    z_min = least_teeth(p.alpha, p.addendum)
    values = {"%1": f"{g1.shift:.6f}", "%2": f"{g2.shift:.6f}", "%3": f"{g1.least_shift:.6f}",
              "%4": f"{g2.least_shift:.6f}", "%5": f"{p.z1 + p.z2}", "%6": f"{2 * z_min:.4f}",
              "%7": f"{pair.centre_mm:.4f}", "%8": f"{g1.shift + g2.shift:.6f}"}
    split = translate("Report", "The pinion, with fewer teeth, is the one that undercuts, so it gets its "
                      "least shift without undercut (not below 0) and the gear the rest; if that left "
                      "the gear undercut, the pinion would give up what the gear needs.")
    if pair.mode == "given":
        text = translate("Report", "The shifts x_1 = %1 and x_2 = %2 are given; α′ and a′ follow from "
                         "the no-backlash condition. Least shifts without undercut: x_1min = %3, "
                         "x_2min = %4.")
    elif pair.mode == "centre":
        text = translate("Report", "The centre distance a′ = %7 mm is given: the no-backlash "
                         "condition asks x_1 + x_2 = %8, shared out as x_1 = %1, x_2 = %2 (x_1min = %3, "
                         "x_2min = %4).")
        text = join_sentences(text, split)
    elif pair.mode == "balanced":
        text = translate("Report", "Neither shifts nor a centre distance are given, and z_1 + z_2 = %5 ≥ "
                         "2 z_min = %6: the pinion gets its least shift without undercut, x_1 = "
                         "max(x_1min, 0) = %1, and the gear x_2 = −x_1 = %2, so a′ = a = %7 mm (a "
                         "height-modified pair).")
    else:
        least = mesh_of_sum(p, max(g1.least_shift, 0.0) + max(g2.least_shift, 0.0))[1]
        values["%9"] = f"{least:.4f}"
        values["%10"] = f"{centre_step(p.module_mm):g}"
        text = translate("Report", "Neither shifts nor a centre distance are given, and z_1 + z_2 = %5 < "
                         "2 z_min = %6, so x_2 = −x_1 would undercut the gear: the least positive pair "
                         "(x_1min = %3, x_2min = %4) meshes at %9 mm, rounded up to a multiple of %10 mm (about m/10) a′ = %7 mm, "
                         "which asks x_1 + x_2 = %8, shared out as x_1 = %1, x_2 = %2.")
        text = join_sentences(text, split)
    for key in sorted(values, reverse=True):          # %9 before %1 …
        text = text.replace(key, values[key])
    return typeset(html.escape(text))


def _pair_rows(pair: GearPair) -> list[tuple[str, str]]:
    """The pair's figures as ``shaper gear`` prints them, under the report's labels."""
    labels = {"centre distance a′ (a)": translate("Report", "Centre distance a′ (a)"),
              "working pressure angle α′": translate("Report", "Working pressure angle α′"),
              "centre shift y / addendum reduction Δy":
                  translate("Report", "Centre distance shift factor y / addendum reduction factor Δy"),
              "line of action N1N2 / B1B2":
                  translate("Report", "Line of action N1N2 / actual line of action B1B2"),
              "base pitch pb": translate("Report", "Base pitch pb"),
              "contact ratio ε": translate("Report", "Contact ratio ε")}
    return [(labels[key], value) for key, value in summary_rows(pair) if key in labels]


def _gear_table(pair: GearPair) -> Table:
    """Each gear's shift and lengths, to the digits ``shaper gear`` prints."""
    g1, g2 = pair.gear1, pair.gear2
    rows = [[translate("Report", "Teeth z"), str(g1.teeth), str(g2.teeth)]]
    for label, attr, digits in (
            (translate("Report", "Shift factor x"), "shift", 6),
            (translate("Report", "Least shift x_min"), "least_shift", 6),
            (translate("Report", "Reference radius r (mm)"), "r", 4),
            (translate("Report", "Base radius r_b (mm)"), "rb", 4),
            (translate("Report", "Tip radius r_a (mm)"), "ra", 4),
            (translate("Report", "Root radius r_f (mm)"), "rf", 4),
            (translate("Report", "Working pitch radius r′ (mm)"), "rw", 4),
            (translate("Report", "Tooth thickness s on the reference circle (mm)"), "s", 4),
            (translate("Report", "Space e on the reference circle (mm)"), "e", 4),
            (translate("Report", "Tip thickness s_a (mm)"), "sa", 4)):
        rows.append([label, f"{getattr(g1, attr):.{digits}f}", f"{getattr(g2, attr):.{digits}f}"])
    rows.append([translate("Report", "Profile angle at the tip α_a (°)"),
                 f"{math.degrees(g1.alpha_a):.4f}", f"{math.degrees(g2.alpha_a):.4f}"])
    return Table([translate("Report", "Quantity"), translate("Report", "Pinion 1"),
                  translate("Report", "Gear 2")], rows, translate("Report", "The two gears"))


def _check_texts(check: Check, p: GearPairInputs) -> tuple[str, str]:
    """(what is checked, the unit of its value and limit) in the report's language; what
    to change when it fails is the Gear tab's advice (``widgets.gear_messages``)."""
    k = check.name[-1]
    sub = lambda text: text.replace("%1", k).replace("%2", "2" if k == "1" else "1")  # noqa: E731
    if check.name.startswith("undercut"):
        return sub(translate("Report", "No undercut of gear %1: x_%1 ≥ x_%1min")), ""
    if check.name.startswith("tip"):
        return (sub(translate("Report", "Tip thickness of gear %1: s_a%1 ≥ %3"))
                .replace("%3", tip_limit_text(p)), " mm")
    if check.name == "contact":
        return translate("Report", "Contact ratio ε ≥ %1").replace("%1", f"{p.contact_limit:g}"), ""
    return (sub(translate("Report", "No interference at the root of gear %1 (N_%1 to the tip of gear %2)")),
            " mm")


def _checks(pair: GearPair) -> list:
    """Every check of core in a table, then each failing one with what to change."""
    rows, shaded, advice = [], [], []
    for check in pair_checks(pair):
        what, unit = _check_texts(check, pair.inputs)
        kind = "gear_length" if unit else "gear_factor"     # as the pair's rows write a length, x or ε
        rows.append([what, f"{figure_text(kind, check.value)}{unit}", f"{figure_text(kind, check.limit)}{unit}",
                     translate("Report", "ok") if check.ok else translate("Report", "fails")])
        shaded.append(not check.ok)
        if not check.ok:
            advice.append(Paragraph(translate("Report", "%1: %2").replace("%1", f"<b>{html.escape(what)}</b>")
                                    .replace("%2", html.escape(check_advice(check)))))
    table = Table([translate("Report", "Check"), translate("Report", "Value"),
                   translate("Report", "Limit"), translate("Report", "Result")], rows,
                  translate("Report", "The checks"), shaded=shaded)
    if not advice:
        return [table, Paragraph(translate("Report", "Every check passes."))]
    return [table, Paragraph(translate("Report", "What to change:"), True)] + advice
