"""Many designs at once: link lengths as arrays, and the rules every design must pass.

The lowest level of core, below :mod:`core.linkage.geometry`. ``geometry.synthesize``,
``from_dimensions`` and ``validate`` run exactly these vectorized rules on one
design, so a design in a sweep of a hundred thousand and the same design typed
into the form are refused by the same rule, naming the same parameter, with the
same message. Rules are checked in a fixed order and a design is refused by the
first one it fails, as a single design's validation raises at the first.
"""
from __future__ import annotations

import math
import re

import numpy as np

from core.base.errors import DesignError, range_text
from .design_array import Designs      # made and checked here; every caller imports it from here
from .drive import ROD_MARGIN, jams, largest_rise, least_rod
from .verdict import Flat, Verdict, check_range, open_range_texts, round_text

MIN_LENGTH_MM = 0.001
MAX_LENGTH_MM = 100_000.0
MAX_TIME_RATIO = 5.0
# L1/L2 = sin(θ/2) at K = 5 (θ = 120°): the largest crank a frame allows.
MAX_CRANK_RATIO = math.sin(math.pi * (MAX_TIME_RATIO - 1.0) / (MAX_TIME_RATIO + 1.0) / 2.0)
ROD_SIDES: tuple[str, ...] = ("trailing", "leading")
GUIDE_RULES: tuple[str, ...] = ("chord", "sagitta")
MAX_ROD_RATIO = 10.0

_LENGTH_TEXT = range_text(MIN_LENGTH_MM, MAX_LENGTH_MM, "mm", low_open=False)


def check_length(verdict: Verdict, name: str, value: np.ndarray) -> None:
    """A link length in [MIN_LENGTH_MM, MAX_LENGTH_MM] mm."""
    check_range(verdict, name, value, MIN_LENGTH_MM, MAX_LENGTH_MM, "mm", low_open=False)


def _floats(*values) -> list[np.ndarray]:
    arrays = [np.asarray(v, dtype=float) for v in values]
    shape = np.broadcast_shapes(*(a.shape for a in arrays))
    return [np.broadcast_to(a, shape) for a in arrays]


def synthesize_many(crank, time_ratio, stroke, *, guide="chord", rod=None, rod_ratio=None,
                    rod_side: str = "trailing",
                    validate: bool = True) -> tuple[Designs, Verdict]:
    """Seed 003's synthesis for arrays of L1, K, H (and guide height, rod or rod ratio).

    Returns the designs (NaN where a rule failed before their lengths existed)
    and the verdict. Without ``validate`` only the synthesis rules are checked
    (``geometry.Design`` checks the rest on construction).
    """
    (crank, time_ratio, stroke), extra = _inputs((crank, time_ratio, stroke), guide, rod, rod_ratio)
    shape = crank.shape
    verdict = Verdict(np.zeros(shape, dtype=np.int16))
    check_length(verdict, "crank", crank)
    check_range(verdict, "time_ratio", time_ratio, 1.0, MAX_TIME_RATIO)
    check_length(verdict, "stroke", stroke)
    if not isinstance(extra[0], str):   # a guide height given: in range before the block's reach reads it
        check_length(verdict, "guide", extra[0])    # (an infinite one made that rule's text overflow)
    with np.errstate(all="ignore"):
        theta = math.pi * (time_ratio - 1.0) / (time_ratio + 1.0)
        half = np.sin(theta / 2.0)
        # L2 = L1/sin(θ/2) and L3 = H/(2 sin(θ/2)) grow without bound as K → 1.
        smallest = np.maximum(crank, stroke / 2.0) / MAX_LENGTH_MM
        angle = 2.0 * np.arcsin(np.minimum(smallest, 1.0))
        k_min = (math.pi + angle) / (math.pi - angle)
        frame = crank / half
        lever = stroke / (2.0 * half)
        need = 2.0 * (crank + frame) * half
        too_short = lever < crank + frame
        ruled = isinstance(extra[0], str)
        if ruled:               # the guide the rule places must clear the crank too: a longer lever
            need = need / guide_share(extra[0], theta)
            too_short = lever <= (crank + frame) / guide_share(extra[0], theta)
        # the block on the lever's tip must reach a guide set above L2 + L1, which needs a
        # lever longer than L2 + L1 (check_designs)
        block_at_height = not ruled and extra[1] is None and extra[2] is None
        if block_at_height:
            too_short = lever <= crank + frame
        tip = np.broadcast_to(block_at_height and (extra[0] > crank + frame), shape) & too_short
        reach = 2.0 * half * extra[0] if np.any(tip) else need     # the stroke the block's reach needs
    verdict.check("time_ratio", half < smallest, time_ratio,
                  lambda i, at=Flat(k_min, shape): _k_min_text(float(at[i])))
    verdict.check("stroke", tip, stroke,
                  lambda i, at=Flat(reach, shape), height=Flat(extra[0] if np.any(tip) else need, shape):
                      f"must be ≥ {math.ceil(at[i] * 10.0) / 10.0:.1f} mm for this crank and K, so that the "
                      f"block on the lever tip reaches the guide height {round_text(height[i])} mm")
    verdict.check("stroke", too_short, stroke,
                  (lambda i, at=Flat(need, shape): f"must be > {round_text(at[i])} mm for this crank and K, "
                   "so that the ram guide its rule places clears the crank") if ruled else
                  (lambda i, at=Flat(need, shape): f"must be > {round_text(at[i])} mm for this crank and K, "
                   "so that the crank pin stays on the lever and a ram guide fits between L2 + L1 and the "
                   "lever tip") if block_at_height else
                  (lambda i, at=Flat(need, shape):
                      f"must be ≥ {math.ceil(at[i] * 10.0) / 10.0:.1f} mm for this crank and K, "
                      "so that the crank pin stays on the lever"))
    return _assemble(verdict, crank, frame, lever, theta, extra, rod_side, validate, guide_checked=True)


