"""Open the real main window on a screen of a given size and report how it fits, as JSON.

Run by tests/test_shaperapp/window/test_gui_layout.py in a subprocess, because the screen size is fixed when
the QApplication starts: ``QT_QPA_PLATFORM=offscreen:configfile=screen.json``.

    python tests/layout_probe.py --settings S.ini --lang en --speeds 40,60 --speeds 20,25,...

For each list of speeds it reports the window's frame and minimum size, and for every
result table its rows, the rows not inside the table's own viewport, the rows that
scrolling the results pane cannot bring into view, and whether its last column can be
scrolled into view.

Several probes on one screen run in one process, separated by ``--next``; each opens a
fresh window, with the language and locale the process started with, and prints its own
JSON line. Why: a process costs about 1 s of CPU to start (Python, Qt, the first
window's imports), a further window about 0.35 s (docs/performance.md, "The window and
widget tests").
"""
from __future__ import annotations

import argparse
import json
import sys

from PySide6.QtCore import QLocale, QPoint, QRect, QRectF, QSettings, QSize, Qt
from PySide6.QtGui import QGuiApplication, QImage, QPainter
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
    table = view.table
    whole = [r for r in range(table.rowCount()) if table.rowViewportPosition(r) >= 0
             and table.rowViewportPosition(r) + table.rowHeight(r) <= table.viewport().height()]
    return {"plots": plots, "legend": [legend.x(), legend.y(), legend.width(), legend.height()],
            "legend_rows": len(view.plots._legend.items),
            "table_rows": table.rowCount(), "table_rows_shown": len(whole)}


def box(r: QRectF) -> list[float]:
    return [r.x(), r.y(), r.width(), r.height()]


def drawn_ticks(axis) -> list[tuple[QRectF, str]]:
    """(box in the axis's coordinates, text) of every tick label the axis draws now (its
    own drawing specification)."""
    image = QImage(8, 8, QImage.Format.Format_ARGB32)
    painter = QPainter(image)
    try:
        specs = axis.generateDrawSpecs(painter)
    finally:
        painter.end()
    return [] if specs is None else [(rect, text) for rect, _, text in specs[2] if text.strip()]


def tick_labels(axis) -> list[list[float]]:
    """The scene boxes of the tick labels the axis draws now."""
    return [box(axis.mapRectToScene(rect)) for rect, _ in drawn_ticks(axis)]


def stacks_report(app: QApplication, window) -> dict:
    """Every plot of the Kinematics (with the lever plots shown) and Forces tabs: its view
    box, the left axis' title and tick-label boxes, the lowest plot's x tick labels (scene
    px), and whether the stack's view is as tall as its plots need (it scrolls)."""
    out = {}
    for name, view in (("kinematics", window.plots), ("forces", window.forces)):
        window.tabs.setCurrentWidget(view)
        stack = view._stack
        for series in stack._series:
            stack.set_plot_visible(series.key, True)
        settle(app)
        stack.ensure_current()
        settle(app)
        plots = []
        for series in stack._series:
            item = stack._plots[series.key].item
            left, bottom = item.getAxis("left"), item.getAxis("bottom")
            title = left.label
            plots.append({"key": series.key, "box": box(item.vb.sceneBoundingRect()),
                          "title": box(title.sceneBoundingRect()) if title.isVisible() else None,
                          "title_text": title.toPlainText(),
                          "ticks": tick_labels(left),
                          "x_ticks": tick_labels(bottom) if bottom.style["showValues"] else None})
        layout = stack._view.ci.layout
        out[name] = {"plots": plots, "view_height": stack._view.height(),
                     "needed_height": layout.effectiveSizeHint(Qt.SizeHint.MinimumSize).height()}
    return out


def polygons_report(app: QApplication, window, angles: list[float]) -> list[dict]:
    """The vector-diagram pane as shown: per kind and crank angle, what its canvas paints
    (text ink boxes, arrowhead boxes, the vectors' box; recorded, device px), the canvas
    and the visible part of its scroll area."""
    from paint_recorder import PaintRecorder, drawing_box
    window.docks["polygons"].show()
    window.docks["polygons"].raise_()
    settle(app)
    view = window.polygon_view
    out = []
    for kind in ("velocity", "acceleration", "force"):
        view.set_kind(kind)
        for angle in angles:
            window.model.set_angle_deg(angle)
            settle(app)
            canvas = view.canvas
            image = QImage(canvas.size(), QImage.Format.Format_ARGB32)
            image.setDotsPerMeterX(round(canvas.logicalDpiX() / 0.0254))
            image.setDotsPerMeterY(round(canvas.logicalDpiY() / 0.0254))
            painter = PaintRecorder(image)
            painter.setFont(canvas.font())
            view.paint(painter, view.canvas_rect())
            painter.end()
            port = view.scroll.viewport()
            out.append({"kind": kind, "angle": angle, "canvas": size(canvas.size()),
                        "viewport": size(port.size()), "dock": size(window.docks["polygons"].size()),
                        "texts": [[t, box(b)] for t, b in painter.texts],
                        "heads": [box(h) for h in painter.heads],
                        "drawing": box(drawing_box(painter.lines))})
    return out


