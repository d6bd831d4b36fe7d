"""Velocity, acceleration and force polygons (图解法) from the exact solution.

The graphical method of the course design draws, at one crank position,

- the velocity polygon: v_A4 = v_A3 + v_A4A3 (A3 the block on the crank pin, moving
  with the crank's A2, A4 the coincident point of the lever), v_B = v_A4·O4B/O4A,
  v_C = v_B + v_CB;
- the acceleration polygon: a_A4 = a^n_A4 + a^t_A4 = a_A3 + a^k_A4A3 + a^r_A4A3
  (Coriolis a^k = 2·ω4 × v_A4A3), a_B, and a_C = a_B + a^n_CB + a^t_CB (rod) or
  a_C = a_B + a^r_CB (block in the ram's vertical slot);
- the force polygon of the ram–rod group: P + G_6 + F_I6 + G_5 + F_I5 + N + R_B = 0.

Here every vector is computed *independently* from the closed-form solution
(kinematics shape derivatives, the dynamics joint forces, masses), and the
polygon's points are chained from some of them. So a polygon that closes —
each vector equals head − tail — is a real check, not a tautology.

Links are numbered as in the course design's task book (docs/methods.md): 1 frame,
2 crank, 3 block, 4 lever, 5 rod, 6 ram; S4 and S6 are the lever's and the ram's
centres of mass.
Vectors are in the polygon's unit (m/s, m/s², N), x toward the cut, y up.
Level: beside ``metrics``; imports ``kinematics`` and ``dynamics`` only.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .dynamics import solve_dynamics
from .masses import MassProperties
from core.linkage.geometry import Design
from core.linkage.kinematics import rpm_to_omega, shape

MM = 1e-3
KINDS = ("velocity", "acceleration", "force")
UNITS = {"velocity": "m/s", "acceleration": "m/s²", "force": "N"}
NICE_MANTISSAS = (1.0, 2.0, 2.5, 5.0)
# Also round, and at most 1.5× the exact scale: a drawing fitted to a view fills at
# least 2/3 of it (with the coarse steps as little as half).
FINE_MANTISSAS = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)
Pair = tuple[float, float]


@dataclass(frozen=True)
class Vector:
    """One arrow of a polygon: from point ``tail`` to point ``head``."""

    key: str
    """Symbol, e.g. ``v_A4A3``, ``a^k_A4A3``, ``F_I6``."""
    tail: str
    head: str
    value: Pair
    """(x, y) in the polygon's unit, computed from its own formula."""
    role: str
    """absolute, relative, normal, tangential, coriolis or force."""

    @property
    def magnitude(self) -> float:
        return math.hypot(*self.value)


@dataclass(frozen=True)
class Polygon:
    """A vector polygon at one crank position and speed."""

    kind: str
    """velocity, acceleration or force."""
    unit: str
    crank_deg: float
    rpm: float
    points: dict[str, Pair]
    """Point label → position from the pole, in ``unit``."""
    vectors: tuple[Vector, ...]

    def largest(self) -> float:
        """Largest extent from the pole or vector length (to choose a scale)."""
        spans = [math.hypot(*p) for p in self.points.values()] + [v.magnitude for v in self.vectors]
        return max(spans + [0.0])

    def closure_error(self) -> float:
        """Largest |head − tail − value| over the vectors, in ``unit``."""
        worst = 0.0
        for v in self.vectors:
            (tx, ty), (hx, hy) = self.points[v.tail], self.points[v.head]
            worst = max(worst, math.hypot(hx - tx - v.value[0], hy - ty - v.value[1]))
        return worst


def nice_scale(largest: float, target_mm: float,
               mantissas: tuple[float, ...] = NICE_MANTISSAS) -> float:
    """The smallest scale μ = {1, 2, 2.5, 5}·10^k (or other ``mantissas``, unit per mm)
    that draws ``largest`` no longer than ``target_mm`` (e.g. μv = 0.01 (m/s)/mm)."""
    if not (largest > 0.0 and math.isfinite(largest)):
        return 1.0
    exact = largest / target_mm
    power = 10.0 ** math.floor(math.log10(exact))
    for mantissa in mantissas + (10.0,):
        if mantissa * power >= exact * (1 - 1e-12):
            return mantissa * power
    return 10.0 * power  # pragma: no cover - the loop always returns


def paper(polygon: Polygon, scale: float) -> dict[str, Pair]:
    """Point positions on the drawing, mm from the pole (y up): value / μ."""
    return {name: (x / scale, y / scale) for name, (x, y) in polygon.points.items()}


def _pair(vec: np.ndarray, factor: float = 1.0) -> Pair:
    return float(vec[0] * factor), float(vec[1] * factor)


