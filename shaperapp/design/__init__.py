"""The design being edited: the model and its results, undo, the document (file), the input forms."""
