"""The window's actions' texts and tips, in the current language (the window sets them
on every language change; the context stays the window's, so the catalogue is one)."""
from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QAction


translate = QCoreApplication.translate


def action_texts(w) -> list[tuple[QAction, str, str]]:
    """(action, text, tip) of the window ``w``'s menu actions."""
    return [
        (w.act_new, translate("MainWindow", "&New"), translate("MainWindow", "Start a new design from the defaults")),
        (w.act_open, translate("MainWindow", "&Open…"), translate("MainWindow", "Open a design file")),
        (w.act_save, translate("MainWindow", "&Save"), translate("MainWindow", "Save the design")),
        (w.act_save_as, translate("MainWindow", "Save &As…"), translate("MainWindow", "Save the design under a new name")),
        (w.act_csv, translate("MainWindow", "Export curves to &CSV…"), translate("MainWindow", "All speeds, at the form's angle step")),
        (w.act_forces_csv, translate("MainWindow", "Export &forces to CSV…"),
         translate("MainWindow", "Crank torque, power and joint forces, all speeds")),
        (w.act_plots_img, translate("MainWindow", "Export &plots (PNG/SVG)…"), translate("MainWindow", "Save the plots of the current tab as an image")),
        (w.act_scheme_img, translate("MainWindow", "Export sc&heme (PNG/SVG)…"), translate("MainWindow", "Save the mechanism drawing as an image")),
        (w.act_scheme_dxf, translate("MainWindow", "Export scheme as D&XF…"),
         translate("MainWindow", "The mechanism at the current crank angle for CAD: 1:1 in mm, with its dimensions")),
        (w.act_report, translate("MainWindow", "Export r&eport (PDF/HTML)…"),
         translate("MainWindow", "The design report: dimensions, positions table, polygons, forces, flywheel")),
        (w.act_sheet, translate("MainWindow", "Export &drawing sheet (PDF/SVG/DXF)…"),
         translate("MainWindow", "The course design's drawing sheet on A0–A3 paper, with a preview")),
        (w.act_course, translate("MainWindow", "Export course desi&gn…"),
         translate("MainWindow", "The report and every drawing sheet into one folder, as shaper course writes them")),
        (w.act_class, translate("MainWindow", "C&lass course design…"),
         translate("MainWindow", "A whole class from a table of data sets: each student's folder, the task sheets and "
                   "the answer key, as shaper class writes them")),
        (w.act_quit, translate("MainWindow", "&Quit"), ""),
        (w.act_goto, translate("MainWindow", "&Go to Crank Angle…"), translate("MainWindow", "Move the mechanism to a crank angle you type")),
        (w.act_fit_plots, translate("MainWindow", "Fi&t plots"), translate("MainWindow", "Show the whole cycle in the plots of the current tab")),
        (w.act_reset_layout, translate("MainWindow", "&Reset layout"),
         translate("MainWindow", "Put every pane back in its place for this window size")),
        (w.act_library_save, translate("MainWindow", "&Save design to library…"), ""),
        (w.act_compare, translate("MainWindow", "&Compare designs"), ""),
        (w.act_about, translate("MainWindow", "&About"), ""),
        (w.act_guide, translate("MainWindow", "User &guide"), translate("MainWindow", "Conventions, method, glossary and command line")),
    ]
