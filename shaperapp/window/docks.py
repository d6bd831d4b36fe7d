"""The window's panes as dock widgets, and their default arrangement.

Panes: inputs (design and loads forms), results (the result tables), the
mechanism (scheme), the vector diagrams and the design library. Users move,
tab, float, close and reopen them; View › Reset layout calls :meth:`Docks.arrange`
again. The arrangement depends on the window's size: on a laptop screen
(narrower than ``WIDE``) the vector diagrams share a tabbed slot with the
results, below the mechanism; on a large screen the results sit under the inputs
and the vector diagrams under the mechanism, all shown at once.
"""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QRect, QSize, Qt, QTimer
from PySide6.QtWidgets import QDockWidget, QMainWindow, QStackedWidget, QWidget

from shaperapp.widgets.lazy import LazyPage

from shaperapp.design.inputs_pane import scrolled

from .state import FRAME_ALLOWANCE, available

WIDE = 1600                 # px: from this window width on, every pane has its own place
# The library docked under the plots gets what the plots can spare: opened shorter than
# LIBRARY_MIN_PX it is given LIBRARY_SHARE of the window, and where docking it there would
# make the window taller than the screen it is a tab beside the Results (``Docks._fit_library``).
LIBRARY_MIN_PX = 280
LIBRARY_SHARE = 0.45
LIBRARY_FLOAT = QSize(1000, 560)    # the floating library on a screen too short to dock it
LIBRARY_TAB_SHARE = 0.61    # of the window's height, the library tabbed beside the Results: 5 rows at 1280×720
# (0.6 before its buttons took two rows: 4 rows then, its list 146 px tall for 150)
# On a laptop the mechanism takes this share of the height above the tabbed results and
# vector diagrams (0.54 left the polygons a 147 px canvas at 1366×768).
MECHANISM_SHARE = 0.47
TOP = Qt.DockWidgetArea.TopDockWidgetArea
NAMES = ("inputs", "results", "mechanism", "polygons", "library")
LEFT = Qt.DockWidgetArea.LeftDockWidgetArea
RIGHT = Qt.DockWidgetArea.RightDockWidgetArea
BOTTOM = Qt.DockWidgetArea.BottomDockWidgetArea
VERTICAL = Qt.Orientation.Vertical
HORIZONTAL = Qt.Orientation.Horizontal


def _titles() -> dict[str, str]:
    return {"inputs": QCoreApplication.translate("Docks", "Inputs"),
            "results": QCoreApplication.translate("Docks", "Results"),
            "mechanism": QCoreApplication.translate("Docks", "Mechanism"),
            "polygons": QCoreApplication.translate("Docks", "Vector diagrams"),
            "library": QCoreApplication.translate("Docks", "Design library")}


