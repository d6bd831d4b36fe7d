"""How many examples a slow random sweep draws in this run.

CI runs every test, the slow tier included, but a slow sweep (a hypothesis test marked
``slow`` whose examples each build a window, a sheet or a process) draws a share of its
examples there: the suite has to finish in minutes on two cores. The hypothesis profile
``thorough`` draws each sweep's full number, for a run after a change to what a sweep
covers: ``HYPOTHESIS_PROFILE=thorough python -m pytest -m slow`` (profiles: tests/conftest.py).
"""
from __future__ import annotations

import math

from hypothesis import settings

# The default run draws this share of a sweep's full number of examples.
SHARE = 0.25


def examples(full: int) -> int:
    """``full`` in the ``thorough`` profile; otherwise ``SHARE`` of it, rounded up."""
    if settings.get_current_profile_name() == "thorough":
        return full
    return max(1, math.ceil(full * SHARE))
