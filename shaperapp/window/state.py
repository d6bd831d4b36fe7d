"""Where the window opens and how its layout is remembered.

The window opens at a size that fits the screen it is on (``QScreen.availableGeometry``);
a saved geometry is used only if it still fits that screen (a window saved on a large
monitor does not open half off a laptop). The docks' and toolbar's arrangement is kept
with ``saveState(STATE_VERSION)``: a state saved by an older layout (another version) is
ignored and the default arrangement used instead.
"""
from __future__ import annotations

from PySide6.QtCore import QByteArray, QPoint, QRect, QSettings, QSize
from PySide6.QtWidgets import QMainWindow

STATE_VERSION = 2           # 1: the splitter layout before the panes became docks
PREFERRED = QSize(1760, 990)     # on a large screen: room for every pane at once
MINIMUM = QSize(1280, 720)  # the window never needs more (tests check it, both languages)
FRAME_ALLOWANCE = QSize(16, 48)   # a window manager's frame and title bar, roughly


def available(window: QMainWindow) -> QRect:
    """The usable part of the screen the window is (or will be) on."""
    screen = window.screen()
    return screen.availableGeometry() if screen is not None else QRect(0, 0, PREFERRED.width(),
                                                                      PREFERRED.height())


def opening_size(window: QMainWindow) -> QSize:
    """The preferred size, shrunk to the screen less a window frame."""
    room = available(window).size() - FRAME_ALLOWANCE
    return PREFERRED.boundedTo(room).expandedTo(window.minimumSizeHint().boundedTo(room))


def opening_corner(screen: QRect, size: QSize) -> QPoint:
    """Where the frame of a window of ``size`` opens: the window with FRAME_ALLOWANCE round it
    centred on ``screen`` (the frame is not known before the window is shown). Centring the
    window alone put a 1366 × 768 laptop's frame 24 px down and its bottom 1 px below the
    screen (openbox: a 745 px frame at y = 24), and opening the library, which made the window
    1 px taller for a moment, then moved it to the screen's top (``Docks._back_on_screen``)."""
    frame = QRect(QPoint(0, 0), size + FRAME_ALLOWANCE)
    frame.moveCenter(screen.center())
    return QPoint(max(frame.left(), screen.left()), max(frame.top(), screen.top()))


def fits(window: QMainWindow) -> bool:
    return available(window).contains(window.frameGeometry())


def restore(window: QMainWindow, settings: QSettings, arrange) -> bool:
    """Saved geometry if it fits the screen, else the opening size centred; the saved dock
    state if it is of this version and its window fits, else ``arrange(size)``, the
    default arrangement for this screen.
    True when a saved dock state was restored."""
    geometry = settings.value("geometry")
    restored = isinstance(geometry, QByteArray) and not geometry.isEmpty() and window.restoreGeometry(geometry)
    fitted = restored and fits(window)
    if not fitted:
        size = opening_size(window)
        window.resize(size)
        window.move(opening_corner(available(window), size))
    arrange(window.size())
    state = settings.value("windowState")
    # The panes' layout belongs to the window it was saved with: one saved on a large
    # screen squeezed the inputs and results on a laptop, so where that window does not
    # fit this screen the default layout for this screen is used instead.
    if fitted and isinstance(state, QByteArray) and not state.isEmpty():
        # False, and nothing changed, for a state of another version.
        return window.restoreState(state, STATE_VERSION)
    return False


def save(window: QMainWindow, settings: QSettings) -> None:
    settings.setValue("geometry", window.saveGeometry())
    settings.setValue("windowState", window.saveState(STATE_VERSION))
