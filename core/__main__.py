"""``python -m core`` is the ``shaper`` command."""
import sys

from .cli import main

sys.exit(main())
