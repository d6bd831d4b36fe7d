"""One BLAS thread for the command line and the window, set before numpy is imported.

Why: numpy's OpenBLAS starts a thread per core when it is loaded, and those
threads spin for a while waiting for work that never comes: about 0.1 s of CPU
in every ``shaper`` command and at every start of the window (``/usr/bin/time``:
user time 0.28–0.30 s against 0.16–0.20 s for ``shaper curves``, issue 24). On
a busy two-core machine that time is taken from the main thread. Nothing here
multiplies matrices large enough to gain from threads. A value the user has set
is kept.
"""
from __future__ import annotations

import os

VARIABLE = "OPENBLAS_NUM_THREADS"


def limit_blas_threads() -> None:
    """Ask OpenBLAS for one thread, unless the user chose; only effective before numpy's
    first import in this process (and for every process started from it)."""
    os.environ.setdefault(VARIABLE, "1")
