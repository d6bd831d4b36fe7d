"""A hard time limit on every test that holds even when Python itself is stuck.

pytest-timeout (pyproject.toml) fails a test that runs too long from a Python thread, which
must take Python's global lock (the GIL) first. A deadlock inside Qt's C++ code can hold
that lock for ever; the thread then never runs and the run only ends at CI's own limit,
with no clue where it stopped. Two mechanisms that need no GIL take over: faulthandler
prints every thread's stack after ``faulthandler_timeout`` (pyproject.toml), and then the
kernel ends the process with SIGALRM's default action after ``HARD_LIMIT_S``.
"""
from __future__ import annotations

import os
import signal

import pytest

# Above pytest-timeout's 600 s and faulthandler_timeout's 620 s, so those act first.
HARD_LIMIT_S = int(os.environ.get("SHAPER_TEST_HARD_LIMIT_S", "660"))


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    """Every phase of a test (setup, call, teardown) under the hard limit."""
    armed = hasattr(signal, "alarm") and signal.getsignal(signal.SIGALRM) == signal.SIG_DFL
    if armed:
        signal.alarm(HARD_LIMIT_S)
    try:
        yield
    finally:
        if armed:
            signal.alarm(0)
