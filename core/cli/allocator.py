"""Keep freed memory in the process for the length of a large command (glibc only).

Why: ``shaper sweep`` works through its designs in chunks whose arrays are a
megabyte or so each. glibc's allocator maps such blocks afresh or trims the top
of its heap once a few megabytes are free, so each chunk faults its pages in
again: about 90 000 page faults for 10⁵ designs, 0.2–0.6 s of kernel time on
the project's machine (``/usr/bin/time``: system time 0.45–0.62 s against
0.05–0.09 s with these settings, issue 24). Raising the mmap and trim
thresholds makes the allocator reuse what it already holds. The peak resident
size stays bounded: only memory once touched stays mapped, a few MB more than
before (95 → 100 MB for that sweep; ``benchmarks/test_bench_sweep_memory.py``).

It only tunes the running process (no effect on results), and does nothing where
the C library is not glibc.
"""
from __future__ import annotations

import ctypes

# mallopt's parameters (malloc.h): M_TRIM_THRESHOLD, M_MMAP_THRESHOLD.
_TRIM, _MMAP = -1, -3
# 32 MiB is the largest mmap threshold glibc accepts on 64-bit (HEAP_MAX_SIZE / 2).
MMAP_BYTES = 32 * 1024 * 1024
TRIM_BYTES = 256 * 1024 * 1024


def keep_freed_memory() -> bool:
    """Raise glibc's mmap and trim thresholds; True when the allocator took both."""
    try:
        libc = ctypes.CDLL(None)
        libc.gnu_get_libc_version       # glibc's own symbol: musl's mallopt does nothing
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes, mallopt.restype = (ctypes.c_int, ctypes.c_int), ctypes.c_int
    return bool(mallopt(_MMAP, MMAP_BYTES)) & bool(mallopt(_TRIM, TRIM_BYTES))


def return_freed_memory() -> bool:
    """Give the memory glibc holds free back to the system (``malloc_trim``), after a large
    piece of work in a long-lived process: the GUI kept about 90 MB it no longer used after
    exporting a course design (issue 42). True when glibc did; False elsewhere."""
    try:
        libc = ctypes.CDLL(None)
        libc.gnu_get_libc_version
        trim = libc.malloc_trim
    except (OSError, AttributeError):
        return False
    trim.argtypes, trim.restype = (ctypes.c_size_t,), ctypes.c_int
    return bool(trim(0))
