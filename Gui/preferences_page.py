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
        self.widgets = {}
        lay = self._group(outer, translate("HoleFill", "Fill hole: starting values of the task panel"))
        self._combo(lay, "FillMethod", translate("HoleFill", "Parameterization:"))
        self._combo(lay, "FillContinuity", translate("HoleFill", "Continuity:"))
        self._combo(lay, "FillOutput", translate("HoleFill", "Output:"))
        tol = self._number(lay, "FillTolerance", translate("HoleFill", "G0 tolerance:"), 7, 0.0, 1e3)
        tol.setSpecialValueText(translate("HoleFill", "auto (1e-6 of hole size)"))
        self._number(lay, "FillAngularTolerance", translate("HoleFill", "G1 tolerance:"), 6, 1e-6, 0.5, 1e-4,
                     translate("HoleFill", " rad"))
        lay = self._group(outer, translate("HoleFill", "Learned models: weights files (empty: the shipped ones)"))
        self._file(lay, "UvtranWeights", translate("HoleFill", "UVTran (Fill hole):"))
        self._file(lay, "BidgcnWeights", translate("HoleFill", "BIDGCN (Fit point cloud):"))
        lay = self._group(outer, translate("HoleFill", "Fitting"))
        self._number(lay, "FitTolerance", translate("HoleFill", "Fit tolerance:"), 6, 1e-6, 0.5, 1e-4,
                     translate("HoleFill", " of the diagonal"))
        lay = self._group(outer, translate("HoleFill", "Inspection"))
        self._combo(lay, "ZebraRenderer", translate("HoleFill", "Zebra stripes drawn by:"))
        outer.addStretch(1)

    def _group(self, outer, title):
        box = QtWidgets.QGroupBox(title)
        outer.addWidget(box)
        return QtWidgets.QFormLayout(box)

    def _setting(self, w, name):
        """`w` edits setting `name`: named after it, its description as tooltip, saved and loaded."""
        w.setObjectName(name)
        w.setToolTip(preferences.SETTINGS[name][1])
        self.widgets[name] = w
        return w

    def _combo(self, lay, name, label):
        w = self._setting(QtWidgets.QComboBox(), name)
        w.addItems(list(preferences.CHOICES[name]))
        lay.addRow(label, w)
        return w

    def _number(self, lay, name, label, decimals, low, high, step=None, suffix=""):
        w = self._setting(QtWidgets.QDoubleSpinBox(), name)
        w.setDecimals(decimals)
        w.setRange(low, high)
        if step is not None:
            w.setSingleStep(step)
        w.setSuffix(suffix)
        lay.addRow(label, w)
        return w

    def _file(self, lay, name, label):
        row = QtWidgets.QWidget()
        h = QtWidgets.QHBoxLayout(row)
        h.setContentsMargins(0, 0, 0, 0)
        edit = self._setting(QtWidgets.QLineEdit(), name)
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
        lay.addRow(label, row)
        return edit

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
