"""Long computations on a worker thread that never touches Qt.

Why not a QThread whose ``run`` is Python, emitting signals to the window: with PySide a
Python thread that calls into Qt (a signal's emit, a QObject's wrapper, the QThread's own
end) holds Python's global lock (the GIL) while it waits for Qt's locks, and the GUI
thread can hold one of those locks while it waits for the GIL. Both then wait for ever,
and nothing written in Python, not even a test's time limit, can run again. CI runs of
the GUI fuzz test hung that way, twice, with a map being computed on such a thread.

So a job here is plain Python (``core`` and numpy). It reports through a ``report``
callable that only puts tuples on a thread-safe queue. The GUI thread empties the queue
on a timer and emits the runner's signals itself, so every Qt call stays on the GUI
thread. One more way a worker reaches Qt objects is Python's cyclic garbage collector,
which runs in whichever thread happens to allocate and would destroy GUI objects caught
in reference cycles from the worker. While a job runs, automatic collection is therefore
off, and the GUI thread collects on the same timer by the same thresholds
(:class:`GuiThreadCollector`).
"""
from __future__ import annotations

import gc
import queue
import sys
import threading
import time
from typing import Any, Callable, Protocol

from PySide6.QtCore import QObject, QTimer, Signal

POLL_MS = 30

Report = Callable[..., None]


class Job(Protocol):
    """What :class:`JobRunner` runs: ``run(report)`` on the worker thread, calling
    ``report("progress", done, total)``, ``report("finished", result)``,
    ``report("failed", error)`` or ``report("cancelled")``, and checking ``stop``."""

    stop: threading.Event

    def run(self, report: Report) -> None: ...


class GuiThreadCollector:
    """Automatic garbage collection moved to the GUI thread while workers run.

    ``hold(thread)`` turns automatic collection off while that thread lives;
    ``collect_due`` collects the generations whose thresholds are passed, as the
    interpreter would have; when the last held thread has ended (``release``, or found
    ended by any later call, if its runner was deleted first), collection is given back
    to the interpreter as it was found.
    """

    def __init__(self) -> None:
        self._threads: set[threading.Thread] = set()
        self._was_enabled = False

    @property
    def holding(self) -> bool:
        self._forget_ended()
        return bool(self._threads)

    def hold(self, thread: threading.Thread) -> None:
        self._forget_ended()
        if not self._threads:
            self._was_enabled = gc.isenabled()
            gc.disable()
        self._threads.add(thread)

    def join(self, timeout: float) -> bool:
        """Wait up to ``timeout`` s for every held worker thread to end, then give collection
        back (tests, so that a job a test left running cannot hold it in the next one).
        False if one is still running."""
        deadline = time.monotonic() + timeout
        for thread in list(self._threads):
            thread.join(max(0.0, deadline - time.monotonic()))
        return not self.holding

    def release(self, thread: threading.Thread) -> None:
        self._forget_ended(thread)

    def _forget_ended(self, released: threading.Thread | None = None) -> None:
        """Drop ``released`` and the threads that have ended; when that leaves none, give
        collection back. (Released as the last one, a thread used to leave collection off
        for good: the set was empty before the check, so nothing was given back, and the
        next hold then found collection off and kept it so.)"""
        if not self._threads:
            return
        self._threads = {t for t in self._threads if t is not released and t.is_alive()}
        if not self._threads:
            self.collect_due()
            if self._was_enabled:
                gc.enable()

    @staticmethod
    def collect_due() -> None:
        counts, thresholds = gc.get_count(), gc.get_threshold()
        generation = -1
        for g in range(3):
            if thresholds[g] and counts[g] > thresholds[g]:
                generation = g
            else:
                break
        if generation >= 0:
            gc.collect(generation)


COLLECTOR = GuiThreadCollector()


def _work(job: Job, events: queue.SimpleQueue) -> None:
    """The worker thread: only the job's own code and the queue (not even the runner, which
    the window may delete meanwhile)."""
    def report(kind: str, *args: Any) -> None:
        events.put((job, kind, args))
    try:
        job.run(report)
    except BaseException:                    # a defect: shown on the GUI thread, by its hook
        report("error", sys.exc_info())
    finally:
        events.put((job, "ended", (threading.current_thread(),)))


class JobRunner(QObject):
    """Runs one job at a time on a worker thread; a new job cancels the previous one.

    Every signal is emitted on the GUI thread and names its job, so a receiver can ignore
    reports of a job it has replaced (``job`` is the current one). ``ended(job)`` follows
    when a job's thread has returned.
    """

    progress = Signal(object, int, int)     # job, done, in all
    finished = Signal(object, object)       # job, result
    failed = Signal(object, object)         # job, the error (None for lack of memory)
    cancelled = Signal(object)              # job
    ended = Signal(object)                  # job

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._threads: dict[threading.Thread, Any] = {}
        self._job: Any = None
        self._events: queue.SimpleQueue = queue.SimpleQueue()
        self._timer = QTimer(self, interval=POLL_MS)
        self._timer.timeout.connect(self.deliver)

    @property
    def job(self) -> Any:
        """The job running now (None once cancelled or ended)."""
        return self._job

    @property
    def running(self) -> bool:
        """Whether any worker thread (the current job's or a cancelled one's) is alive."""
        return bool(self._threads)

    def start(self, job: Job) -> None:
        self.cancel()
        thread = threading.Thread(target=_work, args=(job, self._events), daemon=True,
                                  name=f"shaper-{type(job).__name__}")
        self._threads[thread] = job
        self._job = job
        COLLECTOR.hold(thread)
        thread.start()
        self._timer.start()

    def deliver(self) -> None:
        """Emit what the workers reported since the last call (the GUI thread's timer)."""
        if COLLECTOR.holding:
            COLLECTOR.collect_due()
        while True:
            try:
                job, kind, args = self._events.get_nowait()
            except queue.Empty:
                break
            if kind == "ended":
                self._thread_ended(job, args[0])
            elif kind == "error":
                sys.excepthook(*args[0])
            else:
                getattr(self, kind).emit(job, *args)

    def _thread_ended(self, job: Any, thread: threading.Thread) -> None:
        thread.join()                        # it has returned from _work; this is at once
        if self._threads.pop(thread, None) is None:
            return
        COLLECTOR.release(thread)
        if job is self._job:
            self._job = None
        if not self._threads:
            self._timer.stop()
        self.ended.emit(job)

    def cancel(self) -> None:
        """Ask the running job to stop; it ends at its next chunk."""
        if self._job is not None:
            self._job.stop.set()
        self._job = None

    def wait(self, msecs: int = 10_000) -> bool:
        """Stop every job and wait until their threads have returned (closing the window,
        tests); what they reported is delivered. False if one is still running."""
        deadline = time.monotonic() + msecs / 1000
        for thread, job in list(self._threads.items()):
            job.stop.set()
            thread.join(max(0.0, deadline - time.monotonic()))
        self.deliver()
        return not self._threads
