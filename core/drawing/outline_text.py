"""A DXF's texts as filled outlines of a TrueType font: ``--cad-font outline``.

Why: a DXF text names its font by the text style, and the GB style names the fonts of
Chinese CAD installations (gbenor.shx with the big font gbcbig.shx). AutoCAD and ZWCAD have
them; LibreCAD 2.2 has neither and no font with the simplified Chinese of the sheets: its
own fonts (``/usr/share/librecad/fonts/*.lff``) lack 64 of the 267 characters of the four
Chinese sheets at best (kst32b.lff: 驱, 动, 转, ≥ …; unicode.lff far more), and it draws a
missing character as a dot. It also takes the font from the style's *name*, not its file
(so the GB DXF names its Chinese texts' style after LibreCAD's wqy-unicode.lff, which
Debian's LibreCAD lacks: ``core.drawing.dxf.UNICODE_STYLE``).
A text drawn as its glyphs' outlines (HATCH entities, solid fill, layer TEXT) prints the
same in every CAD program; it is no longer editable as text, which the GB style keeps.
A DIMENSION rendered with CAD's own measurement ("<>", the scheme's) gets the text of its
rendered block as outlines in its place (:func:`outline_dimension_texts`).

The font is a CJK TrueType font with Latin and Greek (Noto Sans CJK SC, the PDF's, first),
at the GB style's width factor 0.7; each run is squeezed further where the font would be
wider than the sheet's estimate, and a subscript is set right after its letter's drawn
width (``text_runs.closed_up``), as the PDF does.
"""
from __future__ import annotations

import functools
import math
from typing import Callable

from ezdxf import path as ezpath
from ezdxf.math import Matrix44

from .dxf import TEXT_WIDTH
from .sheet import Text
from .text_runs import closed_up

# (font file, face number in a collection, family): searched in this order in the system's
# font folders (ezdxf's font manager); the first present is used.
OUTLINE_FONTS = (
    ("NotoSansCJK-Regular.ttc", 2, "Noto Sans CJK SC"),
    ("NotoSansCJKsc-Regular.otf", 0, "Noto Sans CJK SC"),
    ("NotoSansSC-Regular.otf", 0, "Noto Sans SC"),
    ("SourceHanSansSC-Regular.otf", 0, "Source Han Sans SC"),
    ("wqy-microhei.ttc", 0, "WenQuanYi Micro Hei"),
    ("wqy-zenhei.ttc", 0, "WenQuanYi Zen Hei"),
    ("msyh.ttc", 0, "Microsoft YaHei"),
    ("simhei.ttf", 0, "SimHei"),
)
FLATNESS = 0.01               # greatest gap between a glyph's curve and its outline, × text height


class OutlineFontMissing(RuntimeError):
    """No font with Chinese glyphs for the outlines is installed."""


@functools.lru_cache(maxsize=1)
def outline_font():
    """The first installed font of :data:`OUTLINE_FONTS` as ezdxf's glyph renderer (loaded
    once per process). OutlineFontMissing names the fonts looked for when none is there."""
    from ezdxf.fonts import fonts
    from ezdxf.fonts.ttfonts import TTFontRenderer
    for file, number, _ in OUTLINE_FONTS:
        if fonts.font_manager.has_font(file):
            return TTFontRenderer(fonts.font_manager.get_ttf_font(file, number))
    names = ", ".join(family for _, _, family in OUTLINE_FONTS[::2])
    raise OutlineFontMissing(f"the outline font needs a font with Chinese glyphs ({names}; "
                             "on Debian/Ubuntu: fonts-noto-cjk)")


def squeeze(run: Text, font) -> float:
    """The width factor ``run`` is drawn at: the GB style's 0.7, less where the font would
    still be wider than the sheet's estimate (the layout's no-overlap guarantee)."""
    natural = font.get_text_length(run.text, run.height, TEXT_WIDTH)
    return TEXT_WIDTH * min(1.0, run.width / natural) if natural > 0 else TEXT_WIDTH


def drawn_width(run: Text, font) -> float:
    """The width of ``run`` as drawn in outline, paper mm."""
    return font.get_text_length(run.text, run.height, squeeze(run, font))


def as_drawn(x: float, y: float) -> tuple[float, float]:
    """A point in the drawing's own coordinates (a text placed where it is drawn)."""
    return float(x), float(y)


def add_outline_text(msp, item: Text, to: Callable[[float, float], tuple[float, float]] = as_drawn,
                     k: float = 1.0) -> None:
    """``item`` as solid HATCH entities on its layer, each run at ``to`` of its paper
    position and ``k`` times its paper size (a sheet with a model is drawn in the model's mm;
    by default the drawing's own coordinates)."""
    font = outline_font()
    for run in closed_up(item, lambda r: drawn_width(r, font)):
        if not run.text.strip():
            continue
        factor = squeeze(run, font)
        width = font.get_text_length(run.text, run.height, factor)
        dx = {"l": 0.0, "c": -width / 2.0, "r": -width}[run.align[0]]
        dy = {"b": 0.0, "m": -run.height / 2.0, "t": -run.height}[run.align[1]]
        x, y = to(*run.position)
        m = Matrix44.chain(Matrix44.translate(dx, dy, 0.0), Matrix44.scale(k, k, 1.0),
                           Matrix44.z_rotate(math.radians(run.rotation)), Matrix44.translate(x, y, 0.0))
        glyphs = font.get_text_path(run.text, run.height, factor).to_path().transform(m)
        ezpath.render_hatches(msp, glyphs.sub_paths(), edge_path=False,
                              distance=FLATNESS * run.height * k,
                              dxfattribs={"layer": item.layer})



# MTEXT's attachment point (1 top left … 9 bottom right) as a Text's alignment
ATTACHMENTS = {1: "lt", 2: "ct", 3: "rt", 4: "lm", 5: "cm", 6: "rm", 7: "lb", 8: "cb", 9: "rb"}


def outline_dimension_texts(msp) -> None:
    """Each rendered DIMENSION's text as outlines where its block shows it. Why: a dimension
    whose text is CAD's own measurement ("θ = <>") is drawn by the reader in the style's
    font, so LibreCAD leaves out its θ. The block's MTEXT (the measurement ezdxf put for
    "<>") becomes HATCH entities on the dimension's layer, and the DIMENSION's own text is
    blank (" "), as a sheet's is in outline (``sheet_dxf``): CAD keeps its lines and points
    and draws no text of its own over the outline."""
    blocks = msp.doc.blocks
    for dim in msp.query("DIMENSION"):
        block = blocks.get(dim.dxf.geometry)
        for mtext in block.query("MTEXT"):
            insert = mtext.dxf.insert
            add_outline_text(msp, Text(mtext.plain_text(), (insert.x, insert.y), mtext.dxf.char_height,
                                       ATTACHMENTS[mtext.dxf.attachment_point], mtext.get_rotation(),
                                       dim.dxf.layer))
            block.delete_entity(mtext)
        dim.dxf.text = " "
