"""GUI test: Edit → Preferences has a HoleFill page; a value chosen there and kept with OK is in
FreeCAD's parameters, and the Fill hole panel of a new fill starts from it (its OK makes a Fill
with those settings, which one undo removes)."""
import FreeCADGui
from PySide2 import QtCore, QtWidgets

import guiharness as h
from HoleFill import preferences


def find_page():
    dlg = QtWidgets.QApplication.activeModalWidget()
    page = dlg.findChild(QtWidgets.QWidget, "HoleFillPreferences") if dlg is not None else None
    return dlg, page


def show_group(dlg):
    """Brings the HoleFill group to the front as a click on its entry would (0.20: a list of groups; 1.0: a tree)."""
    for lw in dlg.findChildren(QtWidgets.QListWidget):
        for it in lw.findItems("HoleFill", QtCore.Qt.MatchExactly):
            lw.setCurrentItem(it)
            return True
    for tv in dlg.findChildren(QtWidgets.QTreeView):
        m = tv.model()
        hits = m.match(m.index(0, 0), QtCore.Qt.DisplayRole, "HoleFill", 1, QtCore.Qt.MatchExactly | QtCore.Qt.MatchRecursive)
        for hit in hits:
            # 1.0: the group and, under it, its page; the page is what shows it.
            index = m.index(0, 0, hit) if m.rowCount(hit) else hit
            tv.setCurrentIndex(index)
            tv.clicked.emit(index)
            return True
    return False


def body():
    import os
    import HoleFill
    preferences.reset()
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    state = {}
    weights = os.path.realpath(os.path.join(os.path.dirname(HoleFill.__file__), "..", "Resources", "models", "uvtran.pt"))

    def in_dialog():
        dlg, page = find_page()
        if page is None:
            state.setdefault("tries", 0)
            state["tries"] += 1
            if state["tries"] < 50:
                QtCore.QTimer.singleShot(100, in_dialog)
            elif dlg is not None:
                dlg.reject()
            return
        state["page"] = True
        state["shown"] = show_group(dlg)
        h.pump(300)
        state["visible"] = page.isVisible()
        page.findChild(QtWidgets.QComboBox, "FillMethod").setCurrentText("mvc")
        page.findChild(QtWidgets.QComboBox, "FillContinuity").setCurrentText("G2")
        page.findChild(QtWidgets.QComboBox, "FillOutput").setCurrentText("Sewn")
        page.findChild(QtWidgets.QComboBox, "ZebraRenderer").setCurrentText("vertex")
        page.findChild(QtWidgets.QDoubleSpinBox, "FitTolerance").setValue(2e-3)
        page.findChild(QtWidgets.QLineEdit, "UvtranWeights").setText(weights)
        page.findChild(QtWidgets.QLineEdit, "BidgcnWeights").setText("/nonexistent/bidgcn.pt")  # not kept, said why
        h.pump(200)
        QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_preferences_page.png"))
        for bb in dlg.findChildren(QtWidgets.QDialogButtonBox):
            ok = bb.button(QtWidgets.QDialogButtonBox.Ok)
            if ok is not None and ok.isVisible():
                ok.click()
                return
        dlg.reject()

    QtCore.QTimer.singleShot(300, in_dialog)
    FreeCADGui.runCommand("Std_DlgPreferences")  # modal: returns when the dialog is closed
    h.pump(500)
    assert state.get("page"), "no HoleFill page in Edit -> Preferences"
    assert state.get("shown"), "the HoleFill group was not found in the dialog's list"
    assert state.get("visible"), "the HoleFill page did not show when its group was chosen"
    got = (preferences.get("FillMethod"), preferences.get("FillContinuity"), preferences.get("FillOutput"))
    assert got == ("mvc", "G2", "Sewn"), got
    got = (preferences.get("ZebraRenderer"), preferences.get("UvtranWeights"), preferences.get("BidgcnWeights"))
    assert got == ("vertex", weights, ""), got
    assert abs(preferences.get("FitTolerance") - 2e-3) < 1e-12, preferences.get("FitTolerance")

    # A new fill's panel starts from the preferences.
    doc, src = h.sample_document("GuiPrefs", "Panel", "panel_6_sided")
    names = sorted(o.Name for o in doc.Objects)
    FreeCADGui.Selection.clearSelection()
    # An edge of the panel's 6-sided hole (Edge1 is on its outer boundary, which no tier fills).
    FreeCADGui.Selection.addSelection(doc.Name, "Panel", HoleFill.findHoles(src.Shape)[0].edges[0])
    FreeCADGui.runCommand("HoleFill_FillHole")
    h.pump(800)
    mw = FreeCADGui.getMainWindow()
    combos = {c.currentText() for c in mw.findChildren(QtWidgets.QComboBox) if c.isVisible()}
    assert {"mvc", "G2", "Sewn"} <= combos, combos
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_preferences_fill_panel.png"))
    # Its Preview and OK make a Fill that names the preferred weights; one undo removes it.
    preview = [b for b in mw.findChildren(QtWidgets.QPushButton) if b.isVisible() and b.text() == "Preview"][0]
    preview.click()
    h.pump(3000)
    assert sorted(o.Name for o in doc.Objects) == names, "a Preview added to the document"
    for bb in mw.findChildren(QtWidgets.QDialogButtonBox):
        b = bb.button(QtWidgets.QDialogButtonBox.Ok)
        if bb.isVisible() and b is not None and b.isVisible():
            b.click()
    h.pump(1500)
    fills = [o for o in doc.Objects if o.Name.startswith("Fill")]
    assert len(fills) == 1 and fills[0].Weights == weights, [(o.Name, getattr(o, "Weights", None)) for o in fills]
    assert fills[0].Method == "mvc" and fills[0].Continuity == "G2" and fills[0].Output == "Sewn", fills[0].Method
    doc.undo()
    h.pump(600)
    assert sorted(o.Name for o in doc.Objects) == names, sorted(o.Name for o in doc.Objects)
    preferences.reset()
    h.finish(True)


h.run(body, 500)
