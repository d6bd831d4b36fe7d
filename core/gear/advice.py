"""What to change when a check fails, from the sign of the check's margin's derivative.

A check's margin (value − limit, ≥ 0 when it passes) is differentiated, in closed form, along
each change the pair's mode leaves free, and an advice names only the changes whose
derivative has the sign that makes the margin grow: followed by a small step, the margin
grows. The free changes by mode (``core.gear.shift.MODES``):

* ``given`` (x1, x2 typed): raise or lower x1 alone, or x2 alone (a′ follows).
* ``centre`` and the rule's ``balanced`` and ``positive`` (a′ typed or the rule's): a larger
  or smaller a′, the rule of :func:`core.gear.shift.split` sharing out the new x1 + x2; or,
  a′ kept (so x1 + x2 kept), shift moved from one gear to the other (given as x1, x2).

The chain (α the rack's, α′ the working pressure angle, Σ = x1 + x2, z = z1 + z2):
inv α′ = 2 tan α Σ / z + inv α gives dα′/dΣ = 2 tan α / (z tan² α′); a′ = a cos α / cos α′
gives dy/dΣ = sin α / sin α′, so dΔy/dΣ = 1 − sin α / sin α′ and da′/dΣ = m sin α / sin α′;
ra_k = r_k + (h*a + x_k − Δy) m; cos α_a = rb / ra gives dα_a = dra / (ra tan α_a);
sa = ra (s / r − 2 (inv α_a − inv α)) gives dsa = ra d(s / r) + (sa / ra − 2 tan α_a) dra with
d(s / r) = 4 tan α / z_k dx_k; ε = Σ z_k (tan α_ak − tan α′) / 2π; N1N2 = (rb1 + rb2) tan α′;
N_kB_k = √(ra_k² − rb_k²), dN_kB_k = dra_k / sin α_ak; N_kF_k = r_k sin α − (h*a − x_k) m / sin α.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .involute import least_shift
from .pair import Gear, GearPair

RELEVANT = 0.05
"""A change is advised when its rate is at least this share of the best change's: a rate
of a few per cent of the best is a second-order effect that a step of any useful size can
reverse (e.g. Δy's pull on the other gear's tip near Σ = 0)."""

MOVES = {"given": ("x1", "x2"), "centre": ("centre", "transfer"),
         "balanced": ("centre", "transfer"), "positive": ("centre", "transfer")}
"""The changes each mode leaves free: ``x1``, ``x2`` (one shift alone, a′ follows),
``centre`` (a′, mm, the rule sharing out x1 + x2), ``transfer`` (x1 + δ, x2 − δ at a′ kept)."""


@dataclass(frozen=True)
class Move:
    """One change that makes a check's margin grow: ``name`` of MOVES' values, ``sign`` +1
    (raise x_k, a larger a′, shift to gear 1) or −1; ``rate`` the margin's derivative along
    it per unit of shift factor (for a′: per unit of x1 + x2, i.e. m sin α / sin α′ mm of
    a′), > 0, so that the rates of the changes compare; ``to`` the values to type, as
    printed, at which the check passes (``core.gear.amounts``: x1 or x2; a′ in mm; x1 and x2
    for a transfer), empty when only the direction is known; ``breaks`` the checks (CHECKS'
    names) that passed and fail at those values."""
    name: str
    sign: int
    rate: float
    to: tuple[str, ...] = ()
    breaks: tuple[str, ...] = ()


@dataclass(frozen=True)
class _Step:
    """A unit change of the pair's inputs: dx1, dx2 and dΣ = dx1 + dx2."""
    dx1: float
    dx2: float

    @property
    def total(self) -> float:
        return self.dx1 + self.dx2


def move_step(pair: GearPair, name: str) -> _Step:
    """(dx1, dx2) of a unit of ``name``: 1 of x1 or x2; the a′ that adds 1 to x1 + x2
    (:func:`centre_per_shift` mm), shared by :func:`core.gear.shift.split` (the gear whose
    shift is not at its bound takes it); or +1 to x1 and −1 to x2."""
    if name == "x1":
        return _Step(1.0, 0.0)
    if name == "x2":
        return _Step(0.0, 1.0)
    if name == "transfer":
        return _Step(1.0, -1.0)
    p = pair.inputs
    need1 = max(least_shift(p.z1, p.alpha, p.addendum), 0.0)
    pinion_at_rule = pair.gear1.shift >= need1 - 1e-12       # split: the rest goes to gear 2
    return _Step(0.0, 1.0) if pinion_at_rule else _Step(1.0, 0.0)


def centre_per_shift(pair: GearPair) -> float:
    """da′/d(x1 + x2) = m sin α / sin α′, mm: the a′ of a unit of the ``centre`` move."""
    return pair.inputs.module_mm * math.sin(pair.inputs.alpha) / math.sin(pair.alpha_w)


def _d_alpha_w(pair: GearPair, step: _Step) -> float:
    p = pair.inputs
    return 2.0 * math.tan(p.alpha) * step.total / ((p.z1 + p.z2) * math.tan(pair.alpha_w) ** 2)


