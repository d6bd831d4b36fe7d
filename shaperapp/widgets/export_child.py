"""The child process that writes an export for the window (``python -m`` this module).

Why a child process and not the GUI thread or a thread: the report and the sheets are
painted by Qt, whose widgets may be drawn on the GUI thread only, so in the window's own
process an export held the window for seconds (issue 40, item 5); and what an export
allocates (figures, pages, arrays) stayed in the window's heap afterwards (issue 42,
item 8). A child paints on its own GUI thread, offscreen, while the window goes on; when
it ends, all its memory goes back to the system.

The job comes on stdin, pickled by the window (:func:`job_bytes`): a function named by
module and name, its keyword arguments (a snapshot of the design taken when the export
started) and the language. The child answers on stdout in lines (:func:`parse_line`):
``progress F`` (fraction done), ``file PATH`` (a file complete), ``error DATA`` (the
exception that stopped it, pickled). SIGTERM asks it to stop at the next step
(``core.base.progress``); the file being made is then not written. Exit status: 0 done,
1 failed, 3 cancelled.
"""
from __future__ import annotations

import base64
import importlib
import os
import pickle
import signal
import sys
from typing import Any, Callable

EXIT_DONE, EXIT_FAILED, EXIT_CANCELLED = 0, 1, 3


def job_bytes(function: Callable[..., Any], language: str, /, **arguments: Any) -> bytes:
    """The job as the child reads it: ``function(progress, file_done, **arguments)`` run
    in ``language``; the function must be importable by its module and name."""
    return pickle.dumps({"module": function.__module__, "name": function.__qualname__,
                         "language": language, "arguments": arguments})


def parse_line(line: str) -> tuple[str, Any] | None:
    """A line of the child's output as (kind, value): ("progress", float), ("file", str),
    ("error", exception); None for any other line (a library's own print)."""
    kind, _, value = line.rstrip("\r\n").partition(" ")
    try:
        if kind == "progress":
            return kind, float(value)
        if kind == "file":
            return kind, value
        if kind == "error":
            return kind, pickle.loads(base64.b64decode(value))
    except Exception:                   # a line cut short or not ours: not a message
        return None
    return None


def error_line(exc: BaseException) -> str:
    """The ``error`` line for ``exc``: an OSError as a plain one (its number, reason and
    file, which the window translates), another as itself when it pickles, else as a
    RuntimeError with its text."""
    if isinstance(exc, OSError):
        exc = OSError(exc.errno, exc.strerror or str(exc), exc.filename)
    try:
        data = pickle.dumps(exc)
        pickle.loads(data)
    except Exception:
        data = pickle.dumps(RuntimeError(str(exc) or type(exc).__name__))
    return "error " + base64.b64encode(data).decode("ascii")


def main() -> int:
    from core.base.progress import Cancelled, Progress
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(True))
    job = pickle.loads(sys.stdin.buffer.read())
    out = sys.stdout
    last = [-1.0]

    def report(fraction: float) -> None:
        if fraction - last[0] >= 0.001 or fraction >= 1.0:        # at most a thousand lines
            last[0] = fraction
            out.write(f"progress {fraction:.4f}\n")
            out.flush()

    def file_done(path: str) -> None:
        out.write(f"file {path}\n")
        out.flush()
    try:
        from shaperapp.widgets.command_line import application, ensure_headless
        from shaperapp.widgets import i18n
        ensure_headless()
        application()
        i18n.set_language(job["language"])
        function = getattr(importlib.import_module(job["module"]), job["name"])
        function(Progress(report, lambda: bool(stop)), file_done, **job["arguments"])
    except Cancelled:
        return EXIT_CANCELLED
    except Exception as exc:            # the window says why, in its language
        out.write(error_line(exc) + "\n")
        out.flush()
        return EXIT_FAILED
    return EXIT_DONE


if __name__ == "__main__":
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")     # never a window of its own
    sys.exit(main())
