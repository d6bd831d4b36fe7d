"""The user guide and the About text.

The guide is packaged HTML (``resources/help/guide_<lang>.html``), one file per
language, so it can be read and reviewed as a document rather than as strings
scattered through the code; it is shown in a ``QTextBrowser``.
"""
from __future__ import annotations

from importlib import resources

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QDialog, QDialogButtonBox, QTextBrowser, QVBoxLayout, QWidget

GUIDE_LANGUAGES = ("en", "zh_CN")
WRAPPED = "pre { white-space: pre-wrap; }"
"""The guide's style beside its HTML's: preformatted lines wrap to the window (a browser's
``pre`` does not, and a reader then scrolls sideways for one line)."""


def version() -> str:
    from importlib import metadata      # 12 ms: not before the About box asks
    try:
        return metadata.version("shaper-designer")
    except metadata.PackageNotFoundError:
        return "unknown"


def guide_html(language: str) -> str:
    """The guide in ``language`` (English when there is none in that language)."""
    code = language if language in GUIDE_LANGUAGES else "en"
    folder = resources.files("shaperapp.resources").joinpath("help")
    return folder.joinpath(f"guide_{code}.html").read_text(encoding="utf-8")


def about_text() -> str:
    return (QCoreApplication.translate("help", "Shaper Designer %1").replace("%1", version()) + "\n\n"
            + QCoreApplication.translate("help", "Synthesis, kinematics and kinetostatics of the quick-return mechanism of a "
                         "shaper (crank, slotted lever, ram).") + "\n"
            + QCoreApplication.translate("help", "Lengths in mm, speeds in r/min, ram velocity in m/s, acceleration in m/s², "
                         "angles in degrees. The crank angle starts at the limit position that begins "
                         "the working stroke; ram motion is positive in the cutting direction.") + "\n\n"
            + QCoreApplication.translate("help", "Help › User guide (F1) explains the conventions, the method and the command line."))


class GuideDialog(QDialog):
    """A non-modal window with the guide, so it can stay open beside the design."""

    def __init__(self, language: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.browser = QTextBrowser(self)
        self.browser.setOpenExternalLinks(False)
        # The command examples wrap at the window's edge like the text (their longest line,
        # the cam's, made the guide 881 px wide in its 722 px view: a sideways scroll bar)
        self.browser.document().setDefaultStyleSheet(WRAPPED)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close, self)
        buttons.rejected.connect(self.close)
        layout = QVBoxLayout(self)
        layout.addWidget(self.browser)
        layout.addWidget(buttons)
        self.resize(760, 640)
        self.set_language(language)

    def set_language(self, language: str) -> None:
        self.setWindowTitle(QCoreApplication.translate("help", "User guide"))
        self.browser.setHtml(guide_html(language))

    def show_section(self, anchor: str) -> None:
        self.browser.scrollToAnchor(anchor)
