"""``shaper class``: a teacher's whole class through the course design in one run (issue 41).

Registered through the ``shaper.commands`` entry point like ``course`` (it paints with Qt).
The task table is read and every row checked first (``core.cli.tasks``): a table that
cannot be used at all is one line and nothing written; a bad row is one line naming its
line and column, its folder is not written, the others are, and the command exits 2 at
the end with the count. The students run in parallel (``class_run``), then the task
sheets and the answer key are written beside their folders (``class_files``).
"""
from __future__ import annotations

import argparse
import os
import sys
import time

from core.cli.common import UsageError, whole_number
from core.cli.notes import say_defaulted
from core.cli.output import OutputError, cad_font_from_args
from shaperapp.widgets.command_line import COVER_OPTIONS, cover_text

from .command import add_file_options, paper_of

HELP = "the course design of a whole class from a table of data sets: folders, task sheets, answer key"
DESCRIPTION = (
    "One row of TASKS.csv per student: the columns student and student-number (and class), "
    "and any design option named as the command line names it without its dashes (crank, K, "
    "stroke, dims, guide, rod-ratio, rpm with speeds separated by spaces, lever-mass, ram-mass, "
    "cut-force, cut-height, the cam's arm, swing, pressure, rise, dwell, return, the gear's z1, z2, "
    "module, centre …; 'shaper design --help' lists them), laid over --base, or a column design "
    "naming a design file beside the table. UTF-8 (with or without BOM) or GBK, comma or "
    "semicolon separated. For each student DIR/<student-number>-<student>/ gets "
    "design.shaper.json and the files of 'shaper course'; DIR gets tasks.pdf (one task sheet a "
    "student), answer-key.pdf, answer-key.csv and answer-key.json. A bad row is named with its "
    "line and column and its folder is not written (exit 2 at the end); a rerun does not redo a "
    "student whose files are complete and current.")
EXAMPLES = ("shaper class --tasks tasks.csv --base base.shaper.json -o 机械2101",
            "shaper class --tasks tasks.csv --base base.shaper.json --lang zh --sheet A1 --dxf "
            "--jobs 2 --school 机械工程学院 --supervisor 李四 -o 机械2101")
MEMORY_MB = 600
"""The whole run's memory: the workers are as many as fit in it (``WORKER_MB`` each)."""
WORKER_MB = 250
PARENT_MB = 100


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--tasks", required=True, metavar="TASKS.csv", help="one row per student")
    parser.add_argument("-o", "--output", required=True, metavar="DIR",
                        help="the class's folder (made, with its parents, if missing)")
    parser.add_argument("--base", metavar="DESIGN.json",
                        help="a design file whose values every row shares (the cam, the gear, the loads …)")
    add_file_options(parser)
    parser.add_argument("--jobs", metavar="N", help="students at once (default: the number of cores, "
                        f"at most as many as fit in {MEMORY_MB} MB)")
    block = parser.add_argument_group("cover and title blocks (a row's student, number and class win)")
    block.add_argument("--title", metavar="TEXT", help="design name (default: the student's folder)")
    for option in ("--school", "--supervisor", "--class"):
        block.add_argument(option, metavar="TEXT", help=COVER_OPTIONS[option][1])
    block.add_argument("--date", metavar="TEXT", help="the date (default: today, YYYY-MM-DD)")


