"""File › Export course design…: the DXFs' CAD texts (``shaper course --dxf --cad-font``,
issue 40 item 7), chosen in the real options dialog: offered with the DXF alone, the GB
style by default, outlines written when chosen and remembered, and no font for them one
line in the dialog, which stays open."""
import ezdxf
import pytest
from PySide6.QtWidgets import QDialog, QFileDialog, QMessageBox

from export_faults import in_child, last_run
from core.drawing import outline_text
from shaperapp.course.dialog import CourseOptions, CourseOptionsDialog
from shaperapp.widgets.cad_font import CAD_FONT_SETTING


def test_the_cad_texts_come_with_the_dxf_and_are_gb_by_default(window, qtbot):
    dialog = CourseOptionsDialog(window.model, settings=window.settings)
    qtbot.addWidget(dialog)
    assert not dialog.cad_font.isEnabled() and dialog.options().cad_font == "gb"
    dialog.dxf.setChecked(True)
    assert dialog.cad_font.isEnabled() and dialog.options() == CourseOptions("A1", True, 0, "gb")
    dialog.cad_font.setCurrentIndex(dialog.cad_font.findData("outline"))
    assert dialog.options() == CourseOptions("A1", True, 0, "outline")
    dialog.dxf.setChecked(False)                # no DXF: nothing to write outlines into
    assert not dialog.cad_font.isEnabled() and dialog.options().cad_font == "gb"


@pytest.fixture
def chosen(window, monkeypatch, tmp_path):
    """File › Export course design… with the real options dialog, answered by ``choose``
    (called with the dialog, then OK pressed): the folder ``tmp_path / "out"``, the
    report and the PDFs stand-ins in the child, the warnings recorded."""
    out = tmp_path / "out"
    out.mkdir()
    seen = {"out": out, "shown": [], "choose": lambda dialog: None, "open": []}

    def answer(dialog):
        seen["open"].append(dialog)
        seen["choose"](dialog)
        dialog.accept()
        return dialog.result()
    monkeypatch.setattr(CourseOptionsDialog, "exec", answer)
    monkeypatch.setattr(QFileDialog, "getExistingDirectory", lambda *a, **k: str(out))
    monkeypatch.setattr(QMessageBox, "warning", lambda parent, title, text: seen["shown"].append(text))
    in_child(monkeypatch, "shaperapp.course.dialog.write_course_of", __import__("export_faults").quick_course_dxfs)
    return seen


def texts_of(folder) -> dict[str, dict[str, int]]:
    """Each DXF's TEXT entities and solid hatches on the TEXT layer."""
    found = {}
    for path in sorted(folder.glob("*.dxf")):
        msp = ezdxf.readfile(path).modelspace()
        found[path.name] = {"TEXT": len(msp.query("TEXT")),
                            "outlines": sum(h.dxf.solid_fill for h in msp.query("HATCH[layer=='TEXT']"))}
    return found


def pick(paper: str, dxf: bool, cad_font: str | None = None):
    def choose(dialog):
        dialog.paper.setCurrentText(paper)
        dialog.dxf.setChecked(dxf)
        if cad_font is not None:
            dialog.cad_font.setCurrentIndex(dialog.cad_font.findData(cad_font))
    return choose


@pytest.mark.parametrize("cad_font", [None, pytest.param("outline", marks=pytest.mark.slow)])   # 15 s
def test_the_dxfs_texts_are_as_chosen(window, chosen, cad_font):
    """Not choosing writes the GB style; outlines leave no TEXT (as ``--cad-font outline``)."""
    chosen["choose"] = pick("A3", True, cad_font)
    window.act_course.trigger()
    assert last_run(window).state == "done" and chosen["shown"] == []
    found = texts_of(chosen["out"])
    assert sorted(found) == ["01-motion.dxf", "02-kinetostatic.dxf", "03-cam.dxf", "04-gear.dxf"]
    for name, kinds in found.items():
        if cad_font == "outline":
            assert kinds["TEXT"] == 0 and kinds["outlines"] > 50, (name, kinds)
        else:
            assert kinds["TEXT"] > 20 and kinds["outlines"] == 0, (name, kinds)
    assert window.settings.value(CAD_FONT_SETTING, "gb") == (cad_font or "gb")


def test_outlines_without_a_font_keep_the_dialog_open_saying_why(window, chosen, monkeypatch):
    monkeypatch.setattr(outline_text, "OUTLINE_FONTS", (("no-such-font.ttf", 0, "None Such"),))
    outline_text.outline_font.cache_clear()
    try:
        chosen["choose"] = pick("A3", True, "outline")
        window.act_course.trigger()
    finally:
        outline_text.outline_font.cache_clear()
    dialog = chosen["open"][-1]
    assert dialog.result() != QDialog.DialogCode.Accepted           # OK did not close it
    note = dialog.message.text()
    assert note.startswith("No font with Chinese characters is installed for the outlines")
    assert "\n" not in note and "fonts-noto-cjk" in note
    assert list(chosen["out"].iterdir()) == [] and chosen["shown"] == []
    assert window.settings.value(CAD_FONT_SETTING) is None
