"""Edit → Preferences → HoleFill: the task panels' starting values (HoleFill/preferences.py holds
them and their defaults). Registered at FreeCAD's start by InitGui.py, so the page is there before
the workbench is first activated."""
import FreeCAD
from PySide2 import QtWidgets

from HoleFill import preferences

translate = FreeCAD.Qt.translate


class PreferencePage:
    """FreeCAD's Python preference page: `form` is the page, loadSettings/saveSettings are called
    when the dialog opens and when OK or Apply is pressed."""

    def __init__(self, parent=None):
        self.form = QtWidgets.QWidget(parent)
        self.form.setWindowTitle(translate("HoleFill", "HoleFill"))
        self.form.setObjectName("HoleFillPreferences")
        outer = QtWidgets.QVBoxLayout(self.form)
        box = QtWidgets.QGroupBox(translate("HoleFill", "Fill hole: starting values of the task panel"))
        lay = QtWidgets.QFormLayout(box)
        self.widgets = {}
        for name, label in (("FillMethod", translate("HoleFill", "Parameterization:")), ("FillContinuity", translate("HoleFill", "Continuity:")),
                            ("FillOutput", translate("HoleFill", "Output:"))):
            w = QtWidgets.QComboBox()
            w.setObjectName(name)
            w.addItems(list(preferences.CHOICES[name]))
            w.setToolTip(preferences.SETTINGS[name][1])
            lay.addRow(label, w)
            self.widgets[name] = w
        tol = QtWidgets.QDoubleSpinBox()
        tol.setDecimals(7)
        tol.setRange(0.0, 1e3)
        tol.setSpecialValueText(translate("HoleFill", "auto (1e-6 of hole size)"))
        tol.setToolTip(preferences.SETTINGS["FillTolerance"][1])
        lay.addRow(translate("HoleFill", "G0 tolerance:"), tol)
        self.widgets["FillTolerance"] = tol
        ang = QtWidgets.QDoubleSpinBox()
        ang.setDecimals(6)
        ang.setRange(1e-6, 0.5)
        ang.setSingleStep(1e-4)
        ang.setSuffix(translate("HoleFill", " rad"))
        ang.setToolTip(preferences.SETTINGS["FillAngularTolerance"][1])
        lay.addRow(translate("HoleFill", "G1 tolerance:"), ang)
        self.widgets["FillAngularTolerance"] = ang
        outer.addWidget(box)
        outer.addStretch(1)

    def loadSettings(self):
        for name, w in self.widgets.items():
            if isinstance(w, QtWidgets.QComboBox):
                w.setCurrentText(preferences.get(name))
            else:
                w.setValue(preferences.get(name))

    def saveSettings(self):
        for name, w in self.widgets.items():
            preferences.put(name, w.currentText() if isinstance(w, QtWidgets.QComboBox) else w.value())
