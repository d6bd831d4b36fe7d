"""PySide6 + pyqtgraph front end of the shaper designer.

One :class:`~shaperapp.design.model.DesignModel` holds the design and its results;
each widget module builds itself from the model and never calls another widget.
"""
