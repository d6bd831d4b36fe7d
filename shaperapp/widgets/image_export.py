"""Images of a graphics scene: PNG (or another raster type Qt writes) and SVG, one code path.

The scheme, both plot stacks, the heat map and the comparison export through here
(:func:`export_painting` takes any paint callback), so they share the checks:
a target whose type is unknown raises ValueError, a folder that is missing or
not writable raises OSError, both with a message naming the path and what is
wrong; nothing is written then. The image is rendered in memory first and
written in one go, so a failed render never leaves a partial file.

pyqtgraph 0.14's SVGExporter fails on the closed paths ("… Z") Qt 6.11+ writes
(pyqtgraph issue #3495), hence Qt's own QSvgGenerator. A raster is scaled
through the device pixel ratio, not a painter transform, so items drawn
ignoring transformations (legends, labels) grow with everything else.
"""
from __future__ import annotations

import errno
import math
import os
from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QBuffer, QByteArray, QCoreApplication, QIODevice, QRectF, QSizeF, Qt
from PySide6.QtGui import QColor, QImage, QImageWriter, QPainter, QPicture
from PySide6.QtSvg import QSvgGenerator
from PySide6.QtWidgets import QGraphicsScene

from core.files.atomic import atomic_write

from .file_messages import describe_os_error

EXPORT_WIDTH = 1600      # minimum width of an exported raster image, px


def raster_types() -> set[str]:
    """Suffixes (lower case, no dot) Qt can write as raster images here."""
    return {bytes(f).decode().lower() for f in QImageWriter.supportedImageFormats()}


def image_type(path: str | os.PathLike) -> str:
    """The image type ``path`` asks for ("svg", "png" …), after checking the target.

    Raises ValueError for a missing or unknown suffix and OSError (with ``filename``
    set) for a folder that does not exist or cannot be written, or a target that is
    a folder."""
    target = Path(path)
    suffix = target.suffix.lower().lstrip(".")
    translate = QCoreApplication.translate
    if suffix != "svg" and suffix not in raster_types():
        if suffix:
            why = translate("ImageExport",
                            "“.{0}” is not an image type this program writes; use .png or .svg")
        else:
            why = translate("ImageExport", "the name has no image type; end it in .png or .svg")
        raise ValueError(translate("ImageExport", "Cannot export to {0}: {1}").format(
            target, why.format(suffix)))
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise OSError(errno.ENOENT, translate("ImageExport", "the folder {0} does not exist")
                      .format(folder), str(target))
    if not os.access(folder, os.W_OK | os.X_OK) and not os.access(target, os.W_OK):
        raise OSError(errno.EACCES, translate("ImageExport", "the folder {0} is not writable")
                      .format(folder), str(target))
    if target.is_dir():
        raise OSError(errno.EISDIR, translate("ImageExport", "{0} is a folder").format(target),
                      str(target))
    return suffix


def render_scene(scene: QGraphicsScene, source: QRectF, painter: QPainter, target: QRectF,
                 background: QColor, prepare: Callable[[bool], None] | None = None,
                 cursor: bool = False) -> None:
    """Paint the ``source`` part of ``scene`` into ``target``, on ``background``.

    ``prepare(True)`` runs before and ``prepare(False)`` after, whatever happens:
    views use it to drop pixmap caches that would blur in a scaled image. Every item
    with ``setExportMode`` (pyqtgraph's, and the plots' own in ``plot_curves``) is
    switched to export mode meanwhile: pyqtgraph's paint vectors, the plots' cut
    themselves to their view (an SVG cannot clip) and leave out the animation
    cursor unless ``cursor``. Nothing is painted outside ``target``."""
    items = [it for it in scene.items() if hasattr(it, "setExportMode")]
    if prepare is not None:
        prepare(True)
    try:
        for it in items:
            it.setExportMode(True, {"antialias": True, "background": background,
                                    "painter": painter, "cursor": cursor})
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.setRenderHint(QPainter.RenderHint.TextAntialiasing)
        painter.fillRect(target, background)
        scene.render(painter, target, source)
    finally:
        for it in items:
            it.setExportMode(False)
        if prepare is not None:
            prepare(False)


def export_scene(scene: QGraphicsScene, source: QRectF, path: str | os.PathLike, title: str,
                 background: QColor, prepare: Callable[[bool], None] | None = None) -> None:
    """Write the ``source`` part of ``scene`` to ``path``: SVG for ``.svg``, else a raster
    image at least EXPORT_WIDTH px wide (see :func:`image_type` for the errors)."""
    export_painting(path, source.size(), _scene_paint(scene, source, background, prepare),
                    title, background)


