"""The inputs pane: the design form and the loads form as two tabs of one dock.

Each form scrolls vertically inside its tab (never clipped, never wider than its
fields). A tab whose inputs the model rejects carries a warning icon, so an
error in the tab behind is not missed.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent
from PySide6.QtGui import QIcon
from PySide6.QtWidgets import QScrollArea, QStyle, QTabWidget, QWidget

from shaperapp.widgets.lazy import LazyPage
from shaperapp.widgets.scroll import vertical_scroll

from .form import DesignForm
from .model import DesignModel

if TYPE_CHECKING:
    from .loads_form import LoadsForm


def scrolled(widget: QWidget) -> QScrollArea:
    """``widget`` in a frameless vertical scroll area exactly as wide as its fields need."""
    area = vertical_scroll(widget)
    area.setMinimumWidth(widget.minimumSizeHint().width() + area.verticalScrollBar().sizeHint().width() + 2)
    return area


def loads_area(model: DesignModel) -> QScrollArea:
    """The Loads form in its scroll area (its module imported then)."""
    from .loads_form import LoadsForm
    return scrolled(LoadsForm(model))


class InputsPane(QTabWidget):
    """Design (``form``) and Loads (``loads``) inputs. The Loads form, behind its tab, is
    built when first shown or asked for (``loads_page``; the window builds it while idle
    after its first paint): 3 ms of every start (issue 43 item 5). Its scroll area is
    narrower than the design form's in both languages, so building it later leaves the
    dock's width as it was."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self.form = DesignForm(model)
        self.loads_page = LazyPage(lambda: loads_area(model))
        self.addTab(scrolled(self.form), "")
        self.addTab(self.loads_page, "")
        self._warning = self.style().standardIcon(QStyle.StandardPixmap.SP_MessageBoxWarning)
        self._marked: tuple[bool, bool] | None = None      # the tabs' warnings as last set
        model.errorChanged.connect(self._mark_errors)
        model.forcesErrorChanged.connect(self._mark_errors)
        self._retranslate()
        self._mark_errors()

    @property
    def loads(self) -> LoadsForm:
        """The Loads form, built now if it was not yet."""
        return self.loads_page.view().widget()

    def show_loads(self) -> None:
        self.setCurrentIndex(1)

    def _mark_errors(self, *_) -> None:
        """The warning icons, set only when one comes or goes: every load edit announces
        its (unchanged) error state, and setting a tab's icon re-lays out the tab bar, the
        dock and the main window, and repaints the pane (a fifth of a Loads edit)."""
        marked = (self._model.error is not None, self._model.forces_error is not None)
        if marked == self._marked:
            return
        self._marked = marked
        for index, error in enumerate(marked):
            self.setTabIcon(index, self._warning if error else QIcon())

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self.setTabText(0, self.tr("Design"))
        self.setTabText(1, self.tr("Loads"))
        self.setTabToolTip(0, self.tr("Dimensions or L1, K, H; mechanism; crank speeds"))
        self.setTabToolTip(1, self.tr("Masses, cutting force and flywheel requirement (for the Forces tab "
                                      "and the forces and flywheel results)"))
