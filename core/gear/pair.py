"""One external spur pair, every length from a closed form: the radii, the thicknesses, the
line of action and the contact ratio, and the checks a teacher makes of them."""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

from core.base.errors import DesignError
from .inputs import GearPairInputs
from . import amounts
from .involute import least_shift, reference_thickness, thickness_at
from .shift import Shifts, bound_text, find_shifts, reference_centre


@dataclass(frozen=True)
class Gear:
    """One gear of the pair. Lengths in mm, angles in radians.

    ``r`` reference radius m z / 2; ``rb`` base radius r cos α; ``ra`` tip radius
    r + (h*a + x − Δy) m; ``rf`` root radius r − (h*a + c* − x) m; ``rw`` working pitch radius
    rb / cos α′; ``s``, ``e`` tooth thickness and space on the reference circle (s + e = π m);
    ``sa`` tip thickness; ``alpha_a`` the profile angle at the tip; ``least_shift`` x_min;
    ``form_length`` the length along the line of action from the limit point N to where the
    rack-generated involute starts (negative: the rack undercuts the tooth).
    """
    teeth: int
    shift: float
    r: float
    rb: float
    ra: float
    rf: float
    rw: float
    s: float
    e: float
    sa: float
    alpha_a: float
    least_shift: float
    form_length: float

    @property
    def undercut(self) -> bool:
        """x < x_min (to 1e-12): the rack cuts into the involute at the root."""
        return self.shift < self.least_shift - 1e-12


@dataclass(frozen=True)
class GearPair:
    """The pair: ``inputs``; ``mode`` how the shifts were found (shift.MODES); ``alpha_w`` α′;
    ``centre_mm`` a′; ``reference_centre_mm`` a; ``y`` (a′ − a)/m; ``dy`` Δy = x1 + x2 − y;
    ``gear1``, ``gear2``; ``pb`` base pitch π m cos α; ``n1n2`` the theoretical line of
    action a′ sin α′; ``b1b2`` the actual one; ``n1p`` N1 to the pitch point P; ``n1b1`` and
    ``n1b2`` N1 to where contact ends (gear 1's tip) and starts (gear 2's tip), all in mm;
    ``contact_ratio`` ε."""
    inputs: GearPairInputs
    mode: str
    alpha_w: float
    centre_mm: float
    reference_centre_mm: float
    y: float
    dy: float
    gear1: Gear
    gear2: Gear
    pb: float
    n1n2: float
    b1b2: float
    n1p: float
    n1b1: float
    n1b2: float
    contact_ratio: float


def make_gear(p: GearPairInputs, teeth: int, shift: float, dy: float, alpha_w: float) -> Gear:
    """One gear's lengths from its teeth and shift and the pair's Δy and α′."""
    m, alpha = p.module_mm, p.alpha
    r = m * teeth / 2.0
    rb = r * math.cos(alpha)
    ra = r + (p.addendum + shift - dy) * m
    s = reference_thickness(m, shift, alpha)
    alpha_a = math.acos(rb / ra) if ra > rb else 0.0
    sa = float(thickness_at(ra, r, s, alpha, rb)) if ra > rb else -math.inf
    form = r * math.sin(alpha) - (p.addendum - shift) * m / math.sin(alpha)
    return Gear(teeth=int(teeth), shift=shift, r=r, rb=rb, ra=ra,
                rf=r - (p.addendum + p.clearance - shift) * m, rw=rb / math.cos(alpha_w), s=s,
                e=math.pi * m - s, sa=sa, alpha_a=alpha_a,
                least_shift=least_shift(teeth, alpha, p.addendum), form_length=form)


def design_pair(inputs: GearPairInputs) -> GearPair:
    """The pair of ``inputs`` (checked here): DesignError names the field when the inputs are
    out of range, when a′ needs more or less shift than the teeth allow, or when a tip comes
    to a point; every milder failure is a check of :func:`core.gear.checks.pair_checks`."""
    p = inputs.check()
    shifts = find_shifts(p)
    return pair_of(p, shifts)


