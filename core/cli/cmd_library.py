"""``shaper library``: keep, find, export and compare designs in a design library.

One subcommand with its own sub-subcommands (add, list, show, remove, rename,
export, import, compare, backup, refresh, check); every one takes ``--library PATH`` (or
``$SHAPER_LIBRARY``). The work is in ``core.library*`` and ``core.space.compare``;
this module only parses, calls and prints.
"""
from __future__ import annotations

import argparse
import json
import os
import stat
import sys
from pathlib import Path
from typing import Any

from core.library.files import export_entries, import_entries, read_design_files
from core.library.names import storable
from core.library.open import library_exists
from core.library.query import QueryError
from core.library.backup import backup_copy
from core.library.store import ENV_VAR, LibraryError

from core.base.errors import DesignError, FileFormatError, os_reason
from core.space.figures import DESIGN_FIGURES, SPEED_FIGURES
from core.base.text import terminal_text
from ..library import Entry, Library
from ..library.entry import too_fine
from .cmd_library_check import check_options, run_check
from .cmd_library_compare import compare_options, run_compare
from .cmd_library_list import filter_help, list_options, run_list
from .cmd_library_refresh import refresh_options, run_refresh
from .common import (Parser, UsageError, add_design_options, add_load_options, NOTES, add_speed_options,
                     design_file, fail, library_path, note_read_only, number, rpms_from_args, spec_from_args)
from .loads import masses_or_none
from .output import OutputError, print_json

HELP = "keep, find, export and compare designs in a library"
DESCRIPTION = ("A design library: named designs with notes, tags and their key figures, in one "
               "SQLite file (--library PATH, or $SHAPER_LIBRARY, or the per-user default). "
               "Filter with --where 'K>=1.4,variant=rod,name~cut' (the syntax: "
               "shaper library list --help). Each action has its own --help with an example.")
EXAMPLES = ("shaper library add --crank 100 --K 1.4 --stroke 300 --name base --notes 'first try'",
            "shaper library list --sort a_max --where 'variant=rod,K>=1.4' --rpm 60",
            "shaper library compare base rod-1.6 --rpm 60 --csv compare.csv")


