"""Language switching with Qt's own translators (no wrapper of our own).

English is the source language; Simplified Chinese ships as a compiled .qm
under resources/. Qt's own strings (dialog buttons) come from PySide6's
qtbase translations when present.
"""
from __future__ import annotations

from importlib import resources

from PySide6.QtCore import QCoreApplication, QLibraryInfo, QLocale, QTranslator

LANGUAGES = (("en", "English"), ("zh_CN", "简体中文"))
_installed: list[QTranslator] = []


def system_language() -> str:
    name = QLocale.system().name()
    return "zh_CN" if name.startswith("zh") else "en"


def qm_path(language: str) -> str:
    return str(resources.files("shaperapp.resources").joinpath(f"shaperapp_{language}.qm"))


def set_language(language: str) -> bool:
    """Install the translators for ``language``; True when a catalogue was loaded."""
    app = QCoreApplication.instance()
    for translator in _installed:
        app.removeTranslator(translator)
    _installed.clear()
    if language == "en":
        return True
    ours = QTranslator(app)
    loaded = ours.load(qm_path(language))
    if loaded:
        app.installTranslator(ours)
        _installed.append(ours)
    qt = QTranslator(app)
    if qt.load(f"qt_{language}", QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)):
        app.installTranslator(qt)
        _installed.append(qt)
    return loaded
