"""What every package of core stands on, knowing nothing of shapers.

``errors`` the one domain error (and the file and write errors); ``arrays`` and ``text``
small array and user-text helpers; ``figure_text`` how a figure is written in a table;
``progress`` how far a long job is; ``blas`` one BLAS thread, set before numpy loads.
"""
