"""Image export of every view: clear errors for bad targets, nothing written then,
pyqtgraph's own (broken) export out of the menus, and vector rendering into any painter."""
from __future__ import annotations

import os

import pytest
from PySide6.QtCore import QRectF, QSize
from PySide6.QtGui import QImage, QPainter
from PySide6.QtSvg import QSvgGenerator, QSvgRenderer
from PySide6.QtTest import QTest

from shaperapp.design.model import DesignModel
from shaperapp.plots.forces_panel import ForcesPanel
from shaperapp.plots.kinematics import PlotsWidget
from shaperapp.scheme.view import SchemeWidget

from gui_helpers import shown

VIEWS = {"scheme": SchemeWidget, "plots": PlotsWidget, "forces": ForcesPanel}


@pytest.fixture(params=list(VIEWS))
def view(request, qtbot, model):
    return shown(qtbot, VIEWS[request.param](model), 800, 600)


@pytest.fixture(scope="module", params=list(VIEWS))
def refusing_view(request, qapp):
    """One view of each kind, shown, for the tests whose target is refused: export_image
    checks the target (image_export.image_type) before it draws anything, and what it
    brings up to date first (the scheme's catch-up, the stacks' ensure_current) a shown
    view has done already, so these tests leave the view as they found it (its grab and
    its SVG compared before and after each refusal, docs/performance.md). A view costs
    about 0.1 s to build and as much to tear down: 15 builds were most of the module."""
    widget = VIEWS[request.param](DesignModel())
    widget.resize(800, 600)
    widget.show()
    QTest.qWaitForWindowExposed(widget)
    yield widget
    widget.close()
    widget.deleteLater()


@pytest.mark.parametrize("name", ["picture.xyz", "picture", "picture.png.txt"])
def test_unknown_type_is_a_clear_value_error(refusing_view, tmp_path, name):
    target = tmp_path / name
    with pytest.raises(ValueError) as caught:
        refusing_view.export_image(str(target))
    message = str(caught.value)
    assert str(target) in message and ".png" in message and ".svg" in message
    assert list(tmp_path.iterdir()) == []


def test_missing_folder_is_a_clear_os_error(refusing_view, tmp_path):
    target = tmp_path / "no such folder" / "picture.png"
    with pytest.raises(OSError) as caught:
        refusing_view.export_image(str(target))
    assert str(target.parent) in caught.value.strerror
    assert "does not exist" in caught.value.strerror
    assert caught.value.filename == str(target)
    assert list(tmp_path.iterdir()) == []


def test_target_that_is_a_folder_is_refused(refusing_view, tmp_path):
    folder = tmp_path / "shot.png"
    folder.mkdir()
    with pytest.raises(OSError) as caught:
        refusing_view.export_image(str(folder))
    assert str(folder) in caught.value.strerror
    assert list(folder.iterdir()) == []


def test_folder_under_a_file_is_refused(refusing_view, tmp_path):
    blocker = tmp_path / "file.txt"
    blocker.write_text("x")
    with pytest.raises(OSError):
        refusing_view.export_image(str(blocker / "picture.svg"))
    assert blocker.read_text() == "x"


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0,
                    reason="permissions do not stop root")
def test_unwritable_folder_is_a_clear_os_error(refusing_view, tmp_path):
    folder = tmp_path / "locked"
    folder.mkdir()
    folder.chmod(0o500)
    try:
        with pytest.raises(OSError) as caught:
            refusing_view.export_image(str(folder / "picture.png"))
        assert "not writable" in caught.value.strerror
    finally:
        folder.chmod(0o700)


def test_good_targets_still_write_png_and_svg(view, tmp_path):
    png, svg = tmp_path / "a.png", tmp_path / "a.SVG"      # the type's case does not matter
    view.export_image(str(png))
    image = QImage(str(png))
    assert not image.isNull() and image.width() >= 1600
    view.export_image(str(svg))
    assert QSvgRenderer(str(svg)).isValid()


def test_render_into_any_painter(view, tmp_path):
    """render(painter, rect) draws the view as vectors, e.g. for a report page."""
    generator = QSvgGenerator()
    path = tmp_path / "page.svg"
    generator.setFileName(str(path))
    generator.setSize(QSize(600, 400))
    generator.setViewBox(QRectF(0, 0, 600, 400))
    painter = QPainter(generator)
    try:
        view.render(painter, QRectF(0, 0, 600, 400))
    finally:
        painter.end()
    text = path.read_text(encoding="utf-8")
    assert QSvgRenderer(str(path)).isValid()
    assert text.count("<path") + text.count("<polyline") > 10


def test_no_pyqtgraph_export_in_any_context_menu(qtbot, model):
    """pyqtgraph's Export… → SVG on the scheme ended in 'An internal error occurred'."""
    widgets = [SchemeWidget(model), PlotsWidget(model), ForcesPanel(model)]
    scenes = [widgets[0].plot_widget().scene(), widgets[1].stack()._view.scene(),
              widgets[2].plots.stack()._view.scene()]
    for widget in widgets:
        qtbot.addWidget(widget)
    for scene in scenes:
        assert scene.contextMenu == []
        for item in scene.items():
            if hasattr(item, "getContextMenus"):
                menus = item.getContextMenus(None)
                actions = menus if isinstance(menus, list) else (menus.actions() if menus else [])
                assert not any("Export" in a.text() for a in actions)
    texts = [a.text() for a in widgets[0].context_menu().actions()]
    assert texts == [widgets[0].fit_action.text(), widgets[0].dimensions_action.text(),
                     widgets[0].forces_action.text()]