def workers(text: str | None, students: int) -> int:
    """--jobs (default the cores), never more than the students or than fit in MEMORY_MB."""
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    wanted = cores if text is None else whole_number("--jobs", text, 1, 256)
    return max(1, min(wanted, students, (MEMORY_MB - PARENT_MB) // WORKER_MB))


def run(args: argparse.Namespace) -> int:
    import datetime

    from core.cli.tasks import TableError, read_tasks
    from core.files.design_file import load_design
    from core.base.errors import FileFormatError

    from .class_run import Job
    paper = paper_of(args)
    cad_font = cad_font_from_args(args, args.dxf)
    school, supervisor, group = (cover_text(o, getattr(args, o[2:])) for o in ("--school", "--supervisor", "--class"))
    title = cover_text("--title", args.title)
    date = cover_text("--date", args.date) or datetime.date.today().isoformat()
    if args.jobs is not None:
        whole_number("--jobs", args.jobs, 1, 256)
    if args.base is not None:
        try:
            say_defaulted("--base", args.base, load_design(args.base))
        except FileFormatError as exc:
            raise UsageError(f"--base: {exc}") from None
    try:
        students, encoding = read_tasks(args.tasks, args.base, group)
    except TableError as exc:
        raise UsageError(str(exc)) from None
    out = args.output
    writes = any(not s.error for s in students)
    try:
        if writes:              # a table of bad rows only writes nothing, not even an empty DIR
            os.makedirs(out, exist_ok=True)
    except FileExistsError:     # a file of that name ('File exists' said nothing of a folder)
        raise OutputError(f"--output: cannot write into {out}: it is not a folder") from None
    except OSError as exc:      # in the plain words of every other output ('File name too long')
        from core.base.errors import os_reason
        raise OutputError(f"--output: cannot make {out}: {os_reason(exc)}") from None
    if writes:                  # a folder it cannot write into: one line before any student
        from core.course_design.plan import CourseError, check_folder
        from .class_files import KEY_FILES, TASKS_FILE
        try:
            check_folder(out, [os.path.join(out, name) for name in (TASKS_FILE, *KEY_FILES)])
        except CourseError as exc:
            raise OutputError(str(exc)) from None
    from .class_run import ClassBusy, lock_class
    try:
        held = lock_class(out) if writes else None
    except ClassBusy:
        raise OutputError(f"--output: another 'shaper class' is writing into {out}; let it finish, "
                          "then run this one") from None
    if encoding != "UTF-8":
        print(f"shaper: note: {os.path.basename(args.tasks)} read as {encoding}", file=sys.stderr)
    bad = [s for s in students if s.error]
    for s in bad:
        print(f"shaper: error: {s.error}", file=sys.stderr, flush=True)
    good = [s for s in students if not s.error]
    from core.cli.cmd_design import design_text
    jobs = [Job(i, os.path.join(out, s.folder), s.folder, design_text(s.document), args.lang, paper, args.dxf,
                title or s.folder, date, {"student": s.name, "number": s.number, "group": s.group,
                                          "school": school, "supervisor": supervisor}, cad_font)
            for i, s in enumerate(good)]
    try:
        return _run(args, out, good, jobs, bad)
    finally:
        if held is not None:
            os.close(held)


def _run(args, out, good, jobs, bad_rows) -> int:
    from .class_run import earlier_folders, run_jobs, student_line
    bad = len(bad_rows)
    start = time.perf_counter()
    count = workers(args.jobs, len(jobs))
    entries: dict[int, dict] = {}
    failed = 0
    for result in run_jobs(jobs, count):
        job = jobs[result.index]
        if result.error:
            failed += 1
            print(f"shaper: error: {result.error}", file=sys.stderr, flush=True)
            continue
        entries[result.index] = result.entry
        print(student_line(job.name, result.skipped, result.seconds), flush=True)
        if result.removed:
            print(f"shaper: note: {job.folder}: removed {', '.join(result.removed)} of an earlier run, drawn from "
                  "its data; this run writes no DXF (--dxf)", file=sys.stderr, flush=True)
    done = sorted(entries)
    if good:        # a table of bad rows only has no task sheet nor answer to write
        _class_files(args, out, good, jobs, [entries[i] for i in done], [good[i].group for i in done])
        files = (f"tasks.pdf and answer-key.pdf, .csv, .json in {out}" if done else
                 f"tasks.pdf in {out}; no answer key, as no student was written (an earlier one is left as it was)")
        print(f"{len(done)} students in {time.perf_counter() - start:.1f} s ({count} at once); {files}")
    lines = {s.folder: s.line for s in bad_rows}
    tasks = os.path.basename(args.tasks)
    for folder in earlier_folders(out, {s.folder for s in good}):
        why = f"its row, line {lines[folder]}, is bad" if folder in lines else f"{tasks} has no row for it"
        print(f"shaper: note: {os.path.join(out, folder)} holds an earlier run's files, not made from this "
              f"table ({why}) and not in its answer key; left as it was", file=sys.stderr)
    if bad or failed:
        print(f"shaper: error: {bad + failed} of {bad + len(jobs)} students not written "
              f"({bad} bad rows, {failed} failed)", file=sys.stderr)
        return 2
    return 0


def _class_files(args, out, good, jobs, entries, groups) -> None:
    """tasks.pdf for every good row, the answer key of the students written (``entries``),
    none when no student was: a run whose every student failed (a full disk) replaced the
    earlier run's answer key with one of nobody, and the Class dialog said "Done"."""
    from shaperapp.widgets.command_line import start_qt
    language = start_qt(args.lang)
    from .class_files import TASKS_FILE, write_answer_key, write_tasks
    try:
        write_tasks(os.path.join(out, TASKS_FILE),
                    [(s.document, {"student": s.name, "number": s.number, "group": s.group, "date": job.date})
                     for s, job in zip(good, jobs)], language)
        if entries:
            write_answer_key(out, entries, groups, language)
    except OSError as exc:
        raise OutputError(f"--output: {exc}") from None
