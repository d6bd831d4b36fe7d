"""How far a long job is, and whether to stop it: one small value a writer takes.

The report, the course design and whatever runs them (the GUI's progress dialog,
``shaper course``, a class of students) share it: the job calls :meth:`Progress.done`
with the fraction it has finished after each step (a section, a page, a file), and
learns there whether it is to stop (:class:`Cancelled`). A step is where stopping
leaves nothing half-made, so a job checks nowhere else. Why a value and not a Qt
signal: the writers run headless too, and ``core`` never imports Qt.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable


class Cancelled(Exception):
    """The job was asked to stop (``should_stop`` returned true at a step); what it was
    writing is not written."""


def _quiet(fraction: float) -> None:
    """No one to tell."""


def _never() -> bool:
    return False


@dataclass(frozen=True)
class Progress:
    """``report(fraction)`` with the whole job's fraction done, 0 to 1 and never going
    back, and ``should_stop()`` read at every step. ``start`` and ``end`` are the slice
    of the whole job this part stands for (:meth:`part`)."""

    report: Callable[[float], None] = _quiet
    should_stop: Callable[[], bool] = _never
    start: float = 0.0
    end: float = 1.0

    def done(self, fraction: float) -> None:
        """This part is ``fraction`` (0 to 1) done: tell it, then stop if asked
        (:class:`Cancelled`)."""
        fraction = min(max(float(fraction), 0.0), 1.0)
        self.report(self.start + fraction * (self.end - self.start))
        if self.should_stop():
            raise Cancelled()

    def note(self, fraction: float) -> None:
        """This part is ``fraction`` done, told without asking whether to stop: for the
        end of a piece of work the caller must still hear of (a file just written)."""
        self.report(self.start + min(max(float(fraction), 0.0), 1.0) * (self.end - self.start))

    def part(self, start: float, end: float) -> "Progress":
        """The progress of a part that is the slice ``start`` to ``end`` (fractions of this
        one): its own 0 to 1 is reported as that slice of the whole."""
        span = self.end - self.start
        return Progress(self.report, self.should_stop, self.start + start * span, self.start + end * span)

    def steps(self, count: int) -> Callable[[], None]:
        """A counter of ``count`` equal steps: each call is one more step :meth:`done`."""
        taken = [0]

        def step() -> None:
            taken[0] += 1
            self.done(taken[0] / max(count, 1))
        return step
