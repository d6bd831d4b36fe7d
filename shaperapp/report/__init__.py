"""The design report (设计说明书): one content, written as an A4 PDF or as HTML.

``content`` builds the report as a list of blocks from ``core`` results (and
figures drawn by the app's own views and painters); ``pdf`` and ``html`` write
those blocks; ``command`` is ``shaper report``; ``dialog`` is File › Export report….
"""