def _k_min_text(k_min: float) -> str:
    """What K must be so that the frame and the lever stay ≤ MAX_LENGTH_MM: a bound, or,
    where none up to MAX_TIME_RATIO exists (a crank or half stroke near MAX_LENGTH_MM,
    where the bound is infinite), that no K does."""
    if k_min <= MAX_TIME_RATIO:
        return (f"must be ≥ {round_text(k_min)} for this crank and stroke, so that the frame "
                f"and the lever stay ≤ {MAX_LENGTH_MM:g} mm")
    return (f"no K up to {MAX_TIME_RATIO:g} keeps the frame and the lever ≤ {MAX_LENGTH_MM:g} mm "
            "for this crank and stroke: shorten them")


def dimensions_many(crank, frame, lever, *, guide="chord", rod=None, rod_ratio=None,
                    rod_side: str = "trailing", validate: bool = True) -> tuple[Designs, Verdict]:
    """Designs from arrays of measured link lengths; K, H and θ are then implied."""
    (crank, frame, lever), extra = _inputs((crank, frame, lever), guide, rod, rod_ratio)
    verdict = Verdict(np.zeros(crank.shape, dtype=np.int16))
    check_length(verdict, "crank", crank)
    check_length(verdict, "frame", frame)
    check_length(verdict, "lever", lever)
    check_crank_ratio(verdict, crank, frame)
    with np.errstate(all="ignore"):
        theta = 2.0 * np.arcsin(np.minimum(crank / frame, 1.0))
        if isinstance(extra[0], str):   # the guide is no input: the lever that places it high enough
            reach = crank + frame
            need = reach / guide_share(extra[0], theta)
            verdict.check("lever", lever <= need, lever,
                          lambda i, at=Flat(need, crank.shape), low=Flat(reach, crank.shape):
                              f"must be > {round_text(at[i])} mm, so that the ram guide its rule places "
                              f"clears the crank (L2 + L1 = {round_text(low[i])} mm above the lever pivot)")
    return _assemble(verdict, crank, frame, lever, theta, extra, rod_side, validate)


def _inputs(lengths, guide, rod, rod_ratio):
    """The three leading lengths as float arrays of one shape, and (guide, rod, rod ratio):
    a guide rule stays a name, every number becomes an array of that shape."""
    numeric = not (isinstance(guide, str) and guide in GUIDE_RULES)
    given = [_guide_number(guide) if numeric else None, rod, rod_ratio]
    arrays = iter(_floats(*lengths, *[v for v in given if v is not None]))
    first = [next(arrays) for _ in lengths]
    extra = tuple(next(arrays) if v is not None else None for v in given)
    return first, (extra[0] if numeric else guide,) + extra[1:]


def _assemble(verdict: Verdict, crank, frame, lever, theta, extra, rod_side: str,
              validate: bool, guide_checked: bool = False) -> tuple[Designs, Verdict]:
    """The rod and guide rules (a given guide height's range unless ``guide_checked``), the
    designs, and (with ``validate``) the design rules."""
    guide, rod, rod_ratio = extra
    rod_length = _rod_length(verdict, rod, rod_ratio, lever)
    if rod_ratio is not None:       # the rod's rules check L4 in mm: each refusal in L4/L3
        ratios = Flat(rod_ratio, verdict.failed.shape)
        verdict.blame = lambda error, index: ratio_error(error, float(ratios[index]))
    if not (guide_checked or isinstance(guide, str)):
        check_length(verdict, "guide", guide)
    designs = Designs(crank, frame, lever, _guide(guide, lever, theta), rod_length, rod_side)
    if validate:
        check_designs(verdict, designs)
    return designs, verdict


