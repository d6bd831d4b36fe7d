"""A part of the design beside the linkage (the cam, the gear pair): the model, form and tab they share."""
