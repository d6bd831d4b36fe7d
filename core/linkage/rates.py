"""The ram's φ-derivatives alone, up to the fourth: what the cycle's peaks are taken from.

Just above :mod:`core.linkage.kinematics` (with the analysis), whose closed form (the lever's,
the tip's and the ram's terms) it differentiates once and twice more. The sweep samples these rates
for ten thousands of designs and polishes their peaks by Newton's method
(:mod:`core.linkage.metrics`), so they are split where designs can share them: the
lever tip's terms depend on L1, L2 and L3 only (:func:`tip_rates`), the ram's on
the guide and the rod too (:func:`ram_rates`). :func:`rates_at` is both at once,
the same arithmetic, so its result does not depend on the split.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .designs import Designs
from .geometry import Design
from .kinematics import _Lever, _Ram, _Tip, _lever_terms, _ram_terms, _tip_terms


class Rates(NamedTuple):
    """The φ-derivatives the cycle's peaks are taken from (no positions)."""

    ram1: np.ndarray     # dCx/dφ, mm/rad
    ram2: np.ndarray     # d²Cx/dφ², mm/rad²
    ram3: np.ndarray     # d³Cx/dφ³, mm/rad³: where it vanishes, |d²Cx/dφ²| peaks


def rates_at(design: Design | Designs, cos_beta: np.ndarray, sin_beta: np.ndarray) -> Rates:
    """The ram's rates only (three φ-derivatives), by the closed form of :func:`shape_at`:
    :func:`ram_rates` of :func:`tip_rates`."""
    return ram_rates(design, *tip_rates(design, cos_beta, sin_beta))


def ram_velocity(design: Design | Designs, cos_beta: np.ndarray, sin_beta: np.ndarray,
                 ) -> np.ndarray:
    """dCx/dφ alone, mm/rad: :func:`rates_at`'s first rate by the same arithmetic, without
    the two higher ones (the dead points' root search needs no more)."""
    return _ram_terms(design, _tip_terms(design, _lever_terms(design, cos_beta, sin_beta))).c1


def tip_rates(design: Design | Designs, cos_beta: np.ndarray, sin_beta: np.ndarray,
              ) -> tuple[_Tip, np.ndarray, np.ndarray]:
    """The lever tip B and its first three φ-derivatives (B, B′, B″, then B‴x, −B‴y), which
    depend on L1, L2 and L3 only: designs sharing those can share them (a sweep of the rod
    and the guide).

    The third derivative is one more differentiation of the same closed
    form: ψ‴ = −L1·L2(L2² − L1²)(q·sin β + 4·L1·L2·cos²β)/q³ (see
    ``_lever_terms``); the tip B = L3·u gives B‴ = L3((ψ‴ − ψ′³)n − 3ψ′ψ″u).
    """
    lv = _lever_terms(design, cos_beta, sin_beta)
    tip = _tip_terms(design, lv)
    bx3, d3 = _tip3(design, lv, _lever3(design, lv.q, cos_beta, sin_beta))
    return tip, bx3, (bx3 if d3 is None else d3)


def _lever3(design, q: np.ndarray, cb: np.ndarray, sb: np.ndarray) -> np.ndarray:
    """ψ‴ = d/dφ of ψ″ = −L1·L2(L2² − L1²)·cos β/q²."""
    l1, l2 = design.crank, design.frame
    return -(l1 * l2 * (l2 * l2 - l1 * l1)) * (sb * q + (4.0 * l1 * l2) * cb * cb) / (q * q * q)


def _tip3(design, lv: _Lever, w3: np.ndarray) -> tuple[np.ndarray, np.ndarray | None]:
    """B‴x and d‴ = −B‴y (the latter for the rod variant only, else None)."""
    (ux, uy), w1, w2, l3 = lv.u, lv.lever1, lv.lever2, design.lever
    cube = w1 * w1 * w1
    bx3 = l3 * ((w3 - cube) * uy - 3.0 * w1 * w2 * ux)
    if design.rod is None:
        return bx3, None
    return bx3, l3 * ((w3 - cube) * ux + 3.0 * w1 * w2 * uy)


def _rod3(ram: _Ram, d3: np.ndarray) -> np.ndarray:
    """r‴ = −(3r′r″ + 3d′d″ + d·d‴)/r, from the rod's reach r² = L4² − d²."""
    return -(3.0 * ram.reach1 * ram.reach2 + 3.0 * ram.rise1 * ram.rise2 + ram.depth * d3) / ram.reach


