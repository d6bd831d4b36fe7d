"""Fonts for the report: a CJK-capable family for Chinese, found through Qt.

A fresh machine may have no Chinese font; then Chinese text would come out as
empty boxes, so the Chinese report is refused with a message naming the
package to install instead.
"""
from __future__ import annotations

from PySide6.QtGui import QFont, QFontDatabase

PREFERRED_CJK = ("Noto Sans CJK SC", "Noto Sans SC", "Source Han Sans SC", "Source Han Sans CN",
                 "WenQuanYi Micro Hei", "WenQuanYi Zen Hei", "Microsoft YaHei", "PingFang SC",
                 "SimHei", "SimSun", "Noto Serif CJK SC", "AR PL UMing CN")
# Latin text and digits come from one of these, before the CJK family: Qt's PDF engine loses
# the text mapping of Noto Sans CJK's digits (pdftotext then reads "386.370 mm" as ". mm").
PREFERRED_LATIN = ("DejaVu Sans", "Noto Sans", "Liberation Sans", "Arial", "Helvetica")
INSTALL_HINT = ("no font with Chinese glyphs found; install one, e.g. 'apt-get install "
                "fonts-noto-cjk' (Debian/Ubuntu) or 'dnf install google-noto-sans-cjk-fonts' (Fedora)")


class MissingFontError(RuntimeError):
    """No font can show the report's language."""


def cjk_family() -> str | None:
    """A family that can write Simplified Chinese, preferring the common sans ones."""
    families = QFontDatabase.families(QFontDatabase.WritingSystem.SimplifiedChinese)
    for name in PREFERRED_CJK:
        if name in families:
            return name
    return families[0] if families else None


def latin_family() -> str | None:
    available = set(QFontDatabase.families())
    return next((name for name in PREFERRED_LATIN if name in available), None)


def report_font(language: str, point_size: float = 9.5) -> QFont:
    """The body font of a report in ``language`` ('en' or 'zh_CN'): a Latin family for
    letters and digits, then (Chinese) a CJK family for the Chinese characters."""
    families = [name for name in (latin_family(),) if name]
    if language.startswith("zh"):
        family = cjk_family()
        if family is None:
            raise MissingFontError(INSTALL_HINT)
        families.append(family)
    font = QFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.GeneralFont))
    if families:
        font.setFamilies(families)
    font.setPointSizeF(point_size)
    return font
