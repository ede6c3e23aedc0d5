"""GUI test: the Fill hole task panel with bad selections (nothing, a face, an edge that is not on a
hole) shows a clear message, OK keeps the panel open, Cancel leaves the document exactly as it was."""
import os

import FreeCAD
import FreeCADGui
import Part
from PySide2 import QtWidgets

import guiharness as h


def visible_texts(mw):
    texts = [w.text() for w in mw.findChildren(QtWidgets.QLabel) if w.isVisible()]
    texts += [w.toPlainText() for w in mw.findChildren(QtWidgets.QPlainTextEdit) if w.isVisible()]
    return " | ".join(texts)


def button(mw, which):
    for box in mw.findChildren(QtWidgets.QDialogButtonBox):
        b = box.button(which)
        if box.isVisible() and b is not None and b.isVisible():
            return b
    return None


def press(mw, which, ms=600):
    """Click the task panel's OK or Cancel button, as a user would, and let the GUI react."""
    button(mw, which).click()
    h.pump(ms)


def open_panel():
    FreeCADGui.runCommand("HoleFill_FillHole")
    h.pump(600)


def body():
    import HoleFill
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    doc = FreeCAD.newDocument("GuiBad")
    box = doc.addObject("Part::Box", "Box")  # a closed solid: no holes at all
    panel = doc.addObject("Part::Feature", "Panel")
    s = Part.Shape()
    s.read(os.path.join(os.path.dirname(HoleFill.__file__), "..", "Resources", "samples", "panel_6_sided.brep"))
    panel.Shape = s
    doc.recompute()
    names = sorted(o.Name for o in doc.Objects)
    mw = FreeCADGui.getMainWindow()

    # 1. Nothing selected: the panel asks for an edge; OK does not create anything.
    FreeCADGui.Selection.clearSelection()
    open_panel()
    assert "Select one edge of a hole" in visible_texts(mw), visible_texts(mw)
    press(mw, QtWidgets.QDialogButtonBox.Ok)
    assert "No hole selected" in visible_texts(mw), visible_texts(mw)
    assert sorted(o.Name for o in doc.Objects) == names
    press(mw, QtWidgets.QDialogButtonBox.Cancel)

    # 2. An edge of a closed box: not on any hole.
    FreeCADGui.Selection.addSelection(doc.Name, "Box", "Edge1")
    open_panel()
    assert "is not on one hole loop" in visible_texts(mw), visible_texts(mw)
    press(mw, QtWidgets.QDialogButtonBox.Ok, 1500)
    assert "Fill failed" in visible_texts(mw), visible_texts(mw)
    # Said in the GUI's words: the box is closed; no command line to run.
    assert "the shape is closed" in visible_texts(mw) and "'holes'" not in visible_texts(mw), visible_texts(mw)
    view = FreeCADGui.ActiveDocument.ActiveView
    view.fitAll()
    h.pump(300)
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_bad_1_not_a_hole.png"))
    press(mw, QtWidgets.QDialogButtonBox.Cancel, 800)
    assert sorted(o.Name for o in doc.Objects) == names, sorted(o.Name for o in doc.Objects)

    # 3. A face selected (no edge): said so, with what to pick instead.
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(doc.Name, "Panel", "Face1")
    open_panel()
    assert "Panel.Face1 is selected, not an edge" in visible_texts(mw) and "select one edge of its boundary" in visible_texts(mw), \
        visible_texts(mw)
    press(mw, QtWidgets.QDialogButtonBox.Cancel)
    assert sorted(o.Name for o in doc.Objects) == names
    assert panel.Shape.isValid() and len(panel.Shape.Faces) == 1
    h.finish(True)


h.run(body, 500)
