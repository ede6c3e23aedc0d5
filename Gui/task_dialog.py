"""What the task panels share. Their OK buttons: the document object is made under a wait cursor,
and when making it fails the panel's status line and the report view say why and the panel
stays open (the make* functions leave the document as it was). Their widgets: the status line
(wrapped, so that it fits the Combo View), the "Show ..." toggles that redraw the preview, and
the buttons, each with the object name the GUI tests find it by."""
import contextlib

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

translate = FreeCAD.Qt.translate


def create(status, make):
    """make() under a wait cursor; its result, or None after showing the error in `status`."""
    QtWidgets.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
    try:
        return make()
    except Exception as e:
        status.setText(translate("HoleFill", "Failed: %s") % e)
        FreeCAD.Console.PrintError("HoleFill: %s\n" % e)
        return None
    finally:
        QtWidgets.QApplication.restoreOverrideCursor()


class Panel:
    """What HoleFill's task panels do alike: OK and Cancel buttons; Cancel closes the panel, and
    so does an OK that made its object. Closing calls self.release() first: the panel's overlay
    (scene_overlay's node named self.overlay) removed, and whatever else it holds given back
    (observers, callbacks). The plain OK makes the object with
    self.make() through create() (the panel stays open, its self.status saying why, when that
    fails) and prints self.made(obj) (what the report view says of it; it may also hide the
    source) — panels whose OK does more override accept and close with self.close()."""

    overlay = None

    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel)

    def release(self):
        if self.overlay:
            from HoleFillGui import scene_overlay
            scene_overlay.remove(self.overlay)

    def close(self):
        self.release()
        FreeCADGui.Control.closeDialog()

    def accept(self):
        obj = create(self.status, self.make)
        if obj is None:
            return False
        FreeCAD.Console.PrintMessage(self.made(obj) + "\n")
        self.close()
        return True

    def reject(self):
        self.close()
        return True


def show(panel):
    """Opens `panel` in the Combo View, its widgets made to fit the view's default width (264 px;
    fit_width): a panel is scrolled down when tall, never sideways."""
    fit_width(panel.form)
    FreeCADGui.Control.showDialog(panel)


def fit_width(form):
    """Lets the widgets of `form` (a widget, or FreeCAD's list of them) narrow to the Combo View:
    form rows put their field under the label where both do not fit side by side, labels wrap,
    combo boxes no longer ask for their longest choice's width, tables and lists scroll their
    columns, and a check box's long text is broken into lines (Qt wraps no check box).
    Panels are built for reading at any width; this is the one place that says how."""
    for widget in form if isinstance(form, (list, tuple)) else [form]:
        for layout in widget.findChildren(QtWidgets.QFormLayout):
            layout.setRowWrapPolicy(QtWidgets.QFormLayout.WrapLongRows)
            layout.setFieldGrowthPolicy(QtWidgets.QFormLayout.AllNonFixedFieldsGrow)
        for label in widget.findChildren(QtWidgets.QLabel):
            if label.pixmap() is None or label.pixmap().isNull():
                label.setWordWrap(True)
        for combo in widget.findChildren(QtWidgets.QComboBox):
            combo.setSizeAdjustPolicy(QtWidgets.QComboBox.AdjustToMinimumContentsLengthWithIcon)
            combo.setMinimumContentsLength(4)
        for box in widget.findChildren(QtWidgets.QAbstractButton):
            if isinstance(box, (QtWidgets.QCheckBox, QtWidgets.QRadioButton)):
                box.setText(_broken(box.text(), box.fontMetrics(), CHECK_TEXT_WIDTH))
        for view in widget.findChildren(QtWidgets.QAbstractItemView):
            view.setMinimumWidth(0)
            view.setSizeAdjustPolicy(QtWidgets.QAbstractScrollArea.AdjustIgnored)
            view.setSizePolicy(QtWidgets.QSizePolicy.Ignored, view.sizePolicy().verticalPolicy())


# What a check box's text may take of the Combo View's 264 px (its frame, margins and indicator
# take the rest).
CHECK_TEXT_WIDTH = 170


def _broken(text, metrics, width):
    """`text` with line breaks between words where a line would pass `width` pixels."""
    lines = []
    for word in " ".join(text.split("\n")).split(" "):
        if lines and metrics.horizontalAdvance(lines[-1] + " " + word) <= width:
            lines[-1] += " " + word
        else:
            lines.append(word)
    return "\n".join(lines)


def failed(what, error):
    """A failure line, "<what> failed at 14:03:12: <error>": a Preview pressed again that fails
    the same way still shows it ran (the line changes)."""
    import time
    return translate("HoleFill", "%s failed at %s: %s") % (what, time.strftime("%H:%M:%S"), error)


def status_line(name=None):
    """The panel's status line: a label that wraps (long reports stay within a narrow Combo View)."""
    label = QtWidgets.QLabel()
    if name:
        label.setObjectName(name)
    label.setWordWrap(True)
    return label


def button(text, name, clicked):
    """A push button named `name` (for the GUI tests) that calls `clicked`."""
    b = QtWidgets.QPushButton(text)
    b.setObjectName(name)
    b.clicked.connect(clicked)
    return b


def show_toggles(layout, prefix, items, redraw):
    """{key: checkbox} for (key, label) in `items`, each checked, named prefix + key, added to the
    form layout `layout`, and calling redraw() when toggled."""
    toggles = {}
    for key, label in items:
        c = QtWidgets.QCheckBox(label)
        c.setObjectName(prefix + key)
        c.setChecked(True)
        c.toggled.connect(lambda *_: redraw())
        layout.addRow(c)
        toggles[key] = c
    return toggles


@contextlib.contextmanager
def progress_dialog(text, parent):
    """A modal progress dialog (shown after half a second) with Cancel, for the length of the
    block; yields the progress callable the core takes: progress(fraction) -> False once the
    user cancelled."""
    dlg = QtWidgets.QProgressDialog(text, translate("HoleFill", "Cancel"), 0, 100, parent)
    dlg.setWindowModality(QtCore.Qt.WindowModal)
    dlg.setMinimumDuration(500)

    def progress(f):
        dlg.setValue(int(100 * f))
        QtWidgets.QApplication.processEvents()
        return not dlg.wasCanceled()

    try:
        yield progress
    finally:
        dlg.close()
