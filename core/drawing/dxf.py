"""DXF documents that open and print the same in any CAD program.

Every drawing this tool writes as DXF (the drawing sheets, the scheme for CAD,
the cam profile) starts from :func:`new_document`, so they share one set of
layers, linetypes and a text style: a CAD user who turns off the dimensions in
one file knows their layer in all of them. Lengths are millimetres
(``$INSUNITS`` = 4), at 1:1 on the paper (sheets) or in model space (scheme).

Layers follow the line types of GB/T 4457.4 and the colours of GB/T 14665
(thick continuous green, thin continuous white, dashed yellow, centre lines
red). Linetypes are defined here in mm after GB/T 4457.4 for a thick line of
d = 0.5 mm (dash 12d, gap 3d; long dash 24d, gap 3d, dot 0.5d), not taken from
ezdxf's inch-based set, so that a drawing at 1:1 in mm shows the standard's
dashes with ``$LTSCALE`` = 1.
"""
from __future__ import annotations

import io
import os
from dataclasses import dataclass
from typing import TYPE_CHECKING

from core.files.atomic import atomic_write

if TYPE_CHECKING:
    from ezdxf.document import Drawing

DXF_VERSION = "R2010"        # UTF-8 text, lineweights, read by AutoCAD 2010+, LibreCAD, QCAD
MILLIMETRES = 4              # $INSUNITS
THICK_MM = 0.5               # d of GB/T 4457.4 for these drawings; thin lines are d/2

CENTER_LINETYPE = "GB_CENTER"
DASHED_LINETYPE = "GB_DASHED"
# (description, pattern in mm: total length, then dashes > 0, gaps < 0, dots 0)
LINETYPES = {
    CENTER_LINETYPE: ("Centre line GB/T 4457.4 ____ . ____ . ____",
                      [15.25, 12.0, -1.5, 0.25, -1.5]),
    DASHED_LINETYPE: ("Dashed line GB/T 4457.4 __ __ __ __",
                      [7.5, 6.0, -1.5]),
}

OUTLINE = "OUTLINE"          # thick continuous: links, visible outlines, limit positions, border
THIN = "THIN"                # thin continuous: intermediate positions, curves, hatch, leaders
CENTER = "CENTER"            # thin dash-dot: centre lines, axes of symmetry, paths
DASHED = "DASHED"            # thin dashed: hidden or auxiliary lines
DIMENSIONS = "DIMENSIONS"    # dimension lines, extension lines and their texts
TEXT = "TEXT"                # notes, labels, tables' texts
TITLE = "TITLE"              # the title block


@dataclass(frozen=True)
class Layer:
    linetype: str
    lineweight: int          # 1/100 mm, one of DXF's standard weights
    color: int               # AutoCAD colour index


LAYERS: dict[str, Layer] = {
    OUTLINE: Layer("Continuous", 50, 3),
    THIN: Layer("Continuous", 25, 7),
    CENTER: Layer(CENTER_LINETYPE, 25, 1),
    DASHED: Layer(DASHED_LINETYPE, 25, 2),
    DIMENSIONS: Layer("Continuous", 25, 7),
    TEXT: Layer("Continuous", 25, 7),
    TITLE: Layer("Continuous", 25, 7),
}

TEXT_STYLE = "GB"
# The fonts Chinese CAD installations use for GB drawings (GB/T 18229): an upright Latin
# shape font and the big font with the Chinese characters. A program without them substitutes
# its own font; the text stays text.
TEXT_FONT = "gbenor.shx"
TEXT_BIGFONT = "gbcbig.shx"
UNICODE_STYLE = "wqy-unicode"
# The style of every text with a character beyond Latin-1 (Chinese, Greek, −, ′): the same
# fonts as GB for AutoCAD, ZWCAD and GstarCAD, which draw a text in its style's font files.
# LibreCAD 2.2 ignores those and draws a text in the LibreCAD font named like its *style*
# (lowercased; a name it lacks falls back to its standard font, which has no Chinese or Greek:
# the GB style's Chinese printed as dots, its Greek not at all). wqy-unicode.lff is the
# font with simplified Chinese and Greek that LibreCAD's own builds for Windows and macOS
# ship (Fedora and openSUSE make it from WenQuanYi Micro Hei with LibreCAD's ttf2lff);
# Debian's librecad-data 2.2.0 lacks it, and none of its 46 fonts has 61 of the sheets'
# 212 characters beyond ASCII (驱, 动, 转, 轮 …). Texts within Latin-1 stay in GB, which
# LibreCAD's standard font draws.
TEXT_HEIGHTS_MM = (2.5, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0)   # GB/T 14691's series
TEXT_WIDTH = 0.7                            # GB/T 14691's long-fang-song proportion


