"""The Cam tab: the data sheet's inputs, the synthesized figures, the cam to scale and the
plots, with CSV, image and DXF exports."""
from __future__ import annotations

from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QWidget

from core.files.atomic import atomic_write
from core.cam.table import cam_table
from core.files.io import table_csv
from core.linkage.kinematics import crank_angles
from shaperapp.design.model import DesignModel
from shaperapp.parts.tab import PartTab
from shaperapp.widgets.cad_font import dxf_filters, remembered_filter, write_as_filtered
from shaperapp.widgets.steady_label import SteadyLabel

from .form import CamForm
from .model import CamModel
from .plots import CamPlots
from .profile_view import CamProfileView
from .words import cam_words


class CamTab(PartTab):
    """One widget taking the design model. The cam's own model lives here, unless the
    window gives one: the window keeps the cam (which Save writes) from the start and
    builds this tab only when it is first shown."""

    MODEL, FORM, VIEW = CamModel, CamForm, CamProfileView
    EXPORTS = ("csv", "image", "dxf")

    def __init__(self, model: DesignModel, parent: QWidget | None = None,
                 cam_model: CamModel | None = None) -> None:
        super().__init__(model, parent, cam_model)
        self.cam_model, self.profile = self.part_model, self.view
        self.plots = CamPlots(self.cam_model)
        figures = SteadyLabel(self)             # a new cam's figures relay nothing out
        self.figures = figures.label
        self.figures.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.figures.setWordWrap(True)
        scroll = self._assemble((self.form, figures), (), self.plots)
        scroll.setMinimumWidth(scroll.widget().sizeHint().width() + 16)
        scroll.setMaximumWidth(scroll.widget().sizeHint().width() + 16)
        self.cam_model.camChanged.connect(self.show_figures)
        self.cam_model.errorChanged.connect(self.show_figures)     # own_value may have changed
        self.retranslate()

    def showEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().showEvent(event)
        self.cam_model.set_active(True)
        self.show_figures()

    def catch_up(self) -> None:
        """While hidden (``LazyPage.catch_up``: the window calls it while idle), what the
        first show would do: the cam computed for the linkage on screen, its plots drawn,
        its outline built; the visit then only paints."""
        self.cam_model.cam                  # noqa: B018 - computed if the linkage changed
        self.plots.catch_up()
        self.profile.shapes()

    def hideEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().hideEvent(event)
        self.cam_model.set_active(False)

    def retranslate(self) -> None:
        self.form.retranslate()
        self.plots.retranslate()
        self.buttons["csv"].setText(self.tr("CSV…"))
        self.buttons["image"].setText(self.tr("Image…"))
        self.buttons["dxf"].setText(self.tr("DXF…"))
        self.show_figures()

    def figure_rows(self) -> list[tuple[str, str]]:
        """(label, value) of the cam's figures, in the current language."""
        cam = self.cam_model.cam
        f = cam.follower
        rows = [(self.tr("Base radius r0"), f"{cam.base_radius_mm:.3f} mm"),
                (self.tr("Centre distance a"), f"{f.distance_mm:.3f} mm"),
                (self.tr("Arm angle ψ0"), f"{f.initial_deg:.3f}°"),
                (self.tr("Roller side"), self.tr("above") if f.side > 0 else self.tr("below")),
                (self.tr("Max α rise"), f"{cam.max_pressure_rise_deg:.3f}°"),
                (self.tr("Max α return"), f"{cam.max_pressure_return_deg:.3f}°"),
                (self.tr("ρmin (convex)"), f"{cam.min_curvature_radius_mm:.3f} mm"),
                (self.tr("Roller r"), f"{cam.roller_mm:.3f} mm"),
                (self.tr("Largest roller"), f"{cam.largest_roller_mm:.3f} mm"),
                (self.tr("Profile radius r0 − r … R1 − r"),
                 f"{cam.profile_min_radius_mm:.3f} … {cam.profile_max_radius_mm:.3f} mm")]
        if cam.base_raised_from_mm is not None:
            rows.append((self.tr("Base radius raised"),
                         self.tr("from %1 mm, to take the roller and clear the hub and the pivot boss").replace(
                             "%1", f"{cam.base_raised_from_mm:.3f}")))
        if cam.timing is not None:
            rows.append((self.tr("Rise at crank φ"), f"{cam.timing.phase_deg:.3f}°"))
        if not cam.within_allowance:
            rows.append((self.tr("Pressure angle"), self.tr("exceeds the allowance")))
        return rows

    def show_figures(self) -> None:
        if not self.isVisible():
            return              # shown when the tab is (showEvent)
        if not self.cam_model.own_value:    # an earlier design's figures: none (the form says why)
            self.figures.setText("")
            return
        cells = "".join(f"<tr><td>{k}</td><td align='right'>&nbsp;{v}</td></tr>" for k, v in self.figure_rows())
        self.figures.setText(f"<table>{cells}</table>")

    # ---- exports -------------------------------------------------------------
    def export_csv(self, path: str) -> None:
        """One row per degree of cam angle at the design's first crank speed."""
        rpm = self.cam_model.design_model.rpms[0]
        atomic_write(path, table_csv(*cam_table(self.cam_model.cam, crank_angles(1.0), rpm)))

    def export_dxf(self, path: str, cad_font: str = "gb") -> None:
        """The cam as ``shaper cam --dxf --cad-font --lang`` writes it, its notes in the app's
        language (the cam sheet's words)."""
        from core.drawing.cam_dxf import write_cam_dxf     # ezdxf: only when a drawing is asked for
        write_cam_dxf(self.cam_model.cam, path, cad_font, cam_words())

    def export_image(self, path: str) -> None:
        self.profile.export_image(path)

    def export_choice(self, kind: str) -> tuple[str, str]:
        filters = {"csv": self.tr("CSV table (*.csv)"), "dxf": ";;".join(dxf_filters()),
                   "image": self.tr("PNG image (*.png);;SVG drawing (*.svg)")}[kind]
        return filters, "cam." + ("png" if kind == "image" else kind)

    def export_selected(self, kind: str) -> str:
        """The last DXF's CAD texts first, as File › Export scheme as DXF… offers them."""
        return remembered_filter(QSettings(), dxf_filters()) if kind == "dxf" else ""

    def export_chosen(self, kind: str, path: str, chosen: str) -> None:
        if kind != "dxf":
            return super().export_chosen(kind, path, chosen)
        write_as_filtered(chosen, lambda cad_font: self.export_dxf(path, cad_font))

    def export_title(self) -> str:
        return self.tr("Export the cam")
