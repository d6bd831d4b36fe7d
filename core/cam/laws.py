"""The follower's motion laws and the cam's program (rise, outer dwell, return, inner dwell).

Each law is a normalized rise s(u) over u ∈ [0, 1] with s(0) = 0, s(1) = 1 and its exact
first and second derivatives; the program scales it to the follower's swing ψmax and the
phase's cam angle, so dψ/dδ and d²ψ/dδ² are closed forms (never differenced). The return
runs the law backwards (ψ = ψmax·(1 − s)), so both phases of every law start and end at
rest and a dwell joins them without a jump in velocity.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, NamedTuple

import numpy as np

from core.base.errors import DesignError, require_range
from .defaults import LAWS  # noqa: F401  (imported from here too)

MIN_SWING_DEG, MAX_SWING_DEG = 1.0, 60.0
"""Follower swing ψmax, degrees: a feed arm swings 10°–30°; these bounds keep the data
sheet's values with a wide margin and refuse what is surely a slip."""
MIN_PHASE_DEG = 1.0
"""Shortest rise or return, degrees of cam angle: shorter would need a cam as large as a room."""

Law = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]


def _parabolic(u: np.ndarray, first: np.ndarray | None = None):
    """Constant acceleration then deceleration (等加速等减速): s = 2u² then 1 − 2(1 − u)².
    ``first`` picks the half whose formula applies (by default the half u lies in)."""
    first = u < 0.5 if first is None else first
    s = np.where(first, 2.0 * u * u, 1.0 - 2.0 * (1.0 - u) ** 2)
    s1 = np.where(first, 4.0 * u, 4.0 * (1.0 - u))
    s2 = np.where(first, 4.0, -4.0)
    return s, s1, s2


def _cosine(u: np.ndarray):
    """Simple harmonic (余弦加速度): s = (1 − cos πu)/2."""
    return ((1.0 - np.cos(math.pi * u)) / 2.0, math.pi / 2.0 * np.sin(math.pi * u),
            math.pi ** 2 / 2.0 * np.cos(math.pi * u))


def _sine(u: np.ndarray):
    """Cycloidal (正弦加速度): s = u − sin(2πu)/(2π); no jump in acceleration."""
    w = 2.0 * math.pi * u
    return u - np.sin(w) / (2.0 * math.pi), 1.0 - np.cos(w), 2.0 * math.pi * np.sin(w)


def _poly345(u: np.ndarray):
    """The 3-4-5 polynomial: s = 10u³ − 15u⁴ + 6u⁵."""
    return (u ** 3 * (10.0 - 15.0 * u + 6.0 * u * u), 30.0 * u * u * (1.0 - u) ** 2,
            60.0 * u * (1.0 - u) * (1.0 - 2.0 * u))


_LAW_FUNCTIONS: dict[str, Law] = {"parabolic": _parabolic, "cosine": _cosine,
                                  "sine": _sine, "poly345": _poly345}


