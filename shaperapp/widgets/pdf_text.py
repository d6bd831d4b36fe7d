"""A PDF's text layer holds the characters it prints: Chinese radicals mapped back.

Qt's PDF engine writes each embedded font's ToUnicode map from the font's cmap
read backwards: for a glyph it takes the *lowest* code point that the cmap maps
to it. A CJK font maps a radical and its unified ideograph to one glyph (牛 and
the Kangxi radical ⽜ U+2F5C, 角 and the radical ⻆ U+2EC6), and the radicals'
blocks come first, so the text layer of a Chinese PDF said "⽜头刨床": printed
right, but searched, copied and read aloud wrong. Qt (6.11) offers no hook into
that choice, so :func:`repair_text_layer` rewrites the finished PDF's ToUnicode
maps (with pikepdf, qpdf's Python binding): every radical or stroke code point
becomes the unified ideograph that the Chinese font draws with the same glyph
(the font's cmap, read through Qt), or, for a font without one, the ideograph of
Unicode's compatibility mapping (NFKC). Only the ToUnicode streams change; the
pages print as before. The writers call it on the bytes they then save
atomically, so the file on disk is the repaired one or the old one.
"""
from __future__ import annotations

import io
import re
import unicodedata
from functools import lru_cache

# The blocks whose code points share glyphs with unified ideographs: CJK Radicals
# Supplement and Kangxi Radicals (2E80–2FDF), CJK Strokes (31C0–31EF).
RADICAL_BLOCKS = ((0x2E80, 0x2FDF), (0x31C0, 0x31EF))
# Where the replacement comes from: CJK Unified Ideographs and Extension A.
IDEOGRAPH_BLOCKS = ((0x4E00, 0x9FFF), (0x3400, 0x4DBF))
_HEX = re.compile(rb"<([0-9A-Fa-f]*)>")
_SECTION = re.compile(rb"begin(bfchar|bfrange)(.*?)end\1", re.DOTALL)
_CHAR = re.compile(rb"<([0-9A-Fa-f]+)>\s*<([0-9A-Fa-f]*)>")
_RANGE = re.compile(rb"<([0-9A-Fa-f]+)>\s*<([0-9A-Fa-f]+)>\s*(<[0-9A-Fa-f]*>|\[[^\]]*\])")


def is_radical(char: str) -> bool:
    """A Kangxi or supplementary radical or a CJK stroke: never what a report means."""
    code = ord(char)
    return any(lo <= code <= hi for lo, hi in RADICAL_BLOCKS)


def radical_ideographs() -> dict[str, str]:
    """Radical → the unified ideograph the Chinese font draws with the same glyph.

    Read from the cmap of the family the report and sheets write Chinese in
    (``fonts.cjk_family``); empty without such a font or a Qt application."""
    from PySide6.QtGui import QGuiApplication

    from .fonts import cjk_family
    family = cjk_family() if QGuiApplication.instance() is not None else None
    return _font_map(family) if family is not None else {}


@lru_cache(maxsize=4)
def _font_map(family: str) -> dict[str, str]:
    from PySide6.QtGui import QFont, QRawFont
    raw = QRawFont.fromFont(QFont(family))
    radicals = "".join(chr(c) for lo, hi in RADICAL_BLOCKS for c in range(lo, hi + 1))
    ideographs = "".join(chr(c) for lo, hi in IDEOGRAPH_BLOCKS for c in range(lo, hi + 1))
    # glyph → ideograph, the first one of the blocks' order where two share a glyph (reversed,
    # so the first is written last); glyph 0 (none) is never looked up
    glyphs = list(raw.glyphIndexesForString(ideographs))
    by_glyph = dict(zip(reversed(glyphs), reversed(ideographs)))
    drawn = dict(zip(ideographs, glyphs))
    out = {}
    for char, glyph in zip(radicals, raw.glyphIndexesForString(radicals)):
        if not glyph:
            continue                                    # not this font's: NFKC decides
        folded = unicodedata.normalize("NFKC", char)
        if drawn.get(folded) == glyph:
            out[char] = folded                          # Unicode's own equivalent, as drawn
        else:
            out[char] = by_glyph.get(glyph, char)       # a glyph of its own: the radical itself
    return out


