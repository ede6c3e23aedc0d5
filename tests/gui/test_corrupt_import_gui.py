"""GUI test (issue 22, every door): corrupt files through the workbench's import path. Import quad
cage is run as a user would, the file picked in its file dialog: a cage at 1e300 (which crashed
FreeCAD through the Python door before the core bounded every cage) and an OBJ cut off in a face
line. Each gives a message box naming the problem, adds nothing to the document, and FreeCAD is
still up and working afterwards (a fill of a sample hole still runs)."""
import os
import tempfile

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

import guiharness as h

TMP = tempfile.mkdtemp()


def write(name, text):
    path = os.path.join(TMP, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def import_through_dialog(path, shot):
    """Runs Import quad cage, picks `path` in its file dialog, grabs and closes the message box;
    returns the box's text ("" when none came)."""
    seen = []

    def pick():
        w = QtWidgets.QApplication.activeModalWidget()
        if isinstance(w, QtWidgets.QFileDialog):
            # The typed name is what the dialog's accept() reads, as when a user types a path.
            edit = [e for e in w.findChildren(QtWidgets.QLineEdit) if e.isVisible()][0]
            edit.setText(path)
            w.accept()
            QtCore.QTimer.singleShot(300, close_box)
        else:
            QtCore.QTimer.singleShot(100, pick)

    def close_box():
        w = QtWidgets.QApplication.activeModalWidget()
        if isinstance(w, QtWidgets.QMessageBox):
            seen.append(w.text())
            QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot(shot))
            w.accept()
        elif not seen:
            QtCore.QTimer.singleShot(100, close_box)

    QtCore.QTimer.singleShot(300, pick)
    FreeCADGui.runCommand("HoleFill_ImportCage")
    h.pump(800)
    return seen[0] if seen else ""


def body():
    import HoleFill
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    doc, src = h.sample_document("GuiCorrupt", "Part", "box_minus_face")
    names = sorted(o.Name for o in doc.Objects)
    cage = HoleFill.sampleCage("cage_valence5")
    # repr of plain floats: numpy 2 (Debian 13) writes its own scalars as "np.float64(...)".
    far = "".join("v %r %r %r\n" % tuple(float(c) * 1e300 for c in p) for p in cage["vertices"])
    far += "".join("f %d %d %d %d\n" % tuple(i + 1 for i in q) for q in cage["quads"])
    text = import_through_dialog(write("far_cage.obj", far), "gui_corrupt_1_far_cage.png")
    assert "coordinate beyond" in text, text
    assert sorted(o.Name for o in doc.Objects) == names, sorted(o.Name for o in doc.Objects)
    cut = "".join("v %r %r %r\n" % tuple(float(c) for c in p) for p in cage["vertices"]) + "f 1 2 3"
    text2 = import_through_dialog(write("cut_cage.obj", cut), "gui_corrupt_2_cut_cage.png")
    assert "cut_cage.obj" in text2, text2
    assert sorted(o.Name for o in doc.Objects) == names
    # Still up and working: the sample's hole fills, and the view draws it.
    face, _, report = HoleFill.fillHole(src.Shape, 1)
    assert report["status"] in ("ok", "tolerance_not_met"), report["status"]
    assert FreeCADGui.getMainWindow().isVisible()
    h.finish(True, far=text, cut=text2)


h.run(body, 500)
