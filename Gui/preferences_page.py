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
        learned = QtWidgets.QGroupBox(translate("HoleFill", "Learned models: weights files (empty: the shipped ones)"))
        lay = QtWidgets.QFormLayout(learned)
        for name, label in (("UvtranWeights", translate("HoleFill", "UVTran (Fill hole):")),
                            ("BidgcnWeights", translate("HoleFill", "BIDGCN (Fit point cloud):"))):
            lay.addRow(label, self.fileRow(name))
        outer.addWidget(learned)
        box = QtWidgets.QGroupBox(translate("HoleFill", "Fitting"))
        lay = QtWidgets.QFormLayout(box)
        fit = QtWidgets.QDoubleSpinBox()
        fit.setObjectName("FitTolerance")
        fit.setDecimals(6)
        fit.setRange(1e-6, 0.5)
        fit.setSingleStep(1e-4)
        fit.setSuffix(translate("HoleFill", " of the diagonal"))
        fit.setToolTip(preferences.SETTINGS["FitTolerance"][1])
        lay.addRow(translate("HoleFill", "Fit tolerance:"), fit)
        self.widgets["FitTolerance"] = fit
        outer.addWidget(box)
        box = QtWidgets.QGroupBox(translate("HoleFill", "Inspection"))
        lay = QtWidgets.QFormLayout(box)
        w = QtWidgets.QComboBox()
        w.setObjectName("ZebraRenderer")
        w.addItems(list(preferences.CHOICES["ZebraRenderer"]))
        w.setToolTip(preferences.SETTINGS["ZebraRenderer"][1])
        lay.addRow(translate("HoleFill", "Zebra stripes drawn by:"), w)
        self.widgets["ZebraRenderer"] = w
        outer.addWidget(box)
        outer.addStretch(1)

    def fileRow(self, name):
        row = QtWidgets.QWidget()
        h = QtWidgets.QHBoxLayout(row)
        h.setContentsMargins(0, 0, 0, 0)
        edit = QtWidgets.QLineEdit()
        edit.setObjectName(name)
        edit.setToolTip(preferences.SETTINGS[name][1])
        edit.setPlaceholderText(translate("HoleFill", "shipped weights"))
        browse = QtWidgets.QToolButton()
        browse.setText("…")

        def choose():
            path, _ = QtWidgets.QFileDialog.getOpenFileName(self.form, translate("HoleFill", "Weights file"), edit.text(),
                                                            translate("HoleFill", "Torch archives (*.pt);;All files (*)"))
            if path:
                edit.setText(path)

        browse.clicked.connect(choose)
        h.addWidget(edit, 1)
        h.addWidget(browse)
        self.widgets[name] = edit
        return row

    def loadSettings(self):
        for name, w in self.widgets.items():
            if isinstance(w, QtWidgets.QComboBox):
                w.setCurrentText(preferences.get(name))
            elif isinstance(w, QtWidgets.QLineEdit):
                w.setText(preferences.get(name))
            else:
                w.setValue(preferences.get(name))

    def saveSettings(self):
        """Stores every value; one that cannot be kept (a weights file that does not exist) keeps
        its stored value and is named in the report view, and the others are stored."""
        for name, w in self.widgets.items():
            if isinstance(w, QtWidgets.QComboBox):
                value = w.currentText()
            elif isinstance(w, QtWidgets.QLineEdit):
                value = w.text().strip()
            else:
                value = w.value()
            try:
                preferences.put(name, value)
            except ValueError as e:
                FreeCAD.Console.PrintError(translate("HoleFill", "HoleFill preferences: %s not stored: %s") % (name, e) + "\n")
                if isinstance(w, QtWidgets.QLineEdit):
                    w.setText(preferences.get(name))
