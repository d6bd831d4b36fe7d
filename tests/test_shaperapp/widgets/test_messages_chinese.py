"""Every message of widgets/messages.py reaches a Chinese user in Chinese (issue 32, item 5):
the templates for core's DesignError texts, the names of the fields, and the reasons a
design file is refused (core.base.errors.FILE_REASONS), each scanned for English words."""
from dataclasses import fields

import pytest

from core.base.errors import FILE_REASONS, DesignError, FileFormatError
from core.linkage.spec import Spec
from language_checks import english_words, words_of
from shaperapp.widgets import i18n, messages


@pytest.fixture
def chinese(qapp):
    assert i18n.set_language("zh_CN")
    yield
    i18n.set_language("en")


def test_every_template_is_chinese(chinese):
    templates = {**messages._translated_templates(), **messages._file_templates()}
    untranslated = {source: text for source, text in templates.items()
                    if english_words(text) or text == source}
    assert untranslated == {}


def test_every_reason_a_file_is_refused_has_a_template():
    assert set(messages._file_templates()) == set(FILE_REASONS)


def test_every_field_a_file_can_name_is_named_in_chinese(chinese):
    from core.cam.file import cam_to_dict
    from core.cam import CamInputs, Program
    from core.forces.masses import MassProperties
    names = [f.name for f in fields(Spec)] + [f.name for f in fields(MassProperties)] + ["rpm", "step", "forces", "cam"]
    names += list(cam_to_dict(CamInputs(arm_mm=120.0, program=Program(15.0, 60.0, 10.0, 60.0)), None))
    shown = {name: messages.field_name(name) for name in names}
    assert {n: s for n, s in shown.items() if s == n or english_words(s)} == {}


@pytest.mark.parametrize("reason", sorted(FILE_REASONS))
def test_a_refused_file_is_described_in_chinese(chinese, reason):
    values = {"too_large": [1], "version": ["2", 1], "no_version": [1], "unreadable": ["No such file"],
              "too_deep": [16], "constant": ["NaN"], "long_integer": [400], "huge_number": ["1e400"],
              "rpm_value": ['"40"'], "duplicate_key": ['"z1"'], "invalid": ["crank = 0: must be > 0 and ≤ 10000 mm"]}.get(reason, [])
    error = FileFormatError(reason, "/tmp/设计.json", *values, errno=2,
                            cause=DesignError("crank", 0.0, "must be > 0 and ≤ 10000 mm"))
    text = messages.describe_file_error(error)
    assert "/tmp/设计.json" in text
    assert english_words(text, words_of("/tmp/设计.json")) == [], text
    assert str(error) == FILE_REASONS[reason].format(*[str(v) for v in values], name="/tmp/设计.json")


def test_a_library_entry_is_named_as_one(chinese):
    error = FileFormatError("not_json", "library entry 'gear'", entry="gear")
    assert messages.describe_file_error(error).startswith("设计库条目“gear”")
    assert english_words(messages.describe_file_error(error), {"gear"}) == []


def test_english_keeps_cores_sentence():
    error = FileFormatError("not_json", "/tmp/a.json")
    assert messages.describe_file_error(error) == str(error) == "/tmp/a.json is not a design file (not valid JSON)"
