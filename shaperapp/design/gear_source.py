"""Where the GUI finds the design's gear pair: the one place the report and the drawing
dialogs ask, so pointing it at the Gear tab's model is a change here alone."""
from __future__ import annotations

from typing import TYPE_CHECKING

from core.gear.file import gear_from_dict

if TYPE_CHECKING:
    from core.gear import GearPairInputs
    from shaperapp.design.model import DesignModel


def design_gear(model: "DesignModel") -> "GearPairInputs | None":
    """The inputs of the design's gear pair, as Save would write them under "gear" (the
    Gear tab's, once it registers the part; else the opened file's); None without one.
    DesignError names the key of a "gear" object that is not valid."""
    data = model.saved_parts().get("gear")
    return None if data is None else gear_from_dict(data)