def ram_rates(design: Design | Designs, tip: _Tip, bx3: np.ndarray, d3: np.ndarray) -> Rates:
    """The ram's rates from the tip's (:func:`tip_rates`, broadcasting against the design)."""
    ram = _ram_terms(design, tip)
    if design.rod is None:
        return Rates(ram.c1, ram.c2, bx3)
    return Rates(ram.c1, ram.c2, bx3 + design.rod_sign * _rod3(ram, d3))


def lever_jet(design: Design | Designs, cos_beta: np.ndarray, sin_beta: np.ndarray,
              fourth: bool = True) -> tuple[_Lever, np.ndarray, np.ndarray | None, np.ndarray,
                                             np.ndarray | None]:
    """The lever's terms with ψ‴ and ψ⁗, and the tip's third and fourth derivatives B‴, B⁗
    ((2, …) mm/rad³, mm/rad⁴): what the ram's and the loads' higher rates are built from.

    With L = L1·L2: ψ⁗ = L(L2² − L1²)·cos β·(q² − 12L·q·sin β − 24L²cos²β)/q⁴; the
    tip B‴ = L3((ψ‴ − ψ′³)n − 3ψ′ψ″u) and B⁗ = L3((ψ⁗ − 6ψ′²ψ″)n − (4ψ′ψ‴ + 3ψ″² − ψ′⁴)u).
    Without ``fourth``, ψ⁗ and B⁗ are None (not taken).
    """
    lv = _lever_terms(design, cos_beta, sin_beta)
    w3 = _lever3(design, lv.q, cos_beta, sin_beta)
    (ux, uy), w1, w2 = lv.u, lv.lever1, lv.lever2
    l1, l2, l3, q = design.crank, design.frame, design.lever, lv.q
    sq = w1 * w1
    normal3, along3 = w3 - sq * w1, 3.0 * w1 * w2         # B‴ = L3(normal·n − along·u)
    b3 = np.stack([l3 * (normal3 * uy - along3 * ux), -l3 * (normal3 * ux + along3 * uy)])
    if not fourth:
        return lv, w3, None, b3, None
    l12 = l1 * l2
    w4 = (l12 * (l2 * l2 - l1 * l1)) * cos_beta \
        * (q * q - (12.0 * l12) * sin_beta * q - (24.0 * l12 * l12) * cos_beta * cos_beta) / (q * q) ** 2
    normal4 = w4 - 6.0 * sq * w2                          # B⁗ = L3(normal·n − along·u)
    along4 = 4.0 * w1 * w3 + 3.0 * w2 * w2 - sq * sq
    b4 = np.stack([l3 * (normal4 * uy - along4 * ux), -l3 * (normal4 * ux + along4 * uy)])
    return lv, w3, w4, b3, b4


def reach_jet(ram: _Ram, by3: np.ndarray,
              by4: np.ndarray | None) -> tuple[np.ndarray, np.ndarray | None]:
    """The rod's reach r = sqrt(L4² − d²), d = guide − By: (r‴, r⁗), from
    r‴ = −(3r′r″ + 3d′d″ + d·d‴)/r and r⁗ = −(3r″² + 4r′r‴ + 3d″² + 4d′d‴ + d·d⁗)/r
    (d′ = −By′ and so on: the sign flips are exact); r⁗ None where ``by4`` is."""
    r3 = -(3.0 * ram.reach1 * ram.reach2 + 3.0 * ram.rise1 * ram.rise2 - ram.depth * by3) / ram.reach
    if by4 is None:
        return r3, None
    r4 = -(3.0 * ram.reach2 ** 2 + 4.0 * ram.reach1 * r3 + 3.0 * ram.rise2 ** 2
           + 4.0 * ram.rise1 * by3 - ram.depth * by4) / ram.reach
    return r3, r4


def rates4_at(design: Design | Designs, cos_beta: np.ndarray, sin_beta: np.ndarray,
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """dCx/dφ … d⁴Cx/dφ⁴: :func:`rates_at`'s three and the fourth, the slope of the third,
    for Newton's method on the peaks of |d²Cx/dφ²| (:func:`lever_jet`, :func:`reach_jet`)."""
    lv, _, _, b3, b4 = lever_jet(design, cos_beta, sin_beta)
    ram = _ram_terms(design, _tip_terms(design, lv))
    if design.rod is None:
        return ram.c1, ram.c2, b3[0], b4[0]
    r3, r4 = reach_jet(ram, b3[1], b4[1])
    sign = design.rod_sign
    return ram.c1, ram.c2, b3[0] + sign * r3, b4[0] + sign * r4
