"""A cam's refusal said at once, its advice found later: :class:`PendingAdvice`.

Why: the advice of some refusals names a value to type only after designing many whole
cams (``advice``: 0.1–0.4 s), and the GUI must not wait for it on its own thread. With
``design_cam(…, advice_later=True)`` such a refusal is raised at once as a PendingAdvice:
its statement and what the search looks for (``SEEKING``); :meth:`PendingAdvice.seek`,
on any thread, then designs the same inputs as ``design_cam`` does without it and gives
the refusal that raises, so the advice shown at last is the synchronous one by
construction. The CLI, the report and the course design never ask for it later.

A search can be stopped: ``seek(should_stop)`` asks ``should_stop()`` before each whole
cam it designs (:func:`check_stop`, called by ``cam._probe``) and raises
``core.base.progress.Cancelled``. The question is held in a context variable, which is
each thread's own, so a search stopped on one thread never stops a design on another.
"""
from __future__ import annotations

from contextvars import ContextVar
from typing import Callable

from core.base.errors import DesignError
from core.base.progress import Cancelled

SEEKING = {
    "swing": "looking for a swing, else an arm, that gives one…",
    "roller": "looking for a roller, else another value, that gives one…",
    "allowance": "looking for the least allowance, else a swing, that gives one…",
    "arm": "looking for an arm that gives one…",
    "synthesis": "looking for what leaving the cam to the synthesis gives…",
}
"""What a pending refusal's search looks for, after its statement and "; " (the interim
text; the GUI translates it as it translates the advice that replaces it)."""


def _never() -> bool:
    return False


_SHOULD_STOP: ContextVar[Callable[[], bool]] = ContextVar("cam_advice_should_stop", default=_never)


def check_stop() -> None:
    """Cancelled if the search running on this thread is asked to stop (before each whole
    cam a search designs)."""
    if _SHOULD_STOP.get()():
        raise Cancelled()


class PendingAdvice(DesignError):
    """A refusal whose advice is still to be found: ``parameter`` and ``value`` as the
    refusal's own, ``allowed`` its statement and what the search looks for (``SEEKING``);
    ``refusal`` the refusal as designed at once (a FitError where the advice will blame
    the fields a FitError blames)."""

    def __init__(self, refusal: DesignError, statement: str, seeking: str,
                 find: Callable[[], DesignError]) -> None:
        super().__init__(refusal.parameter, refusal.value, f"{statement}; {SEEKING[seeking]}")
        self.refusal = refusal
        self._find = find

    def seek(self, should_stop: Callable[[], bool] = _never) -> DesignError:
        """The refusal with its advice, as ``design_cam`` raises it without ``advice_later``;
        Cancelled when ``should_stop()`` turns true meanwhile."""
        token = _SHOULD_STOP.set(should_stop)
        try:
            return self._find()
        finally:
            _SHOULD_STOP.reset(token)
