"""The design space: many designs at once, and the figures they are ranked by.

``figures`` a design's key figures; ``sweep`` grids of designs; ``optimize`` the best
design within bounds; ``compare`` 2 to 6 designs side by side.
"""
