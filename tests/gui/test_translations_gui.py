"""GUI test: the workbench's words go through Qt's translation, so that a translation file can be
added. A pseudo-translator installed in the running FreeCAD wraps every string of HoleFill's
contexts in ⟦ ⟧; the HoleFill menu's commands and every label, button, check box and group of the
Fill hole panel and of the Preferences page must then come out wrapped (choices in combo boxes are
values, not words, and stay as they are)."""
import re

import FreeCADGui
from PySide2 import QtCore, QtWidgets

import guiharness as h


class Pseudo(QtCore.QTranslator):
    def translate(self, context, source, disambiguation=None, n=-1):
        if context and str(context).startswith("HoleFill") and source:
            return "⟦%s⟧" % source
        return None


def unwrapped(root):
    """Texts with words, shown by `root`'s labels, buttons, check boxes and group boxes, that did not
    come through the pseudo-translator."""
    bad = []
    for cls, text in ((QtWidgets.QLabel, "text"), (QtWidgets.QAbstractButton, "text"), (QtWidgets.QGroupBox, "title")):
        for w in root.findChildren(cls):
            t = getattr(w, text)()
            if isinstance(w, QtWidgets.QLabel) and w.buddy() is None and not w.isVisible():
                continue
            if re.search("[A-Za-z]{2}", t or "") and "⟦" not in t:
                bad.append("%s %r" % (type(w).__name__, t))
    return bad


def body():
    app = QtWidgets.QApplication.instance()
    tr = Pseudo(app)
    app.installTranslator(tr)
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(500)
    mw = FreeCADGui.getMainWindow()
    # The commands' actions, as the HoleFill menu and toolbar show them.
    from HoleFillGui import commands
    texts = [a.text().replace("&", "") for a in mw.findChildren(QtWidgets.QAction)]
    names = [n for n in commands.COMMANDS if n != "Separator"]
    menus = {n: FreeCADGui.Command.get(n).getInfo()["menuText"] for n in names}
    items = [t for t in texts if t.startswith("⟦") and any(t == "⟦%s⟧" % m for m in menus.values())]
    plain = [t for t in texts if t in menus.values()]
    assert len(set(items)) == len(names) and not plain, (sorted(set(items)), plain, menus)

    import FreeCAD
    FreeCAD.newDocument("GuiTr")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.runCommand("HoleFill_FillHole")
    h.pump(800)
    panel = next(w for w in mw.findChildren(QtWidgets.QWidget) if w.windowTitle() == "⟦Fill hole⟧")
    bad = unwrapped(panel)
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_translations_fill_panel.png"))
    assert not bad, bad
    FreeCADGui.Control.closeDialog()
    h.pump(300)

    from HoleFillGui.preferences_page import PreferencePage
    page = PreferencePage()
    page.loadSettings()
    bad = unwrapped(page.form)
    assert not bad, bad
    app.removeTranslator(tr)
    h.finish(True, menu=items)


h.run(body, 500)