CAPTION_PX = 28
"""Height of the caption line over a captioned export, logical px."""


def export_scene_captioned(scene: QGraphicsScene, source: QRectF, path: str | os.PathLike,
                           caption: str, title: str, background: QColor) -> None:
    """:func:`export_scene` with ``caption`` on one line over the picture (cut with "…" to
    its width): what the exported view alone does not say, such as at which speeds the
    Explore tab's map was computed (its colour bar has the figure's short title only)."""
    def paint(painter: QPainter, page: QRectF) -> None:
        line = QRectF(8.0, 0.0, page.width() - 16.0, CAPTION_PX)
        painter.setPen(QColor("black"))
        painter.drawText(line, Qt.AlignmentFlag.AlignVCenter, painter.fontMetrics().elidedText(
            caption, Qt.TextElideMode.ElideRight, int(line.width())))
        render_scene(scene, source, painter, QRectF(0.0, CAPTION_PX, source.width(), source.height()),
                     background)
    export_painting(path, QSizeF(source.width(), source.height() + CAPTION_PX), paint, title, background)


def scene_svg(scene: QGraphicsScene, source: QRectF, title: str, background: QColor,
              prepare: Callable[[bool], None] | None = None) -> bytes:
    """The SVG :func:`export_scene` writes to a ``.svg`` path, in memory: the report
    replays its figures without a temporary folder (issue 42: a killed run left one
    behind each time, and a write failure there named the temporary file)."""
    return painting_bytes("svg", source.size(), _scene_paint(scene, source, background, prepare),
                          title, background)


def _scene_paint(scene: QGraphicsScene, source: QRectF, background: QColor,
                 prepare: Callable[[bool], None] | None) -> "Paint":
    return lambda painter, page: render_scene(scene, source, painter, page, background, prepare)


Paint = Callable[[QPainter, QRectF], None]


def export_painting(path: str | os.PathLike, size: QSizeF, paint: Paint, title: str,
                    background: QColor) -> None:
    """Write what ``paint(painter, page)`` draws on a page of ``size`` (logical px) to
    ``path``: SVG for ``.svg``, else a raster image at least EXPORT_WIDTH px wide.

    The target is checked first (:func:`image_type`: ValueError, OSError), the picture
    rendered in memory, then written atomically (OSError naming the path)."""
    kind = image_type(path)
    data = painting_bytes(kind, size, paint, title, background)
    try:
        atomic_write(path, data)      # the old picture or the whole new one
    except OSError as exc:
        raise OSError(exc.errno, QCoreApplication.translate(
            "ImageExport", "could not write {0}: {1}").format(path, describe_os_error(exc)), str(path)) from exc


def painting_bytes(kind: str, size: QSizeF, paint: Paint, title: str,
                   background: QColor) -> bytes:
    """The bytes of an image of type ``kind`` ("svg" or a raster type Qt writes) of what
    ``paint(painter, page)`` draws on a ``background``-filled page of ``size``.

    A raster is at least EXPORT_WIDTH px wide, scaled through the device pixel ratio;
    OSError if Qt cannot encode it."""
    page = QRectF(0.0, 0.0, size.width(), size.height())
    data = QByteArray()
    buffer = QBuffer(data)
    buffer.open(QIODevice.OpenModeFlag.WriteOnly)
    if kind == "svg":
        device = QSvgGenerator()
        device.setOutputDevice(buffer)
        device.setSize(page.size().toSize())
        device.setViewBox(page)
        device.setTitle(title)
        device.setResolution(QPicture().logicalDpiX())   # axes replay DPI-bound QPictures
    else:
        scale = max(1.0, EXPORT_WIDTH / max(page.width(), 1.0))
        device = QImage(math.ceil(page.width() * scale), math.ceil(page.height() * scale),
                        QImage.Format.Format_ARGB32)
        device.setDevicePixelRatio(scale)
        device.fill(background)
    painter = QPainter(device)
    try:
        painter.fillRect(page, background)
        paint(painter, page)
    finally:
        painter.end()
    if kind != "svg" and not device.save(buffer, kind.upper()):
        raise OSError(errno.EIO, QCoreApplication.translate(
            "ImageExport", "Qt could not encode the image as {0}").format(kind.upper()))
    buffer.close()
    return bytes(data)
