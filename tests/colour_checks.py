"""Colour differences as a reader sees them: sRGB → CIELAB (D65) and CIEDE2000.

Written out from the standard formulas (CIE 15:2004 for CIELAB; Sharma, Wu and Dalal,
"The CIEDE2000 color-difference formula: implementation notes", Color Res. Appl. 30,
2005, whose test pairs ``test_colour_checks`` reproduces), so that no colour library is
needed to check the speed colours.
"""
from __future__ import annotations

import numpy as np


def lab(hex_colour: str) -> np.ndarray:
    """``#rrggbb`` (sRGB) → CIELAB L*, a*, b* (D65 white)."""
    rgb = np.array([int(hex_colour[i:i + 2], 16) / 255.0 for i in (1, 3, 5)])
    lin = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
    m = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]])
    xyz = m @ lin / np.array([0.95047, 1.0, 1.08883])
    f = np.where(xyz > 0.008856, np.cbrt(xyz), 7.787 * xyz + 16.0 / 116.0)
    return np.array([116.0 * f[1] - 16.0, 500.0 * (f[0] - f[1]), 200.0 * (f[1] - f[2])])


def ciede2000(lab1: np.ndarray, lab2: np.ndarray) -> float:
    """ΔE00 between two CIELAB colours (kL = kC = kH = 1)."""
    (l1, a1, b1), (l2, a2, b2) = lab1, lab2
    c_mean = (np.hypot(a1, b1) + np.hypot(a2, b2)) / 2.0
    g = 0.5 * (1.0 - np.sqrt(c_mean ** 7 / (c_mean ** 7 + 25.0 ** 7)))
    a1p, a2p = (1.0 + g) * a1, (1.0 + g) * a2
    c1p, c2p = np.hypot(a1p, b1), np.hypot(a2p, b2)
    h1p = np.degrees(np.arctan2(b1, a1p)) % 360.0 if c1p else 0.0
    h2p = np.degrees(np.arctan2(b2, a2p)) % 360.0 if c2p else 0.0
    dl, dc = l2 - l1, c2p - c1p
    dh = 0.0
    if c1p * c2p:
        dh = h2p - h1p
        dh = dh - 360.0 if dh > 180.0 else dh + 360.0 if dh < -180.0 else dh
    dhh = 2.0 * np.sqrt(c1p * c2p) * np.sin(np.radians(dh / 2.0))
    lm, cm = (l1 + l2) / 2.0, (c1p + c2p) / 2.0
    if c1p * c2p == 0:
        hm = h1p + h2p
    elif abs(h1p - h2p) <= 180.0:
        hm = (h1p + h2p) / 2.0
    else:
        hm = (h1p + h2p + 360.0) / 2.0 if h1p + h2p < 360.0 else (h1p + h2p - 360.0) / 2.0
    t = (1.0 - 0.17 * np.cos(np.radians(hm - 30.0)) + 0.24 * np.cos(np.radians(2.0 * hm))
         + 0.32 * np.cos(np.radians(3.0 * hm + 6.0)) - 0.20 * np.cos(np.radians(4.0 * hm - 63.0)))
    d_theta = 30.0 * np.exp(-(((hm - 275.0) / 25.0) ** 2))
    rc = 2.0 * np.sqrt(cm ** 7 / (cm ** 7 + 25.0 ** 7))
    sl = 1.0 + 0.015 * (lm - 50.0) ** 2 / np.sqrt(20.0 + (lm - 50.0) ** 2)
    sc, sh = 1.0 + 0.045 * cm, 1.0 + 0.015 * cm * t
    rt = -np.sin(np.radians(2.0 * d_theta)) * rc
    return float(np.sqrt((dl / sl) ** 2 + (dc / sc) ** 2 + (dhh / sh) ** 2
                         + rt * (dc / sc) * (dhh / sh)))


def closest_pair(colours: list[str]) -> tuple[float, str, str]:
    """The smallest ΔE00 among ``colours`` and the pair that has it."""
    labs = [lab(c) for c in colours]
    return min((ciede2000(labs[i], labs[j]), colours[i], colours[j])
               for i in range(len(colours)) for j in range(i + 1, len(colours)))
