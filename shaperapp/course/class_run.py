"""One student's course design, written in a worker process (``shaper class``, issue 41).

Each student's folder gets ``design.shaper.json`` and the course design of ``shaper course``
(``write_course``, the same code), each file atomically, then a stamp naming what they
were made from. A student whose stamp matches and whose files are all there is complete
and current and is not made again, so a class killed half-way is finished by a rerun. The
stamp goes first, before any file is replaced, so a run killed in a student's middle
leaves no stamp claiming the mix of old and new files.

Students run in forked worker processes (``multiprocessing``'s Pool, made before this
process starts Qt, so each worker starts its own); ``jobs`` 1 runs them here.
"""
from __future__ import annotations

import functools
import hashlib
import json
import os
import time
from itertools import islice
from dataclasses import dataclass, field
from typing import Any, Iterator, Sequence

from core.files.atomic import atomic_write, remove_stale_temps
from core.course_design.plan import PARTS, file_names
from core.version import source_fingerprint, version_text

DESIGN_FILE = "design.shaper.json"
STAMP_FILE = ".class-stamp"
STATES = ("written", "up to date")      # what ``shaper class`` says of a student it did not fail


def student_line(name: str, skipped: bool, seconds: float) -> str:
    """The line ``shaper class`` prints on stdout for a student written (or current, so
    not written again): the Class dialog reads each row's outcome from it."""
    return f"{name}  {STATES[skipped]}  {seconds:.1f} s"


def student_outcome(line: str, names: Sequence[str]) -> tuple[str, str] | None:
    """(name, state) of a line ``student_line`` wrote for one of ``names``, else None."""
    for name in names:
        for state in STATES:
            head = f"{name}  {state}  "
            if line.startswith(head) and line.endswith(" s") and line[len(head):-2].replace(".", "", 1).isdigit():
                return name, state
    return None


def failure_line(name: str, reason: str) -> str:
    """A failed student's error as ``Result.error`` holds it (printed after "shaper: error: ")."""
    return f"{name}: {reason}"


@dataclass(frozen=True)
class Job:
    """What one student's folder is made from (sent to a worker: plain values only)."""

    index: int
    folder: str               # the student's folder, DIR/<number>-<student>
    name: str                 # its name, as the answer key lists it
    design_text: str          # design.shaper.json's text
    lang: str
    paper: str
    dxf: bool
    title: str
    date: str
    cover: dict[str, str] = field(default_factory=dict)   # student, number, group, school, supervisor
    cad_font: str = "gb"      # how the DXFs write their texts (--cad-font)


@dataclass(frozen=True)
class Result:
    index: int
    seconds: float
    entry: dict[str, Any] | None        # the student's answer-key object; None on failure
    error: str = ""
    skipped: bool = False               # complete and current: not written again
    removed: tuple[str, ...] = ()       # an earlier run's DXFs this run does not make


@functools.cache
def made_by() -> str:
    """The program that makes the files: its version and its code's fingerprint (once a
    process; a forked worker inherits it). The version alone stays the same from one fix
    to the next, and a rerun then kept the students' files the fix would have changed."""
    return f"{version_text('shaper')} {source_fingerprint('core', 'shaperapp', 'shaperapp.resources')}"


def stamp_of(job: Job) -> str:
    """What the folder's files depend on, hashed: the design, the options, the program."""
    made = {"design": job.design_text, "lang": job.lang, "paper": job.paper, "dxf": job.dxf,
            "title": job.title, "date": job.date, "cover": job.cover, "cad_font": job.cad_font,
            "version": made_by()}
    return hashlib.sha256(json.dumps(made, sort_keys=True, ensure_ascii=False).encode()).hexdigest()


def expected_files(job: Job) -> list[str]:
    return [DESIGN_FILE] + [name for _, name in file_names(PARTS, job.dxf)]


def is_current(job: Job) -> bool:
    """The folder holds every file, made from exactly this job (its stamp)."""
    try:
        with open(os.path.join(job.folder, STAMP_FILE), encoding="utf-8") as handle:
            if handle.read().strip() != stamp_of(job):
                return False
    except (OSError, UnicodeDecodeError):
        return False
    return all(os.path.isfile(os.path.join(job.folder, name)) for name in expected_files(job))


class ClassBusy(RuntimeError):
    """Another ``shaper class`` is writing into the same folder."""


