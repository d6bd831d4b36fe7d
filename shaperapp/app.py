"""``shaperapp``: start the GUI on the default design (or a file given as argument).

Unexpected errors are logged and shown as a plain message, never as a traceback.
"""
from __future__ import annotations

import argparse
import gc
import sys
import time
import traceback

START = time.perf_counter()


def _install_error_hook(app) -> None:
    from PySide6.QtCore import QCoreApplication, QStandardPaths
    from PySide6.QtWidgets import QMessageBox

    def hook(kind, value, tb) -> None:
        import os
        folder = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppDataLocation)
        try:
            os.makedirs(folder, exist_ok=True)
            with open(os.path.join(folder, "error.log"), "a", encoding="utf-8") as log:
                log.write("".join(traceback.format_exception(kind, value, tb)))
            where = os.path.join(folder, "error.log")
        except OSError:
            where = ""
        QMessageBox.critical(None, "Shaper Designer",
                             QCoreApplication.translate("app", "An internal error occurred; the design on screen "
                                                  "is unchanged. Details were written to %1.").replace("%1", where))

    sys.excepthook = hook


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="shaperapp", description="Shaper Designer (GUI)")
    parser.add_argument("file", nargs="?", help="a design file to open")
    parser.add_argument("--lang", choices=("en", "zh", "zh_CN"),
                        help="UI language: en, or zh (= zh_CN) for Chinese (default: the system's)")
    parser.add_argument("--screenshot", metavar="PNG",
                        help="render the window to PNG once shown and laid out, then quit")
    parser.add_argument("--quit-after-show", action="store_true",
                        help="print the time to the first painted window and quit (for benchmarks)")
    args = parser.parse_args(argv)

    # Python's automatic garbage collection is off from here on; the event loop's timer
    # collects (below). Why from here: start-up allocates some 70 000 tracked objects
    # (Qt's classes, pyqtgraph, the window), and the automatic collections among them
    # cost 35-55 ms before the first paint, a full one alone 15-25 ms.
    gc.disable()
    from core.base.blas import limit_blas_threads
    limit_blas_threads()
    _import_engine_first()
    from PySide6.QtCore import QSettings, QTimer
    _skip_pyside_source_checks()
    from PySide6.QtWidgets import QApplication

    from shaperapp.widgets.style import configure_plots
    configure_plots()
    app = QApplication.instance() or QApplication(sys.argv[:1])
    from shaperapp.widgets.fonts import prefer_simplified_chinese
    prefer_simplified_chinese()          # before any text is laid out (see its docstring)
    app.setApplicationName("shaperapp")
    app.setOrganizationName("ShaperDesigner")
    app.setApplicationDisplayName("Shaper Designer")
    _install_error_hook(app)

    from shaperapp.widgets import dialog_titles, i18n
    from shaperapp.window.main_window import MainWindow
    from shaperapp.design.model import DesignModel

    settings = QSettings()
    language = (i18n.language_of(args.lang) if args.lang else None) or settings.value("language") \
        or i18n.system_language()
    dialog_titles.hold()        # its application-wide filter from the first paint on (see hold)
    model = DesignModel()
    window = MainWindow(model, settings)
    window.set_language(language if language in dict(i18n.LANGUAGES) else "en")
    window.show()
    if args.file:      # after show: a file that cannot be opened is reported over the window
        dialog_titles.release(app)
        window.document.open_path(args.file)

    def finish() -> None:
        if args.screenshot:
            window.grab().save(args.screenshot)
        window.model.set_clean(window.model.path)
        window.close()
        app.quit()

    def painted() -> None:
        # What start-up made (Qt's classes, pyqtgraph, the window) lives as long as the app.
        # Frozen, the timer's full collections no longer walk its 80 000 objects: one took
        # 31-39 ms, a stutter about every two minutes while the animation runs. (The few
        # hundred objects of cyclic garbage start-up leaves stay until the app quits.)
        gc.freeze()
        dialog_titles.release(app)
        if args.quit_after_show or args.screenshot:
            print(f"first window painted after {(time.perf_counter() - START) * 1000:.0f} ms",
                  flush=True)
            # A screenshot waits for pending layouts (e.g. after a language switch) to run.
            QTimer.singleShot(300 if args.screenshot else 0, finish)
    _when_painted(window, painted)
    # The timer collects from the event loop, where no Qt call is under way: an automatic
    # collection could start inside a Qt call that holds Qt's connection lock (a signal's
    # disconnect) and destroy a widget that needs that lock; the window froze (seen in
    # the tests with py-spy).
    from pyqtgraph.util.garbage_collector import GarbageCollector
    collector = GarbageCollector(interval=1.0)
    try:
        return app.exec()
    finally:
        collector.timer.stop()
        dialog_titles.release(app)      # (a window closed before its first paint)
        gc.unfreeze()
        gc.enable()