def configure(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="library_command", metavar="ACTION", parser_class=Parser)
    for name, help_text, build in ACTIONS:
        epilog = ("example:\n  " + ACTION_EXAMPLES[name]
                  + ("\n\n" + filter_help() if name == "list" else ""))
        p = sub.add_parser(name, help=help_text, description=help_text, epilog=epilog,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        p.add_argument("--library", metavar="PATH",
                       help=f"the library file (default: ${ENV_VAR}, else the per-user library)")
        build(p)
    parser.set_defaults(_library_parser=parser)


def _add_options(p: argparse.ArgumentParser) -> None:
    add_design_options(p)
    add_speed_options(p)
    p.add_argument("--step", metavar="DEG", help="angle step saved with the design (default 1, or the file's)")
    add_load_options(p, required=False)
    p.add_argument("--name", required=True, help="the entry's name (unique in the library)")
    p.add_argument("--notes", default="", help="free text kept with the design")
    p.add_argument("--tags", nargs="+", default=[], metavar="TAG", help="tags for filtering (tag=TAG)")
    p.add_argument("--replace", action="store_true", help="replace an entry of the same name")


def _name_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("name", metavar="NAME")


def _show_options(p: argparse.ArgumentParser) -> None:
    _name_option(p)
    p.add_argument("--json", action="store_true", help="print JSON (with the design document)")


def _rename_options(p: argparse.ArgumentParser) -> None:
    _name_option(p)
    p.add_argument("new_name", metavar="NEW_NAME")


def _export_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("name", metavar="NAME", nargs="?")
    p.add_argument("-o", "--output", metavar="FILE", required=True,
                   help="the design file to write (with --all: a folder)")
    p.add_argument("--all", action="store_true", help="export every entry into the folder -o")
    p.add_argument("--step", metavar="DEG", help="the crank-angle step the file gets, in ° (one NAME "
                   "only): an entry stored before the design file's sample limit, at a step it holds")


def _import_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("files", metavar="FILE", nargs="+", help="design files, or folders of them")
    p.add_argument("--rename-duplicates", action="store_true",
                   help="name a design whose name is taken 'NAME (2)' instead of refusing")
    p.add_argument("--skip-invalid", action="store_true",
                   help="import the valid files and list the others instead of refusing all")


def _backup_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("-o", "--output", metavar="FILE", help="where to write the copy "
                   "(default: beside the library, NAME.backup-TIME)")


# ---- running -------------------------------------------------------------------
def run(args: argparse.Namespace) -> int:
    if args.library_command is None:
        args._library_parser.print_help()
        return 0
    NOTES.clear()
    try:
        _check_text(args)
        status = ACTION_RUN[args.library_command](args)
        for note in NOTES:
            print(note, file=sys.stderr)
        return status
    except LibraryError as exc:
        return _library_failure(args, exc)
    except QueryError as exc:
        return fail(f"--where: {exc}")
    except FileFormatError as exc:          # a design file given to add, or a damaged entry
        return fail(f"{'--design' if args.library_command == 'add' else 'NAME'}: {exc}")


# text arguments stored in or matched against the library (paths are not: any bytes are a path)
_TEXT_ARGUMENTS = (("name", "NAME"), ("new_name", "NEW_NAME"), ("names", "NAME"), ("notes", "--notes"),
                   ("tags", "--tags"), ("where", "--where"), ("search", "--search"), ("sort", "--sort"))


def _check_text(args: argparse.Namespace) -> None:
    """Refuse text SQLite cannot store: bytes that are not UTF-8 in the command line reach
    Python as lone surrogates, which no UTF-8 text can hold."""
    for dest, option in _TEXT_ARGUMENTS:
        value = getattr(args, dest, None)
        for text in value if isinstance(value, list) else [value]:
            if isinstance(text, str) and not storable(text):
                shown = "--name" if (dest, args.library_command) == ("name", "add") else option
                raise UsageError(f"{shown}: {text.encode('utf-8', 'replace').decode()!r} holds bytes "
                                 "that are not UTF-8 text")


# the argument a name problem is reported against, per action
_NAME_ARGUMENT = {"add": "--name", "rename": "NEW_NAME", "import": "FILE"}


def _library_failure(args: argparse.Namespace, exc: LibraryError) -> int:
    return library_failure(exc, args.library, args.library_command)


def library_failure(exc: LibraryError, library: str | None, action: str,
                    name_option: str = "NAME") -> int:
    """Report ``exc`` as one line naming the option at fault (``name_option`` for an entry
    name that is missing, ``--library`` for the file); returns the exit status."""
    if exc.kind == "tag":
        return fail(f"--tags: {exc}")
    if exc.kind == "notes":
        return fail(f"--notes: {exc}")
    if exc.kind in ("name", "exists"):
        hint = " (or use --rename-duplicates)" if action == "import" else ""
        return fail(f"{_NAME_ARGUMENT.get(action, name_option)}: {exc}{hint}")
    if exc.kind == "entry":
        return fail(f"{name_option}: {exc}")
    if exc.kind == "missing" and exc.path is not None and exc.path.exists():
        return fail(f"{name_option}: {exc} (see 'shaper library list')")
    source = "--library" if library else (f"--library (from ${ENV_VAR})" if os.environ.get(ENV_VAR)
                                          else "--library (default)")
    hint = ""
    if exc.refused_file:
        import shlex                # a path holding ' broke the command printed in quotes
        hint = f"; keep a copy with: shaper library backup --library {shlex.quote(str(exc.path))}"
    return fail(f"{source}: {exc}{hint}", status=1 if exc.kind in ("io", "busy") else 2)


_READING = ("list", "show", "export", "compare", "check", "backup")


def _open(args: argparse.Namespace, create: bool = True) -> Library:
    """The library, checked; a read-only one gets a note on stderr when only read (a write
    to it is refused in one line saying why)."""
    lib = Library(library_path(args.library), create=create)
    if args.library_command in _READING:
        note_read_only(lib)
    return lib


def _run_add(args: argparse.Namespace) -> int:
    from core.linkage.kinematics import check_file_samples, check_rpms
    spec = spec_from_args(args)
    design = spec.design()
    rpms = [float(r) for r in check_rpms(rpms_from_args(args))]
    doc = design_file(args)
    step = number("step", args.step) if args.step is not None else (doc["step_deg"] if doc else 1.0)
    check_file_samples(step, len(rpms))      # what the library keeps is a design file
    masses = masses_or_none(args, design)
    loaded: dict[str, Any] = dict(doc) if doc is not None else {}
    loaded.update(spec=spec, rpm=rpms, step_deg=float(step), masses=masses)
    with _open(args) as lib:
        entry = lib.add(args.name, loaded, notes=args.notes, tags=args.tags, replace=args.replace)
    print(f"{'saved' if args.replace else 'added'} {entry.name!r} to {lib.path}")
    return 0


def _entry_document(entry: Entry) -> dict[str, Any]:
    f = entry.figures
    return {"name": entry.name, "notes": entry.notes, "tags": list(entry.tags),
            "created": entry.created, "modified": entry.modified,
            "figures_version": entry.figures_version, "figures_current": entry.figures_current,
            **f.design_values(),
            "speeds": [s.__dict__ for s in f.speeds], "document": json.loads(entry.text)}


def _run_show(args: argparse.Namespace) -> int:
    from core.base.figure_text import value_text
    with _open(args, create=False) as lib:
        entry = lib.get(args.name)
    try:
        entry.document()      # a document that cannot be opened is refused, as compare and export do
    except FileFormatError as exc:
        fine = too_fine(exc)
        if fine is None:
            raise
        return fail(f"NAME: {_too_fine_text(args, entry.name, fine, '')}")
    if args.json:
        print_json(_entry_document(entry))
        return 0
    f = entry.figures
    rows = [("name", entry.name), ("notes", entry.notes or "—"), ("tags", ", ".join(entry.tags) or "—"),
            ("created", entry.created), ("modified", entry.modified), ("variant", f.variant)]
    if not entry.figures_current:
        rows.append(("figures", "computed by an older version; 'shaper library refresh' recomputes them"))
    if f.rod_side:
        rows.append(("rod side", f.rod_side))
    rows += [(key, value_text(getattr(f, key), key)) for key, _, _, _ in DESIGN_FIGURES]
    width = max(len(k) for k, _ in rows)
    for key, value in rows:       # the file's texts escaped: an ESC in a note drove the terminal
        print(f"{key:<{width}}  {terminal_text(value, multi_line=key == 'notes')}")
    for s in f.speeds:
        print(f"\n{s.rpm:g} r/min")
        for key, _, _, _ in SPEED_FIGURES:
            print(f"  {key:<24}  {value_text(getattr(s, key), key)}")
    return 0


def _run_remove(args: argparse.Namespace) -> int:
    with _open(args, create=False) as lib:
        lib.remove(args.name)
    print(f"removed {args.name!r}")
    return 0


def _run_rename(args: argparse.Namespace) -> int:
    with _open(args, create=False) as lib:
        lib.rename(args.name, args.new_name)
    print(f"renamed {args.name!r} to {args.new_name.strip()!r}")
    return 0


def _run_export(args: argparse.Namespace) -> int:
    if args.all == (args.name is not None):
        raise UsageError("NAME: give one entry name, or --all with a folder")
    if not args.output.strip():
        raise UsageError("-o: the path is empty")
    if args.step is not None and args.all:
        raise UsageError("--step: give it with one entry NAME, not with --all")
    step = number("step", args.step) if args.step is not None else None
    with _open(args, create=False) as lib:
        try:
            if args.all:
                done = export_entries(lib, args.output)
                for name, why in done.skipped:
                    fine = too_fine(why)
                    print(f"shaper: skipped {name!r}: "
                          f"{why if fine is None else _too_fine_text(args, name, fine, '')}", file=sys.stderr)
                print(f"exported {len(done.paths)} designs to {args.output}")
            else:
                lib.export(args.name, args.output, step)
        except OSError as exc:
            raise OutputError(f"-o: cannot write {args.output}: {exc.strerror or exc}") from None
        except FileFormatError as exc:
            fine = too_fine(exc)
            cause = getattr(exc, "cause", None)
            if fine is None and step is not None and isinstance(cause, DesignError) and cause.parameter == "step":
                return fail(f"--step: {cause.allowed} (got {args.step})")     # it named NAME, not the step typed
            if fine is None:
                raise
            return fail(f"{'NAME' if step is None else '--step'}: {_too_fine_text(args, args.name, fine, args.output)}")
    return 0


def _too_fine_text(args: argparse.Namespace, name: str, fine, output: str) -> str:
    """What an entry stored before the design file's sample limit is, and the command that
    exports it: the same library and file with the coarsest step that fits (a test runs it)."""
    import shlex
    library = f" --library {shlex.quote(args.library)}" if args.library is not None else ""
    return (f"{name!r} is too fine for a design file ({fine.samples} samples, angles × speeds, at a "
            f"step of {fine.value:g}°; the limit is {fine.limit}); export it at a coarser step: "
            f"shaper library export {shlex.quote(name)}{library} --step {fine.coarsest:g} "
            f"-o {shlex.quote(output or 'FILE')}")


def _run_import(args: argparse.Namespace) -> int:
    good, bad = read_design_files(args.files)
    if bad and not args.skip_invalid:
        path, why = bad[0]
        return fail(f"FILE: {why}; nothing was imported" + (f" ({len(bad) - 1} more refused)" if len(bad) > 1 else ""))
    with _open(args) as lib:
        entries = import_entries(lib, good, rename_duplicates=args.rename_duplicates) if good else []
    for path, why in bad:
        print(f"shaper: skipped {why}", file=sys.stderr)
    print(f"imported {len(entries)} design{'s' if len(entries) != 1 else ''}"
          + (": " + ", ".join(e.name for e in entries) if entries else ""))
    return 0


def _run_backup(args: argparse.Namespace) -> int:
    path = library_path(args.library)
    if not library_exists(path):
        raise LibraryError("missing", f"there is no design library at {path}", path)
    if args.output is not None:
        _check_backup_output(args.output)
    try:
        lib: Library | None = Library(path, create=False)
    except LibraryError as exc:
        if not (exc.refused_file or exc.kind == "io"):
            raise
        lib = None                      # a file that cannot be opened: copied byte for byte
    try:
        if lib is None:
            target = backup_copy(path, args.output)
        else:
            with lib:
                target = lib.backup(args.output)
    except LibraryError as exc:                      # writing the copy failed
        if args.output is None or exc.kind != "io":
            raise
        raise OutputError(f"--output: {exc}") from None
    # a copy written to standard output, a pipe or a device must not get this line mixed in
    special = os.path.abspath(target).startswith(("/dev/", "/proc/")) or not os.path.isfile(target)
    print(f"copied {path} to {target}", file=sys.stderr if special else sys.stdout)
    return 0


def _check_backup_output(text: str) -> None:
    """Refuse, naming ``--output``, a copy's path that cannot name a file: empty, a folder,
    in a missing folder, too long, a link loop (a pipe or a link is fine: written through)."""
    if not text.strip():
        raise UsageError(f"--output: {text!r} is not a file name")
    out = Path(text)
    folder = out.parent if str(out.parent) else Path(".")
    try:
        if stat.S_ISDIR(os.stat(out).st_mode):
            raise UsageError(f"--output: {out} is a folder; name the copy's file")
    except FileNotFoundError:
        if not folder.is_dir():
            raise UsageError(f"--output: cannot write {out}: the folder {folder} does not exist") from None
    except OSError as exc:
        raise UsageError(f"--output: cannot write {out}: {os_reason(exc)}") from None


def _run_refresh(args: argparse.Namespace) -> int:
    with _open(args, create=False) as lib:
        return run_refresh(args, lib)


ACTIONS = (
    ("add", "store a design (from options or --design FILE) under a name", _add_options),
    ("list", "list, filter and sort the designs", list_options),
    ("show", "one design's notes, figures and (with --json) document", _show_options),
    ("remove", "delete a design from the library", _name_option),
    ("rename", "give a design a new name", _rename_options),
    ("export", "write a design as a design file (or all, with --all)", _export_options),
    ("import", "add design files (or folders of them) named after the files", _import_options),
    ("compare", "compare 2 to 6 designs at one speed: figure table and curves", compare_options),
    ("backup", "copy the library file (also one that cannot be opened)", _backup_options),
    ("refresh", "recompute the figures an older version of the program stored", refresh_options),
    ("check", "list the designs whose stored values are damaged (exit 1 if any)", check_options),
)
ACTION_EXAMPLES = {
    "add": "shaper library add --crank 100 --K 1.4 --stroke 300 --rpm 40 60 --name base --tags course",
    "list": "shaper library list --where 'variant=rod, K>=1.4, a_max<5' --sort a_max --rpm 60",
    "show": "shaper library show base --json",
    "remove": "shaper library remove old-try",
    "rename": "shaper library rename base base-K1.4",
    "export": "shaper library export base -o base.shaper.json",
    "import": "shaper library import designs/ --skip-invalid",
    "compare": "shaper library compare base rod-1.6 --rpm 60 --csv compare.csv",
    "backup": "shaper library backup -o library-copy.sqlite",
    "refresh": "shaper library refresh --all",
    "check": "shaper library check --library designs.sqlite",
}
ACTION_RUN = {"add": _run_add, "list": lambda args: run_list(args, _open), "show": _run_show, "remove": _run_remove,
              "rename": _run_rename, "export": _run_export, "import": _run_import,
              "compare": run_compare, "backup": _run_backup, "refresh": _run_refresh,
              "check": lambda args: run_check(args, lambda: _open(args, create=False))}