def velocity_polygon(design: Design, crank_deg: float, rpm: float) -> Polygon:
    """Pole p; a3 (crank pin), a4 (coincident lever point), b (lever tip), c (ram)."""
    w = float(rpm_to_omega(rpm))
    sh = shape(design, np.radians([crank_deg]))
    u = sh.crank_pin[:, 0] / sh.slide[0]                  # along the lever, away from O4
    n = np.array([u[1], -u[0]])                           # direction of increasing ψ
    k = w * MM                                            # mm/rad → m/s
    v_a3 = _pair(sh.pin1[:, 0], k)
    v_a4 = _pair(n, k * sh.slide[0] * sh.lever1[0])       # ω4 × O4A
    v_rel = _pair(u, -k * sh.slide1[0])                   # lever point relative to the block
    v_b = _pair(sh.tip1[:, 0], k)
    v_c = (float(k * sh.ram1[0]), 0.0)
    points = {"p": (0.0, 0.0), "a3": v_a3, "a4": v_a4, "b": v_b, "c": v_c}
    if design.rod is None:
        v_cb = (0.0, -v_b[1])                             # block slides in the ram's vertical slot
        cb_role = "relative"
    else:
        lam = sh.rod[0]
        v_cb = _pair(np.array([-math.sin(lam), math.cos(lam)]), design.rod * k * sh.rod1[0])
        cb_role = "relative"
    vectors = (
        Vector("v_A3", "p", "a3", v_a3, "absolute"),
        Vector("v_A4A3", "a3", "a4", v_rel, "relative"),
        Vector("v_A4", "p", "a4", v_a4, "absolute"),
        Vector("v_B", "p", "b", v_b, "absolute"),
        Vector("v_CB", "b", "c", v_cb, cb_role),
        Vector("v_C", "p", "c", v_c, "absolute"),
    )
    return Polygon("velocity", UNITS["velocity"], float(crank_deg), float(rpm), points, vectors)


def acceleration_polygon(design: Design, crank_deg: float, rpm: float) -> Polygon:
    """Pole p′; a3′, k′ (after Coriolis), a4′, n4′ (normal of A4), b′, [n5′], c′."""
    w = float(rpm_to_omega(rpm))
    sh = shape(design, np.radians([crank_deg]))
    s, s1, s2 = sh.slide[0], sh.slide1[0], sh.slide2[0]
    l1, l2 = sh.lever1[0], sh.lever2[0]
    u = sh.crank_pin[:, 0] / s
    n = np.array([u[1], -u[0]])
    k = w * w * MM                                        # mm/rad² → m/s²
    a_a3 = _pair(sh.pin2[:, 0], k)
    a_cor = _pair(n, -2.0 * k * s1 * l1)                  # 2·ω4 × v_A4A3
    a_rel = _pair(u, -k * s2)                             # a^r_A4A3, along the lever
    a_n4 = _pair(u, -k * s * l1 * l1)                     # toward O4
    a_t4 = _pair(n, k * s * l2)
    a_b = _pair(sh.tip2[:, 0], k)
    a_c = (float(k * sh.ram2[0]), 0.0)
    k_pt = (a_a3[0] + a_cor[0], a_a3[1] + a_cor[1])
    a4_pt = (a_n4[0] + a_t4[0], a_n4[1] + a_t4[1])
    points = {"p'": (0.0, 0.0), "a3'": a_a3, "k'": k_pt, "n4'": a_n4, "a4'": a4_pt,
              "b'": a_b, "c'": a_c}
    vectors = [
        Vector("a_A3", "p'", "a3'", a_a3, "absolute"),
        Vector("a^k_A4A3", "a3'", "k'", a_cor, "coriolis"),
        Vector("a^r_A4A3", "k'", "a4'", a_rel, "relative"),
        Vector("a^n_A4", "p'", "n4'", a_n4, "normal"),
        Vector("a^t_A4", "n4'", "a4'", a_t4, "tangential"),
        Vector("a_B", "p'", "b'", a_b, "absolute"),
    ]
    if design.rod is None:
        vectors.append(Vector("a^r_CB", "b'", "c'", (0.0, -a_b[1]), "relative"))
    else:
        lam, r1, r2 = sh.rod[0], sh.rod1[0], sh.rod2[0]
        along = np.array([math.cos(lam), math.sin(lam)])  # B → C
        across = np.array([-math.sin(lam), math.cos(lam)])
        a_ncb = _pair(along, -k * design.rod * r1 * r1)
        a_tcb = _pair(across, k * design.rod * r2)
        points["n5'"] = (a_b[0] + a_ncb[0], a_b[1] + a_ncb[1])
        vectors += [Vector("a^n_CB", "b'", "n5'", a_ncb, "normal"),
                    Vector("a^t_CB", "n5'", "c'", a_tcb, "tangential")]
    vectors.append(Vector("a_C", "p'", "c'", a_c, "absolute"))
    return Polygon("acceleration", UNITS["acceleration"], float(crank_deg), float(rpm), points,
                   tuple(vectors))


