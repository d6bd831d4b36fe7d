"""Fonts for the report: a CJK-capable family for Chinese, found through Qt.

A fresh machine may have no Chinese font; then Chinese text would come out as
empty boxes, so the Chinese report is refused with a message naming the
package to install instead.
"""
from __future__ import annotations

from PySide6.QtGui import QFont, QFontDatabase, QFontInfo, QGuiApplication

PREFERRED_CJK = ("Noto Sans CJK SC", "Noto Sans SC", "Source Han Sans SC", "Source Han Sans CN",
                 "WenQuanYi Micro Hei", "WenQuanYi Zen Hei", "Microsoft YaHei", "PingFang SC",
                 "SimHei", "SimSun", "Noto Serif CJK SC", "AR PL UMing CN")
# Latin text and digits come from one of these, before the CJK family: Qt's PDF engine loses
# the text mapping of Noto Sans CJK's digits (pdftotext then reads "386.370 mm" as ". mm").
PREFERRED_LATIN = ("DejaVu Sans", "Noto Sans", "Liberation Sans", "Arial", "Helvetica")
INSTALL_HINT = ("no font with Chinese glyphs found; install one, e.g. 'apt-get install "
                "fonts-noto-cjk' (Debian/Ubuntu) or 'dnf install google-noto-sans-cjk-fonts' (Fedora)")


def prefer_simplified_chinese() -> None:
    """Chinese characters in the application's font come from the Simplified Chinese family.

    A font without Chinese glyphs (DejaVu Sans) falls back to whatever CJK font the
    system's font configuration ranks first for the process's locale: under an
    English or C locale that is Noto Sans CJK JP, whose Japanese forms differ from
    the Chinese ones and some of whose glyphs got no entry in the text layer of Qt's
    PDF (the report's plot labels 滑枕位移, 速度 … were missing from pdftotext's text). Qt
    keeps the fallback of a font once the font is first used, so this runs right
    after the QApplication is made (``app.main``, ``command_line.application``),
    before any text is laid out. The Latin letters stay in the family they were in:
    an alias (Qt's "Sans Serif") is substituted by the family it stood for, then the
    Chinese one.
    """
    family = cjk_family() if QGuiApplication.instance() is not None else None
    if family is None:
        return
    base = QGuiApplication.font()
    resolved = QFontInfo(base).family()
    for name, substitutes in ((base.family(), [resolved, family]), (resolved, [family])):
        wanted = [s for s in substitutes if s != name and s not in QFont.substitutes(name)]
        if wanted:
            QFont.insertSubstitutions(name, wanted)


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


def drawing_lettering(font: QFont) -> QFont:
    """``font`` lettered as the drawings letter points and symbols: upright. GB/T 14691
    lets a drawing letter upright or sloped (75°), one way throughout; the sheets are
    upright. One definition for the sheets' texts and the scheme's joint names, which the
    screen and the report's figures show, so that O₂, A, B stand alike on a sheet and in
    the report (the report's were italic). The weight is each one's own: the scheme keeps
    its names bold on screen (in regular weight B went under the force caption in the
    laptop pane at 6 of 72 angles against 4, test_gui_scheme_clashes.py)."""
    font = QFont(font)
    font.setItalic(False)
    return font


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
