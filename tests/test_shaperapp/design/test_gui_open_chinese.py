"""A design file the Chinese window refuses is refused in Chinese (issue 32, item 5): every
case of the hostile corpus, opened through the document as the File menu does, gives a
message with no English word but the file's own (its path, what it holds)."""
import errno
import os
import stat

import pytest
from PySide6.QtCore import QSettings

from hostile_files import CASES, build_case
from language_checks import english_words, words_of
from shaperapp.design.document import Document
from shaperapp.design.model import DesignModel
from shaperapp.widgets import i18n

# The values a design's input mode may take: identifiers a file holds, named as they are.
MODES = {"synthesis", "dimensions"}


@pytest.fixture(scope="module")
def document(qapp, tmp_path_factory):
    assert i18n.set_language("zh_CN")
    folder = tmp_path_factory.mktemp("zh")
    yield Document(DesignModel(), QSettings(str(folder / "s.ini"), QSettings.Format.IniFormat))
    i18n.set_language("en")


def file_words(path) -> set[str]:
    """The words a small regular file holds (a message may quote them)."""
    try:
        info = os.stat(path)
    except OSError:
        return set()
    if not stat.S_ISREG(info.st_mode) or info.st_size > 100_000:
        return set()
    try:
        return words_of(open(path, "rb").read().decode("utf-8", "replace"))
    except OSError:
        return set()


def failure(document, action) -> str:
    """The one message ``action()`` makes the document fail with."""
    said = []
    document.failed.connect(said.append)
    try:
        assert not action()
    finally:
        document.failed.disconnect(said.append)
    assert len(said) == 1
    return said[0]


@pytest.mark.parametrize("name", sorted(CASES))
def test_a_refused_file_is_refused_in_chinese(document, tmp_path, name):
    path = build_case(name, tmp_path)
    said = failure(document, lambda: document.open_path(str(path)))
    assert said.startswith("无法打开")
    assert english_words(said, words_of(str(path)) | file_words(path) | MODES) == [], said


def test_a_save_into_a_missing_folder_fails_in_chinese(document, tmp_path):
    path = tmp_path / "missing" / "a.shaper.json"
    said = failure(document, lambda: document.save_to(str(path)))
    assert str(path) in said
    assert english_words(said, words_of(str(path))) == [], said


@pytest.mark.parametrize("number", [errno.ENOSPC, errno.EACCES, errno.EROFS, errno.EDQUOT])
def test_a_failed_save_says_why_in_chinese(document, tmp_path, monkeypatch, number):
    """The reasons core gives a WriteError (core.base.errors.os_reason), in the UI's language."""
    from core.base.errors import WriteError

    def full(path, *args, **kwargs):
        raise WriteError(path, OSError(number, os.strerror(number)))
    monkeypatch.setattr("shaperapp.design.document.save_design", full)
    path = tmp_path / "a.shaper.json"
    said = failure(document, lambda: document.save_to(str(path)))
    assert english_words(said, words_of(str(path))) == [], said
