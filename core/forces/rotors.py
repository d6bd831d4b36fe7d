"""The other rotating parts of the drive (crank shaft, gears, motor rotor) as the flywheel
sees them: each a moment of inertia J_i and its speed over the crank's, ω_i/ω2.

Turning with the crank at a fixed ratio, a part holds the kinetic energy ½·J_i·ω_i² =
½·J_i·(ω_i/ω2)²·ω2², so reduced to the crank it is J_i·(ω_i/ω2)² and all of them
J_c = Σ J_i·(ω_i/ω2)²: the flywheel the task book asks for is J_F − J_c.

Text form (the CLI's ``--rotor J:RATIO``, the Loads form's field): ``J:RATIO`` per part,
several separated by ``;``. Level: beside ``errors``; imports nothing of the mechanism.
"""
from __future__ import annotations

from core.base.errors import DesignError, require_range

MAX_ROTORS = 20
MAX_INERTIA_KG_M2 = 1e6
MAX_ROTOR_RATIO = 1e4        # ω_i/ω2: a motor at 1500 r/min over a crank at 0.15 r/min
Rotors = tuple[tuple[float, float], ...]


def check_rotors(value: object) -> Rotors:
    """The rotating parts as a tuple of checked (J kg·m², ω_i/ω2) pairs; DesignError names
    ``rotors`` (a bad shape), ``rotor_inertia_kg_m2`` or ``rotor_ratio``. Text (a form's
    field as typed) is read by :func:`rotors_from_text`."""
    if isinstance(value, str):
        return rotors_from_text(value)
    try:
        pairs = [tuple(p) for p in value]  # type: ignore[union-attr]
    except TypeError:
        raise DesignError("rotors", value, "must be a list of (J kg·m², speed ratio) pairs") from None
    if len(pairs) > MAX_ROTORS:
        raise DesignError("rotors", len(pairs), f"at most {MAX_ROTORS} rotating parts")
    out = []
    for pair in pairs:
        if len(pair) != 2:
            raise DesignError("rotors", pair, "each must be a pair (J kg·m², speed ratio)")
        out.append((require_range("rotor_inertia_kg_m2", pair[0], 0.0, MAX_INERTIA_KG_M2, "kg·m²",
                                  low_open=False),
                    require_range("rotor_ratio", pair[1], 0.0, MAX_ROTOR_RATIO)))
    return tuple(out)


def reduced_inertia(rotors: Rotors) -> float:
    """J_c = Σ J_i·(ω_i/ω2)², kg·m²."""
    return float(sum(j * ratio ** 2 for j, ratio in rotors))


def rotor_from_text(text: str, gear_ratio: float | None = None) -> tuple[float, float]:
    """One ``J:RATIO`` as (J, ratio); ``J:gear`` takes ``gear_ratio`` (z2/z1 of the design's
    gear pair, the pinion shaft's speed over the crank's). DesignError names the part."""
    inertia, sep, ratio = text.partition(":")
    if not sep:
        raise DesignError("rotors", text, "must be J:RATIO (kg·m² and speed over the crank's) or J:gear")
    j = _number("rotor_inertia_kg_m2", inertia)
    if ratio.strip().lower() == "gear":
        if gear_ratio is None:
            raise DesignError("rotors", text, "J:gear needs a design with a gear pair")
        return j, gear_ratio
    return j, _number("rotor_ratio", ratio)


def rotors_from_text(text: str, gear_ratio: float | None = None) -> Rotors:
    """``J:RATIO; J:RATIO …`` (empty: none) as checked pairs."""
    parts = [p.strip() for p in text.split(";") if p.strip()]
    return check_rotors([rotor_from_text(p, gear_ratio) for p in parts])


def rotors_text(rotors: Rotors) -> str:
    """The text form of ``rotors``, read back by :func:`rotors_from_text`."""
    return "; ".join(f"{j:g}:{r:g}" for j, r in rotors)


def _number(name: str, text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise DesignError(name, text, "must be a number") from None
    return value