def law(name: str, u: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """s, ds/du, d²s/du² of the normalized rise ``name`` at ``u`` (clipped to [0, 1])."""
    return _LAW_FUNCTIONS[name](np.clip(np.asarray(u, dtype=float), 0.0, 1.0))


PIECES = {"parabolic": (0.0, 0.5, 1.0)}
"""Where a law's acceleration jumps inside its phase, as the edges of the pieces on which it
is smooth (u; a law not listed is smooth on [0, 1]): a figure that depends on d²s/du² (the
curvature) has a one-sided value at each edge, and both count."""


def pieces(name: str) -> tuple[float, ...]:
    """The edges of the smooth pieces of law ``name`` over u ∈ [0, 1]."""
    return PIECES.get(name, (0.0, 1.0))


def law_piece(name: str, u: np.ndarray, piece: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """s, ds/du, d²s/du² of law ``name`` by the formula of its smooth piece ``piece`` (the
    index into :func:`pieces`), even at that piece's closed ends: at u = ½ the parabolic
    law's first piece gives its acceleration's left limit, which :func:`law` does not."""
    u = np.clip(np.asarray(u, dtype=float), 0.0, 1.0)
    if name == "parabolic":
        return _parabolic(u, np.asarray(piece) == 0)
    return _LAW_FUNCTIONS[name](u)


PEAKS = {"parabolic": (2.0, 4.0), "cosine": (math.pi / 2.0, math.pi ** 2 / 2.0),
         "sine": (2.0, 2.0 * math.pi), "poly345": (15.0 / 8.0, 10.0 / math.sqrt(3.0))}
"""max |ds/du| and max |d²s/du²| of each law, in closed form: the velocity peaks at u = ½
for all four (4·½, π/2, 1 − cos π, 30·¼·¼); the acceleration at the ends for the
cosine law (π²/2), at u = ¼ for the sine law (2π·sin(π/2)), on either half for the parabolic
law, and at u = ½ ∓ √3/6 for the 3-4-5 polynomial (60·u(1 − u)(1 − 2u) there is 10/√3)."""


class Motion(NamedTuple):
    """The follower over cam angles: ψ (rad, from the lowest position), dψ/dδ, d²ψ/dδ²."""

    psi: np.ndarray
    psi1: np.ndarray
    psi2: np.ndarray


@dataclass(frozen=True)
class Program:
    """What the data sheet gives for the follower's motion; angles in degrees.

    The cam turns through ``rise_deg`` while the follower swings out by ``swing_deg``,
    dwells for ``dwell_deg``, swings back over ``return_deg`` and rests for the rest of
    the turn (the inner dwell)."""

    swing_deg: float = 15.0
    rise_deg: float = 60.0
    dwell_deg: float = 10.0
    return_deg: float = 60.0
    rise_law: str = "sine"
    return_law: str = "sine"

    def __post_init__(self) -> None:
        for name in ("rise_law", "return_law"):
            if getattr(self, name) not in LAWS:
                raise DesignError(name, getattr(self, name), "must be one of " + ", ".join(LAWS))
        require_range("swing", self.swing_deg, MIN_SWING_DEG, MAX_SWING_DEG, "°", low_open=False)
        require_range("rise", self.rise_deg, MIN_PHASE_DEG, 360.0, "°", low_open=False, high_open=True)
        require_range("return", self.return_deg, MIN_PHASE_DEG, 360.0, "°", low_open=False,
                      high_open=True)
        require_range("dwell", self.dwell_deg, 0.0, 360.0, "°", low_open=False, high_open=True)
        total = self.rise_deg + self.dwell_deg + self.return_deg
        if total > 360.0:
            raise DesignError("dwell", self.dwell_deg,
                              f"rise + outer dwell + return must fit in 360° (they add up to {total:g}°)")

    @property
    def inner_dwell_deg(self) -> float:
        return 360.0 - self.rise_deg - self.dwell_deg - self.return_deg

    @property
    def feed_deg(self) -> float:
        """The cam angle over which the follower moves or is out: rise + outer dwell + return."""
        return self.rise_deg + self.dwell_deg + self.return_deg

    def motion(self, delta: np.ndarray) -> Motion:
        """ψ, dψ/dδ, d²ψ/dδ² at cam angles ``delta`` (rad, any turn; 0 = start of the rise)."""
        d = np.mod(np.asarray(delta, dtype=float), 2.0 * math.pi)
        swing = math.radians(self.swing_deg)
        rise, dwell, ret = (math.radians(v) for v in (self.rise_deg, self.dwell_deg, self.return_deg))
        s, s1, s2 = law(self.rise_law, d / rise)
        r, r1, r2 = law(self.return_law, (d - rise - dwell) / ret)
        up = d < rise
        out = (d >= rise) & (d < rise + dwell)
        back = (d >= rise + dwell) & (d < rise + dwell + ret)
        psi = swing * np.select([up, out, back], [s, 1.0, 1.0 - r], 0.0)
        psi1 = swing * np.select([up, back], [s1 / rise, -r1 / ret], 0.0)
        psi2 = swing * np.select([up, back], [s2 / rise ** 2, -r2 / ret ** 2], 0.0)
        return Motion(psi, psi1, psi2)

    def peaks(self) -> tuple[float, float]:
        """max |dψ/dδ| and max |d²ψ/dδ²| over the turn (rad, per rad and per rad²), in closed
        form from each law's peaks (:data:`PEAKS`) scaled by ψmax/Φ and ψmax/Φ²."""
        swing = math.radians(self.swing_deg)
        spans = ((self.rise_law, math.radians(self.rise_deg)),
                 (self.return_law, math.radians(self.return_deg)))
        return (max(swing * PEAKS[name][0] / span for name, span in spans),
                max(swing * PEAKS[name][1] / span ** 2 for name, span in spans))

    def phase(self, delta: np.ndarray) -> np.ndarray:
        """0 in the rise, 1 in the outer dwell, 2 in the return, 3 in the inner dwell."""
        d = np.degrees(np.mod(np.asarray(delta, dtype=float), 2.0 * math.pi))
        edges = np.cumsum([self.rise_deg, self.dwell_deg, self.return_deg])
        return np.searchsorted(edges, d, side="right")
