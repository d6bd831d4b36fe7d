"""Language switching with Qt's own translators (no wrapper of our own).

English is the source language; Simplified Chinese ships as a compiled .qm
under resources/. Qt's own strings (dialog buttons, the file dialog) come from
Qt's ``qtbase_<language>`` catalogue in Qt's translations folder (``qt_zh_CN``
is only a meta catalogue that PySide6 does not ship complete).

The two translators are created once and reloaded on each switch, so switching
back and forth never leaves translators behind.
"""
from __future__ import annotations

from importlib import resources

from PySide6.QtCore import QCoreApplication, QLibraryInfo, QLocale, QTranslator
from PySide6.QtGui import QGuiApplication

LANGUAGES = (("en", "English"), ("zh_CN", "简体中文"))
# What a command line accepts for --lang, everywhere (shaperapp, shaper report): one
# spelling was zh_CN for the app and zh for the report.
LANGUAGE_CHOICES = ("en", "zh", "zh_CN")


def join_sentences(*texts: str) -> str:
    """Translated sentences as one paragraph: a space after an English full stop, none
    after a Chinese one (。: Chinese sentences follow each other without a space), empty
    texts left out. The report's paragraphs and the dialogs' messages of several sentences."""
    out = ""
    for text in filter(None, texts):
        out += ("" if not out or out.endswith("。") else " ") + text
    return out


def language_of(choice: str) -> str:
    """A --lang choice as a UI language: "zh" and "zh_CN" are both simplified Chinese."""
    return "zh_CN" if choice in ("zh", "zh_CN") else "en"
_translators: dict[str, QTranslator] = {}
_installed: list[QTranslator] = []


def system_language() -> str:
    name = QLocale.system().name()
    return "zh_CN" if name.startswith("zh") else "en"


def qm_path(language: str) -> str:
    return str(resources.files("shaperapp.resources").joinpath(f"shaperapp_{language}.qm"))


def qt_translations_dir() -> str:
    return QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)


def _translator(role: str, app: QCoreApplication) -> QTranslator:
    """The one translator for ``role`` ('app' or 'qt'), owned by the application."""
    translator = _translators.get(role)
    try:
        if translator is not None:
            translator.objectName()          # still alive (not deleted with an old app)?
            return translator
    except RuntimeError:
        pass
    translator = QTranslator(app)
    _translators[role] = translator
    return translator


def set_language(language: str) -> bool:
    """Install the translators for ``language``; True when our catalogue was loaded.

    Also names the application in that language, so the window title (to which
    Qt appends the application's display name) is in one language."""
    app = QCoreApplication.instance()
    for translator in _installed:
        app.removeTranslator(translator)
    _installed.clear()
    loaded = language == "en"
    if language != "en":
        ours = _translator("app", app)
        if ours.load(qm_path(language)):
            app.installTranslator(ours)
            _installed.append(ours)
            loaded = True
        qt = _translator("qt", app)
        if qt.load(f"qtbase_{language}", qt_translations_dir()):
            app.installTranslator(qt)
            _installed.append(qt)
    if isinstance(app, QGuiApplication):
        QGuiApplication.setApplicationDisplayName(QCoreApplication.translate("app", "Shaper Designer"))
    # Dates and numbers that Qt formats itself (the file dialog's dates) in the UI's language.
    QLocale.setDefault(QLocale(language if language != "en" else "en_US"))
    return loaded
