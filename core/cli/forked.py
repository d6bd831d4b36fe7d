"""Pieces of a long output made on every core, written in order by this process.

Why: a large CSV from ``shaper curves`` or ``shaper dynamics`` is computed and
formatted block by block, and formatting alone (``core.files.numtext``) is most of a
run. The blocks are independent, so forked copies of this process make every
other block while this one makes the rest and writes all of them, in order.
The text is the same as one process makes (each block's text is a pure function
of the block), and this process stays in charge of the file:

- a child only computes and sends; it never touches the output, and it leaves
  through ``os._exit``, so none of this process's clean-up (removing a
  half-written temporary file, flushing stdout) runs twice;
- a piece a child does not deliver (it died, or was killed) is made here
  instead, so a lost child costs time, never text;
- when the consumer stops early (an error, an interrupt), the children are
  killed and reaped before the error goes on.

Only on Linux, in a process without other threads, and not for small outputs;
``SHAPER_WORKERS=1`` turns it off.
"""
from __future__ import annotations

import os
import signal
import struct
import sys
from typing import Callable, Iterator

MAX_WORKERS = 4
PIPE_BYTES = 1 << 20
_LENGTH = struct.Struct("<q")
_FAILED = -1                 # a child's "I could not make this piece"


def worker_count(pieces: int) -> int:
    """How many processes share ``pieces`` pieces: one per usable core (at most
    MAX_WORKERS, or ``$SHAPER_WORKERS``), one when forking is unsafe or pointless."""
    if pieces < 2 or not sys.platform.startswith("linux") or _threads() != 1:
        return 1
    wanted = os.environ.get("SHAPER_WORKERS", "").strip()
    try:
        limit = int(wanted) if wanted else MAX_WORKERS
    except ValueError:
        limit = MAX_WORKERS
    return max(1, min(limit, len(os.sched_getaffinity(0)), pieces))


def _threads() -> int:
    """This process's threads as the kernel counts them (numpy's BLAS threads too, which
    Python's ``threading`` does not see): a fork copies only the calling one."""
    try:
        with open("/proc/self/stat", "rb") as stat:
            return int(stat.read().rsplit(b")", 1)[1].split()[17])
    except (OSError, ValueError, IndexError):
        return 0


def owner(index: int, workers: int) -> int:
    """Which process makes piece ``index``: 0 (this one) or a child 1 … workers − 1.
    This one makes the first ``workers`` pieces, then every ``workers``-th; a child
    starts further on, since its first piece takes it about twice as long (each page it
    writes is first copied from this process's)."""
    return 0 if index < workers else (index - workers) % workers


def pieces_in_order(make: Callable[[int], str], count: int, workers: int) -> Iterator[str]:
    """``make(0)``, ``make(1)`` … ``make(count − 1)``, in order. With ``workers`` > 1,
    piece i is made by forked child ``owner(i, workers)`` (this process for 0)."""
    if workers <= 1:
        for index in range(count):
            yield make(index)
        return
    children: dict[int, tuple[int, int]] = {}        # worker → (pid, read end)
    try:
        for worker in range(1, workers):
            started = _start(make, [i for i in range(count) if owner(i, workers) == worker])
            if started is not None:                       # else its pieces are made here
                children[worker] = started
        for index in range(count):
            worker = owner(index, workers)
            text = None
            if worker in children:
                text = _receive(children[worker][1])
                if text is None:                          # the child is gone: on our own
                    _stop(*children.pop(worker))
            yield make(index) if text is None else text
    finally:
        for pid, read_end in children.values():
            _stop(pid, read_end)


def _start(make: Callable[[int], str], indices: list[int]) -> tuple[int, int] | None:
    """Fork a child making ``indices``: its pid and the pipe's read end; None if the
    system refuses a pipe or a process (too many processes, no memory)."""
    try:
        read_end, write_end = os.pipe()
    except OSError:
        return None
    _widen(write_end)
    try:
        pid = os.fork()
    except OSError:
        os.close(read_end)
        os.close(write_end)
        return None
    if pid == 0:                                          # the child never returns
        os.close(read_end)
        _child(make, indices, write_end)
    os.close(write_end)
    return pid, read_end


def _widen(pipe: int) -> None:
    """Let a child run a few pieces ahead: a pipe holds 64 KB by default, so a child
    would wait for each piece to be read before making the next. Up to the system's
    limit for a user (1 MB by default); left as it is where that is refused."""
    try:
        import fcntl
        fcntl.fcntl(pipe, fcntl.F_SETPIPE_SZ, PIPE_BYTES)
    except (ImportError, AttributeError, OSError):
        pass


def _child(make: Callable[[int], str], indices: list[int], write_end: int) -> None:
    """Make the pieces ``indices`` and send each, length first; then leave at once."""
    status = 1
    try:
        signal.signal(signal.SIGINT, signal.SIG_DFL)     # Ctrl-C ends a child quietly
        with os.fdopen(write_end, "wb") as pipe:
            for index in indices:
                try:
                    data = make(index).encode("ascii")
                except Exception:                         # the parent makes it and reports
                    pipe.write(_LENGTH.pack(_FAILED))
                    break
                pipe.write(_LENGTH.pack(len(data)))
                pipe.write(data)
        status = 0
    finally:
        os._exit(status)


def _receive(read_end: int) -> str | None:
    """The next piece from a child; None if it failed or died before sending it whole."""
    try:
        head = _read_exactly(read_end, _LENGTH.size)
        if head is None:
            return None
        (length,) = _LENGTH.unpack(head)
        if length < 0:
            return None
        data = _read_exactly(read_end, length)
    except OSError:
        return None
    return None if data is None else data.decode("ascii")


def _read_exactly(fd: int, size: int) -> bytearray | None:
    buffer = bytearray(size)
    view = memoryview(buffer)
    got = 0
    while got < size:
        count = os.readv(fd, [view[got:]])
        if count == 0:
            return None
        got += count
    return buffer


def _stop(pid: int, read_end: int) -> None:
    """Kill and reap a child (it may have ended already) and close its pipe."""
    try:
        os.kill(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    try:
        os.waitpid(pid, 0)
    except ChildProcessError:
        pass
    os.close(read_end)
