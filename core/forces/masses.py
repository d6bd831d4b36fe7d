"""The loads a kinetostatic solve adds to a design: masses, weights, inertias, centres of mass,
the cutting force and the flywheel target, each validated on construction.

Kept apart from :mod:`core.forces.dynamics`, which solves with them, so that a design file,
a form or the sweep can hold and check loads without the solver.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from core.base.errors import DesignError, require_range
from core.linkage.geometry import MAX_LENGTH_MM, Design
from .rotors import MAX_INERTIA_KG_M2, check_rotors, reduced_inertia

GRAVITY = 9.81               # m/s², acting toward −y
MM = 1e-3                    # m per mm
MAX_MASS_KG = 1e6

MAX_FORCE_N = 1e9
WEIGHTS = (("lever_mass_kg", "lever_weight_N"), ("ram_mass_kg", "ram_weight_N"))
"""Each link whose load may be stated as a weight: (mass field, weight field)."""
MIN_DELTA = 1e-4             # finest speed fluctuation: keeps J_F = ΔW/(ω²·δ) finite at any speed


@dataclass(frozen=True)
class MassProperties:
    """Masses, loads and the flywheel target: what dynamics adds to a design.

    Every value is validated on construction (DesignError naming the field)
    and stored as a float, so a ``MassProperties`` is always usable.
    """

    lever_mass_kg: float = 0.0
    """Mass of the slotted lever O4B, kg."""
    lever_cg_mm: float | None = None
    """Distance of the lever's centre of mass from O4 along O4→B, mm; None = L3/2."""
    lever_inertia_kg_m2: float = 0.0
    """Lever moment of inertia about its own centre of mass, kg·m²."""
    ram_mass_kg: float = 0.0
    """Ram plus tool, kg."""
    ram_cg_mm: tuple[float, float] = (0.0, 0.0)
    """(dx, dy) of the ram's centre of mass from the ram joint C, mm."""
    rod_mass_kg: float = 0.0
    """Connecting rod BC (rod variant only), a uniform slender bar: cg mid-way, J = m·L4²/12."""
    crank_mass_kg: float = 0.0
    """Crank, balanced (cg at O2): adds its weight to the bearing O2 only, kg."""
    block_mass_kg: float = 0.0
    """Sliding block at the crank pin A, a point mass turning with the lever, kg."""
    cut_force_N: float = 0.0
    """Cutting force P on the tool, acting in −x on the ram while cutting, N."""
    cut_height_mm: float = 0.0
    """Height of the tool point below the ram guide line, mm (negative = above)."""
    idle_fraction: float = 0.05
    """Uncut run-in and run-out, each as a fraction of the stroke H, in [0, 0.5)."""
    gravity: bool = True
    """Whether the links' weights (g = 9.81 m/s² toward −y) are loads."""
    delta: float = 1.0 / 30.0
    """Coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_mean the flywheel must hold, (0, 1)."""
    lever_weight_N: float | None = None
    """The lever's weight G4 as the task book states it, N; None = given as a mass. When
    given, ``lever_mass_kg`` is G4/g (g = :data:`GRAVITY`), so G4 prints back as typed."""
    ram_weight_N: float | None = None
    """The ram's weight G6 (ram plus tool), N; None = given as a mass. As ``lever_weight_N``."""
    rotors: tuple[tuple[float, float], ...] = ()
    """The other rotating parts (crank shaft, gears, motor rotor), each (J_i kg·m², ω_i/ω2):
    reduced to the crank, Σ J_i·(ω_i/ω2)², they count toward the flywheel J_F."""
    guide_length_mm: float | None = None
    """Length of the ram's guide (the column's ways), mm, centred on the mid-travel of the
    ram joint C; None = the stroke H. Where the guide's resultant falls outside it, the ram
    tilts and bears on its two ends (:mod:`core.forces.guide`)."""

    def __post_init__(self) -> None:
        def put(name: str, value: object) -> None:
            object.__setattr__(self, name, value)

        for name in ("lever_mass_kg", "ram_mass_kg", "rod_mass_kg", "crank_mass_kg",
                     "block_mass_kg"):
            put(name, require_range(name, getattr(self, name), 0.0, MAX_MASS_KG, "kg",
                                    low_open=False))
        put("lever_inertia_kg_m2", require_range("lever_inertia_kg_m2", self.lever_inertia_kg_m2,
                                                 0.0, MAX_INERTIA_KG_M2, "kg·m²", low_open=False))
        if self.lever_cg_mm is not None:
            put("lever_cg_mm", require_range("lever_cg_mm", self.lever_cg_mm, -MAX_LENGTH_MM,
                                             MAX_LENGTH_MM, "mm", low_open=False))
        put("ram_cg_mm", _offset("ram_cg_mm", self.ram_cg_mm))
        put("cut_force_N", require_range("cut_force_N", self.cut_force_N, 0.0, MAX_FORCE_N, "N",
                                         low_open=False))
        put("cut_height_mm", require_range("cut_height_mm", self.cut_height_mm, -MAX_LENGTH_MM,
                                           MAX_LENGTH_MM, "mm", low_open=False))
        put("idle_fraction", require_range("idle_fraction", self.idle_fraction, 0.0, 0.5,
                                           low_open=False, high_open=True))
        put("delta", require_range("delta", self.delta, MIN_DELTA, 1.0, low_open=False,
                                   high_open=True))
        for mass, weight in WEIGHTS:
            put(mass, self._from_weight(mass, weight))
        put("rotors", check_rotors(self.rotors))
        if self.guide_length_mm is not None:
            # at least 1 mm: the end forces are the moment over the length, and a length
            # of 1e-320 mm made them infinite (the CLI fuzz's edge values)
            put("guide_length_mm", require_range("guide_length_mm", self.guide_length_mm, 1.0,
                                                 MAX_LENGTH_MM, "mm", low_open=False))
        if not isinstance(self.gravity, (bool, np.bool_)):
            raise DesignError("gravity", self.gravity, "must be true or false")
        put("gravity", bool(self.gravity))

    def _from_weight(self, mass: str, weight: str) -> float:
        """The link's mass: as given, or its weight / g. A mass and a weight of one link
        given together are refused (the mass that a weight gave is accepted back, so that
        ``dataclasses.replace`` keeps working)."""
        value = getattr(self, weight)
        if value is None:
            return getattr(self, mass)
        value = require_range(weight, value, 0.0, MAX_MASS_KG * GRAVITY, "N", low_open=False)
        object.__setattr__(self, weight, value)
        derived = value / GRAVITY
        if getattr(self, mass) not in (0.0, derived):
            raise DesignError(mass, getattr(self, mass), f"give either {mass} or {weight}, not both")
        return derived

    def weight(self, mass: str) -> float:
        """The weight of the link whose mass field is ``mass``, N: as given (G4 = 200 N
        prints 200), else mass·g."""
        given = getattr(self, dict(WEIGHTS)[mass])
        return given if given is not None else getattr(self, mass) * GRAVITY

    @property
    def rotor_inertia_kg_m2(self) -> float:
        """J_c = Σ J_i·(ω_i/ω2)²: the other rotating parts reduced to the crank, kg·m²."""
        return reduced_inertia(self.rotors)

    def guide_length(self, design: Design) -> float:
        """The ram guide's length for ``design``, mm (None = the stroke H)."""
        return design.stroke if self.guide_length_mm is None else self.guide_length_mm

    def lever_cg(self, design: Design) -> float:
        """The lever's centre-of-mass distance from O4 for ``design``, mm."""
        return design.lever / 2.0 if self.lever_cg_mm is None else self.lever_cg_mm

    @property
    def g(self) -> float:
        """Gravitational acceleration used, m/s² (0 when gravity is off)."""
        return GRAVITY if self.gravity else 0.0


def masses_for_design(design: Design, masses: MassProperties) -> MassProperties:
    """The loads as solved for ``design``: the block variant has no rod, so a rod mass
    left over from the rod variant (a form or file keeps it) is ignored."""
    if design.rod is None and masses.rod_mass_kg:
        return replace(masses, rod_mass_kg=0.0)
    return masses


def _offset(name: str, value: object) -> tuple[float, float]:
    try:
        dx, dy = value  # type: ignore[misc]
    except (TypeError, ValueError):
        raise DesignError(name, value, "must be a pair (dx, dy) in mm") from None
    return (require_range(name, dx, -MAX_LENGTH_MM, MAX_LENGTH_MM, "mm", low_open=False),
            require_range(name, dy, -MAX_LENGTH_MM, MAX_LENGTH_MM, "mm", low_open=False))
