"""``shaper drawing --content scheme``: the mechanism alone for CAD, at a crank angle.

No sheet, no Qt: the DXF comes from :mod:`core.drawing.scheme`. ``shaper drawing``
adds :func:`add_scheme_options` to its options and hands ``--content scheme`` to
:func:`write_scheme_file`, which checks every word before anything is written.
"""
from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from core.cli.common import number
from core.cli.output import OutputError, cad_font_from_args
from shaperapp.widgets.command_line import check_output_folder

if TYPE_CHECKING:
    from core.linkage.geometry import Design

SCHEME = "scheme"


def add_scheme_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--angle", metavar="DEG", default="0",
                        help="with --content scheme: the crank angle φ it is drawn at, 0 to 360 "
                             "degrees (default 0, the limit position that starts the cut)")


def write_scheme_file(design: Design, args: argparse.Namespace) -> int:
    """The scheme at ``--angle`` to ``--output`` (a .dxf name), its texts in ``--cad-font``:
    DesignError naming --angle, OutputError naming --output, UsageError naming --cad-font
    (no CJK font for outline), and nothing written, for bad words."""
    from core.drawing.scheme import check_angle, write_scheme   # ezdxf: not for --help
    angle = check_angle(number("angle", args.angle))
    target = Path(args.output)
    if target.suffix.lower() != ".dxf":
        raise OutputError(f"--output: the scheme is written as DXF: the file name must end in "
                          f".dxf (got {target.name!r})")
    check_output_folder(args.output)
    cad_font = cad_font_from_args(args, writes_dxf=True)
    try:
        write_scheme(design, angle, target, cad_font)
    except OSError as exc:      # a WriteError: names the path and a plain reason
        raise OutputError(f"--output: {exc}") from None
    print(f"wrote {target} (scheme at φ = {angle:g}°, 1:1 in mm, DXF)")
    return 0
