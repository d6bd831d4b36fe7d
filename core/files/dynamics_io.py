"""Dynamics results as CSV and JSON: formatting only, never computing.

Beside ``io`` at the last level of core; it reuses ``io.table_csv`` so the
dynamics CSV has the same number format as the curves CSV.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from core.forces.dynamics import Dynamics, DynamicsSummary
from core.forces.masses import GRAVITY, MassProperties
from core.linkage.geometry import Design
from .io import finite_or_none, table_csv

LEAD_COLUMNS = ("rpm", "crank_deg", "crank_torque_N_m", "power_W")

# (CSV column, Dynamics field); the C columns exist for the rod variant only.
FORCE_COLUMNS = (
    ("O2_x_N", "o2_x"), ("O2_y_N", "o2_y"),
    ("pin_A_x_N", "pin_x"), ("pin_A_y_N", "pin_y"),
    ("A_x_N", "a_x"), ("A_y_N", "a_y"), ("A_normal_N", "slot_normal"),
    ("O4_x_N", "o4_x"), ("O4_y_N", "o4_y"),
    ("B_x_N", "b_x"), ("B_y_N", "b_y"),
    ("C_x_N", "c_x"), ("C_y_N", "c_y"),
    ("guide_normal_N", "guide_normal"), ("guide_moment_N_m", "guide_moment"),
    ("guide_offset_mm", "guide_offset_mm"), ("guide_rear_N", "guide_rear_N"),
    ("guide_front_N", "guide_front_N"), ("guide_tilted", "guide_tilted"), ("cut_force_N", "cut_force"),
)

FLAG_COLUMNS = ("guide_tilted",)
"""Columns that are a yes/no, 1 or 0 in the tables and the CSV (a spreadsheet sums them:
the positions where the ram tilts); a reader shows them as yes and no (the Positions tab)."""


def dynamics_table(dyn: Dynamics) -> tuple[tuple[str, ...], np.ndarray]:
    """Long-form table, one row per (rpm, angle): column names and a 2-D array."""
    m, n = dyn.crank_torque.shape
    columns: list[tuple[str, np.ndarray]] = [
        ("rpm", np.broadcast_to(dyn.rpm[:, None], (m, n))),
        ("crank_deg", np.broadcast_to(np.degrees(dyn.crank_angle), (m, n))),
        ("crank_torque_N_m", dyn.crank_torque),
        ("power_W", dyn.power),
    ]
    columns += [(name, getattr(dyn, field)) for name, field in FORCE_COLUMNS
                if getattr(dyn, field) is not None]
    names = tuple(name for name, _ in columns)
    data = np.stack([np.asarray(v, dtype=float).reshape(-1) for _, v in columns], axis=1)
    return names, data


def dynamics_csv(dyn: Dynamics) -> str:
    return table_csv(*dynamics_table(dyn))


def masses_document(masses: MassProperties, design: Design) -> dict[str, Any]:
    """The inputs as used (lever cg resolved for ``design``), units in the keys."""
    return {
        "lever_mass_kg": masses.lever_mass_kg,
        "lever_weight_N": masses.weight("lever_mass_kg"),
        "lever_cg_mm": masses.lever_cg(design),
        "lever_inertia_kg_m2": masses.lever_inertia_kg_m2,
        "ram_mass_kg": masses.ram_mass_kg,
        "ram_weight_N": masses.weight("ram_mass_kg"),
        "ram_cg_mm": list(masses.ram_cg_mm),
        "rod_mass_kg": masses.rod_mass_kg,
        "crank_mass_kg": masses.crank_mass_kg,
        "block_mass_kg": masses.block_mass_kg,
        "cut_force_N": masses.cut_force_N,
        "cut_height_mm": masses.cut_height_mm,
        "idle_fraction": masses.idle_fraction,
        "gravity": masses.gravity,
        "g_m_s2": GRAVITY if masses.gravity else 0.0,
        "delta": masses.delta,
        "guide_length_mm": masses.guide_length(design),
        "rotors": [{"J_kg_m2": j, "speed_ratio": r} for j, r in masses.rotors],
    }


def summary_document(summary: DynamicsSummary, design: Design) -> dict[str, Any]:
    """JSON-ready cycle values per speed plus the inputs they came from."""
    return {
        "inputs": masses_document(summary.masses, design),
        "energy_intervals": int(summary.crank_angle.size - 1),
        "equivalent_inertia_mean_kg_m2": summary.equivalent_inertia_mean_kg_m2,
        "rotor_inertia_kg_m2": summary.rotor_inertia_kg_m2,
        "speeds": [
            {"rpm": s.rpm, "omega_rad_s": s.omega_rad_s,
             "mean_torque_N_m": finite_or_none(s.mean_torque_N_m),
             "max_torque_N_m": finite_or_none(s.max_torque_N_m),
             "min_torque_N_m": finite_or_none(s.min_torque_N_m),
             "mean_power_W": finite_or_none(s.mean_power_W),
             "max_power_W": finite_or_none(s.max_power_W),
             "energy_fluctuation_J": finite_or_none(s.energy_fluctuation_J),
             "flywheel_inertia_kg_m2": finite_or_none(s.flywheel_inertia_kg_m2),
             "flywheel_inertia_needed_kg_m2": finite_or_none(s.flywheel_inertia_needed_kg_m2),
             "flywheel_needed": s.flywheel_needed,
             "flywheel_inertia_net_kg_m2": finite_or_none(s.flywheel_inertia_net_kg_m2)}
            for s in summary.speeds
        ],
    }