def force_polygon(design: Design, crank_deg: float, rpm: float,
                  masses: MassProperties) -> Polygon:
    """Forces on the ram–rod group (the ram alone for the block variant), head to tail.

    Known loads first (cutting force P, weights G, inertia forces F_I = −m·a from the
    kinematics), then the guide's normal force N and the lever's force R_B at B from
    ``core.forces.dynamics``. d'Alembert: the chain returns to its start. Zero forces are left out.
    """
    phi = np.radians([crank_deg])
    w = float(rpm_to_omega(rpm))
    sh = shape(design, phi)
    dyn = solve_dynamics(design, phi, [rpm], masses)
    g = masses.g
    a_c = np.array([w * w * sh.ram2[0] * MM, 0.0])
    loads = [("P", (-float(dyn.cut_force[0, 0]), 0.0)),
             ("G_6", (0.0, -masses.ram_mass_kg * g)),
             ("F_I6", _pair(-masses.ram_mass_kg * a_c))]
    if design.rod is not None:
        a_s5 = (w * w * sh.tip2[:, 0] * MM + a_c) / 2.0
        loads += [("G_5", (0.0, -masses.rod_mass_kg * g)),
                  ("F_I5", _pair(-masses.rod_mass_kg * a_s5))]
    loads += [("N", (0.0, float(dyn.guide_normal[0, 0]))),
              ("R_B", (float(dyn.b_x[0, 0]), float(dyn.b_y[0, 0])))]
    return _chain(loads, crank_deg, rpm)


def lever_force_polygon(design: Design, crank_deg: float, rpm: float,
                        masses: MassProperties) -> Polygon:
    """Forces on the lever (link 4), head to tail: its weight G_4 and inertia force
    F_I4 = −m4·a_S4 (a_S4 from the kinematics, the centre of mass on the lever at
    ``masses.lever_cg``), then from ``core.forces.dynamics`` the block's force R_A at A, the
    frame's R_O4 and the next link's force at B, R_4B = −R_B. They close: the inertia
    moment −J_S4·α4 turns the lever but adds no force. Zero forces are left out."""
    phi = np.radians([crank_deg])
    w = float(rpm_to_omega(rpm))
    sh = shape(design, phi)
    dyn = solve_dynamics(design, phi, [rpm], masses)
    psi, psi1, psi2 = float(sh.lever[0]), float(sh.lever1[0]), float(sh.lever2[0])
    along, across = np.array([math.sin(psi), math.cos(psi)]), np.array([math.cos(psi), -math.sin(psi)])
    a_g = w * w * masses.lever_cg(design) * MM * (psi2 * across - psi1 ** 2 * along)
    at = lambda a: float(a[0, 0])          # noqa: E731
    loads = [("G_4", (0.0, -masses.lever_mass_kg * masses.g)),
             ("F_I4", _pair(-masses.lever_mass_kg * a_g)),
             ("R_A", (at(dyn.a_x), at(dyn.a_y))),
             ("R_O4", (at(dyn.o4_x), at(dyn.o4_y))),
             ("R_4B", (-at(dyn.b_x), -at(dyn.b_y)))]
    return _chain(loads, crank_deg, rpm)


def _chain(loads: list[tuple[str, Pair]], crank_deg: float, rpm: float) -> Polygon:
    """The force polygon of ``loads`` (name, force in N) chained head to tail from the
    pole "0"; the last arrow's head is named "0" too (it ends where the first began)."""
    points: dict[str, Pair] = {"0": (0.0, 0.0)}
    vectors = []
    x = y = 0.0
    for key, value in loads:
        if value == (0.0, 0.0):
            continue
        tail = str(len(vectors))
        x, y = x + value[0], y + value[1]
        head = str(len(vectors) + 1)
        points[head] = (x, y)
        vectors.append(Vector(key, tail, head, value, "force"))
    if vectors:   # the last arrow ends where the first began: name its head "0"
        last = vectors[-1]
        points.pop(last.head)
        vectors[-1] = Vector(last.key, last.tail, "0", last.value, last.role)
    return Polygon("force", UNITS["force"], float(crank_deg), float(rpm), points, tuple(vectors))


def polygons(design: Design, crank_deg: float, rpm: float,
             masses: MassProperties | None = None) -> dict[str, Polygon]:
    """The velocity, acceleration and (with ``masses``) force polygons at one position."""
    out = {"velocity": velocity_polygon(design, crank_deg, rpm),
           "acceleration": acceleration_polygon(design, crank_deg, rpm)}
    if masses is not None:
        out["force"] = force_polygon(design, crank_deg, rpm, masses)
    return out