def probe_pair(inputs: GearPairInputs) -> GearPair:
    """:func:`design_pair` whose pointed tip is refused without a search for the value that
    mends it: what that search (``amounts``) designs along a change."""
    p = inputs.check()
    return pair_of(p, find_shifts(p), advise=False)


def pair_of(p: GearPairInputs, shifts: Shifts, advise: bool = True) -> GearPair:
    """The results of ``p`` meshed with ``shifts``; a pointed tip refused, with the value
    that mends it when ``advise``, and so is a pair whose teeth never touch (:func:`meshes`)."""
    pair = _geometry(p, shifts)
    for k, gear in ((1, pair.gear1), (2, pair.gear2)):
        if not gear.sa > 0.0:
            raise _pointed(k, gear, shifts, p) if advise else DesignError(f"x{k}", gear.shift, "pointed")
    if not meshes(pair):
        raise _apart(pair, shifts, advise)
    return pair


def meshes(pair: GearPair) -> bool:
    """Whether the teeth touch: the actual line of action B1B2 has a length and each tooth
    has a height (tip circle outside its root circle). Why: the addendum reduction Δy of a
    large x1 + x2 cuts both tips down; past about Δy = 2 h*a they no longer reach each
    other (ε and B1B2 came out negative, printed as results) and past 2 h*a + c* a tip
    circle lies inside its own root circle (the sheet's tooth outline then failed with an
    internal error, exit 1)."""
    return pair.b1b2 > 0.0 and all(g.ra > g.rf for g in (pair.gear1, pair.gear2))


def _geometry(p: GearPairInputs, shifts: Shifts) -> GearPair:
    """Every length of ``p`` meshed with ``shifts``, nothing refused (a tip inside its base
    circle has no line of action beyond N: its B is taken at N)."""
    m = p.module_mm
    a = reference_centre(p)
    y = (shifts.centre_mm - a) / m
    dy = shifts.x1 + shifts.x2 - y
    g1 = make_gear(p, p.z1, shifts.x1, dy, shifts.alpha_w)
    g2 = make_gear(p, p.z2, shifts.x2, dy, shifts.alpha_w)
    n1n2 = shifts.centre_mm * math.sin(shifts.alpha_w)
    n1b1 = math.sqrt(max(g1.ra ** 2 - g1.rb ** 2, 0.0))
    n1b2 = n1n2 - math.sqrt(max(g2.ra ** 2 - g2.rb ** 2, 0.0))
    pb = math.pi * m * math.cos(p.alpha)
    eps = (p.z1 * (math.tan(g1.alpha_a) - math.tan(shifts.alpha_w))
           + p.z2 * (math.tan(g2.alpha_a) - math.tan(shifts.alpha_w))) / (2.0 * math.pi)
    return GearPair(inputs=p, mode=shifts.mode, alpha_w=shifts.alpha_w, centre_mm=shifts.centre_mm,
                    reference_centre_mm=a, y=y, dy=dy, gear1=g1, gear2=g2, pb=pb, n1n2=n1n2,
                    b1b2=n1b1 - n1b2, n1p=g1.rb * math.tan(shifts.alpha_w), n1b1=n1b1, n1b2=n1b2,
                    contact_ratio=eps)


def _apart(pair: GearPair, shifts: Shifts, advise: bool) -> DesignError:
    """The error of a pair whose teeth never touch, naming what made x1 + x2 that large (the
    larger shift given, a′, or the teeth of the rule's pair) and, when ``advise``, the value of
    the shift or a′ at which they touch."""
    what = (f"x1 + x2 is too large: the addendum reduction Δy = {pair.dy:.4f} cuts both tips so far "
            "that the teeth never touch")
    big = 1 if shifts.x1 >= shifts.x2 else 2
    if shifts.mode == "centre":
        bound = _touch_bound(pair.inputs, shifts, "centre") if advise else None
        return DesignError("centre", shifts.centre_mm, what + ("" if bound is None else f"; give a′ ≤ {bound} mm"))
    if shifts.mode == "given":
        bound = _touch_bound(pair.inputs, shifts, f"x{big}") if advise else None
        return DesignError(f"x{big}", max(shifts.x1, shifts.x2),
                           what + ("" if bound is None else f"; give x{big} ≤ {bound}"))
    return DesignError(f"z{big}", pair.gear1.teeth if big == 1 else pair.gear2.teeth, what)


