"""The checks a teacher makes of a gear pair, each with what to change when it fails.

undercut (x ≥ x_min), tip thickness (sa ≥ limit · m), contact ratio (ε ≥ limit) and involute
interference at each root: the mating tip must meet the flank no lower than where the rack's
involute starts (the form point F, N F = r sin α − (h*a − x) m / sin α along the line of action;
an undercut flank is judged from N itself, and the undercut check fails anyway).
"""
from __future__ import annotations

from dataclasses import dataclass

from .advice import Move, helpful_moves, move_text
from .pair import Gear, GearPair
from .shift import bound_text

CHECKS = ("undercut1", "undercut2", "tip1", "tip2", "contact", "interference1", "interference2")


@dataclass(frozen=True)
class Check:
    """One check: ``name`` (of CHECKS), ``ok``, ``value`` and ``limit`` (the quantity and its
    bound, in the units of ``what``), ``what`` it measures, ``advice`` what to change (empty
    when it passes), ``moves`` the changes it names (``core.gear.advice``: each makes
    value − limit grow), for the front ends to say in their language."""
    name: str
    ok: bool
    value: float
    limit: float
    what: str
    advice: str
    moves: tuple[Move, ...] = ()


NO_MOVE = "no small change of the shifts or of a′ helps: try other teeth"
"""The advice when no free change makes the margin grow (its derivative is 0 along each)."""


def advice_text(problem: str, moves: tuple[Move, ...]) -> str:
    """'problem: move or move', or the problem and NO_MOVE."""
    return f"{problem}: " + (" or ".join(move_text(m) for m in moves) if moves else NO_MOVE)


def _undercut(k: int, gear: Gear) -> Check:
    """x_k − x_kmin grows with x_k alone (its derivative is 1) and with z_k (x_min falls);
    only typed shifts can undercut (a′ and the rule share x1 + x2 out uncut)."""
    ok = not gear.undercut
    return Check(f"undercut{k}", ok, gear.shift, gear.least_shift, f"x{k} ≥ x{k}min",
                 "" if ok else f"raise x{k} to ≥ {bound_text(gear.least_shift, True)} (or give gear {k} "
                 "more teeth)", () if ok else (Move(f"x{k}", 1, 1.0),))


def _tip(k: int, pair: GearPair, limit_mm: float) -> Check:
    gear = pair.gear1 if k == 1 else pair.gear2
    ok = gear.sa >= limit_mm
    moves = () if ok else helpful_moves(pair, f"tip{k}")
    return Check(f"tip{k}", ok, gear.sa, limit_mm, f"sa{k}, mm",
                 "" if ok else advice_text(f"the tip of gear {k} is too thin", moves), moves)


def _interference(k: int, pair: GearPair) -> Check:
    """Gear k's root against the other's tip: the length from N_k to the contact point of
    the mating tip must be ≥ max(N_k F_k, 0)."""
    gear = pair.gear1 if k == 1 else pair.gear2
    reach = pair.n1b2 if k == 1 else pair.n1n2 - pair.n1b1
    need = max(gear.form_length, 0.0)
    ok = reach >= need - 1e-9
    other = 2 if k == 1 else 1
    moves = () if ok else helpful_moves(pair, f"interference{k}")
    return Check(f"interference{k}", ok, reach, need, f"N{k} to the tip of gear {other}, mm",
                 "" if ok else advice_text(f"the tip of gear {other} digs into the root of gear {k}",
                                           moves), moves)


def pair_checks(pair: GearPair) -> tuple[Check, ...]:
    """Every check of ``pair``, in the order of CHECKS."""
    p = pair.inputs
    limit = p.tip_limit * p.module_mm
    eps_ok = pair.contact_ratio >= p.contact_limit
    moves = () if eps_ok else helpful_moves(pair, "contact")
    contact = Check("contact", eps_ok, pair.contact_ratio, p.contact_limit, "ε",
                    "" if eps_ok else advice_text("ε is too small", moves), moves)
    return (_undercut(1, pair.gear1), _undercut(2, pair.gear2), _tip(1, pair, limit),
            _tip(2, pair, limit), contact, _interference(1, pair), _interference(2, pair))
