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


def pixels(image: QImage) -> np.ndarray:
    """H × W × 3 array (RGB, 0…255, float) of ``image``."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    raw = np.frombuffer(image.constBits(), np.uint8, image.sizeInBytes())
    rows = raw.reshape(image.height(), image.bytesPerLine())[:, :image.width() * 4]
    return rows.reshape(image.height(), image.width(), 4)[..., 2::-1].astype(float)


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
    h, w = (a.shape[0] // BLOCK) * BLOCK, (a.shape[1] // BLOCK) * BLOCK
    return a[:h, :w].reshape(h // BLOCK, BLOCK, w // BLOCK, BLOCK, 3).mean(axis=(1, 3))


def differing_share(png: QImage, svg: bytes | str) -> float:
    """Share of BLOCK-px blocks whose mean colour differs by more than BLOCK_DIFF
    between the PNG and the SVG replayed at the PNG's size."""
    a = block_means(pixels(png))
    b = block_means(pixels(replay(svg, png.width(), png.height())))
    return float((np.abs(a - b).max(axis=2) > BLOCK_DIFF).mean())


def margin_ink(svg: bytes | str, width: int, height: int) -> int:
    """Pixels that are not white in the MARGIN around the SVG replayed at width × height."""
    a = pixels(replay(svg, width, height, MARGIN))
    inside = np.zeros(a.shape[:2], bool)
    inside[MARGIN:MARGIN + height, MARGIN:MARGIN + width] = True
    return int(((a < 250).any(axis=2) & ~inside).sum())
