"""A text cut with an ellipsis to its room (``sheet.clipped``) is its longest start that fits
with "…", as measuring each shorter start again finds it; found in one pass, since the title
block cuts thousands of candidate lines of a 200-character name."""
from hypothesis import given, strategies as st

from core.drawing.sheet import clipped, text_width


def _shortened_one_by_one(text: str, room: float, height: float) -> str:
    if text_width(text, height) <= room:
        return text
    while text and text_width(text + "…", height) > room:
        text = text[:-1]
    return text + "…" if text else ""


@given(st.text(alphabet="abc XYZ,，机械工程（）…2101éO-AL", max_size=80), st.floats(0.0, 150.0),
       st.sampled_from([1.8, 2.5, 3.5, 5.0, 7.0]))
def test_the_cut_is_the_longest_start_that_fits(text, room, height):
    cut = clipped(text, room, height)
    assert cut == _shortened_one_by_one(text, room, height)
    assert cut == text or text_width(cut, height) <= room
