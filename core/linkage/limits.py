"""The bounds of a request (speeds, crank-angle step, samples) and their checks, without the
kinematics.

Why a module of its own: every ``shaper`` command's ``--help`` prints these numbers, and
``core.linkage.kinematics`` (which re-exports the checks) imports numpy, about 0.3 s of a
help that prints text only (issue 43 item 5). The checks are arithmetic on counts.
"""
from __future__ import annotations

import math

from core.base.errors import DesignError, require_range

MIN_RPM = 0.01
"""Slowest crank speed, r/min (one turn in 100 minutes): every time and rate stays finite."""
MAX_RPM = 1000.0
MAX_SPEEDS = 16
MIN_STEP_DEG = 0.0002
"""Finest crank-angle step, degrees (1 800 001 angles per cycle)."""
MAX_STEP_DEG = 90.0
MAX_SAMPLES = 2_000_000
"""Largest request, crank angles × crank speeds: what one computation may hold in memory."""
MAX_ANGLES = MAX_SAMPLES
MAX_FILE_SAMPLES = 60_000
"""Largest design a design file holds, its crank angles × crank speeds: what the GUI
recomputes and redraws on every edit within about half a second (set when 60 000 samples
took 0.34–0.68 s on the shared 2-core machine under a load of 3.5; docs/performance.md). It is
the file's own limit, checked by its reader and by ``shaper design``, so every file the
CLI writes or the library keeps opens in the GUI; commands that write no design file
(``shaper curves --step``) go up to :data:`MAX_SAMPLES`."""


def angle_count(step_deg: float) -> int:
    """How many angles ``kinematics.crank_angles`` gives for ``step_deg`` (validated), without making them."""
    _, steps, closing = angle_steps(step_deg)
    return steps + 1 + int(closing)


def angle_steps(step_deg: float) -> tuple[float, int, bool]:
    """The validated step, the whole steps in 360° and whether 360° must be appended."""
    step = require_range("step", step_deg, MIN_STEP_DEG, MAX_STEP_DEG, "°", low_open=False)
    steps = int(math.floor(360.0 / step + 1e-9))
    return step, steps, steps * step < 360.0 - 1e-9


def smallest_step(n_speeds: int, limit: int = MAX_SAMPLES) -> float:
    """The finest angle step, °, rounded up to 3 significant digits, whose angles times
    ``n_speeds`` stay within ``limit`` samples."""
    most_angles = limit // max(int(n_speeds), 1)
    # crank_angles gives floor(360/s) + 1 angles, plus 360° when s does not divide it.
    step = 360.0 / max(most_angles - 2, 1)
    scale = 10.0 ** (2 - math.floor(math.log10(step)))
    return max(math.ceil(step * scale) / scale, MIN_STEP_DEG)


def check_request(n_angles: int, n_speeds: int, parameter: str = "step",
                  value: object = None, limit: int = MAX_SAMPLES) -> int:
    """Refuse a request of more than ``limit`` samples (angles × speeds); return the count.

    Every front end calls this before computing, so that no request can
    exhaust memory: the CLI with the option the user typed as ``parameter``
    (and its ``value``, e.g. the step), the GUI with its own, smaller
    ``limit`` if it must stay responsive. For the step the message names the
    finest step allowed with this many speeds.
    """
    samples = int(n_angles) * int(n_speeds)
    if samples > limit:
        advice = "use a larger step or fewer speeds"
        if parameter == "step":
            speeds = "1 speed" if int(n_speeds) == 1 else f"{int(n_speeds)} speeds"
            advice = f"use a step of at least {smallest_step(n_speeds, limit):g}° for {speeds}"
        raise DesignError(parameter, samples if value is None else value,
                          f"gives {samples} samples (angles × speeds), more than {limit}; {advice}")
    return samples


def check_file_samples(step: float, n_speeds: int) -> int:
    """Refuse a design whose crank-angle ``step`` (°) with ``n_speeds`` speeds holds more
    samples than a design file may (:data:`MAX_FILE_SAMPLES`); return the count.

    The one check of that limit: the design file's reader, ``shaper design`` and the GUI's
    step field all call it, so a file one of them accepts the others accept too. The
    message names the limit as the file's and the coarsest step that fits."""
    samples = angle_count(step) * int(n_speeds)
    if samples > MAX_FILE_SAMPLES:
        raise TooManySamples(step, samples, int(n_speeds))
    return samples


class TooManySamples(DesignError):
    """:func:`check_file_samples`' refusal, with what a front end says of it and offers:
    ``samples`` (angles × speeds), ``limit`` (:data:`MAX_FILE_SAMPLES`) and ``coarsest``,
    the finest step that fits with these speeds (° rounded up to 3 digits). Why a class: a
    library entry stored before the limit is whole but too fine, not damaged, and
    ``shaper library export --step`` writes it at a step that fits."""

    def __init__(self, step: float, samples: int, n_speeds: int) -> None:
        self.samples, self.limit = samples, MAX_FILE_SAMPLES
        self.coarsest = smallest_step(n_speeds, MAX_FILE_SAMPLES)
        speeds = "1 speed" if n_speeds == 1 else f"{n_speeds} speeds"
        super().__init__("step", step, f"gives {samples} samples (angles × speeds) with {speeds}, more "
                         f"than a design file holds ({MAX_FILE_SAMPLES}); use a step of at least "
                         f"{self.coarsest:g}°")
