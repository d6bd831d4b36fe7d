"""The pair's results as JSON (the keys other tools read) and as the rows a table prints."""
from __future__ import annotations

import math
from typing import Any

from core.base.figure_text import figure_text
from .checks import pair_checks
from .inputs import GearPairInputs
from .pair import Gear, GearPair

MODE_TEXT = {"given": "x1 and x2 given",
             "centre": "from the centre distance: the pinion's least uncut shift, the rest to the gear",
             "balanced": "rule: z1 + z2 ≥ 2 zmin, the pinion's least uncut shift and x2 = −x1",
             "positive": "rule: z1 + z2 < 2 zmin, the least positive pair at a′ rounded up to a "
                         "step of about m/10"}


def tip_limit_text(p: GearPairInputs) -> str:
    """The least tip thickness as the factor of the module and in mm, '0.25·m (= 1.5 mm)':
    "0.25 m" read as metres (issue 40)."""
    return f"{p.tip_limit:g}·m (= {p.tip_limit * p.module_mm:.6g} mm)"


def _gear_json(gear: Gear) -> dict[str, Any]:
    return {"teeth": gear.teeth, "shift_factor": gear.shift, "least_shift_factor": gear.least_shift,
            "reference_diameter_mm": 2 * gear.r, "base_diameter_mm": 2 * gear.rb,
            "tip_diameter_mm": 2 * gear.ra, "root_diameter_mm": 2 * gear.rf,
            "working_diameter_mm": 2 * gear.rw, "reference_thickness_mm": gear.s,
            "reference_space_mm": gear.e, "tip_thickness_mm": gear.sa, "undercut": gear.undercut}


def gear_summary(pair: GearPair) -> dict[str, Any]:
    """Every result, keyed as issue 35 lists them (``pair``, ``gear1``, ``gear2``) plus the
    inputs, the checks and how the shifts were chosen."""
    p = pair.inputs
    return {
        "inputs": {"module_mm": p.module_mm, "pressure_angle_deg": p.pressure_angle_deg,
                   "addendum_factor": p.addendum, "clearance_factor": p.clearance,
                   "tip_limit_module": p.tip_limit, "contact_ratio_limit": p.contact_limit,
                   "module_note": p.module_note},
        "pair": {"centre_mm": pair.centre_mm, "reference_centre_mm": pair.reference_centre_mm,
                 "working_pressure_angle_deg": math.degrees(pair.alpha_w),
                 "centre_shift_factor": pair.y, "addendum_reduction_factor": pair.dy,
                 "contact_ratio": pair.contact_ratio, "base_pitch_mm": pair.pb,
                 "line_of_action_mm": pair.n1n2, "actual_line_of_action_mm": pair.b1b2,
                 "ratio": p.z2 / p.z1, "shift_mode": pair.mode},
        "gear1": _gear_json(pair.gear1),
        "gear2": _gear_json(pair.gear2),
        "checks": [{"name": c.name, "ok": c.ok, "value": c.value, "limit": c.limit,
                    "advice": c.advice} for c in pair_checks(pair)],
    }


def summary_rows(pair: GearPair) -> list[tuple[str, str]]:
    """(label, value) of the results, as ``shaper gear`` prints them."""
    g1, g2, f = pair.gear1, pair.gear2, figure_text
    rows = [("shifts", MODE_TEXT[pair.mode]),
            ("centre distance a′ (a)", f"{f('gear_length', pair.centre_mm)} mm "
                                       f"({f('gear_length', pair.reference_centre_mm)} mm)"),
            ("working pressure angle α′", f"{f('gear_angle', math.degrees(pair.alpha_w))}°"),
            ("centre shift y / addendum reduction Δy", f"{pair.y:.6f} / {pair.dy:.6f}"),
            ("shift factor x1 / x2", f"{f('gear_factor', g1.shift)} / {f('gear_factor', g2.shift)}"),
            ("least shift x1min / x2min", f"{g1.least_shift:.6f} / {g2.least_shift:.6f}")]
    for label, attr in (("reference diameter d", "r"), ("base diameter db", "rb"),
                        ("tip diameter da", "ra"), ("root diameter df", "rf"),
                        ("working diameter d′", "rw")):
        rows.append((f"{label}1 / {label.split()[-1]}2",
                     f"{2 * getattr(g1, attr):.4f} / {2 * getattr(g2, attr):.4f} mm"))
    rows += [("thickness s1 / s2 (reference)", f"{g1.s:.4f} / {g2.s:.4f} mm"),
             ("space e1 / e2 (reference)", f"{g1.e:.4f} / {g2.e:.4f} mm"),
             ("tip thickness sa1 / sa2", f"{g1.sa:.4f} / {g2.sa:.4f} mm"),
             ("line of action N1N2 / B1B2", f"{pair.n1n2:.4f} / {pair.b1b2:.4f} mm"),
             ("base pitch pb", f"{pair.pb:.4f} mm"),
             ("contact ratio ε", f('gear_factor', pair.contact_ratio)),
             ("least tip thickness", tip_limit_text(pair.inputs))]
    if pair.inputs.module_note:
        rows.append(("note", pair.inputs.module_note))
    for check in pair_checks(pair):
        rows.append((f"check {check.name}", "ok" if check.ok else f"FAILS: {check.advice}"))
    return rows


def summary_csv(summary: dict) -> str:
    """One row per quantity: name (units in it), gear 1 (or the pair's value), gear 2."""
    lines = ["quantity,pair_or_gear1,gear2"]
    for key, value in summary["pair"].items():
        lines.append(f"{key},{_cell(value)},")
    for key in summary["gear1"]:
        lines.append(f"{key},{_cell(summary['gear1'][key])},{_cell(summary['gear2'][key])}")
    return "\n".join(lines) + "\n"


def _cell(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else ""
    return str(value)
