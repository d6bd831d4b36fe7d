"""The main window: docks, menus, actions, the animation bar, help and the saved layout."""