def explore_report(app: QApplication, window) -> dict:
    """The Explore tab after its first map: the map's height against the tab's, the colour
    bar's title and every tick label's box against the map's view (scene px)."""
    import time
    view = window.explore
    window.tabs.setCurrentWidget(view)
    deadline = time.monotonic() + 60
    while (view.result is None or view.runner.job is not None) and time.monotonic() < deadline:
        settle(app, 5)
        time.sleep(0.02)
    settle(app)
    heat = view.map
    shown = heat.mapToScene(heat.viewport().rect()).boundingRect()
    axes = {"left": heat.getPlotItem().getAxis("left"), "bottom": heat.getPlotItem().getAxis("bottom"),
            "colorbar": heat.colorbar.axis}
    return {"map_height": heat.height(), "tab_height": view.height(),
            "colorbar_title": heat.colorbar.axis.label.toPlainText() if heat.colorbar.axis.label.isVisible() else "",
            "colorbar_title_box": box(heat.colorbar.axis.label.sceneBoundingRect()),
            "view": box(shown), "ticks": {name: tick_labels(axis) for name, axis in axes.items()}}


def parse(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser()
    parser.add_argument("--settings", required=True)
    parser.add_argument("--lang", default="en")
    parser.add_argument("--speeds", action="append", default=[])
    parser.add_argument("--resize", help="WxH before closing (to save that geometry)")
    parser.add_argument("--library", action="store_true", help="then show the library pane and report it")
    parser.add_argument("--compare", action="store_true", help="then compare two designs and report the plots")
    parser.add_argument("--stacks", action="store_true", help="report the plots of each case")
    parser.add_argument("--variant", help="the ram drive (block, rod)")
    parser.add_argument("--explore", action="store_true", help="report the Explore tab's map")
    parser.add_argument("--polygons", help="crank angles (°, comma separated): report the vector diagrams")
    return parser.parse_args(argv)


def fresh_start(app: QApplication, locale: QLocale, name: str) -> None:
    """The language, locale and display name the process started with, as the next
    probe's window would find them in a process of its own; and no job of the last
    window still running."""
    from shaperapp.widgets import i18n
    from shaperapp.widgets.worker import COLLECTOR
    assert COLLECTOR.join(60.0), "a worker thread of the last probe still runs"
    i18n.set_language("en")
    QLocale.setDefault(locale)
    QGuiApplication.setApplicationDisplayName(name)
    settle(app)


def probe(app: QApplication, args: argparse.Namespace, closed: list) -> dict:
    """One probe: a fresh window with ``args``' settings file, measured, closed and kept
    in ``closed`` (alive, as a process of one probe keeps its window to the end)."""
    from shaperapp.window.main_window import MainWindow
    from shaperapp.design.model import DesignModel
    window = MainWindow(DesignModel(), QSettings(args.settings, QSettings.Format.IniFormat))
    window.set_language(args.lang)
    window.show()
    settle(app)
    closed.append(window)
    report = {"screen": rect(window.screen().availableGeometry()), "language": args.lang, "cases": []}
    if args.variant:
        window.model.set_spec(variant=args.variant)
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
            "results_area": window.dockWidgetArea(window.docks["results"]).name,
            "results_tabbed_with": [d.objectName() for d in window.tabifiedDockWidgets(window.docks["results"])],
            "tables": [table_report(app, t) for t in window.metrics.tables()],
        })
        if args.stacks:
            report["cases"][-1]["stacks"] = stacks_report(app, window)
    if args.library:
        window.library_dock.show()
        settle(app)
        view = window.library.view
        report["library"] = {"floating": window.library_dock.isFloating(),
                             "area": window.dockWidgetArea(window.library_dock).name,
                             "tabbed_with": [d.objectName() for d in window.tabifiedDockWidgets(window.library_dock)],
                             "frame": rect(window.frameGeometry()), "dock": rect(window.library_dock.frameGeometry()),
                             "rows_room": view.viewport().height() // max(view.verticalHeader().defaultSectionSize(), 1)}
    if args.explore:        # before the comparison, which changes the design
        report["explore"] = explore_report(app, window)
    if args.compare:
        report["compare"] = compare_report(app, window)
    if args.polygons:
        report["polygons"] = polygons_report(app, window, [float(a) for a in args.polygons.split(",")])
    if args.resize:
        w, h = (int(v) for v in args.resize.split("x"))
        window.resize(w, h)
        settle(app)
        report["resized"] = size(window.size())
    window.model.set_clean("")
    window.close()
    window.settings.sync()
    return report


def main(argv: list[str]) -> int:
    jobs = [[]]
    for arg in argv:
        if arg == "--next":
            jobs.append([])
        else:
            jobs[-1].append(arg)
    jobs = [parse(job) for job in jobs]
    from shaperapp.widgets.style import configure_plots
    configure_plots()
    app = QApplication(sys.argv[:1])
    start = (QLocale(), QGuiApplication.applicationDisplayName())
    closed: list = []
    for i, args in enumerate(jobs):
        if i:
            fresh_start(app, *start)
        print(json.dumps(probe(app, args, closed)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