def ideograph_of(char: str, table: dict[str, str] | None = None) -> str:
    """The unified ideograph a radical ``char`` stands for in printed text; other
    characters unchanged. ``table``: :func:`radical_ideographs`, looked up once by a caller
    with many characters."""
    if not is_radical(char):
        return char
    found = (radical_ideographs() if table is None else table).get(char)
    if found is not None:
        return found
    folded = unicodedata.normalize("NFKC", char)
    return folded if folded != char and not is_radical(folded) else char


# ---- the ToUnicode CMap ----------------------------------------------------------------
def _utf16(hex_text: bytes) -> str:
    return bytes.fromhex(hex_text.decode()).decode("utf-16-be", errors="surrogatepass")


def _hex(text: str) -> str:
    return text.encode("utf-16-be", errors="surrogatepass").hex().upper()


def parse_cmap(data: bytes) -> tuple[dict[int, str], int]:
    """A ToUnicode CMap's mapping (code → text) and its code width in bytes."""
    space = re.search(rb"begincodespacerange\s*<([0-9A-Fa-f]+)>", data)
    width = len(space.group(1)) // 2 if space else 2
    mapping: dict[int, str] = {}
    for kind, body in _SECTION.findall(data):
        if kind == b"bfchar":
            mapping.update((int(code, 16), _utf16(dst)) for code, dst in _CHAR.findall(body))
            continue
        for lo, hi, dst in _RANGE.findall(body):
            first, last = int(lo, 16), int(hi, 16)
            if dst.startswith(b"["):
                for k, item in enumerate(_HEX.findall(dst)):
                    mapping[first + k] = _utf16(item)
            else:
                start = _utf16(dst[1:-1])
                for k in range(last - first + 1):      # the last character counts up
                    mapping[first + k] = start[:-1] + chr(ord(start[-1]) + k) if start else ""
    return mapping, width


def write_cmap(mapping: dict[int, str], width: int) -> bytes:
    """A ToUnicode CMap (Adobe-Identity-UCS) of ``mapping``, in bfchar blocks of 100."""
    codes = sorted(mapping)
    digits = 2 * width
    lines = ["/CIDInit /ProcSet findresource begin", "12 dict begin", "begincmap",
             "/CIDSystemInfo << /Registry (Adobe) /Ordering (UCS) /Supplement 0 >> def",
             "/CMapName /Adobe-Identity-UCS def", "/CMapType 2 def",
             "1 begincodespacerange", f"<{'0' * digits}> <{'F' * digits}>", "endcodespacerange"]
    for start in range(0, len(codes), 100):
        block = codes[start:start + 100]
        lines.append(f"{len(block)} beginbfchar")
        lines += [f"<{code:0{digits}X}> <{_hex(mapping[code])}>" for code in block]
        lines.append("endbfchar")
    lines += ["endcmap", "CMapName currentdict /CMap defineresource pop", "end", "end", ""]
    return "\n".join(lines).encode("ascii")


def repaired_cmap(data: bytes) -> bytes | None:
    """``data`` with every radical mapped to its ideograph, or None when it has none."""
    mapping, width = parse_cmap(data)
    if not any(is_radical(c) for text in mapping.values() for c in text):
        return None
    table = radical_ideographs()
    fixed = {code: "".join(ideograph_of(c, table) for c in text) for code, text in mapping.items()}
    return write_cmap(fixed, width) if fixed != mapping else None


def repair_text_layer(pdf: bytes) -> bytes:
    """The PDF ``pdf`` with its fonts' ToUnicode maps repaired (see the module's
    docstring); the same bytes when no map holds a radical."""
    import pikepdf
    with pikepdf.open(io.BytesIO(pdf)) as doc:
        changed = False
        seen: set[tuple[int, int]] = set()
        for obj in doc.objects:
            if not isinstance(obj, pikepdf.Dictionary) or "/ToUnicode" not in obj:
                continue
            stream = obj.ToUnicode
            if not isinstance(stream, pikepdf.Stream) or stream.objgen in seen:
                continue
            seen.add(stream.objgen)
            fixed = repaired_cmap(stream.read_bytes())
            if fixed is not None:
                stream.write(fixed)        # compressed again by save
                changed = True
        if not changed:
            return pdf
        out = io.BytesIO()
        # the PDF version is Qt's, so its XMP metadata needs no update (a fifth of the time)
        doc.save(out, deterministic_id=True, fix_metadata_version=False)
        return out.getvalue()
