"""The Class dialog's Chinese line for a value a row left to its design file: the table's
refusal names the column and "(got 300 from --base)"; the dialog gives both in Chinese
(the value kept, its source said), as it gives the row's own values."""
from __future__ import annotations

import pytest

from shaperapp.widgets import i18n


@pytest.fixture
def chinese(qapp):
    assert i18n.set_language("zh_CN")
    yield
    i18n.set_language("en")


def test_a_value_from_the_base_is_said_in_chinese(chinese):
    from shaperapp.course.class_messages import table_message
    text = table_message("tasks.csv line 28, column stroke: must be > 300.007 mm for this crank and K, so that "
                         "the ram guide its rule places clears the crank (got 300 from --base)")
    assert text.startswith("tasks.csv 第 28 行，stroke 列：") and text.endswith("（输入的是 300，取自 --base 文件）")
    assert "from" not in text and "got" not in text
    mine = table_message("tasks.csv line 3, column K: must be > 1 and ≤ 5 (got 0.9)")
    assert mine.endswith("（输入的是 0.9）")
    theirs = table_message("tasks.csv line 3, column K: must be > 1 and ≤ 5 (got 0.9 from the design file)")
    assert theirs.endswith("（输入的是 0.9，取自设计文件）")
