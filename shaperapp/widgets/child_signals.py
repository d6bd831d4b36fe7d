"""Children started here take SIGINT, whatever this process was started with.

Why: the class dialog's Cancel sends its ``shaper class`` child SIGINT, which the child
turns into "start no new student, finish those being written". A process started in the
background by a shell without job control (a script's ``shaper-gui &``, CI) has SIGINT
ignored, and an ignored signal stays ignored across ``exec``: Python then installs no
handler in the child, and Cancel did nothing (the class ran to its end). A caught signal
is reset to its default at ``exec``, so this process catches SIGINT, doing nothing with
it, while the child starts, and puts its own disposition back afterwards.
"""
from __future__ import annotations

import signal
import threading
from contextlib import contextmanager
from typing import Iterator


def _ignore(_signum: int, _frame: object) -> None:
    """Caught and dropped: this process keeps ignoring SIGINT meanwhile."""


@contextmanager
def children_take_sigint() -> Iterator[None]:
    """Within the block, children started (QProcess, subprocess) begin with SIGINT at its
    default, so a Python child turns it into KeyboardInterrupt. Only the main thread can
    change a signal's handler; elsewhere the block changes nothing."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    before = signal.getsignal(signal.SIGINT)
    if before is not signal.SIG_IGN:
        yield                       # not ignored: children get the default already
        return
    signal.signal(signal.SIGINT, _ignore)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, before)
