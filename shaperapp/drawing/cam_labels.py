"""The cam sheet's words in the user's language (``core.drawing.cam_sheet.ENGLISH``'s keys)."""
from __future__ import annotations

from shaperapp.cam.words import cam_words

from .labels import title_labels


def cam_labels() -> dict[str, str]:
    """Every text of the feed cam's sheet: its title block's and the cam's own."""
    return {**title_labels(), **cam_words()}
