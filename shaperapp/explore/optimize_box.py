"""The Explore tab's Optimize group: the objective, which of the map's two parameters
are free, the proposal found and the one step back from it.

A widget of its own beside the map's controls because it has its own state: the
proposal it loaded stays undoable from here only while it is the undo stack's top.
The view runs the job (one worker for the map and the optimizer) and hands the
result to :meth:`OptimizeBox.proposal_loaded`. Texts keep the tab's translation
context, "ExploreView", so the catalogue keeps its entries.
"""
from __future__ import annotations

from typing import Callable

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtWidgets import QCheckBox, QComboBox, QGridLayout, QGroupBox, QLabel, QPushButton, QWidget

from shaperapp.design.model import DesignModel

translate = QCoreApplication.translate   # lupdate extracts translate("Context", "text")


class OptimizeBox(QGroupBox):
    """Objective, free parameters, the Optimize button and the proposal's message."""

    def __init__(self, model: DesignModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self._label = QLabel()
        self.objective = QComboBox()
        self.free = [QCheckBox(), QCheckBox()]
        for box in self.free:
            box.setChecked(True)
        self.optimize = QPushButton()
        self.undo_proposal = QPushButton()      # back to the design before the optimum, one step
        self.undo_proposal.setVisible(False)
        self._proposal_index = -1               # the undo stack's index right after loading it
        self.optimum = QLabel()
        self.optimum.setWordWrap(True)
        self.optimum.setVisible(False)
        self._message: Callable[[], str] = str     # the optimizer's message, made in the current language
        grid = QGridLayout(self)
        grid.addWidget(self._label, 0, 0)
        grid.addWidget(self.objective, 0, 1)
        grid.addWidget(self.optimize, 0, 2)
        grid.addWidget(self.free[0], 1, 0)
        grid.addWidget(self.free[1], 1, 1)
        grid.addWidget(self.optimum, 2, 0, 1, 2)
        grid.addWidget(self.undo_proposal, 2, 2, Qt.AlignmentFlag.AlignTop)
        self.undo_proposal.clicked.connect(self._undo_proposal)
        model.undo_stack.indexChanged.connect(self._proposal_still_on_top)

    def retranslate(self) -> None:
        self._label.setText(translate("ExploreView", "Objective"))
        self.optimize.setText(translate("ExploreView", "Optimize"))
        self.setTitle(translate("ExploreView", "Optimize over the map's ranges"))
        self.free[0].setText(translate("ExploreView", "vary across"))
        self.free[1].setText(translate("ExploreView", "vary up"))
        for box in self.free:
            box.setToolTip(translate("ExploreView", "Let Optimize change this parameter. K and H are your "
                                     "requirements: they stay fixed unless you tick this."))
        self.undo_proposal.setText(translate("ExploreView", "Undo proposal"))
        self.undo_proposal.setToolTip(translate(
            "ExploreView", "Back to the design before Optimize (Edit › Undo does the same)"))
        self.say(self._message)

    def say(self, message: Callable[[], str]) -> None:
        """Show the optimizer's message, hidden (no empty line under the map) when there is
        none. ``message`` makes the text, and makes it again in the new language when the
        language changes (``retranslate``): a text made once stayed in the old one."""
        self._message = message
        text = message()
        self.optimum.setText(text)
        self.optimum.setVisible(bool(text))

    def proposal_loaded(self) -> None:
        """The model's last undo step is the proposal: Undo proposal takes that one back."""
        self._proposal_index = self._model.undo_stack.index()
        self.undo_proposal.setVisible(True)
        self._proposal_still_on_top(self._proposal_index)

    def _undo_proposal(self) -> None:
        if self._model.undo_stack.index() == self._proposal_index:
            self._model.undo_stack.undo()

    def _proposal_still_on_top(self, index: int) -> None:
        """(the stack's indexChanged: the index comes with it, also while the stack goes)"""
        self.undo_proposal.setEnabled(index == self._proposal_index)
