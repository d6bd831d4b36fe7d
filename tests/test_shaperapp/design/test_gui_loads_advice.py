"""The Loads form's refusals followed as a user follows them: the bound it names, typed into
the marked field, is taken. The idle margin is typed in % and core checks the fraction: the
form said "must be at least 0 and less than 0.5" beside a field in %, so a user who typed 60
(for 60 %) and then 0.49 got an idle margin of 0.49 %, not the 49 % the check allows."""
from __future__ import annotations

import re

import pytest
from PySide6.QtCore import QSettings

from shaperapp.design import document as document_module
from shaperapp.design.document import Document
from shaperapp.design.loads_form import LoadsForm
from shaperapp.design.model import DesignModel


@pytest.fixture
def form(qtbot):
    model = DesignModel()
    form = LoadsForm(model)
    qtbot.addWidget(form)
    form.show()
    return form


def type_text(form, name, text):
    edit = form.field(name)
    edit.setText(text)
    edit.textEdited.emit(text)
    edit.editingFinished.emit()


@pytest.mark.parametrize("typed", ["60", "-1"])
def test_the_idle_margin_is_refused_in_percent_and_its_bound_typed_is_taken(form, typed):
    type_text(form, "idle_percent", typed)
    assert form.marked_fields() == ["idle_percent"]
    low, high = re.search(r"at least (\S+) and less than (\S+) %", form.error_text()).groups()
    assert (float(low), float(high)) == (0.0, 50.0)
    type_text(form, "idle_percent", low if typed == "-1" else "49.99")
    model = form._model
    assert model.forces_error is None and form.marked_fields() == []
    assert model.masses.idle_fraction == pytest.approx(0.0 if typed == "-1" else 0.4999, rel=1e-12)


def test_save_while_the_idle_margin_is_refused_says_it_in_percent(form, tmp_path, monkeypatch):
    """File › Save's question names the refused input as the form does."""
    type_text(form, "idle_percent", "60")
    asked = []
    monkeypatch.setattr(document_module, "use_last_valid", lambda parent, title, reason, question:
                        asked.append(reason) or False)
    document = Document(form._model, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    assert document.confirm_valid(form, saving=True) is False
    assert asked and "less than 50 %" in asked[0] and "0.5" not in asked[0], asked
