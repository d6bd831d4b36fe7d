"""Views built when first shown: a tab page or pane that nobody looks at costs nothing.

Why: building every tab at start-up (Forces, Positions, Explore, Compare: their
plots, tables and the modules behind them) made up about a fifth of the time
to the first window (issue 24). A ``LazyPage`` stands in the tab or dock and
builds its view from a factory the first time it is shown, the first time
code asks for the view (``view()``), or once the window is on screen
(``build_when_idle``), whichever comes first. The factory may
import the view's module, so that nothing the first screen does not show is
imported before it.

``ViewTabs`` is a QTabWidget that speaks of views, not of their stand-ins:
``widget``, ``currentWidget``, ``indexOf`` and ``setCurrentWidget`` take and
give the view itself, so code (and tests) written for eagerly built tabs stay
true.
"""
from __future__ import annotations

from typing import Callable, Sequence

import shiboken6

from PySide6.QtCore import QCoreApplication, QEvent, QTimer, Signal
from PySide6.QtWidgets import QTabWidget, QVBoxLayout, QWidget

from .guards import guard_wheel


class LazyPage(QWidget):
    """Holds the view ``factory()`` builds, built on the first show or ``view()``."""

    built = Signal(QWidget)

    def __init__(self, factory: Callable[[], QWidget], parent: QWidget | None = None,
                 defer: bool = False) -> None:
        super().__init__(parent)
        self._factory: Callable[[], QWidget] | None = factory
        # A page in a tabbed dock is shown for a moment while the window is first laid out,
        # then hidden behind its neighbour's tab: with ``defer`` a show builds the view two
        # turns of the event loop later, and only if the page is still visible then. Two:
        # Qt shows a window's children before the window itself, so the window's own
        # layout pass (Docks.apply_sizes, which tabs the dock) is queued after the first.
        self._defer = defer
        self._view: QWidget | None = None
        self._caught_up = False
        self._layout = QVBoxLayout(self)
        self._layout.setContentsMargins(0, 0, 0, 0)

    def is_built(self) -> bool:
        return self._view is not None

    def is_ready(self) -> bool:
        """Built, and its view's first drawing done while hidden (see ``catch_up``)."""
        return self._view is not None and self._caught_up

    def catch_up(self) -> None:
        """While the page is hidden, let the view do what its first show would (its
        ``catch_up()``, if it has one: compute and draw for the model as it is), so that
        the first visit only paints: the Forces tab's first drawing of 16 speeds was half
        its first visit (issue 40 item 5). Once; not for a page on screen, whose show did it."""
        if self._view is None or self._caught_up:
            return
        self._caught_up = True
        catch_up = getattr(self._view, "catch_up", None)
        if catch_up is not None and not self.isVisible():
            catch_up()

    def built_view(self) -> QWidget | None:
        """The view if it has been built, else None (never builds it)."""
        return self._view

    def view(self) -> QWidget:
        """The view, built now if it was not yet."""
        if self._view is None:
            factory, self._factory = self._factory, None
            assert factory is not None
            self._view = factory()
            self._layout.addWidget(self._view)
            if self.isVisible():            # now, as the view would have been; Qt would queue it,
                self._view.show()           # and laid out to the page's size at once
                self._layout.activate()
            guard_wheel(self._view)         # as the window guarded what it held when built
            # A hidden page's size change reaches no layout by itself; the tabs' and the
            # window's minimum sizes must count the view (the window fits the screen by them).
            widget: QWidget | None = self
            while widget is not None:
                if widget.layout() is not None:
                    widget.layout().invalidate()
                widget = widget.parentWidget()
            self.built.emit(self._view)
        return self._view

    def showEvent(self, event) -> None:
        if not self._defer:
            self.view()
        elif self._view is None:
            QTimer.singleShot(0, self, lambda: QTimer.singleShot(0, self, self._build_if_visible))
        super().showEvent(event)

    def _build_if_visible(self) -> None:
        if self.isVisible():
            self.view()


class ViewTabs(QTabWidget):
    """Tabs whose pages may be LazyPages; every method below takes or gives the view."""

    def widget(self, index: int) -> QWidget | None:  # type: ignore[override]
        page = super().widget(index)
        return page.view() if isinstance(page, LazyPage) else page

    def currentWidget(self) -> QWidget | None:  # type: ignore[override]
        index = self.currentIndex()
        return self.widget(index) if index >= 0 else None

    def indexOf(self, widget: QWidget) -> int:  # type: ignore[override]
        for i in range(self.count()):
            page = super().widget(i)
            if page is widget or (isinstance(page, LazyPage) and page.built_view() is widget):
                return i
        return -1

    def setCurrentWidget(self, widget: QWidget) -> None:  # type: ignore[override]
        index = self.indexOf(widget)
        if index >= 0:
            self.setCurrentIndex(index)


def build_when_idle(pages: Sequence[LazyPage]) -> None:
    """Build ``pages`` one per turn of the event loop, from the next turn on: called once
    the window is painted, so the views come in while the user looks at the first screen,
    and the window's minimum size is that of every view again, as it was when all were
    built at start-up. Then, one per turn again, each page catches up while hidden
    (``LazyPage.catch_up``): every view is built before any draws."""
    waiting = [page for page in pages if not page.is_ready()]

    def next_page() -> None:
        # Not for a window already closed: its views would be built for a model that may
        # be going away (a test's window, closed while the turns were queued).
        waiting[:] = [page for page in waiting if shiboken6.isValid(page) and page.window().isVisible()]
        unbuilt = next((page for page in waiting if not page.is_built()), None)
        if unbuilt is not None:
            unbuilt.view()
        elif waiting:
            waiting.pop(0).catch_up()
        _queue()

    def _queue() -> None:
        # Tied to a page still alive: a deleted context drops the call instead of running it.
        alive = [page for page in waiting if shiboken6.isValid(page)]
        waiting[:] = alive
        if alive:
            QTimer.singleShot(0, alive[0], next_page)

    _queue()


def lay_out_page(widget: QWidget) -> None:
    """Give ``widget`` (in a tab page) its size now, before it draws: Qt shows a tab page
    before its tab widget has laid it out (the children first), so at the window's first
    show the Kinematics stack refreshed at a provisional size (its pane 336 px tall instead
    of 533), put its legend beside the plots and moved it back above them at the next
    resize. A tab widget lays out its page when asked (a layout request); where the page
    already has its size nothing changes."""
    parent = widget.parentWidget()
    while parent is not None:
        if isinstance(parent, QTabWidget):
            QCoreApplication.sendEvent(parent, QEvent(QEvent.Type.LayoutRequest))
        parent = None if parent.isWindow() else parent.parentWidget()
