"""Where the window opens, and that opening the library does not move it (1 December).

Under openbox at 1366 × 768 the window opened with its frame 24 px down and 1 px below the
screen (the opening size centred without its frame), and Ctrl+L (the library, tabbed beside
the Results, made the window 1 px taller for a moment) moved it to the screen's top: the
whole window jumped 24 px up. The offscreen platform draws no frame, so these tests place
the window as a window manager would see it, with ``FRAME_ALLOWANCE`` round it.
"""
import pytest
from PySide6.QtCore import QRect

from shaperapp.window.state import FRAME_ALLOWANCE, PREFERRED, available, opening_corner


@pytest.mark.parametrize("screen", [QRect(0, 0, 1366, 768), QRect(0, 0, 1280, 720), QRect(0, 24, 1366, 744),
                                    QRect(1920, 0, 1920, 1080)])
def test_the_window_opens_with_its_frame_on_the_screen(screen):
    """The frame a window manager adds (FRAME_ALLOWANCE) is inside the screen, centred
    where there is room (before: the window alone was centred, its frame's bottom
    FRAME_ALLOWANCE / 2 below a laptop's screen: at 1366 × 768 a 720 px window at y = 24)."""
    size = PREFERRED.boundedTo(screen.size() - FRAME_ALLOWANCE)
    frame = QRect(opening_corner(screen, size), size + FRAME_ALLOWANCE)
    assert screen.contains(frame), (frame, screen)
    assert abs(frame.center().x() - screen.center().x()) <= 1
    assert abs(frame.center().y() - screen.center().y()) <= 1


def test_a_window_back_on_the_screen_moves_only_as_far_as_it_must(window):
    """Made too tall for a moment (the library tabbed beside the Results), the window is
    made short again and raised by as much as it still reaches below the screen (before:
    to the screen's top)."""
    screen = available(window)
    room = screen.height() - FRAME_ALLOWANCE.height()
    window.show()
    window.resize(window.width(), room + 1)
    top = screen.bottom() - room + 2 - (window.frameGeometry().height() - window.height())
    window.move(window.x(), top)                    # at ``room`` tall, 1 px below the screen
    window.docks._back_on_screen(room)
    assert window.height() == room
    assert window.frameGeometry().bottom() == screen.bottom()
    assert window.y() == top - 1
