"""The driving torque and its first two φ-derivatives in closed form, split by speed.

A level beside :mod:`core.forces.dynamics`, below :mod:`core.forces.flywheel`, which takes the
cycle's torque peaks and energy extrema from it. A frictionless chain turning at a constant
crank speed ω stores the energy ω²·K(φ) + V(φ) (K the kinetic energy per unit ω², ½·J_e, V
the potential one), and the driving torque less the cut is its rate of change (virtual
work), so

    T(φ, ω) = V′(φ) + ω²·K′(φ) + P·dCx/dφ while cutting,

and T′, T″ follow from V″, V‴, K″, K‴ and d²Cx/dφ², d³Cx/dφ³. Every one of these is the
same at all speeds: a sweep samples them once per design and takes each speed's torque and
slope as a sum of these arrays, and Newton's method polishes a peak on them in two or three
steps (the elimination of :mod:`core.forces.dynamics` gives T alone, which Brent's method
needed eight or more steps to polish). ``tests/test_core/test_torque_jet.py`` checks T
against that elimination and T′, T″ against finite differences.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from core.linkage.kinematics import _ram_terms, _tip_terms
from core.linkage.rates import lever_jet, reach_jet
from .masses import MM, MassProperties


class TorqueJet(NamedTuple):
    """Speed-independent parts of the driving torque and its φ-derivatives, each shaped as
    the angles: the torque at crank speed ω, cutting (c = 1) or not (c = 0), is
    ``static + ω²·inertial + c·cut`` in N·m, its slope the same sum of the ``*1`` fields in
    N·m/rad and its curvature of the ``*2`` fields in N·m/rad²."""

    static: np.ndarray      # V′: the weights' torque, N·m
    static1: np.ndarray
    static2: np.ndarray
    inertial: np.ndarray    # K′: the inertia loads' torque per unit ω², N·m·s²
    inertial1: np.ndarray
    inertial2: np.ndarray
    cut: np.ndarray         # P·dCx/dφ: the cutting force's torque while it acts, N·m
    cut1: np.ndarray
    cut2: np.ndarray
    kinetic: np.ndarray     # K = ½·J_e: the kinetic energy per unit ω², J·s² (= kg·m²/2)
    potential: np.ndarray   # V: the weights' potential energy, J
    ram_x: np.ndarray       # Cx, the ram joint's x, mm (the cut's work is P times its travel)


def grid_trig(design, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """cos β and sin β, β = π + θ/2 − φ, for designs with a trailing axis (Designs.column())
    at crank angles ``phi`` (n,) that all of them share (a sweep's grid): the grid's cos φ and
    sin φ once, each design's cos and sin of π + θ/2 once, joined by the angle-addition
    formulas. numpy's cos and sin cost 20-35 ns a sample here against a few for the four
    products; both are within 6e-16 of β's exact cosine (long double, 10^5 samples)."""
    phi = np.asarray(phi, dtype=float)
    shift = np.pi + np.asarray(design.theta) / 2.0
    ca, sa, cp, sp = np.cos(shift), np.sin(shift), np.cos(phi), np.sin(phi)
    return ca * cp + sa * sp, sa * cp - ca * sp


def torque_jet(design, phi: np.ndarray, masses: MassProperties,
               curvature: bool = True,
               trig: tuple[np.ndarray, np.ndarray] | None = None) -> TorqueJet:
    """:class:`TorqueJet` of ``design`` (a Design or Designs broadcasting against ``phi``)
    at crank angles ``phi`` (rad). Without ``curvature`` the three ``*2`` fields are None and
    the fourth derivatives they need are not taken (the energy's polish reads T and T′ only:
    a quarter of a point's arithmetic); every other field is the same, bit for bit.
    ``trig``: cos β and sin β at ``phi`` where the caller has them (:func:`grid_trig`).

    The kinetic energy per unit ω² is K = ½(J4·ψ′² + m3·L1² + m6·Cx′² + m5(|G5′|² + L4²/12·λ′²))
    with J4 = m4·cg² + J_lever, G5 = (B + C)/2 and the rod angle λ, so K′ = J4·ψ′ψ″ + m6·Cx′Cx″
    + m5(G5′·G5″ + L4²/12·λ′λ″) and so on by the product rule; the potential energy is
    V = g(h·By + m3·Ay), h = m4·cg/L3 + m5/2 (the ram moves level: its weight stores nothing).
    The jet carries K, V and the ram's x as well, from which the cycle's energy curve is
    built (:func:`core.forces.flywheel._energy`).
    """
    if trig is None:
        beta = np.pi + np.asarray(design.theta) / 2.0 - np.asarray(phi, dtype=float)
        trig = np.cos(beta), np.sin(beta)
    cb, sb = trig
    lv, w3, w4, b3, b4 = lever_jet(design, cb, sb, fourth=curvature)
    tip = _tip_terms(design, lv)
    ram = _ram_terms(design, tip)
    w1, w2 = lv.lever1, lv.lever2
    cg = masses.lever_cg(design) * MM
    j4 = masses.lever_mass_kg * cg * cg + masses.lever_inertia_kg_m2
    m3, m6 = masses.block_mass_kg, masses.ram_mass_kg
    b1, b2 = tip.b1, tip.b2
    if design.rod is None:
        c3, c4 = b3[0], (b4[0] if curvature else None)
    else:
        r34 = reach_jet(ram, b3[1], b4[1] if curvature else None)
        c3 = b3[0] + design.rod_sign * r34[0]
        c4 = b4[0] + design.rod_sign * r34[1] if curvature else None
    c1, c2 = ram.c1, ram.c2
    k1 = j4 * (w1 * w2) + m6 * MM * MM * (c1 * c2)
    k2 = j4 * (w2 * w2 + w1 * w3) + m6 * MM * MM * (c2 * c2 + c1 * c3)
    k3 = j4 * (3.0 * w2 * w3 + w1 * w4) + m6 * MM * MM * (3.0 * c2 * c3 + c1 * c4) \
        if curvature else None
    height = masses.lever_mass_kg * masses.lever_cg(design) / design.lever
    l1 = design.crank
    k0 = 0.5 * (j4 * (w1 * w1) + m6 * MM * MM * (c1 * c1) + m3 * (l1 * MM) ** 2)
    if design.rod is not None and masses.rod_mass_kg > 0.0:
        k0, k1, k2, k3 = (None if k is None else k + v for k, v in zip((k0, k1, k2, k3), _rod_kinetic(
            design, masses, ram, tip, (b3, b4), r34, (c1, c2, c3, c4))))
        height = height + masses.rod_mass_kg / 2.0
    # Ay = L2 + L1·sin β with β′ = −1: Ay′ = −L1·cos β, Ay″ = −L1·sin β, Ay‴ = L1·cos β.
    scale = masses.g * MM
    v0 = scale * (height * tip.b[1] + m3 * lv.pin[1])
    v1 = scale * (height * b1[1] - m3 * l1 * cb)
    v2 = scale * (height * b2[1] - m3 * l1 * sb)
    v3 = scale * (height * b3[1] + m3 * l1 * cb) if curvature else None
    p = masses.cut_force_N * MM
    return TorqueJet(v1, v2, v3, k1, k2, k3, p * c1, p * c2, p * c3 if curvature else None,
                     k0, v0, ram.joint[0])


def _rod_kinetic(design, masses: MassProperties, ram, tip, b34, r34, c14) -> tuple:
    """The rod's share of K, K′, K″, K‴: K = ½m5(|G5′|² + L4²/12·λ′²), K′ = m5(G5′·G5″ +
    L4²/12·λ′λ″) and its two derivatives,
    with λ′ = −sign(r·By′ + d·r′)/L4² and the same pattern one and two orders up; K‴ None
    where the fourth derivatives (``b34[1]``) are None."""
    (b3, b4), (c1, c2, c3, c4) = b34, c14
    fourth = b4 is not None
    sign, length = design.rod_sign, design.rod
    r, d = ram.reach, ram.depth
    r3, r4 = r34
    by1, by2, by3 = tip.b1[1], tip.b2[1], b3[1]
    r1, r2 = ram.reach1, ram.reach2
    k = -sign / (length * length)
    l1 = k * (r * by1 + d * r1)
    l2 = k * (r * by2 + d * r2)
    l3 = k * (r1 * by2 + r * by3 - by1 * r2 + d * r3)
    ends = (tip.b1[0], tip.b2[0], b3[0]) + ((b4[0],) if fourth else ())
    gx = [(b + c) / 2.0 for b, c in zip(ends, (c1, c2, c3, c4))]
    gy = [by1 / 2.0, by2 / 2.0, by3 / 2.0]
    rot = (length * MM) ** 2 / 12.0
    m5 = masses.rod_mass_kg
    mm2 = MM * MM
    dot = lambda i, j: gx[i] * gx[j] + gy[i] * gy[j]  # noqa: E731
    out = (0.5 * m5 * (mm2 * dot(0, 0) + rot * l1 * l1),
           m5 * (mm2 * dot(0, 1) + rot * l1 * l2),
           m5 * (mm2 * (dot(1, 1) + dot(0, 2)) + rot * (l2 * l2 + l1 * l3)))
    if not fourth:
        return out + (None,)
    by4 = b4[1]
    gy.append(by4 / 2.0)
    l4 = k * (2.0 * r1 * by3 + r * by4 - 2.0 * by1 * r3 + d * r4)
    return out + (m5 * (mm2 * (3.0 * dot(1, 2) + dot(0, 3)) + rot * (3.0 * l2 * l3 + l1 * l4)),)
