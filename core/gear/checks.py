"""The checks a teacher makes of a gear pair (``margins``), each with what to change when it
fails and by how much: the changes that help (``advice``, from the margin's derivative), each
with the value to type at which the check passes (``amounts``), those that break no other
check first."""
from __future__ import annotations

from dataclasses import dataclass, replace

from . import amounts
from .advice import BREAK_TEXT, Move, helpful_moves, move_text
from .margins import CHECKS, Margin, check_margins
from .pair import GearPair, probe_pair
from .shift import bound_text

__all__ = ["CHECKS", "Check", "advised_moves", "pair_checks"]


@dataclass(frozen=True)
class Check:
    """One check: ``name`` (of CHECKS), ``ok``, ``value`` and ``limit`` (the quantity and its
    bound, in the units of ``what``), ``what`` it measures, ``advice`` what to change (empty
    when it passes), ``moves`` the changes it names (``core.gear.advice``: each makes
    value − limit grow, with the value to type), for the front ends to say in their language."""
    name: str
    ok: bool
    value: float
    limit: float
    what: str
    advice: str
    moves: tuple[Move, ...] = ()


NO_MOVE = "no change of one shift or of a′ makes it pass: try other teeth"
"""The advice when no free change makes the check pass (none makes its margin grow, or each
runs out of range or into a refusal first)."""


def advice_text(problem: str, moves: tuple[Move, ...]) -> str:
    """'problem: move or move', or the problem and NO_MOVE."""
    return f"{problem}: " + (" or ".join(move_text(m) for m in moves) if moves else NO_MOVE)


def advised_moves(pair: GearPair, check: str, margins: dict[str, Margin] | None = None) -> tuple[Move, ...]:
    """The helpful changes of ``check`` (``advice.helpful_moves``) that make it pass, each with
    the least value to type (``amounts``) and the checks it then breaks; those that break none
    first, then by rate. A change that runs out of range or into a refusal first is left out."""
    before = check_margins(pair) if margins is None else margins
    start = amounts.start_of(pair)
    found = []
    for move in helpful_moves(pair, check):
        step = amounts.least_step(probe_pair, start, check, move.name, move.sign)
        done = None if step is None else amounts.printed(probe_pair, start, check, move.name, move.sign, step)
        if done is None:
            continue
        values, after = done
        now = check_margins(after)
        breaks = tuple(n for n in CHECKS if n != check and before[n].ok and not now[n].ok)
        found.append(replace(move, to=values, breaks=breaks))
    return tuple(sorted(found, key=lambda m: (bool(m.breaks), -m.rate)))


def _check(pair: GearPair, name: str, margins: dict[str, Margin], what: str) -> Check:
    """Check ``name``, its advice led by the problem as a move's 'but then' note states it
    (``advice.BREAK_TEXT``: one wording for both)."""
    margin = margins[name]
    moves = () if margin.ok else advised_moves(pair, name, margins)
    return Check(name, margin.ok, margin.value, margin.limit, what,
                 "" if margin.ok else advice_text(BREAK_TEXT[name], moves), moves)


def _undercut(k: int, margin: Margin) -> Check:
    """x_k − x_kmin grows with x_k alone (its derivative is 1) and with z_k (x_min falls);
    only typed shifts can undercut (a′ and the rule share x1 + x2 out uncut)."""
    ok = margin.ok
    return Check(f"undercut{k}", ok, margin.value, margin.limit, f"x{k} ≥ x{k}min",
                 "" if ok else f"raise x{k} to ≥ {bound_text(margin.limit, True)} (or give gear {k} "
                 "more teeth)", () if ok else (Move(f"x{k}", 1, 1.0, (bound_text(margin.limit, True),)),))


def pair_checks(pair: GearPair) -> tuple[Check, ...]:
    """Every check of ``pair``, in the order of CHECKS."""
    m = check_margins(pair)
    return (_undercut(1, m["undercut1"]), _undercut(2, m["undercut2"]),
            _check(pair, "tip1", m, "sa1, mm"), _check(pair, "tip2", m, "sa2, mm"),
            _check(pair, "contact", m, "ε"),
            _check(pair, "interference1", m, "N1 to the tip of gear 2, mm"),
            _check(pair, "interference2", m, "N2 to the tip of gear 1, mm"))
