"""Output of the ``shaper`` subcommands: tables, JSON, files, and a guarded stdout.

Every write failure becomes one line naming the option (or standard output), and
symbols a console cannot encode are spelled out instead of raising.
"""
from __future__ import annotations

import codecs
import json
import sys
from pathlib import Path
from typing import Any, Iterable

from core.base.errors import WriteError, os_reason
from core.files.atomic import atomic_write
from .common import UsageError


class OutputError(Exception):
    """An output file could not be written; the message names the option and path."""


class StdoutError(OutputError):
    """Standard output could not be written (a full disk, a closed descriptor)."""


_ASCII = {"θ": "theta", "²": "^2", "·": "*", "−": "-", "°": "deg", "Δ": "Delta", "δ": "delta",
          "≤": "<=", "≥": ">=", "→": "->", "φ": "phi", "ψ": "psi", "λ": "lambda", "…": "...",
          "×": "x", "μ": "u", "ω": "omega", "α": "alpha", "′": "'", "ε": "epsilon"}


def _ascii_fallback(error: UnicodeError) -> tuple[str, int]:
    if not isinstance(error, UnicodeEncodeError):
        raise error
    text = error.object[error.start:error.end]
    return "".join(_ASCII.get(ch, "?") for ch in text), error.end


codecs.register_error("shaper-ascii", _ascii_fallback)


def install_safe_output() -> None:
    """Symbols a console cannot encode (θ, ² …) are spelled out instead of crashing."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.reconfigure(errors="shaper-ascii")  # type: ignore[union-attr]
        except (AttributeError, ValueError, OSError):
            pass


def print_table(rows: list[tuple[str, str]]) -> None:
    width = max(len(k) for k, _ in rows)
    for key, value in rows:
        print(f"{key:<{width}}  {value}")


def print_json(document: Any) -> None:
    """JSON on stdout; refuses NaN/Infinity, which no JSON reader accepts (an undefined
    value must already be None, i.e. null)."""
    print(json.dumps(document, indent=2, allow_nan=False))


def write_output(option: str, target: str, text: str | Iterable[str]) -> None:
    """``text`` (a string or pieces of it) to stdout for ``-``, else to the file ``target``
    (atomically for a regular file, see ``core.files.atomic.atomic_write``)."""
    if target == "-":
        try:
            for piece in [text] if isinstance(text, str) else text:
                sys.stdout.write(piece)
            sys.stdout.flush()
        except StdoutError as exc:
            raise StdoutError(f"{option}: {exc}") from None
        return
    try:
        atomic_write(target, text)
    except OSError as exc:      # a WriteError: names the user's path and a plain reason
        raise OutputError(f"{option}: {exc}") from None


def check_target(option: str, target: str) -> None:
    """OutputError naming ``option`` when ``target`` cannot be a file to write, found before
    any work: its folder is missing, it is a folder, or the system refuses the path itself
    (a name too long, a part that is not a folder), in the words ``atomic_write`` uses.
    Standard output (``-``) is always fine."""
    if target == "-":
        return
    path = Path(target)
    try:
        if not (path.parent if str(path.parent) else Path(".")).is_dir():
            raise OutputError(f"{option}: cannot write {path}: no such directory")
        if path.is_dir():
            raise OutputError(f"{option}: cannot write {path}: it is a folder")
        path.exists()           # the name itself: ENAMETOOLONG, ELOOP …
    except OSError as exc:      # pathlib lets the errors other than "not found" through
        raise OutputError(f"{option}: {WriteError(target, exc)}") from None


class GuardedStdout:
    """sys.stdout for the length of one command: a failed write (a full disk, a closed
    descriptor) becomes a StdoutError, reported as one line instead of a traceback.
    BrokenPipeError passes through: the reader left, which is not an error."""

    def __init__(self, stream: Any) -> None:
        self._stream = stream

    def write(self, text: str) -> int:
        return self._guard("write", text)

    def flush(self) -> None:
        self._guard("flush")

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)

    def _guard(self, method: str, *args: Any) -> Any:
        if self._stream is None:      # started with stdout closed (``>&-``)
            raise StdoutError("cannot write to standard output: it is closed")
        try:
            return getattr(self._stream, method)(*args)
        except BrokenPipeError:
            raise
        except (OSError, ValueError) as exc:
            reason = os_reason(exc) if isinstance(exc, OSError) else "it is closed"
            raise StdoutError(f"cannot write to standard output: {reason}") from None


def add_cad_font_option(parser) -> None:
    """``--cad-font``, one option for every command that writes a drawing sheet as DXF."""
    from ..drawing import CAD_FONTS     # here, not at the top: output.py serves every command,
                                        # and `shaper curves` loads no drawing package
    parser.add_argument("--cad-font", choices=CAD_FONTS,
                        help="how the DXF writes its texts: gb (default), as text in the GB fonts "
                             "(gbenor.shx, gbcbig.shx) for AutoCAD and ZWCAD (LibreCAD: its "
                             "wqy-unicode font, where it has it); outline, as the "
                             "glyphs' filled outlines (Noto Sans CJK), which LibreCAD draws too, "
                             "not editable as text")


def cad_font_from_args(args, writes_dxf: bool) -> str:
    """``--cad-font`` checked before any work: UsageError when it is given and no DXF is
    written, or when "outline" finds no font with Chinese glyphs; "gb" when not given."""
    if args.cad_font is None:
        return "gb"
    if not writes_dxf:
        raise UsageError("--cad-font: only when a .dxf is written")
    if args.cad_font == "outline":
        from ..drawing.outline_text import OutlineFontMissing, outline_font
        try:
            outline_font()
        except OutlineFontMissing as exc:
            raise UsageError(f"--cad-font: {exc}") from None
    return args.cad_font


def add_lang_option(parser, texts: str) -> None:
    """``--lang``: the language of a DXF's ``texts`` (the gear's sheet, the cam's notes)."""
    parser.add_argument("--lang", choices=("en", "zh", "zh_CN"), help=f"language of {texts}: en, or "
                        "zh (= zh_CN) for Chinese (default en)")


def sheet_labels(lang: str, part: str) -> dict[str, str] | None:
    """The words of ``part``'s drawing ("gear", "cam": ``core.drawing.<part>_sheet.ENGLISH``'s
    keys) in ``lang``: None for English (core's own); else from the ``drawing`` command's
    module (the translations are Qt's, which core never imports), found through the
    ``shaper.commands`` entry points as ``core.cli`` finds that command. UsageError naming
    --lang when it is not installed."""
    if lang == "en":
        return None
    from importlib import import_module, metadata
    try:
        entry = next((e for e in metadata.entry_points(group="shaper.commands") if e.name == "drawing"), None)
        module = import_module(entry.value) if entry is not None else None
    except ImportError:
        module = None
    if module is None or not hasattr(module, "sheet_labels_in"):
        raise UsageError("--lang: Chinese texts need the GUI package (shaperapp, with PySide6) "
                         "installed; leave out --lang for English")
    return module.sheet_labels_in(lang, part)
