"""``shaper report`` and ``shaper drawing`` on the inputs of issue 33: partial or zero
loads, too-long names, undecodable bytes, long design-file names. Each gives a result or
exit status 2 with one line naming the option or file; never status 1."""
import os

import pytest

from cli_runner import shaper_in_process

DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40"]
ZERO = ["--lever-mass", "0", "--lever-inertia", "0", "--ram-mass", "0", "--cut-force", "0"]


@pytest.mark.parametrize("command, loads, name", [
    ("report", ["--lever-mass", "20"], "a.html"),
    ("report", ZERO, "z.html"),
    ("drawing", ZERO + ["--content", "forces"], "z.dxf"),
    ("drawing", ["--cut-force", "7000", "--no-gravity", "--content", "forces"], "p.svg"),
], ids=["report partial", "report zero", "drawing zero", "drawing cut force only"])
def test_partial_and_zero_loads_give_a_file(command, loads, name, tmp_path):
    status, out, err = shaper_in_process(command, *DESIGN, *loads, "-o", tmp_path / name)
    assert (status, err) == (0, "")
    assert (tmp_path / name).stat().st_size > 0 and out.startswith("wrote ")


LONG = "a" * 252        # + ".pdf": 256 bytes, one more than a file name may have


@pytest.mark.parametrize("command, extra, suffix", [
    ("drawing", [], ".pdf"), ("drawing", [], ".svg"), ("drawing", [], ".dxf"),
    ("drawing", ["--content", "scheme"], ".dxf"), ("report", [], ".pdf"), ("report", [], ".html"),
])
def test_a_name_too_long_is_refused_naming_the_option(command, extra, suffix, tmp_path):
    """As cam, curves and every other writer say it (core.files.atomic), before any work."""
    target = tmp_path / (LONG + suffix)
    status, out, err = shaper_in_process(command, *DESIGN, *extra, "-o", target)
    assert status == 2 and out == ""
    assert err == f"shaper: error: --output: cannot write {target}: the name is too long\n"
    assert list(tmp_path.iterdir()) == []


UNDECODABLE = "x\udcffy"        # how Python holds the byte 0xFF of a non-UTF-8 argument


@pytest.mark.parametrize("command, option, suffix", [
    ("drawing", "--title", ".dxf"), ("drawing", "--school", ".dxf"), ("drawing", "--student", ".pdf"),
    ("drawing", "--title", ".svg"), ("report", "--title", ".html"), ("report", "--school", ".html"),
    ("report", "--student", ".pdf"),
])
def test_an_undecodable_byte_in_a_text_option_is_refused_naming_it(command, option, suffix, tmp_path):
    """Every writer the same: not status 1 for DXF and HTML and a U+FFFD for PDF and SVG."""
    status, out, err = shaper_in_process(command, *DESIGN, option, UNDECODABLE, "-o", tmp_path / f"t{suffix}")
    assert status == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(f"shaper: error: {option}: must be text; it holds a byte that is not ")
    assert list(tmp_path.iterdir()) == []


@pytest.fixture(scope="module")
def design_text(tmp_path_factory):
    """A valid design file's text (exported from a library)."""
    folder = tmp_path_factory.mktemp("design")
    lib, path = folder / "lib.sqlite", folder / "d.shaper.json"
    assert shaper_in_process("library", "add", *DESIGN, "--name", "d", "--library", lib)[0] == 0
    assert shaper_in_process("library", "export", "d", "-o", path, "--library", lib)[0] == 0
    return path.read_text(encoding="utf-8")


NAMES = [("b" * 205, "b" * 199 + "…"),                 # no --title given: not "--title: at most 200"
         ("x\udcffy", "x\ufffdy"),                       # a byte that is not UTF-8 in the file's name
         ("tab\x01esc\x1bdel\x7f", "tab\ufffdesc\ufffddel\ufffd")]
WRITERS = [("drawing", ".dxf"), ("drawing", ".svg"), ("report", ".html")]


# (the SVG already showed an undecodable byte as U+FFFD: the case that passed before is left out)
@pytest.mark.parametrize("stem, shown, command, suffix", [
    (*name, *writer) for name in NAMES for writer in WRITERS if (name[0], writer[1]) != ("x\udcffy", ".svg")])
def test_a_design_file_is_titled_by_its_name_made_printable(design_text, tmp_path, stem, shown, command,
                                                           suffix):
    """The file's name titles the sheet or report: a long one is cut, an undecodable byte or a
    control character is shown as U+FFFD; the file is never refused for its name."""
    design = tmp_path / f"{stem}.shaper.json"
    design.write_text(design_text, encoding="utf-8")
    target = tmp_path / f"out{suffix}"
    status, _, err = shaper_in_process(command, "--design", design, "-o", target)
    assert (status, err) == (0, "")
    if suffix == ".dxf":
        import ezdxf
        texts = [t.dxf.text for t in ezdxf.readfile(target).modelspace().query("TEXT")]
        # the title block's cell cuts a long name to what fits, with "…"
        assert any(t == shown or (t.endswith("…") and shown.startswith(t[:-1])) for t in texts)
    elif suffix == ".svg":
        import xml.etree.ElementTree as ET
        root = ET.parse(target).getroot()
        assert root.find("{http://www.w3.org/2000/svg}title").text == shown
    else:
        page = target.read_text(encoding="utf-8")
        assert "<title>" in page and shown in page
        assert not any(ch in page for ch in "\x01\x1b\x7f")


@pytest.mark.parametrize("suffix", [".html", ".pdf"])
def test_a_compared_file_with_a_control_character_in_its_name_is_labelled_printably(design_text, tmp_path,
                                                                                    suffix):
    """Its name labels the comparison's figures (SVG drawings inside the report): a raw 0x01
    made them unreadable and the report failed with an internal error."""
    base, other = tmp_path / "base.shaper.json", tmp_path / "e\x01f.shaper.json"
    base.write_text(design_text, encoding="utf-8")
    other.write_text(design_text.replace('"time_ratio": 1.4', '"time_ratio": 1.6'), encoding="utf-8")
    target = tmp_path / f"r{suffix}"
    status, _, err = shaper_in_process("report", "--design", base, "--compare-file", other, "-o", target)
    assert (status, err) == (0, "")
    if suffix == ".html":
        page = target.read_text(encoding="utf-8")
        assert "“base”, beside “e\ufffdf”" in page and "\x01" not in page