def guide_share(rule: str, theta) -> np.ndarray:
    """The guide height a rule places, as a share of the lever L3 (``_guide``): cos(θ/2) for
    the chord, (1 + cos(θ/2))/2 for the sagitta."""
    chord = np.cos(np.asarray(theta) / 2.0)
    return chord if rule == "chord" else (1.0 + chord) / 2.0


def _guide_number(guide):
    """An explicit guide height (a number, an array, or a number as text)."""
    if isinstance(guide, str):
        try:
            return float(guide)
        except ValueError:
            raise DesignError("guide", guide,
                              "must be 'chord', 'sagitta' or a height in mm") from None
    return guide


def _guide(guide, lever: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Guide height above O4 for a named rule (see ``geometry.guide_height``) or given heights."""
    if isinstance(guide, str):
        with np.errstate(all="ignore"):     # a lever near the float limit: inf, refused later
            return lever * guide_share(guide, theta)
    return guide


def _rod_length(verdict: Verdict, rod, rod_ratio, lever: np.ndarray) -> np.ndarray | None:
    if rod is not None and rod_ratio is not None:
        raise DesignError("rod", float(np.ravel(rod)[0]),
                          "must be given either as a length or as a ratio L4/L3, not both")
    if rod_ratio is not None:
        check_range(verdict, "rod_ratio", rod_ratio, 0.0, MAX_ROD_RATIO)
        with np.errstate(all="ignore"):
            return rod_ratio * lever
    if rod is not None:
        check_length(verdict, "rod", rod)
        return rod
    return None


def check_crank_ratio(verdict: Verdict, crank: np.ndarray, frame: np.ndarray) -> None:
    """K = (π + θ)/(π − θ) with sin(θ/2) = L1/L2 must stay ≤ 5, like a synthesized K."""
    shape = verdict.failed.shape
    verdict.check("crank", crank >= frame, crank,
                  lambda i, at=Flat(frame, shape):
                      f"must be shorter than the frame O2O4 ({round_text(at[i], down=True)} mm)")
    with np.errstate(all="ignore"):
        too_long = crank > MAX_CRANK_RATIO * frame * (1.0 + 1e-12)
    verdict.check("crank", too_long, crank,
                  lambda i, at=Flat(frame, shape):
                      f"must be ≤ {round_text(MAX_CRANK_RATIO * at[i], down=True)}"
                      f" mm (0.866·L2), so that the time ratio K stays ≤ {MAX_TIME_RATIO:g}")


def check_designs(verdict: Verdict, d: Designs) -> None:
    """Refuse designs that cannot be assembled or would jam somewhere in the cycle.

    Each refusal's bound, followed, leads on to a valid design (tests/test_core/
    test_linkage_advice.py follows them): the block variant's guide must lie in (L2 + L1, L3],
    so its lever is refused at L2 + L1 itself, which would leave the guide no height."""
    shape = verdict.failed.shape
    for name in ("crank", "frame", "lever", "guide"):
        check_length(verdict, name, getattr(d, name))
    check_crank_ratio(verdict, d.crank, d.frame)
    verdict.check("rod_side", d.rod_side not in ROD_SIDES, d.rod_side,
                  "must be 'trailing' or 'leading'")
    reach = d.frame + d.crank
    if d.rod is None:
        _check_block(verdict, d, reach)
        return
    verdict.check("lever", d.lever < reach, d.lever,
                  lambda i, at=Flat(reach, shape):
                      f"must be ≥ L2 + L1 = {round_text(at[i])} mm, "
                      "so that the crank pin stays on the lever")
    verdict.check("guide", d.guide <= reach, d.guide,
                  lambda i, at=Flat(reach, shape):
                      f"must be > L2 + L1 = {round_text(at[i])} mm above the lever "
                      "pivot, so that the ram clears the crank")
    check_length(verdict, "rod", d.rod)
    # The rod's rise |d| = |guide − By| is largest at a limit position (By lowest) or at
    # ψ = 0 (By = L3); its horizontal reach sqrt(L4² − d²) must stay ≥ ROD_MARGIN·L4.
    with np.errstate(all="ignore"):
        need = largest_rise(d) / math.sqrt(1.0 - ROD_MARGIN ** 2)
    verdict.check("rod", d.rod <= need, d.rod,
                  lambda i, at=Flat(need, shape):
                      f"must be > {round_text(at[i])} mm to reach the guide line "
                      "over the whole cycle")
    stuck = jams(d, verdict.ok)
    # the least rod that clears the dead centre costs a search: made only when a reason is
    # read, then for every design this rule refuses at once (a sweep reads them all)
    verdict.check("rod", stuck, d.rod,
                  lambda i, at=Flat(lambda: _least_rods(d, stuck), shape): _dead_centre_text(at[i]))


def _check_block(verdict: Verdict, d: Designs, reach: np.ndarray) -> None:
    """The block variant's lever and guide: the guide in (L2 + L1, L3]. A lever that is too
    short is told to reach the guide where the guide is set above L2 + L1, else to pass
    L2 + L1 (strictly: the guide needs a height above it); the guide is told both ends."""
    shape = verdict.failed.shape
    high = np.asarray(d.guide > reach)
    short = d.lever <= reach
    verdict.check("lever", short & ~high, d.lever,
                  lambda i, at=Flat(reach, shape):
                      f"must be > L2 + L1 = {round_text(at[i])} mm, so that the crank pin stays on the lever "
                      "and a ram guide fits between L2 + L1 and the lever tip")
    verdict.check("lever", short & high, d.lever,
                  lambda i, at=Flat(d.guide, shape), low=Flat(reach, shape):
                      f"must be ≥ the guide height {round_text(at[i])} mm, so that the block on the lever tip "
                      f"reaches the guide (and the crank pin stays on the lever: L2 + L1 = {round_text(low[i])} mm)")
    verdict.check("guide", ~high | (d.guide > d.lever), d.guide,
                  lambda i, low=Flat(reach, shape), high=Flat(d.lever, shape):
                      "must be > L2 + L1 = {} mm and ≤ the lever length {} mm, so that the ram clears the "
                      "crank and the block on the lever tip reaches the guide".format(
                          *open_range_texts(float(low[i]), float(high[i]))))


def _least_rods(d: Designs, stuck: np.ndarray) -> np.ndarray:
    """The least rod that clears the dead centre where ``stuck``, NaN elsewhere (the designs' shape)."""
    out = np.full(stuck.shape, np.nan)
    out[stuck] = least_rod(d.take(stuck))
    return out


def _dead_centre_text(least: float) -> str:
    """The dead-centre refusal: the least rod that clears it, rounded up (so that it passes as
    printed), or, where that is longer than MAX_LENGTH_MM, the guide line alone."""
    if least <= MAX_LENGTH_MM:
        return ("the rod passes a dead-centre position against the lever; lengthen it to at least "
                f"{round_text(least)} mm or move the guide line")
    return ("the rod passes a dead-centre position against the lever at every length up to "
            f"{MAX_LENGTH_MM:g} mm; move the guide line")


def ratio_error(error: DesignError, ratio: float) -> DesignError:
    """A refusal of the rod L4 (mm) restated for a rod given as ``ratio`` = L4/L3: named
    ``rod_ratio``, its value the ratio, its bound in mm divided by L3 and rounded up to 4
    digits, so that typing it passes (the reach's "must be > X mm", the dead centre's
    "lengthen it to at least X mm"). The GUI's form, the command line (``--rod-ratio``), a
    design file's ``rod_ratio`` and a sweep's reasons all get it: the command line named
    ``--rod`` with a length in mm nobody had typed."""
    if error.parameter != "rod" or not isinstance(error.value, float) or not error.value > 0 or not ratio > 0:
        return error
    lever = error.value / ratio
    span = re.match(r"^must be ≥ (\S+) and ≤ (\S+) mm$", error.allowed)
    if span:        # the rod's length range (check_length), as ratios of this lever, inward
        low, high = (float(v) / lever for v in span.groups())
        return DesignError("rod_ratio", ratio, f"must be ≥ {round_text(low, 4)} and ≤ {round_text(high, 4, down=True)}")
    scaled = lambda m: round_text(float(m.group(2)) / lever, 4)  # noqa: E731
    allowed = re.sub(r"^(must be > )(\S+) mm ", lambda m: f"{m.group(1)}{scaled(m)} ", error.allowed)
    allowed = re.sub(r"(; )lengthen it to at least (\S+) mm ",
                     lambda m: f"{m.group(1)}raise L4/L3 to at least {scaled(m)} ", allowed)
    return DesignError("rod_ratio", ratio, allowed)