def _import_engine_first() -> None:
    """Import numpy and the engine modules the first screen uses before Qt.

    Why: once imported, PySide6 hooks every later import and reads the module's source
    to see whether it uses PySide's ``__feature__`` switches; numpy's and core's
    hundred-odd modules imported before it skip that."""
    import core.base.figure_text  # noqa: F401  (the Results panel's one precision per figure)
    import core.base.lettering  # noqa: F401  (the scheme's labels' gap)
    import core.forces.dynamics  # noqa: F401  (the forces; their cycle summary when first shown)
    import core.files.io  # noqa: F401  (core, numpy, the design files)
    import core.linkage.metrics  # noqa: F401  (the results panel's cycle figures)


class _NoFeatures:
    """An import finder that finds nothing: it only gives each module about to be
    imported PySide6's verdict "uses no ``__feature__``" before PySide6 looks for one."""

    def __init__(self, verdicts: dict) -> None:
        self._verdicts = verdicts

    def find_spec(self, name: str, path=None, target=None) -> None:
        self._verdicts.setdefault(name, -1)


def _skip_pyside_source_checks() -> None:
    """Spare PySide6 reading the source of every module the app imports after it.

    Why: from its import on, PySide6 hooks every import statement, and for each module
    it has no verdict on yet it reads the whole source (``inspect.getsource``) to see
    whether it mentions PySide6, so that its ``from __feature__ import`` switches
    (snake_case, true_property) know which modules to leave alone. The modules
    imported before it are read too, the first time a later import names them. At
    start-up that was 300-odd modules, 60-75 ms of CPU (issue 43 item 5). The app
    and its libraries select no feature (``test_app_start.py`` checks the app's
    sources), and while no module selects one, PySide6 treats a module it has no
    verdict on, or one marked -1 ("ignore this module"), like one marked 0 ("no
    feature"): so every module is marked -1, those already imported now and the others
    as they are found. A module that selects a feature still gets its own mark then.
    The table is PySide6's (``PySide6.support.feature.pyside_feature_dict``, not a
    documented API): a PySide6 without it is left as it is."""
    verdicts = getattr(sys.modules.get("PySide6.support.feature"), "pyside_feature_dict", None)
    if not isinstance(verdicts, dict):
        return
    for name in list(sys.modules):
        verdicts.setdefault(name, -1)
    if not any(isinstance(finder, _NoFeatures) for finder in sys.meta_path):     # main() run again
        sys.meta_path.insert(0, _NoFeatures(verdicts))


def _when_painted(window, callback) -> None:
    """Call ``callback`` once the window's first paint is done: at its first paint event,
    Qt paints the whole window (its children after it) before it returns to the event
    loop, where a zero timer started then fires."""
    from PySide6.QtCore import QEvent, QObject, QTimer

    class FirstPaint(QObject):
        def eventFilter(self, watched, event) -> bool:
            if event.type() == QEvent.Type.Paint:
                watched.removeEventFilter(self)
                QTimer.singleShot(0, callback)
            return False

    window._first_paint = FirstPaint(window)
    window.installEventFilter(window._first_paint)


if __name__ == "__main__":
    sys.exit(main())
