"""Names refuse what every text option refuses, and are found as they were stored
(issue 33, item 6).

``--name`` took U+2028 and U+0085 line breaks that ``cover_text`` (the other text
options) refuses; ``--name $'\\u00a0x'`` was stored as ``x`` (Python's strip knows
Unicode white space) but ``show $'\\u00a0x'`` found nothing.
"""
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from core.files.io import save_design
from core.library import Library
from core.library.names import check_name, check_tags
from core.library.store import LibraryError
from core.linkage.spec import Spec
from shaperapp.widgets.command_line import cover_text

from cli_runner import shaper_in_process

DESIGN = ("--crank", "100", "--K", "1.4", "--stroke", "300")
# every character str.splitlines() breaks at, and C1 controls around U+0085
REFUSED = ["\n", "\r", "\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029", "\x80",
           "\x9f", "\x00", "\x7f"]
PADDING = st.text(alphabet=" \t\u00a0\u3000\u2002\u200a", max_size=3)


def design():
    return {"spec": Spec(), "rpm": [40.0], "step_deg": 1.0, "masses": None}


@pytest.mark.parametrize("ch", REFUSED, ids=[f"U+{ord(c):04X}" for c in REFUSED])
def test_a_name_or_tag_with_a_line_break_or_control_character_is_refused(tmp_path, ch):
    library = tmp_path / "L.sqlite"
    with pytest.raises(Exception):       # the rule every other text option keeps
        cover_text("--title", f"a{ch}b")
    status, _, err = shaper_in_process("library", "add", *DESIGN, "--name", f"a{ch}b", "--library", library)
    assert status == 2 and err.count("\n") == 1 and err.startswith("shaper: error: --name: ")
    status, _, err = shaper_in_process("library", "add", *DESIGN, "--name", "ok", "--tags", f"t{ch}u",
                                       "--library", library)
    assert status == 2 and err.startswith("shaper: error: --tags: ")
    with Library(library) as lib:
        lib.add("a", design())
        assert lib.names() == ["a"]
        with pytest.raises(LibraryError) as caught:
            lib.rename("a", f"b{ch}c")
        assert caught.value.kind == "name" and lib.names() == ["a"]


def test_a_file_whose_name_cannot_be_an_entry_name_is_named(tmp_path):
    path = tmp_path / "a\u2028b.shaper.json"
    save_design(path, Spec(), [40.0], 1.0)
    status, _, err = shaper_in_process("library", "import", path, "--library", tmp_path / "L.sqlite")
    assert status == 2 and err.count("\n") == 1 and err.startswith("shaper: error: FILE: ")
    assert "a\\u2028b.shaper.json" in err


def test_the_name_of_the_issue_is_found_as_it_was_typed(tmp_path):
    library = tmp_path / "L.sqlite"
    status, _, err = shaper_in_process("library", "add", *DESIGN, "--name", "\u00a0x", "--library", library)
    assert status == 0, err
    for shown in ("\u00a0x", "x", "x\u3000"):
        status, out, err = shaper_in_process("library", "show", shown, "--library", library)
        assert status == 0 and out.startswith("name"), err
    status, _, err = shaper_in_process("library", "rename", "\u00a0x", "y", "--library", library)
    assert status == 0, err
    status, _, err = shaper_in_process("library", "remove", "\u2002y", "--library", library)
    assert status == 0, err


@settings(max_examples=40, deadline=None)
@given(core=st.text(alphabet=st.characters(blacklist_categories=("Cs", "Cc", "Zs", "Zl", "Zp")),
                    min_size=1, max_size=20), before=PADDING, after=PADDING)
def test_what_is_stored_is_what_is_looked_up(tmp_path_factory, core, before, after):
    """Property: a name saved with white space around it is found by the same text, and
    by its stored form; a name check and a lookup agree on what is stored."""
    typed = before + core + after
    stored = check_name(typed)
    if "," not in stored:               # a comma separates tags
        assert check_tags([typed]) == (stored,)
    with Library(tmp_path_factory.mktemp("names") / "L.sqlite") as lib:
        lib.add(typed, design())
        assert typed in lib and stored in lib
        assert lib.get(typed).name == stored == lib.names()[0]
        lib.remove(typed)
        assert lib.count() == 0
