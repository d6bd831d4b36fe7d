"""Jobs for the export's child process that misbehave on purpose (tests only): the child
imports them by module name, so a test puts this folder on the child's PYTHONPATH."""
import time

from core.atomic import atomic_write


def stuck_report(progress, file_done, path, **_inputs):
    """Begin writing ``path`` (its temporary file is on disk), then hang without ever
    looking at ``progress`` again: deaf to Cancel, as a long step would be."""
    def pieces():
        yield b"%PDF-1.4 begun"
        progress.note(0.5)
        while True:
            time.sleep(1.0)
    atomic_write(path, pieces())
