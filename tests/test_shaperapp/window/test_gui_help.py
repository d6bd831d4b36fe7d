"""Help: the packaged guide in both languages, the About text with the version."""
import re

import pytest

from core.linkage.geometry import synthesize
from shaperapp.window.help import GuideDialog, about_text, guide_html, version


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_guide_has_every_section(language):
    html = guide_html(language)
    for anchor in ("start", "window", "conventions", "synthesis", "example", "glossary", "files", "cli"):
        assert f'id="{anchor}"' in html
    assert "曲柄" in html and "crank" in html          # the glossary is bilingual in both


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_worked_example_figures_are_the_engine_s(language):
    """The guide's numbers for L1 = 100, K = 1.4, H = 300 are what core computes."""
    html = guide_html(language)
    design = synthesize(100.0, 1.4, 300.0)
    assert f"{design.frame:.2f}" in html and f"{design.lever:.2f}" in html
    assert f"{design.guide_above_crank:.2f}" in html
    from core.linkage.metrics import analyze
    speed = analyze(design, [40.0]).speeds[0]
    assert f"{speed.v_work_max_m_s:.4f}" in html and f"{speed.v_return_max_m_s:.4f}" in html
    assert f"{speed.work_time_s:.3f}" in html and f"{speed.return_time_s:.3f}" in html


def test_unknown_language_falls_back_to_english():
    assert guide_html("fr") == guide_html("en")


def test_about_names_the_installed_version(qapp):
    assert re.match(r"\d+\.\d+", version())
    assert version() in about_text()


def test_guide_dialog_switches_language(qtbot):
    dialog = GuideDialog("en")
    qtbot.addWidget(dialog)
    assert "User guide" in dialog.browser.toPlainText()
    dialog.set_language("zh_CN")
    assert "使用指南" in dialog.browser.toPlainText()



def _plain(text: str) -> str:
    """A menu text as the guide names it: no accelerator marks, no ellipsis."""
    text = re.sub(r"\(&.\)", "", text).replace("&", "").replace("…", "")
    return text.strip()


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_menu_paths_named_in_the_guide_exist(language, tmp_path):
    """Every 'Menu › Entry' the guide tells the user to choose is in the window's menus,
    in the guide's language (a guide that names menus the app lacks misleads)."""
    from PySide6.QtWidgets import QApplication

    from gui_helpers import main_window

    html = guide_html(language)
    paths = re.findall(r"<b>([^<›]+) › ([^<]+)</b>", html)
    assert len(paths) >= 6
    with main_window(tmp_path) as window:
        window.set_language(language)
        QApplication.processEvents()                  # the LanguageChange events
        menus = {_plain(action.text()): action.menu() for action in window.menuBar().actions()}
        for menu_name, entry in paths:
            menu = menus.get(menu_name.strip())
            assert menu is not None, (menu_name, sorted(menus))
            entries = [_plain(a.text()) for a in menu.actions()]
            assert any(e.startswith(entry.strip()) for e in entries), (entry, entries)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_guide_covers_every_subcommand_with_a_command_that_parses(language):
    """The command-line section listed 4 of the 9 subcommands (issue 20 item 9)."""
    import html as html_lib
    import re
    import shlex

    from core.cli import _command_modules, build_parser
    text = html_lib.unescape(guide_html(language).split('id="cli"')[1])
    lines = [line.strip() for line in re.sub(r"<[^>]+>", "\n", text).splitlines()
             if line.strip().startswith("shaper ")]
    named = {shlex.split(line)[1] for line in lines}
    assert set(_command_modules()) <= named, set(_command_modules()) - named
    parser = build_parser()
    for line in lines:
        parser.parse_args(shlex.split(line)[1:])        # each example is a valid command


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_guide_wraps_to_its_window(qtbot, language):
    """No sideways scrolling, at the guide's own size and narrower: the command examples
    (``pre``) made the guide 881 px wide in its 722 px view, with a horizontal scroll bar."""
    dialog = GuideDialog(language)
    qtbot.addWidget(dialog)
    dialog.show()
    qtbot.waitExposed(dialog)
    for width in (dialog.width(), 500):
        dialog.resize(width, dialog.height())
        qtbot.waitUntil(lambda: dialog.browser.viewport().width() < width)
        browser = dialog.browser
        assert browser.document().size().width() <= browser.viewport().width(), width
        qtbot.waitUntil(lambda: browser.horizontalScrollBar().maximum() == 0, timeout=2000)   # laid out
