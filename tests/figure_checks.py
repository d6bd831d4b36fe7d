"""Pictures compared as pictures: an SVG export replayed with QSvgRenderer against the
PNG of the same view, and the margin around a replay checked for ink.

Why a tolerance at all: the PNG is painted by Qt's raster engine straight from the
scene, the SVG by QSvgGenerator and replayed by QSvgRenderer. Text is laid out
again from the SVG's font attributes (other hinting, sub-pixel positions), and
antialiased edges and dash phases land on other pixels. So single pixels differ
along every line and glyph. A spilled band, a shifted legend or a missing curve
differ over whole blocks: the images are compared in blocks of BLOCK × BLOCK px,
by their mean colour.
"""
from __future__ import annotations

import numpy as np
from PySide6.QtCore import QByteArray, QRectF
from PySide6.QtGui import QColor, QImage, QPainter
from PySide6.QtSvg import QSvgRenderer

BLOCK = 16               # px of the PNG; a line or a glyph is a few px of one block
BLOCK_DIFF = 24.0        # mean |Δ| of a block (0…255 per channel) that counts as different
MAX_DIFFERENT = 0.002    # share of blocks allowed to differ (measured: at most 0.01 % at 24)
MARGIN = 120             # px of blank canvas around a replay


def channels(image: QImage) -> np.ndarray:
    """H × W × 3 array (RGB, 0…255, uint8) of ``image``."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    raw = np.frombuffer(image.constBits(), np.uint8, image.sizeInBytes())
    rows = raw.reshape(image.height(), image.bytesPerLine())[:, :image.width() * 4]
    return rows.reshape(image.height(), image.width(), 4)[..., 2::-1].copy()


def pixels(image: QImage) -> np.ndarray:
    """H × W × 3 array (RGB, 0…255, float) of ``image``."""
    return channels(image).astype(float)


def replay(svg: bytes | str, width: int, height: int, margin: int = 0) -> QImage:
    """The SVG rendered into a ``width`` × ``height`` rect on a white canvas with
    ``margin`` px around it (as a viewer or the report replays it)."""
    renderer = QSvgRenderer(svg if isinstance(svg, str) else QByteArray(svg))
    image = QImage(width + 2 * margin, height + 2 * margin, QImage.Format.Format_ARGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    renderer.render(painter, QRectF(margin, margin, width, height))
    painter.end()
    return image


def block_means(a: np.ndarray) -> np.ndarray:
    """Mean colour of each BLOCK × BLOCK block of ``a`` (H × W × 3 uint8, whole blocks only).
    Summed down each block's rows first, then across: the same means as ``mean`` over both
    axes of the blocks at once (integer sums, exact in any order; a power of two divides
    them), five times faster on a 1600 × 1244 px image."""
    h, w = (a.shape[0] // BLOCK) * BLOCK, (a.shape[1] // BLOCK) * BLOCK
    columns = a[:h, :w].reshape(h // BLOCK, BLOCK, w, 3).sum(axis=1, dtype=np.int64)
    return columns.reshape(h // BLOCK, w // BLOCK, BLOCK, 3).sum(axis=2) / BLOCK ** 2


def differing_share(png: QImage, svg: bytes | str) -> float:
    """Share of BLOCK-px blocks whose mean colour differs by more than BLOCK_DIFF
    between the PNG and the SVG replayed at the PNG's size."""
    a = block_means(channels(png))
    b = block_means(channels(replay(svg, png.width(), png.height())))
    return float((np.abs(a - b).max(axis=2) > BLOCK_DIFF).mean())


def margin_ink(svg: bytes | str, width: int, height: int, edge: int = 0) -> int:
    """Pixels that are not white in the MARGIN around the SVG replayed at width × height,
    farther than ``edge`` px from the frame (the three channels compared one by one: an
    ``any`` over the short last axis took three times as long)."""
    a = channels(replay(svg, width, height, MARGIN))
    near = np.zeros(a.shape[:2], bool)
    near[MARGIN - edge:MARGIN + height + edge, MARGIN - edge:MARGIN + width + edge] = True
    ink = (a[..., 0] < 250) | (a[..., 1] < 250) | (a[..., 2] < 250)
    return int((ink & ~near).sum())
