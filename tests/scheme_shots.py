"""The scheme as the report draws it at its limit positions, and an exported picture as
pixels: what the report's and the scheme's label tests read their labels' ink from."""
from __future__ import annotations

from typing import Iterator

import numpy as np
from PySide6.QtCore import QByteArray, QCoreApplication, QRectF
from PySide6.QtGui import QColor, QImage, QPainter
from PySide6.QtSvg import QSvgRenderer

import shaperapp.report.figures as figures
from core.linkage.metrics import analyze
from core.linkage.spec import Spec
from shaperapp.scheme.view import SchemeWidget


def darkest(svg: bytes | str, scale: float) -> np.ndarray:
    """The SVG (bytes, or a file's path) painted on white paper at ``scale`` px per exported
    px: its darkest channel per pixel."""
    renderer = QSvgRenderer(svg if isinstance(svg, str) else QByteArray(svg))
    box = renderer.viewBoxF()
    image = QImage(int(box.width() * scale), int(box.height() * scale), QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    renderer.render(painter, QRectF(0, 0, image.width(), image.height()))
    painter.end()
    bits = np.frombuffer(image.constBits(), dtype=np.uint8).reshape(image.height(), image.bytesPerLine() // 4, 4)
    blue, green, red = (bits[:, :image.width(), channel] for channel in range(3))
    # the same as .min(axis=2) over the three channels, a tenth of its time: numpy reduces
    # a short strided last axis slowly (60 % of test_label_gaps.py's time went there)
    return np.minimum(np.minimum(blue, green), red)


def limit_frames(spec: Spec, rpms=(60.0,)) -> Iterator[tuple[SchemeWidget, int]]:
    """The report's scheme at each limit position, as ``limit_schemes`` shows it: yields
    (scheme, frame index)."""
    rpms = list(rpms)
    views = figures.ReportViews(spec, rpms, None, analyze(spec.design(), rpms))
    try:
        scheme = views._show(SchemeWidget(views.model), *figures.SCHEME_PX)
        for index in (0, views._end_index):
            views.model.set_angle_index(index)
            scheme.fit()
            QCoreApplication.processEvents()
            yield scheme, index
    finally:
        views.close()
