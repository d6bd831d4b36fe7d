"""Many designs of one variant as arrays of link lengths (:class:`Designs`): the type the
vectorized kinematics, dynamics and sweeps take, with the derived θ, K and H a single
:class:`core.linkage.geometry.Design` has. Made and checked by :mod:`core.linkage.designs`
(synthesis, direct dimensions, the rules), which every caller imports it from."""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Callable, Sequence

import numpy as np


@dataclass(frozen=True)
class Designs:
    """Link lengths of many designs of one variant and rod side, mm.

    Every length is an array; all of them broadcast to one shape (the
    designs' shape). ``rod`` is None for the block variant. The fields and
    derived properties have the names and meanings of :class:`core.linkage.geometry.Design`,
    so kinematics and dynamics take either.
    """

    crank: np.ndarray
    frame: np.ndarray
    lever: np.ndarray
    guide: np.ndarray
    rod: np.ndarray | None = None
    rod_side: str = "trailing"

    @property
    def variant(self) -> str:
        return "block" if self.rod is None else "rod"

    @cached_property
    def theta(self) -> np.ndarray:
        """Extreme-position angle θ, rad. Kept once computed (as is the stroke): the loaded
        sweep's polish reads both several times per step on a fresh set of designs."""
        return 2.0 * np.arcsin(self.crank / self.frame)

    @property
    def time_ratio(self) -> np.ndarray:
        theta = self.theta
        return (math.pi + theta) / (math.pi - theta)

    @cached_property
    def stroke(self) -> np.ndarray:
        """Nominal stroke 2·L3·sin(θ/2) = 2·L3·L1/L2, mm."""
        return 2.0 * self.lever * (self.crank / self.frame)

    @property
    def rod_sign(self) -> float:
        return 1.0 if self.rod_side == "leading" else -1.0

    @property
    def shape(self) -> tuple[int, ...]:
        return np.broadcast_shapes(*(np.shape(v) for v in self._lengths()))

    def _lengths(self) -> list[np.ndarray]:
        values = [self.crank, self.frame, self.lever, self.guide]
        return values if self.rod is None else values + [self.rod]

    def lengths(self) -> list[np.ndarray]:
        """L1, L2, L3, guide height [, L4]: the arrays a vectorized root search carries as
        its arguments and subsets as brackets close (see :meth:`with_lengths`)."""
        return self._lengths()

    def with_lengths(self, lengths: Sequence[np.ndarray],
                     theta: np.ndarray | None = None) -> "Designs":
        """Designs of this variant and rod side from lengths in the order of :meth:`lengths`.
        ``theta``, where given, is their θ (taken with the lengths from designs that had it:
        the same arcsine of the same numbers), kept as if computed: the loaded sweep's
        polish builds designs afresh for every Newton step, an arcsine a point each time."""
        crank, frame, lever, guide, *rod = lengths
        out = Designs(crank, frame, lever, guide, rod[0] if rod else None, self.rod_side)
        if theta is not None:
            out.__dict__["theta"] = theta          # functools.cached_property's own slot
        return out

    def _map(self, fun: Callable[[np.ndarray], np.ndarray]) -> "Designs":
        shape = self.shape
        return self.with_lengths([fun(np.broadcast_to(v, shape)) for v in self._lengths()])

    def take(self, index) -> "Designs":
        """The designs at ``index`` (an index array or boolean mask over the designs)."""
        return self._map(lambda v: v[index])

    def flat(self) -> "Designs":
        """The same designs as one axis (every length broadcast to the designs' shape)."""
        return self._map(lambda v: v.reshape(-1))

    def column(self) -> "Designs":
        """The same designs with a trailing axis, to broadcast against (…, n) crank angles."""
        return self._map(lambda v: v[..., None])

    @classmethod
    def of(cls, design) -> "Designs":
        """One :class:`~core.linkage.geometry.Design` (or anything with its fields) as shape (1,)."""
        one = lambda v: np.array([float(v)])  # noqa: E731
        return cls(one(design.crank), one(design.frame), one(design.lever), one(design.guide),
                   None if design.rod is None else one(design.rod), design.rod_side)
