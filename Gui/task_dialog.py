"""What the task panels' OK buttons share: the document object is made under a wait cursor,
and when making it fails the panel's status line and the report view say why and the panel
stays open (the make* functions leave the document as it was)."""
import FreeCAD
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