def _d_tip_radius(pair: GearPair, k: int, step: _Step) -> float:
    p = pair.inputs
    d_dy = (1.0 - math.sin(p.alpha) / math.sin(pair.alpha_w)) * step.total
    return p.module_mm * ((step.dx1 if k == 1 else step.dx2) - d_dy)


def _d_reach(gear: Gear, d_ra: float) -> float:
    """d N_kB_k: the length from N_k to where gear k's tip circle cuts the line of action."""
    return d_ra / math.sin(gear.alpha_a)


def margin_rate(pair: GearPair, check: str, step: _Step) -> float:
    """The derivative of the margin of ``check`` (core.gear.checks.CHECKS) along ``step``."""
    p = pair.inputs
    k = int(check[-1]) if check[-1].isdigit() else 0
    dx = (step.dx1, step.dx2)
    if check.startswith("undercut"):
        return dx[k - 1]
    gears = (pair.gear1, pair.gear2)
    d_ra = (_d_tip_radius(pair, 1, step), _d_tip_radius(pair, 2, step))
    if check.startswith("tip"):
        g = gears[k - 1]
        return (g.ra * 4.0 * math.tan(p.alpha) / g.teeth * dx[k - 1]
                + (g.sa / g.ra - 2.0 * math.tan(g.alpha_a)) * d_ra[k - 1])
    d_aw = _d_alpha_w(pair, step)
    if check == "contact":
        tips = sum(g.teeth * d / (g.ra * math.sin(g.alpha_a) * math.cos(g.alpha_a))
                   for g, d in zip(gears, d_ra))
        return (tips - (p.z1 + p.z2) * d_aw / math.cos(pair.alpha_w) ** 2) / (2.0 * math.pi)
    other = 2 if k == 1 else 1
    d_n1n2 = (pair.gear1.rb + pair.gear2.rb) * d_aw / math.cos(pair.alpha_w) ** 2
    gear = gears[k - 1]
    d_need = p.module_mm / math.sin(p.alpha) * dx[k - 1] if gear.form_length > 0.0 else 0.0
    return d_n1n2 - _d_reach(gears[other - 1], d_ra[other - 1]) - d_need


def helpful_moves(pair: GearPair, check: str) -> tuple[Move, ...]:
    """The changes free in the pair's mode that make ``check``'s margin grow, best first
    (see RELEVANT); empty when none does."""
    rates = [(name, margin_rate(pair, check, move_step(pair, name))) for name in MOVES[pair.mode]]
    best = max((abs(r) for _, r in rates), default=0.0)
    if not best > 0.0 or not math.isfinite(best):
        return ()
    moves = [Move(name, 1 if r > 0 else -1, abs(r)) for name, r in rates if abs(r) >= RELEVANT * best]
    return tuple(sorted(moves, key=lambda m: -m.rate))


BREAK_TEXT = {"undercut1": "gear 1 is undercut", "undercut2": "gear 2 is undercut",
              "tip1": "the tip of gear 1 is too thin", "tip2": "the tip of gear 2 is too thin",
              "contact": "ε is too small", "interference1": "the tip of gear 2 digs into the root of gear 1",
              "interference2": "the tip of gear 1 digs into the root of gear 2"}
"""A check that fails, as its own advice states the problem (a move's note: 'but then …')."""


def move_text(move: Move) -> str:
    """A move in words: 'raise x1 to ≥ 0.2130', 'lower a′ to ≤ 161.2500 mm', 'x1 = 0.4000 and
    x2 = 0.1000 (a′ about the same)', with '(but then ε is too small)' when it breaks a check;
    without ``to`` the direction alone ('raise x1', 'a smaller a′')."""
    if not move.to:
        return _direction_text(move)
    if move.name in ("x1", "x2"):
        text = f"{'raise' if move.sign > 0 else 'lower'} {move.name} to {'≥' if move.sign > 0 else '≤'} {move.to[0]}"
    elif move.name == "centre":
        text = f"{'raise' if move.sign > 0 else 'lower'} a′ to {'≥' if move.sign > 0 else '≤'} {move.to[0]} mm"
    else:
        text = f"x1 = {move.to[0]} and x2 = {move.to[1]} (a′ about the same)"
    if move.breaks:
        text += f" (but then {', '.join(BREAK_TEXT[b] for b in move.breaks)})"
    return text


def _direction_text(move: Move) -> str:
    """A move with no amount: 'raise x1', 'a smaller a′', 'x1 + δ and x2 − δ at the same a′'."""
    if move.name in ("x1", "x2"):
        return f"{'raise' if move.sign > 0 else 'lower'} {move.name}"
    if move.name == "centre":
        return f"a {'larger' if move.sign > 0 else 'smaller'} a′"
    return ("x1 + δ and x2 − δ at the same a′" if move.sign > 0
            else "x1 − δ and x2 + δ at the same a′")
