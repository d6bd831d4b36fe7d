"""How many equally spaced crank positions a course table has: by default, and at most.

Why a module of its own: ``shaper table``, ``report`` and ``drawing`` print the default in
their ``--help``, and ``core.course_design.positions`` (which tabulates the positions)
imports numpy and the whole engine, most of a help's time (issue 43 item 5).
"""
from __future__ import annotations

DEFAULT_COUNT = 12
MAX_COUNT = 3600
