"""Small array helpers shared by core and the GUI, each giving what a numpy function
gives, where numpy's own is slow for the way it is used here.

``np.unique`` imports ``numpy.ma`` on its first call (7–9 ms here), which every ``shaper``
command and the window's first paint would pay for one call on a few dozen numbers.
``np.nonzero`` of a 2-D mask is an order of magnitude slower than of the same mask
flattened (numpy 2.4): see :func:`nonzero_pairs`.
"""
from __future__ import annotations

import numpy as np


def sorted_unique(values: np.ndarray) -> np.ndarray:
    """The values of a 1-D array sorted, each once, as ``np.unique(values)`` gives them
    for numbers without NaN."""
    ordered = np.sort(np.asarray(values).ravel())
    if ordered.size == 0:
        return ordered
    return ordered[np.concatenate(([True], ordered[1:] != ordered[:-1]))]


def nonzero_pairs(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The (row, column) indices of a 2-D mask's True entries, as ``np.nonzero(mask)``
    gives them (the same two integer arrays, in row-major order), from the flattened mask.

    Why: the label searches ask it of (boxes × strokes) masks of up to 1.6 million
    entries, some 3000 times a crowded sheet; there ``np.nonzero`` took 2.4 ms where this
    takes 0.19 ms (400 × 4000, 0.05 % True), and it was 40 % of the strokes' test
    (docs/performance.md). On a mask of a few dozen entries it costs a microsecond more."""
    mask = np.asarray(mask)
    return np.divmod(np.flatnonzero(mask), mask.shape[1])