def lock_class(out: str) -> int | None:
    """Hold the folder ``out`` for this run: an exclusive ``flock`` on the folder itself
    (no file left in it), which the system drops when the process ends, a kill included;
    ClassBusy if another run holds it. Returns the descriptor to close at the end. Two
    runs into one folder at once wrote each other's students (a rerun with a changed
    table and the first run, still going): the first run's answer key listed the second
    run's crank for a student its own table gave another. None where there is no
    ``flock`` (Windows) or the folder cannot be opened (its writes then fail by name)."""
    try:
        import fcntl
    except ImportError:
        return None
    try:
        handle = os.open(out, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        return None
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        os.close(handle)
        raise ClassBusy(out) from None
    except OSError:                 # a file system without locks: not held
        pass
    return handle


def earlier_folders(out: str, made: set[str]) -> list[str]:
    """The folders in ``out`` that an earlier run made (they hold a stamp) and this one did
    not (``made``: the folders of this table's good rows): a student whose row is now bad
    or gone. They are left as they were, complete but from other data and in no answer key
    of this run, so the run names them; the teacher found a bad row's folder from the run
    before, whole and stamped, beside the new ones and nothing said which was which."""
    try:
        entries = list(os.scandir(out))
    except OSError:
        return []
    return sorted(e.name for e in entries if e.name not in made and e.is_dir(follow_symlinks=False)
                  and os.path.isfile(os.path.join(e.path, STAMP_FILE)))


_LANGUAGE: list[str] = []


def _language(lang: str) -> str:
    """This process's Qt, started once for all its students."""
    if not _LANGUAGE:
        from shaperapp.widgets.command_line import start_qt
        _LANGUAGE.append(start_qt(lang))
    return _LANGUAGE[0]


def write_student(job: Job) -> tuple[str, ...]:
    """The folder's files, each atomically, the stamp last (OSError names the file); the
    names of the earlier run's DXFs it removed (a run without --dxf after one with it left
    them beside the new PDFs, drawn for the row's earlier data, and stamped the folder as
    current)."""
    from core.course_design.plan import plan_course, read_document
    from shaperapp.report.kept_views import keep_plot_views

    from .write import Covering, write_course
    language = _language(job.lang)
    keep_plot_views()            # the students' reports draw their plots with the same widgets
    os.makedirs(job.folder, exist_ok=True)
    stamp = os.path.join(job.folder, STAMP_FILE)
    if os.path.lexists(stamp):
        os.remove(stamp)
    wanted = set(expected_files(job))
    removed = []
    for _, name in file_names(PARTS, dxf=True):
        path = os.path.join(job.folder, name)
        if name not in wanted and os.path.isfile(path):
            os.remove(path)
            removed.append(name)
    design = os.path.join(job.folder, DESIGN_FILE)
    atomic_write(design, job.design_text)
    doc, keys = read_document(design)
    course = plan_course(doc, keys, DESIGN_FILE, job.folder, dxf=job.dxf)
    for _ in write_course(course, language, Covering(job.paper, job.title, job.date, dict(job.cover),
                                                             cad_font=job.cad_font)):
        pass
    atomic_write(stamp, stamp_of(job) + "\n")
    return tuple(removed)


def run_student(job: Job) -> Result:
    """Write one student's folder unless it is current, and its answer-key object; any
    failure is the Result's one-line error (never a traceback out of a worker)."""
    from core.cli.answers import answer_entry
    start = time.perf_counter()
    try:
        skipped = is_current(job)
        removed: tuple[str, ...] = ()
        if skipped:                 # a run killed mid-save may have left its temporary files
            for name in (*expected_files(job), STAMP_FILE):
                remove_stale_temps(os.path.join(job.folder, name))
        else:
            removed = write_student(job)      # each atomic write removes its target's stale ones
        entry = answer_entry(job.cover.get("student", ""), job.cover.get("number", ""), job.name,
                             os.path.join(job.folder, DESIGN_FILE))
        return Result(job.index, time.perf_counter() - start, entry, skipped=skipped, removed=removed)
    except FileExistsError:         # makedirs: "cannot write …: File exists" said nothing of a folder
        error = failure_line(job.name, f"cannot make the folder {job.folder}: a file of that name is in the way; "
                                       "move it, then run the class again")
    except OSError as exc:          # a WriteError names its file; a bare one ('[Errno 1] …') in plain words
        from core.base.errors import WriteError
        error = failure_line(job.name, str(exc if isinstance(exc, WriteError)
                                           else WriteError(exc.filename or job.folder, exc)))
    except Exception as exc:        # a font, a drawing that cannot be made: named, never raised
        error = failure_line(job.name, f"{type(exc).__name__}: {exc}")
    return Result(job.index, time.perf_counter() - start, None, error)


def _preload() -> None:
    """Import, before the fork, the modules every worker needs (the course writer, the
    report, the sheets, the DXF writer, the five commands of the answer key): imported
    once here, their pages are shared by the forked workers instead of being read and
    compiled again in each (about 1 s a worker). Qt's modules are imported, not started:
    each worker starts its own application."""
    from importlib import import_module
    from core.cli.answers import COMMANDS
    for name in ("shaperapp.course.write", "shaperapp.report.content", "shaperapp.drawing.content",
                 "core.drawing.sheet_dxf", "ezdxf", *(f"core.cli.cmd_{c}" for c in COMMANDS)):
        import_module(name)
    made_by()          # the code's fingerprint, once for every worker


def run_jobs(jobs: Sequence[Job], workers: int) -> Iterator[Result]:
    """Every job's Result as it finishes, on ``workers`` processes (1: in this one). A job
    is handed to a worker only when one is free, so an interrupt (Ctrl+C; the GUI's Cancel
    sends SIGINT to this process alone) starts nothing new and waits for the students being
    written, whose files are then complete, before it goes on."""
    if workers <= 1 or len(jobs) <= 1:
        try:
            for job in jobs:
                yield run_student(job)
        finally:
            if _LANGUAGE:           # this process goes on (and ends) without them
                from shaperapp.report.kept_views import release_plot_views
                release_plot_views()
        return
    import multiprocessing
    from collections import deque
    _preload()
    waiting = iter(jobs)
    with multiprocessing.get_context("fork").Pool(workers) as pool:
        running = deque(pool.apply_async(run_student, (job,)) for job in islice(waiting, workers))
        try:
            while running:
                done = next((r for r in running if r.ready()), None)
                if done is None:
                    running[0].wait(0.05)
                    continue
                running.remove(done)
                job = next(waiting, None)
                if job is not None:
                    running.append(pool.apply_async(run_student, (job,)))
                yield done.get()
        except KeyboardInterrupt:
            for result in running:
                result.wait()
            raise
