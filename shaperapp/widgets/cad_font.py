"""The "CAD texts" choice of the dialogs that write DXF: the GB style or outlines.

The GUI's side of ``--cad-font`` (``core.drawing.CAD_FONTS``): a DXF's texts either as text
in the GB style, editable in AutoCAD and ZWCAD, or as filled glyph outlines, which every
CAD program draws alike, LibreCAD 2.2 included (it draws the GB style's Chinese as dots
and leaves out its Greek letters). The drawing dialog and the course export offer the same
combo box, remembered under one settings key: a user whose CAD is LibreCAD wants outlines
in every DXF.
"""
from __future__ import annotations

from typing import Callable

from PySide6.QtCore import QCoreApplication, QSettings
from PySide6.QtWidgets import QComboBox, QWidget

CAD_FONT_SETTING = "export/cadFont"     # QSettings key: "gb" or "outline"


def outline_font_problem(cad_font: str) -> str:
    """'' or one line, in the UI's language, saying why ``cad_font`` cannot be drawn: for
    "outline", no font with Chinese characters (core's lookup, ``outline_text.outline_font``,
    refuses); "gb" needs none."""
    if cad_font != "outline":
        return ""
    from core.drawing.outline_text import OutlineFontMissing, outline_font   # ezdxf: on demand
    try:
        outline_font()
    except OutlineFontMissing:
        return missing_font_text()
    return ""


def dxf_filters() -> dict[str, str]:
    """The file dialog's two DXF filters (name → "gb" or "outline"), in the UI's language:
    the dialogs that write only a DXF or one by its suffix (File › Export scheme as DXF…,
    the Gear tab's meshing sheet) offer the CAD texts as two filters of one type rather
    than a combo box of their own."""
    return {QCoreApplication.translate(
                "CadFontChoice", "DXF drawing, texts in the GB style for AutoCAD and ZWCAD (*.dxf)"): "gb",
            QCoreApplication.translate(
                "CadFontChoice", "DXF drawing, texts as outlines for every CAD program, LibreCAD too (*.dxf)"):
                "outline"}


def stored_cad_font(settings: QSettings) -> str:
    """The CAD texts the last DXF was written with (``CAD_FONT_SETTING``), "gb" when none
    was (a damaged value is the caller's to check against its choices)."""
    return str(settings.value(CAD_FONT_SETTING, "gb") or "gb")


def remembered_filter(settings: QSettings, filters: dict[str, str]) -> str:
    """The filter of ``filters`` (:func:`dxf_filters`) that the last DXF was written with
    (``CAD_FONT_SETTING``), for the dialog to select first; '' when none matches."""
    remembered = stored_cad_font(settings)
    return next((name for name, kind in filters.items() if kind == remembered), "")


def filter_cad_font(chosen: str) -> str:
    """The CAD texts of the file dialog's filter ``chosen`` (one of :func:`dxf_filters`; "gb"
    for any other), checked before anything is built: ValueError with
    :func:`missing_font_text`, one line, for outlines without a font for them. For the
    parts' tabs, whose export dialog shows an exception's text in its message."""
    cad_font = dxf_filters().get(chosen, "gb")
    problem = outline_font_problem(cad_font)
    if problem:
        raise ValueError(problem)
    return cad_font


def write_as_filtered(chosen: str, write: Callable[[str], None]) -> None:
    """``write(cad_font)`` with the CAD texts of the file dialog's filter ``chosen``
    (:func:`filter_cad_font`, which refuses outlines without a font before anything is
    written), then remember them for the next DXF, as every DXF export does."""
    cad_font = filter_cad_font(chosen)
    write(cad_font)
    QSettings().setValue(CAD_FONT_SETTING, cad_font)


def missing_font_text() -> str:
    """Why outlines cannot be drawn, and what to do, in the UI's language."""
    return QCoreApplication.translate(
        "CadFontChoice", "No font with Chinese characters is installed for the outlines: "
        "install one (on Debian/Ubuntu: fonts-noto-cjk) or choose the GB style.")


class CadFontChoice(QComboBox):
    """GB style (the default, as ``--cad-font``'s) or outlines; the dialog disables it
    while no DXF will be written."""

    def __init__(self, settings: QSettings | None = None, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._settings = settings
        self.addItem(self.tr("GB style (AutoCAD, ZWCAD; editable)"), "gb")
        self.addItem(self.tr("Outlines (every CAD program, LibreCAD too)"), "outline")
        import html      # here: the window's first screen imports this module, never the dialogs
        # in <p>: rich text, which Qt wraps (a plain tooltip this long ran off the screen)
        self.setToolTip("<p>" + html.escape(self.tr(
            "How a DXF writes its texts. GB style: text in the GB fonts (gbenor.shx, gbcbig.shx), "
            "editable in AutoCAD and ZWCAD, which have them; LibreCAD draws its Chinese and Greek "
            "in its font wqy-unicode, which its Windows and macOS builds have and Debian's and "
            "Ubuntu's lack (there, Chinese as dots, no Greek letters). Outlines: each character "
            "as a filled outline, drawn "
            "alike by every CAD program, LibreCAD included, but no longer editable as text; they "
            "need a font with Chinese characters (fonts-noto-cjk).")) + "</p>")
        stored = stored_cad_font(settings) if settings is not None else "gb"
        self.setCurrentIndex(max(self.findData(stored), 0))       # a damaged value: the default

    def value(self) -> str:
        """"gb" or "outline", as ``write_sheet`` and ``Covering`` take it."""
        return str(self.currentData())

    def remember(self) -> None:
        """Keep the choice for the next dialog (when the file is written, as the cover fields)."""
        if self._settings is not None:
            self._settings.setValue(CAD_FONT_SETTING, self.value())

    def problem(self) -> str:
        """:func:`outline_font_problem` of the choice while it is enabled (a PDF or an SVG
        needs no outline font)."""
        return outline_font_problem(self.value()) if self.isEnabled() else ""
