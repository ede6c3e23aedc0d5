"""Harness for scripts run inside the FreeCAD GUI (`freecad test.py` imports them as modules):
run(fn) schedules fn in the Qt event loop, pump(ms) lets the GUI work, finish(ok, **info)
writes $HF_RESULT and leaves with os._exit (FreeCAD's teardown after sys.exit is unreliable)."""
import json
import os
import sys
import time
import traceback

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/: fc_exit
import fc_exit  # noqa: E402

T0 = time.time()


def log(msg):
    # Straight to file descriptor 1: FreeCAD 1.0's GUI sends Python's sys.stdout to its report view.
    os.write(1, ("[guitest %.1fs] %s\n" % (time.time() - T0, msg)).encode())


def pump(ms=200):
    from PySide2 import QtCore, QtWidgets
    app = QtWidgets.QApplication.instance()
    end = time.time() + ms / 1000.0
    while time.time() < end:
        app.processEvents(QtCore.QEventLoop.AllEvents, 50)
        time.sleep(0.01)


def shot(name):
    return os.path.join(os.environ.get("HOLEFILL_SHOTS", "/tmp"), name)


def finish(ok, **info):
    info["ok"] = bool(ok)
    log("RESULT %s %s" % ("PASS" if ok else "FAIL", json.dumps(info, default=str)[:1500]))
    fc_exit.write_result_and_exit(info, 0 if ok else 2)


def run(fn, delay_ms=0):
    from PySide2 import QtCore

    def wrapper():
        try:
            fn()
        except Exception:
            finish(False, error=traceback.format_exc())

    QtCore.QTimer.singleShot(delay_ms, wrapper)


def run_expecting_message(command):
    """Runs a FreeCAD command that should refuse with a message box; closes the box and
    returns its text ("" when none appeared)."""
    import FreeCADGui
    from PySide2 import QtCore, QtWidgets
    seen = []

    def close_box():
        w = QtWidgets.QApplication.activeModalWidget()
        if isinstance(w, QtWidgets.QMessageBox):
            seen.append(w.text())
            w.accept()
        elif not seen:
            QtCore.QTimer.singleShot(100, close_box)

    QtCore.QTimer.singleShot(200, close_box)
    FreeCADGui.runCommand(command)
    pump(500)
    return seen[0] if seen else ""


def sample_document(doc_name, label, sample):
    """A new document holding one bundled sample model (Resources/samples/<sample>.brep)."""
    import FreeCAD
    import Part
    import HoleFill
    doc = FreeCAD.newDocument(doc_name)
    src = doc.addObject("Part::Feature", label)
    shape = Part.Shape()
    shape.read(os.path.join(os.path.dirname(HoleFill.__file__), "..", "Resources", "samples", sample + ".brep"))
    src.Shape = shape
    doc.recompute()
    return doc, src


def click_screen(x, y):
    """A real left click (xdotool) at global screen position (x, y)."""
    import subprocess
    subprocess.run(["xdotool", "mousemove", str(x), str(y)], check=True)
    pump(250)
    subprocess.run(["xdotool", "click", "1"], check=True)
    pump(400)


def click_at(view, p):
    """A real click (xdotool) at the screen position of 3D point p in the active view."""
    from PySide2 import QtCore
    vp = view.graphicsView().viewport()
    sx, sy = view.getPointOnScreen(p)
    g = vp.mapToGlobal(QtCore.QPoint(sx, vp.height() - 1 - sy))
    click_screen(g.x(), g.y())


def task_ok_button():
    """The visible OK button of the open task panel (AssertionError when there is none)."""
    import FreeCADGui
    from PySide2 import QtWidgets
    for bb in FreeCADGui.getMainWindow().findChildren(QtWidgets.QDialogButtonBox):
        b = bb.button(QtWidgets.QDialogButtonBox.Ok)
        if bb.isVisible() and b is not None and b.isVisible():
            return b
    raise AssertionError("no OK button")


def visible_hole_edge(view, obj, edge_names):
    """(name, screen x, screen y) of the first of `edge_names` whose midpoint the view shows
    unhidden (a click there picks that edge); (None, 0, 0) when none is."""
    from PySide2 import QtCore
    vp = view.graphicsView().viewport()
    for name in edge_names:
        e = obj.Shape.getElement(name)
        mid = e.valueAt(0.5 * (e.FirstParameter + e.LastParameter))
        sx, sy = view.getPointOnScreen(mid)
        info = view.getObjectInfo((sx, sy))
        if info and info.get("Component") == name:
            g = vp.mapToGlobal(QtCore.QPoint(sx, vp.height() - 1 - sy))
            return name, g.x(), g.y()
    return None, 0, 0


def click_button(button):
    """A real mouse click at the button's centre (xdotool), scrolled into view first when it sits
    in a scroll area (a task panel taller than the Combo View)."""
    import subprocess
    from PySide2 import QtWidgets
    parent = button.parentWidget()
    while parent is not None:
        if isinstance(parent, QtWidgets.QScrollArea):
            parent.ensureWidgetVisible(button)
            pump(200)
        parent = parent.parentWidget()
    g = button.mapToGlobal(button.rect().center())
    subprocess.run(["xdotool", "mousemove", str(g.x()), str(g.y())], check=True)
    pump(200)
    subprocess.run(["xdotool", "click", "1"], check=True)


def assert_panel_fits():
    """The open task panel fits the Combo View's width (FreeCAD's default, 264 px): it scrolls
    down when tall, never sideways, so no field, column or button is cut off at its right."""
    import FreeCADGui
    from PySide2 import QtWidgets
    pump(300)
    areas = [a for a in FreeCADGui.getMainWindow().findChildren(QtWidgets.QScrollArea)
             if a.isVisible() and "TaskView" in a.metaObject().className()]
    assert len(areas) == 1, "no task view, or several: %s" % [a.metaObject().className() for a in areas]
    area = areas[0]
    bar = area.horizontalScrollBar()
    log("task panel: %d px wide, %d px scrolled sideways at most" % (area.viewport().width(), bar.maximum()))
    if bar.maximum() > 0:
        # The widest widgets, to say what to change.
        wide = sorted(((w.minimumSizeHint().width(), w.metaObject().className(), (getattr(w, "text", lambda: "")() or w.objectName())[:40])
                       for w in area.widget().findChildren(QtWidgets.QWidget) if w.isVisible()), reverse=True)[:6]
        log("widest: %s" % wide)
    if os.environ.get("HF_MEASURE_ONLY"):
        return
    assert bar.maximum() == 0, "the task panel needs %d px more than the Combo View's %d" % (bar.maximum(), area.viewport().width())


def wait_for(done, seconds=30.0):
    """Lets the GUI work until done() or `seconds` pass; done()'s last answer. For what runs
    under a progress dialog or in a child process (a fixed wait is too short on a loaded machine)."""
    end = time.time() + seconds
    while not done() and time.time() < end:
        pump(200)
    return done()
