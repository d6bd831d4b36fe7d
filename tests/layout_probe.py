"""Open the real main window on a screen of a given size and report how it fits, as JSON.

Run by tests/test_gui_layout.py in a subprocess, because the screen size is fixed when
the QApplication starts: ``QT_QPA_PLATFORM=offscreen:configfile=screen.json``.

    python tests/layout_probe.py --settings S.ini --lang en --speeds 40,60 --speeds 20,25,...

For each list of speeds it reports the window's frame and minimum size, and for every
result table its rows, the rows not inside the table's own viewport, the rows that
scrolling the results pane cannot bring into view, and whether its last column can be
scrolled into view.
"""
from __future__ import annotations

import argparse
import json
import sys

from PySide6.QtCore import QPoint, QRect, QSettings, QSize
from PySide6.QtWidgets import QApplication, QScrollArea


def rect(r: QRect) -> list[int]:
    return [r.x(), r.y(), r.width(), r.height()]


def size(s: QSize) -> list[int]:
    return [s.width(), s.height()]


def settle(app: QApplication, rounds: int = 20) -> None:
    for _ in range(rounds):
        app.processEvents()


def table_report(app: QApplication, table) -> dict:
    area = table.parentWidget()
    while area is not None and not isinstance(area, QScrollArea):
        area = area.parentWidget()
    unreachable = []
    for row in range(table.rowCount()):
        top = table.rowViewportPosition(row)
        inside = table.viewport().mapTo(area.widget(), QPoint(0, top + table.rowHeight(row) // 2))
        area.ensureVisible(inside.x(), inside.y(), 0, table.rowHeight(row))
        settle(app, 2)
        box = QRect(table.viewport().mapTo(area.viewport(), QPoint(0, top)),
                    QSize(table.viewport().width(), table.rowHeight(row)))
        if not area.viewport().rect().contains(box):
            unreachable.append(row)
    last = table.columnCount() - 1
    table.scrollTo(table.model().index(0, last))
    settle(app, 2)
    x = table.columnViewportPosition(last)
    last_shown = 0 <= x and x + table.columnWidth(last) <= table.viewport().width() + 1
    table.horizontalScrollBar().setValue(0)
    return {"rows": table.rowCount(), "columns": table.columnCount(), "hidden_rows": table.hidden_rows(),
            "unreachable_rows": unreachable, "last_column_reachable": last_shown,
            "h_scroll_visible": table.horizontalScrollBar().isVisible(),
            "needs_h_scroll": sum(table.columnWidth(c) for c in range(table.columnCount()))
            > table.viewport().width() + 1,
            "titles": [table.verticalHeaderItem(r).text() for r in range(table.rowCount())]}


def compare_report(app: QApplication, window) -> dict:
    """The Compare tab with two designs: each plot's view box and left-axis title (px) and
    the legend's box, in the plots' scene."""
    view = window.compare
    window.tabs.setCurrentWidget(view)
    view.add_current()
    window.model.set_spec(time_ratio=1.6)
    view.add_current()
    settle(app)
    plots = {}
    for key in ("ram_x_mm", "ram_v_m_s", "ram_a_m_s2", "crank_torque_N_m"):
        item = view.plots.item(key)
        box = item.getViewBox().sceneBoundingRect()
        title = item.getAxis("left").label
        shown = title.sceneBoundingRect()
        plots[key] = {"box": [box.x(), box.y(), box.width(), box.height()],
                      "title": [shown.x(), shown.y(), shown.width(), shown.height()],
                      "title_text": title.toPlainText() if title.isVisible() else ""}
    legend = view.plots._legend.sceneBoundingRect()
    return {"plots": plots, "legend": [legend.x(), legend.y(), legend.width(), legend.height()],
            "legend_rows": len(view.plots._legend.items)}


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--settings", required=True)
    parser.add_argument("--lang", default="en")
    parser.add_argument("--speeds", action="append", default=[])
    parser.add_argument("--resize", help="WxH before closing (to save that geometry)")
    parser.add_argument("--library", action="store_true", help="then show the library pane and report it")
    parser.add_argument("--compare", action="store_true", help="then compare two designs and report the plots")
    args = parser.parse_args(argv)
    from shaperapp.style import configure_plots
    configure_plots()
    app = QApplication(sys.argv[:1])
    from shaperapp.main_window import MainWindow
    from shaperapp.model import DesignModel
    window = MainWindow(DesignModel(), QSettings(args.settings, QSettings.Format.IniFormat))
    window.set_language(args.lang)
    window.show()
    settle(app)
    report = {"screen": rect(window.screen().availableGeometry()), "language": args.lang, "cases": []}
    for speeds in args.speeds:
        window.model.set_rpms([float(s) for s in speeds.split(",")])
        settle(app)
        window.docks["results"].raise_()
        settle(app)
        report["cases"].append({
            "speeds": speeds.count(",") + 1,
            "frame": rect(window.frameGeometry()), "size": size(window.size()),
            "minimum": size(window.minimumSizeHint()),
            "results_visible": window.metrics.isVisible(),
            "tables": [table_report(app, t) for t in window.metrics.tables()],
        })
    if args.library:
        window.library_dock.show()
        settle(app)
        view = window.library.view
        report["library"] = {"floating": window.library_dock.isFloating(),
                             "frame": rect(window.frameGeometry()), "dock": rect(window.library_dock.frameGeometry()),
                             "rows_room": view.viewport().height() // max(view.verticalHeader().defaultSectionSize(), 1)}
    if args.compare:
        report["compare"] = compare_report(app, window)
    if args.resize:
        w, h = (int(v) for v in args.resize.split("x"))
        window.resize(w, h)
        settle(app)
        report["resized"] = size(window.size())
    window.model.set_clean("")
    window.close()
    window.settings.sync()
    print(json.dumps(report))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
