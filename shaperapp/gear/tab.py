"""The Gear tab (issue 35, item 4): the pair's inputs, the pair to scale turning with the
crank, the results with the checks, and the exports (the results as CSV, the meshing sheet
as PDF, SVG or DXF by the drawing sheets' own code)."""
from __future__ import annotations

import datetime
import os

from PySide6.QtCore import QLocale, QSettings, Qt
from PySide6.QtWidgets import QCheckBox, QScrollArea, QWidget

from core.files.atomic import atomic_write
from core.gear.table import gear_summary, summary_csv
from shaperapp.design.model import DesignModel
from shaperapp.parts.tab import PartTab
from shaperapp.widgets.cad_font import dxf_filters, remembered_filter, write_as_filtered

from .form import GearForm
from .model import GearModel
from .pair_view import GearPairView
from .results import GearResults

SHEET_SUFFIXES = (".pdf", ".svg", ".dxf")


class TablesArea(QScrollArea):
    """The results' scroll area, never narrower than the per-gear table with both gears'
    columns whole (``ResultTable.whole_width``): a plain area cut their right edge at
    1280 × 720, and a pinion of 13 teeth read "1"; an area one column wide hid "Gear 2"
    behind the table's own scroll bar, which sat below the area's fold."""

    def minimumSizeHint(self):  # noqa: N802 - Qt's name
        hint = super().minimumSizeHint()
        results = self.widget()
        if results is not None:
            need = max(results.minimumSizeHint().width(), results.gears.whole_width())
            hint.setWidth(max(hint.width(), need + self.verticalScrollBar().sizeHint().width()
                              + 2 * self.frameWidth()))
        return hint


class GearTab(PartTab):
    """One widget taking the design model. The window keeps the gear model (which Save
    writes) from the start and builds this tab only when it is first shown."""

    MODEL, FORM, VIEW = GearModel, GearForm, GearPairView
    EXPORTS = ("csv", "sheet")

    def __init__(self, model: DesignModel, parent: QWidget | None = None,
                 gear_model: GearModel | None = None) -> None:
        super().__init__(model, parent, gear_model)
        self._dxf_last = False          # the sheet's last export was a DXF: its filter first
        self.gear_model = self.part_model
        self.results = GearResults(self.gear_model)
        self.close_up = QCheckBox(self)
        self.close_up.toggled.connect(self.view.set_close_up)
        tables = TablesArea()
        tables.setWidget(self.results)
        tables.setWidgetResizable(True)
        tables.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.gear_model.pairChanged.connect(tables.updateGeometry)   # its least width follows
        self._side = self._assemble((self.form, self.close_up), (self.results.checks,), tables)
        self.retranslate()

    def retranslate(self) -> None:
        self.form.retranslate()
        self.results.retranslate()
        self.close_up.setText(self.tr("Close-up of the line of action"))
        self.buttons["csv"].setText(self.tr("CSV…"))
        self.buttons["sheet"].setText(self.tr("Meshing sheet…"))
        self.buttons["sheet"].setToolTip(self.tr("The meshing drawing (sheet 4/4) as PDF, SVG or DXF"))
        self.view.update()
        self._fit_side()

    def _fit_side(self) -> None:
        """The inputs' column as wide as the form in the current language: the checks'
        lines under it wrap (their one-line width made the window wider than 1280 px)."""
        for layout in (self.form.layout(), *self.form.layout().children()):
            layout.invalidate()             # the new labels' widths, not the cached ones
        margins = self._side.widget().layout().contentsMargins()
        self._side.setFixedWidth(self.form.sizeHint().width() + margins.left() + margins.right() + 16)

    # ---- exports -------------------------------------------------------------
    def export_csv(self, path: str) -> None:
        """The results as ``shaper gear --csv`` writes them, atomically."""
        atomic_write(path, summary_csv(gear_summary(self.gear_model.pair)))

    def export_sheet(self, path: str, paper: str | None = None, cad_font: str = "gb") -> None:
        """The meshing sheet of the pair on screen (PDF, SVG or DXF by the suffix), built
        and written by the drawing sheets' code (``shaper drawing --content gear``), in the
        UI's language; a DXF's texts in ``cad_font`` (``--cad-font``)."""
        from shaperapp.drawing.content import ALONE, DEFAULT_PAPER, SheetChoice, build_sheet
        from shaperapp.drawing.render import write_sheet
        suffix = os.path.splitext(path)[1].lower()
        if suffix not in SHEET_SUFFIXES:
            raise ValueError(self.tr("%1 is not a PDF, SVG or DXF file name").replace("%1", os.path.basename(path)))
        design = self.gear_model.design_model
        # the pair on its own, not the course design's fourth sheet: a set of one ("4/4" claimed
        # three sheets that were not printed)
        choice = SheetChoice("gear", paper or DEFAULT_PAPER["gear"], design_name=design.source_name,
                             date=datetime.date.today().isoformat(), gear=self.gear_model.pair,
                             sheet_number=ALONE)
        sheet = build_sheet(design.valid_spec, design.rpms, None, choice)
        language = "zh_CN" if QLocale().language() == QLocale.Language.Chinese else "en"
        write_sheet(sheet, path, language, design.source_name, cad_font)

    def export_choice(self, kind: str) -> tuple[str, str]:
        if kind == "csv":
            return self.tr("CSV table (*.csv)"), "gear.csv"
        return ";;".join((self.tr("PDF document (*.pdf)"), self.tr("SVG image (*.svg)"),
                          *dxf_filters())), "gear.pdf"

    def export_selected(self, kind: str) -> str:
        """The sheet's DXF filter of the last DXF's CAD texts, as File › Export scheme as DXF…
        offers it, when the sheet was last written as DXF; else Qt's first (PDF)."""
        return remembered_filter(QSettings(), dxf_filters()) if kind == "sheet" and self._dxf_last else ""

    def export_chosen(self, kind: str, path: str, chosen: str) -> None:
        if kind != "sheet":
            return super().export_chosen(kind, path, chosen)
        dxf = os.path.splitext(path)[1].lower() == ".dxf"
        if dxf:
            write_as_filtered(chosen, lambda cad_font: self.export_sheet(path, cad_font=cad_font))
        else:
            self.export_sheet(path)
        self._dxf_last = dxf

    def export_title(self) -> str:
        return self.tr("Export the gear pair")
