"""Compare two folders of written files: ``python tools/compare_outputs.py OLD NEW``.

Why: a speed-up of ``shaper course`` or ``shaper class`` must not change what a user
reads, yet the PDFs carry their creation time and the DXFs their creation stamp, so the
bytes differ from run to run. This compares what matters, file by file (same relative
paths): PDFs by their text with its positions (``pdftotext -bbox``) and by their pages
rendered at 30 dpi (``pdftoppm -r 30``, compared pixel by pixel); DXFs by their entities
(type, attributes, points, texts, in order, through ezdxf); every other file by its
bytes. It prints one line per file that differs and a count; exit status 1 if any does.
Only a developer's tool (needs poppler-utils).
"""
from __future__ import annotations

import re
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

STAMPS = re.compile(rb"/(CreationDate|ModDate) \([^)]*\)")


def pdf_text(path: Path) -> str:
    """The text and its boxes, as poppler lays them out."""
    done = subprocess.run(["pdftotext", "-bbox", str(path), "-"], capture_output=True, text=True, check=True)
    return re.sub(r"<meta[^>]*>", "", done.stdout)


def pdf_pages(path: Path) -> list[np.ndarray]:
    """Every page at 30 dpi, as arrays of grey levels."""
    with tempfile.TemporaryDirectory() as scratch:
        subprocess.run(["pdftoppm", "-r", "30", "-gray", str(path), f"{scratch}/p"], check=True)
        return [_pgm(p) for p in sorted(Path(scratch).glob("p*"))]


def _pgm(path: Path) -> np.ndarray:
    data = path.read_bytes()
    fields = data.split(maxsplit=4)            # P5 width height maxval pixels
    width, height = int(fields[1]), int(fields[2])
    return np.frombuffer(fields[4][:width * height], np.uint8).reshape(height, width)


def dxf_entities(path: Path) -> list[tuple]:
    """Each model-space entity: its type, attributes but its handle and owner, and its points."""
    import ezdxf
    doc = ezdxf.readfile(str(path))
    out = []
    for entity in doc.modelspace():
        attribs = {k: v for k, v in entity.dxfattribs().items() if k not in ("handle", "owner")}
        points = tuple(map(tuple, entity.get_points())) if entity.dxftype() == "LWPOLYLINE" else ()
        out.append((entity.dxftype(), sorted((k, str(v)) for k, v in attribs.items()), points))
    return out


def differs(old: Path, new: Path) -> str:
    """'' when the two files read the same, else what differs."""
    suffix = old.suffix.lower()
    if suffix == ".pdf":
        if STAMPS.sub(b"", old.read_bytes()) == STAMPS.sub(b"", new.read_bytes()):
            return ""
        a, b = pdf_text(old).split("<page "), pdf_text(new).split("<page ")
        texts = [i for i, (p, q) in enumerate(zip(a, b)) if p != q and i]
        a, b = pdf_pages(old), pdf_pages(new)
        if len(a) != len(b):
            return f"{len(a)} against {len(b)} pages"
        pixels = [i + 1 for i, (p, q) in enumerate(zip(a, b)) if p.shape != q.shape or (p != q).any()]
        return (f"text or its positions on pages {texts}, pixels on pages {pixels}"
                if texts or pixels else "")
    if suffix == ".dxf":
        a, b = dxf_entities(old), dxf_entities(new)
        if a == b:
            return ""
        first = next((i for i, (p, q) in enumerate(zip(a, b)) if p != q), min(len(a), len(b)))
        return f"entities ({len(a)} against {len(b)}; first difference at {first})"
    return "" if old.read_bytes() == new.read_bytes() else "bytes"


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        print(__doc__.splitlines()[0], file=sys.stderr)
        return 2
    old_root, new_root = Path(argv[0]), Path(argv[1])
    names = sorted({p.relative_to(old_root) for p in old_root.rglob("*") if p.is_file()}
                   | {p.relative_to(new_root) for p in new_root.rglob("*") if p.is_file()})
    bad = 0
    for name in names:
        old, new = old_root / name, new_root / name
        if not (old.is_file() and new.is_file()):
            why = "only in " + (str(old_root) if old.is_file() else str(new_root))
        else:
            why = differs(old, new)
        if why:
            bad += 1
            print(f"{name}: {why}")
    print(f"{len(names) - bad} of {len(names)} files the same")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