def _touch_bound(p: GearPairInputs, shifts: Shifts, name: str) -> str | None:
    """The value of ``name`` (a shift given, or a′), lowered and printed to 4 decimals, at
    which the teeth touch (:func:`meshes`); None if none within the inputs' ranges. Δy grows
    with x1 + x2, so the touching values are one range below the start: doubled steps find
    a value inside it, bisection its edge."""
    start = amounts.Start(p, shifts.x1, shifts.x2, shifts.centre_mm)
    field = {"x1": "x1", "x2": "x2", "centre": "centre_mm"}[name]

    def touch(inputs: GearPairInputs) -> bool:
        try:
            q = inputs.check()
            return meshes(_geometry(q, find_shifts(q)))
        except DesignError:
            return False
    unit = amounts.unit(start, name)
    lo, hi = 0.0, amounts.STEP_START * unit
    while not touch(amounts.typed(start, name, -hi)):
        if hi > amounts.STEP_MOST * unit:
            return None
        lo, hi = hi, 2.0 * hi
    for _ in range(amounts.EDGE_HALVINGS):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if touch(amounts.typed(start, name, -mid)) else (mid, hi)
    for bump in range(amounts.BUMPS + 1):
        value = amounts.rounded(getattr(start, field) - hi, amounts.LEAST_DECIMALS, False, bump)
        if touch(replace(amounts.typed(start, name, 0.0), **{field: value})):
            return f"{value + 0.0:.{amounts.LEAST_DECIMALS}f}"
    return None


def _pointed(k: int, gear: Gear, shifts: Shifts, p: GearPairInputs) -> DesignError:
    """The error of a pointed tip, naming what set the shift (x_k given, the centre distance,
    or the teeth that the rule's shifts needed) and the value of it at which the tip is at
    least the least tip thickness (``amounts``, each value designed before it is named)."""
    what = f"the tip of gear {k} pointed (x{k} = {gear.shift:.4f})"
    start = amounts.Start(p, shifts.x1, shifts.x2, shifts.centre_mm)
    tip = f"{p.tip_limit * p.module_mm:.6g}"
    thick = f"for a tip at least {tip} mm thick"
    if shifts.mode == "given" and gear.ra <= gear.rb:     # Δy took its whole flank
        big = 1 if shifts.x1 >= shifts.x2 else 2
        bound = amounts.tip_bound(probe_pair, start, k, f"x{big}")
        amount = "" if bound is None else f"; give x{big} ≤ {bound}, {thick.replace('a tip', f'a tip of gear {k}')}"
        return DesignError(f"x{big}", max(shifts.x1, shifts.x2), "x1 + x2 is too large: the "
                           f"addendum reduction leaves gear {k} no flank above its base circle{amount}")
    if shifts.mode == "given":
        bound = amounts.tip_bound(probe_pair, start, k, f"x{k}")
        fix = (f"no smaller x{k} found that gives a tip at least {tip} mm thick; give gear {k} more teeth" if bound is None
               else f"give x{k} ≤ {bound}, {thick}")
        return DesignError(f"x{k}", gear.shift, f"makes {what}: {fix}")
    if shifts.mode == "centre":
        bound = amounts.tip_bound(probe_pair, start, k, "centre")
        fix = (f"no smaller centre distance found that gives a tip at least {tip} mm thick; give gear {k} more teeth"
               if bound is None else f"give a′ ≤ {bound} mm, {thick}")
        return DesignError("centre", shifts.centre_mm, f"makes {what}: {fix}")
    teeth = amounts.least_teeth(probe_pair, p, k, f"tip{k}")
    fix = ("give more teeth, or the shifts or the centre distance" if teeth is None
           else f"give z{k} ≥ {teeth}, {thick}")
    return DesignError(f"z{k}", gear.teeth, f"too few teeth for the rule's shifts, which make {what}: {fix}")