class Docks:
    """One QDockWidget per pane, named for saveState (``<name>Dock``)."""

    def __init__(self, window: QMainWindow, panes: dict[str, QWidget]) -> None:
        self._window = window
        self.docks: dict[str, QDockWidget] = {}
        self._sizes: tuple[QSize, bool] | None = None
        for name in NAMES:
            dock = QDockWidget(window)
            dock.setObjectName(f"{name}Dock")
            # The results scroll as a whole; each table inside shows all its rows.
            # Qt keeps a dock whose tab is not selected "visible", only moved out of sight:
            # its pane is then swapped for an empty page, so that the pane's lazy updates
            # (nothing done while hidden, caught up in showEvent) hold for tabbed docks too.
            # A stack keeps the dock's size hints those of the pane while it is hidden.
            holder = QStackedWidget()
            holder.addWidget(scrolled(panes[name]) if name == "results" else panes[name])
            holder.addWidget(QWidget())
            dock.setWidget(holder)
            dock.visibilityChanged.connect(lambda shown, d=dock: self._follow_tab(d, shown))
            self.docks[name] = dock
        self.docks["library"].visibilityChanged.connect(self._room_for_library)
        window.setCorner(Qt.Corner.BottomLeftCorner, LEFT)
        window.setCorner(Qt.Corner.BottomRightCorner, RIGHT)
        window.setCorner(Qt.Corner.TopLeftCorner, LEFT)
        window.setCorner(Qt.Corner.TopRightCorner, RIGHT)
        self.retranslate()

    @staticmethod
    def _follow_tab(dock: QDockWidget, shown: bool) -> None:
        """Hide the pane of a docked dock whose tab was deselected; show it otherwise (a
        closed dock hides its pane anyway)."""
        tabbed_away = not shown and dock.isVisible() and not dock.isFloating()
        dock.widget().setCurrentIndex(1 if tabbed_away else 0)

    def _room_for_library(self, shown: bool) -> None:
        """The library shown docked above or below the plots is checked once laid out."""
        dock, w = self.docks["library"], self._window
        if shown and not dock.isFloating() and w.dockWidgetArea(dock) in (BOTTOM, TOP):
            self.pane("library")        # built now if it was not, so that its size counts
            QTimer.singleShot(0, w, self._fit_library)    # dropped if the window goes first

    def _fit_library(self) -> None:
        """Docked under the plots on a laptop screen the library made the window taller
        than the screen (1366×768: 810 px): it docks as a tab beside the Results instead
        (floats over the window only when neither the Results nor the vector diagrams are
        docked at a side), and the window comes back onto the screen. Docked but too short
        to list a row, it is made taller."""
        dock, w = self.docks["library"], self._window
        if not dock.isVisible() or dock.isFloating():
            return
        screen = available(w)
        room = screen.height() - FRAME_ALLOWANCE.height()
        beside = next((d for d in (self.docks["results"], self.docks["polygons"])
                       if d.isVisible() and not d.isFloating() and w.dockWidgetArea(d) in (LEFT, RIGHT)), None)
        if w.minimumSizeHint().height() > room and beside is not None:
            # no room under the plots: a tab beside the Results (tabbed with the vector
            # diagrams on a laptop), where the panes dock; it floated over the window
            w.tabifyDockWidget(beside, dock)
            dock.raise_()
            QTimer.singleShot(0, w, lambda: self._tab_height(room))     # once laid out as a tab
        elif w.minimumSizeHint().height() > room:
            dock.setFloating(True)
            size = QSize(min(LIBRARY_FLOAT.width(), int(screen.width() * 0.8)),
                         min(LIBRARY_FLOAT.height(), int(screen.height() * 0.7)))
            frame = QRect(0, 0, size.width(), size.height())
            frame.moveCenter(screen.center())           # at most 80 % × 70 % of it: inside
            dock.setGeometry(frame)
            QTimer.singleShot(0, w, lambda: self._back_on_screen(room))   # once the window's
            # layout has dropped the dock's minimum height
        elif dock.height() < LIBRARY_MIN_PX:
            w.resizeDocks([dock], [int(w.height() * LIBRARY_TAB_SHARE)], VERTICAL)

    def _tab_height(self, room: int) -> None:
        """The library's tab group given LIBRARY_TAB_SHARE of the window, the window on the screen."""
        w, h = self._window, self._window.height()
        # both sizes: given the library's alone, Qt took a third of the change from it
        w.resizeDocks([self.docks["mechanism"], self.docks["library"]],
                      [int(h * (1.0 - LIBRARY_TAB_SHARE)), int(h * LIBRARY_TAB_SHARE)], VERTICAL)
        self._back_on_screen(room)

    def _back_on_screen(self, room: int) -> None:
        """The window made at most ``room`` tall again, and raised by as much as its frame
        still reaches below the screen, no more (it went to the screen's top: 24 px up on
        a laptop, for a frame 1 px too low)."""
        w, screen = self._window, available(self._window)
        if w.height() > room and not w.isMaximized() and not w.isFullScreen():
            w.resize(w.width(), max(room, w.minimumSizeHint().height()))
            below = w.frameGeometry().bottom() - screen.bottom()
            if below > 0:
                w.move(w.x(), max(screen.top(), w.y() - below))

    def __getitem__(self, name: str) -> QDockWidget:
        return self.docks[name]

    def pane(self, name: str) -> QWidget:
        """The widget a dock shows (the results pane's scroll area)."""
        pane = self.docks[name].widget().widget(0)
        return pane.view() if isinstance(pane, LazyPage) else pane

    def arrange(self, size: QSize) -> None:
        """The default layout for a window of ``size``: every pane docked and shown
        (the library hidden)."""
        w, d = self._window, self.docks
        for dock in d.values():
            dock.setFloating(False)
            w.removeDockWidget(dock)
        wide = size.width() >= WIDE
        w.addDockWidget(LEFT, d["inputs"])
        w.addDockWidget(RIGHT, d["mechanism"])
        if wide:
            w.splitDockWidget(d["inputs"], d["results"], VERTICAL)
            w.splitDockWidget(d["mechanism"], d["polygons"], VERTICAL)
        else:       # results and polygons are tabbed in apply_sizes (Qt cannot size a tab group)
            w.splitDockWidget(d["mechanism"], d["results"], VERTICAL)
            w.splitDockWidget(d["results"], d["polygons"], VERTICAL)
        w.addDockWidget(BOTTOM, d["library"])
        for name, dock in d.items():
            dock.setVisible(name != "library")
        d["results"].raise_()
        self._sizes = (size, wide)
        if w.isVisible():
            self.apply_sizes()

    def keep_sizes(self) -> None:
        """A restored state brought its own sizes: forget the default ones."""
        self._sizes = None

    def apply_sizes(self) -> None:
        """The default pane sizes: applied once the window is laid out (before it is shown
        Qt divides the space by the panes' size hints instead)."""
        if self._sizes is None:
            return
        (size, wide), self._sizes = self._sizes, None
        w, d = self._window, self.docks
        height = size.height()
        side = 380 if wide else 345
        right = 560 if wide else max(380, int(size.width() * 0.31))
        w.resizeDocks([d["inputs"], d["mechanism"]], [side, right], HORIZONTAL)
        if wide:
            # the whole design form (down to the angle step) without scrolling; results scroll
            w.resizeDocks([d["inputs"], d["results"]], [int(height * 0.6), int(height * 0.4)], VERTICAL)
            w.resizeDocks([d["mechanism"], d["polygons"]], [int(height * 0.5), int(height * 0.5)], VERTICAL)
        else:
            w.tabifyDockWidget(d["results"], d["polygons"])
            d["results"].raise_()
            w.resizeDocks([d["mechanism"]], [int(height * MECHANISM_SHARE)], VERTICAL)

    def enlarge_polygons(self) -> None:
        """Float the vector diagrams over most of the screen, or dock them again."""
        dock = self.docks["polygons"]
        if dock.isFloating():
            dock.setFloating(False)
            return
        room = available(self._window)
        dock.setFloating(True)
        size = room.size() * 0.7
        dock.setGeometry(room.x() + (room.width() - size.width()) // 2,
                         room.y() + (room.height() - size.height()) // 2, size.width(), size.height())

    def toggle_actions(self) -> list:
        """View-menu actions that hide and show each pane (Qt keeps them in step)."""
        return [self.docks[name].toggleViewAction() for name in NAMES]

    def retranslate(self) -> None:
        for name, title in _titles().items():
            self.docks[name].setWindowTitle(title)