def new_document() -> Drawing:
    """An empty DXF document in mm with this tool's layers, linetypes and text style."""
    import ezdxf        # here, not with the module: the sheets' PDF, SVG and --help need none of it
    doc = ezdxf.new(DXF_VERSION, units=MILLIMETRES)
    doc.header["$MEASUREMENT"] = 1          # metric
    doc.header["$LTSCALE"] = 1.0
    doc.header["$LWDISPLAY"] = 1            # show lineweights: thick and thin lines differ
    for name, (description, pattern) in LINETYPES.items():
        doc.linetypes.add(name, pattern=pattern, description=description)
    for name, layer in LAYERS.items():
        doc.layers.add(name, color=layer.color, linetype=layer.linetype,
                       lineweight=layer.lineweight)
    for name in (TEXT_STYLE, UNICODE_STYLE):
        style = doc.styles.add(name, font=TEXT_FONT)
        style.dxf.bigfont = TEXT_BIGFONT
        style.dxf.width = TEXT_WIDTH        # what CAD gives text a user adds
    doc.header["$TEXTSTYLE"] = TEXT_STYLE
    return doc


def text_style(text: str) -> str:
    """The text style of a TEXT showing ``text``: GB within Latin-1, else
    :data:`UNICODE_STYLE` (the same fonts in AutoCAD; in LibreCAD, its font with Chinese
    and Greek, which the GB style's stand-in lacks)."""
    return TEXT_STYLE if all(ord(ch) <= 0xFF for ch in text) else UNICODE_STYLE


def text_attribs(layer: str = TEXT, text: str = "") -> dict[str, object]:
    """A TEXT entity's attributes: the layer, the style for ``text`` (:func:`text_style`),
    and the style's width factor on the entity itself. Why: CAD draws a TEXT at its own
    width factor (group 41, default 1), not its style's, so without it every text came out
    wider than the sheet's layout reckons, and a subscript ran into its letter."""
    return {"layer": layer, "style": text_style(text), "width": TEXT_WIDTH}


def literal_text(text: str) -> str:
    """``text`` as a DXF TEXT shows it literally: CAD reads "%%" and a letter as a control code
    (%%c is ⌀, %%d is °, %%u underlines), so a user's "%%" is written as "%%%" twice, which
    CAD shows as "%%"."""
    return text.replace("%%", "%%%%%%")


class DxfAuditError(RuntimeError):
    """The document failed ezdxf's audit: it would be refused or misread by CAD."""


def dxf_text(doc: Drawing) -> str:
    """The document as DXF text, after an audit that must find nothing to fix: a fix (an
    undefined linetype dropped, say) means this tool drew something CAD would not show."""
    auditor = doc.audit()
    found = auditor.errors + auditor.fixes
    if found:
        problems = "; ".join(str(entry.message) for entry in found[:3])
        raise DxfAuditError(f"the DXF document has {len(found)} fault(s): {problems}")
    stream = io.StringIO()
    doc.write(stream)
    return stream.getvalue()


def save_dxf(doc: Drawing, path: str | os.PathLike) -> None:
    """Write ``doc`` to ``path`` atomically (the old file or the whole new one).
    WriteError (an OSError naming the path) when it cannot be written; DxfAuditError when
    the document itself is faulty, before anything is written."""
    atomic_write(path, dxf_text(doc).encode("utf-8"))
