"""Large CSV tables computed and written piece by piece, with progress on a terminal.

A request may hold up to ``core.linkage.kinematics.MAX_SAMPLES`` samples (angles ×
speeds). Computed in one piece, that would hold every column of every row,
and its formatted text, in memory at once; computed per block of
``CHUNK_ANGLES`` angles of one speed, memory stays at a few tens of MB
however large the request. The rows come out in the same order as the whole
table (speed by speed, angles in order) and each value is computed by the
same closed form, so the text is the same as the unchunked ``table_csv``.
"""
from __future__ import annotations

import sys
import time
from types import TracebackType
from typing import TYPE_CHECKING, Callable, Iterator, Sequence, TextIO

from .allocator import keep_freed_memory
from .forked import pieces_in_order, worker_count
from .output import write_output

if TYPE_CHECKING:
    import numpy as np

CHUNK_ANGLES = 16_384
SCALE_ANGLES = 4_096     # angles per speed sampled for the columns' magnitudes
FORK_ROWS = 20_000       # smaller tables are made in this process alone (a fork costs ~ms)
SHARED_ANGLES = 4_096    # a block shared with a child: its text (~0.3 MB) fits in the pipe

# compute(angles in rad, one rpm) -> (column names, rows); one speed, a block of angles
TableBlock = Callable[["np.ndarray", float], "tuple[Sequence[str], np.ndarray]"]


LOG_EVERY = 5.0          # seconds between progress lines when stderr is not a terminal


class Progress:
    """Progress of long work on stderr. On a terminal: ``shaper: LABEL 42%``, rewritten in
    place once a run has taken longer than ``delay`` seconds, erased on the way out (used
    as a context manager), before any error message is printed. Elsewhere (a log, a pipe),
    with ``log``: a whole line ``shaper: LABEL 42% after 15 s`` every ``LOG_EVERY`` seconds
    once the run has taken that long, so a log keeps it (issue 42: a 12-minute sweep said
    nothing); without it, nothing (``curves``' tables promise a quiet stderr there).
    ``lines`` (``--progress``) asks for those lines from the start, at most one a second,
    and a last one at 100%, on a terminal too."""

    def __init__(self, label: str, total: int, delay: float = 1.0,
                 stream: TextIO | None = None, lines: bool = False, log: bool = False) -> None:
        self.label, self.total, self.delay = label, max(int(total), 1), delay
        self.stream = sys.stderr if stream is None else stream
        self.start = time.monotonic()
        self.last = 0.0
        self.shown = False
        self.forced = lines
        try:
            self.in_place = bool(self.stream.isatty()) and not lines
        except (AttributeError, ValueError, OSError):
            self.in_place = False
        self.enabled = self.in_place or lines or log
        self.printed = -1           # the work done when the last line was printed

    def __enter__(self) -> "Progress":
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        self.close(finished=kind is None)

    def update(self, done: int) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if self.in_place:
            if now - self.start < self.delay or now - self.last < 0.1:
                return
            self.last = now
            self._write(f"\rshaper: {self.label} {self._percent(done):3d}%")
            self.shown = True
            return
        wait = 1.0 if self.forced else LOG_EVERY
        if (not self.forced and now - self.start < LOG_EVERY) or (self.last and now - self.last < wait):
            return
        self.last = now
        self._line(done, now)

    def _percent(self, done: int) -> int:
        return min(100, 100 * done // self.total)

    def _line(self, done: int, now: float) -> None:
        self.printed = done
        self._write(f"shaper: {self.label} {self._percent(done)}% after {now - self.start:.0f} s\n")

    def close(self, finished: bool = True) -> None:
        if self.shown:
            self._write("\r" + " " * (len(self.label) + 13) + "\r")
            self.shown = False
        if finished and self.enabled and not self.in_place and (self.forced or self.last) \
                and self.printed < self.total:
            self._line(self.total, time.monotonic())
        self.enabled = False

    def _write(self, text: str) -> None:
        try:
            self.stream.write(text)
            self.stream.flush()
        except (OSError, ValueError):
            self.enabled = False


def table_pieces(block: TableBlock, angles: np.ndarray, rpms: Sequence[float],
                 progress: Progress | None = None, workers: int | None = None) -> Iterator[str]:
    """The CSV text of the whole (speeds × angles) table, one block at a time; the blocks
    are made by ``workers`` processes (default: one per core, see ``core.cli.forked``).

    Round-off zeros are judged against the whole table's column magnitudes, taken
    first from every speed at (up to) SCALE_ANGLES of the same angles, so that the
    text is that of the unchunked table."""
    import numpy as np

    from core.files.io import table_chunks, zero_scale
    step = max(1, -(-angles.size // SCALE_ANGLES))
    scale = np.max([zero_scale(block(angles[::step], rpm)[1]) for rpm in rpms], axis=0)
    if workers is None:
        workers = worker_count(angles.size * len(rpms) // SHARED_ANGLES) \
            if angles.size * len(rpms) >= FORK_ROWS else 1
    chunk = CHUNK_ANGLES if workers == 1 else SHARED_ANGLES
    spans = [(rpm, angles[start:start + chunk])
             for rpm in rpms for start in range(0, angles.size, chunk)]

    def text(index: int) -> str:
        rpm, some = spans[index]
        names, data = block(some, rpm)
        return "".join(table_chunks(names if index == 0 else None, data, scale=scale))

    done = 0
    for index, piece in enumerate(pieces_in_order(text, len(spans), workers)):
        yield piece
        done += spans[index][1].size
        if progress is not None:
            progress.update(done)


def write_table(option: str, target: str, label: str, block: TableBlock, angles: np.ndarray,
                rpms: Sequence[float]) -> None:
    """The whole table as CSV to ``target`` (``-`` for stdout; see ``write_output``), block
    by block, with ``shaper: LABEL n%`` on a terminal."""
    keep_freed_memory()             # each block's arrays are not faulted in anew
    with Progress(label, angles.size * len(rpms)) as progress:
        write_output(option, target, table_pieces(block, angles, rpms, progress))
