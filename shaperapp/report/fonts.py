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


def report_font(language: str, point_size: float = 9.5) -> QFont:
    """The body font of a report in ``language`` ('en' or 'zh_CN')."""
    if language.startswith("zh"):
        family = cjk_family()
        if family is None:
            raise MissingFontError(INSTALL_HINT)
        font = QFont(family)
    else:
        font = QFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.GeneralFont))
    font.setPointSizeF(point_size)
    return font
