"""The views the window builds when first shown or while idle: each page's factory, which
imports its view's module only then (issue 24: start-up).

Split from main_window.py, which only assembles: a factory takes the models and the
callbacks its view's signals go to, never the window.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from PySide6.QtCore import QObject, QSettings, QTimer
from PySide6.QtWidgets import QWidget

from shaperapp.design.model import DesignModel
from shaperapp.parts.lazy import LazyPart

if TYPE_CHECKING:
    from shaperapp.cam.model import CamModel
    from shaperapp.gear.model import GearModel

TABS = ("forces", "positions", "explore", "compare")     # the central tabs built on demand, in order


def tab_view(name: str, model: DesignModel) -> QWidget:
    """The central tab ``name`` of TABS."""
    if name == "forces":
        from shaperapp.plots.forces import ForcePlots
        return ForcePlots(model)
    if name == "positions":
        from shaperapp.positions.view import PositionsView
        return PositionsView(model)
    if name == "explore":
        from shaperapp.explore.view import ExploreView
        return ExploreView(model)
    from shaperapp.compare.view import CompareView
    return CompareView(model)


def polygon_view(model: DesignModel, enlarge: Callable[[], None]) -> QWidget:
    """The vector diagrams' pane; its enlarge button calls ``enlarge``."""
    from shaperapp.vectors.view import PolygonView
    view = PolygonView(model)
    view.enlargeRequested.connect(enlarge)
    return view


def library_pane(model: DesignModel, settings: QSettings, compare: Callable[[list], None]) -> QWidget:
    """The Library pane; the designs it asks to compare go to ``compare``."""
    from shaperapp.library.pane import LibraryPane
    pane = LibraryPane(model, settings=settings)
    pane.compareRequested.connect(compare)
    return pane


def cam_part(model: DesignModel, parent: QObject) -> LazyPart[CamModel]:
    """The cam's model, made (and its module imported) when first used; Save writes its cam
    from the start."""
    def make() -> CamModel:
        from shaperapp.cam.model import CamModel
        return CamModel(model, parent)
    return LazyPart(model, "cam", make)


def gear_part(model: DesignModel, parent: QObject) -> LazyPart[GearModel]:
    """The gear pair's model, made when first used; Save writes its pair and Open checks a
    file's pair (``check_gear``) from the start."""
    def make() -> GearModel:
        from shaperapp.gear.model import GearModel
        return GearModel(model, parent)
    return LazyPart(model, "gear", make, check_gear)


def check_gear(data: Any) -> Any:
    """``shaperapp.gear.model.check_part``, its module imported when a file holds a pair."""
    from shaperapp.gear.model import check_part
    return check_part(data)


def cam_tab(model: DesignModel, cam_model: CamModel) -> QWidget:
    """The Cam tab, showing ``cam_model``."""
    from core.cam.synthesis import import_solvers
    from shaperapp.cam.tab import CamTab
    tab = CamTab(model, cam_model=cam_model)
    QTimer.singleShot(0, tab, import_solvers)   # built while idle: scipy too, before the visit
    return tab


def gear_tab(model: DesignModel, gear_model: GearModel) -> QWidget:
    """The Gear tab, showing ``gear_model``."""
    from shaperapp.gear.tab import GearTab
    return GearTab(model, gear_model=gear_model)
