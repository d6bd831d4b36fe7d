"""The report's views kept from one report to the next in a ``shaper class`` worker.

A worker writes a report per student; building the three plot views (pyqtgraph's
``PlotItem``s) anew for each was some 9 % of a student's time, and the scheme's widget
and its first show a fifth of §3's 9 % (docs/performance.md). After
:func:`keep_plot_views` each report loads its design into one kept model, and the views
on it redraw themselves for it.
"""
from __future__ import annotations

from typing import Iterable, Sequence

from PySide6.QtCore import QCoreApplication, QEvent
from PySide6.QtWidgets import QWidget

from core.forces.masses import MassProperties
from core.linkage.spec import Spec
from shaperapp.cam.model import CamModel
from shaperapp.design.model import DesignModel


class KeptViews:
    """One process's report views (scheme, s/v/a, forces, cam) on a model of their own."""

    def __init__(self) -> None:
        self.model = DesignModel()
        self.views: dict[str, QWidget] = {}
        self.cam_model: CamModel | None = None
        self._shape: tuple = ()

    def load(self, spec: Spec, rpms: Sequence[float], step: float, masses: MassProperties | None) -> None:
        """The model loaded with the design; the views dropped where their items would
        change in number (speeds, loads, the variant's links and series): the items a kept
        view adds come after the others in its scene, so its SVG would list them out of the
        order a new view draws them in."""
        shape = (len(rpms), masses is None, spec.variant)
        if shape != self._shape:
            delete_widgets(self.views.values())
            self.views.clear()
            self._shape = shape
        scheme = self.views.get("scheme")
        if scheme is not None:      # hidden, it only marks its labels (placed once shown again)
            scheme.hide()
        self.model.load_state(spec, rpms, step, masses=masses)


_KEPT: list[KeptViews] = []


def kept() -> KeptViews | None:
    """This process's kept views, or None when each report makes its own."""
    return _KEPT[0] if _KEPT else None


def keep_plot_views() -> None:
    """From now on this process's reports draw their scheme, s/v/a, force and cam figures
    with the same widgets, each report loading its design into their model. A kept plot
    view is fitted as on its first show (whole cycle in x, every curve in y) and the
    scheme places its labels afresh for each design and view, so each exports what a new
    one would (tests/test_shaperapp/report/test_kept_plot_views.py)."""
    if not _KEPT:
        _KEPT.append(KeptViews())


def release_plot_views() -> None:
    """Delete the kept views (:func:`keep_plot_views`) and keep none from now on: Qt
    objects left for interpreter shutdown can outlive the application and crash it. (A
    forked worker ends without the interpreter's shutdown.)"""
    for views in _KEPT:
        delete_widgets(views.views.values())
    _KEPT.clear()


def delete_widgets(widgets: Iterable[QWidget]) -> None:
    """Close the widgets and delete them now: a command-line run has no event loop to do
    it later, and Qt objects left for interpreter shutdown can outlive the application
    and crash it."""
    for widget in widgets:
        widget.close()
        widget.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
