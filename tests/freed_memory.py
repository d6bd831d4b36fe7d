"""Freed memory written over on purpose, as other allocations under load write it: a test
forces what timing left to chance. Under load two runs of `shaper report` placed the
scheme's labels differently (issue 40): a read of memory already freed gave what the
allocator had put there since, which depends on what else ran in between."""
from __future__ import annotations

import ctypes
from collections.abc import Callable
from typing import TypeVar

LIBC = ctypes.CDLL(None)
LIBC.malloc.restype = ctypes.c_void_p
LIBC.malloc.argtypes = [ctypes.c_size_t]
LIBC.free.argtypes = [ctypes.c_void_p]
SIZES = range(16, 4096, 16)    # bytes: a QPolygonF of up to some 250 points, with its header
EACH = 4                       # blocks taken of each size
FILL = 0x41                    # 0x4141… read as a float64 is 2.26e6: no drawing's mm

T = TypeVar("T")


def scribbled(call: Callable[..., T]) -> Callable[..., T]:
    """``call`` wrapped: before it runs, the small blocks the allocator hands out next (EACH
    of each of SIZES, which a block just freed is among) are taken and filled with FILL;
    they are given back after it."""
    def wrapped(*args, **kwargs) -> T:
        blocks = []
        try:
            for size in SIZES:
                for _ in range(EACH):
                    block = LIBC.malloc(size)
                    if block:
                        ctypes.memset(block, FILL, size)
                        blocks.append(block)
            return call(*args, **kwargs)
        finally:
            for block in blocks:
                LIBC.free(block)
    return wrapped
