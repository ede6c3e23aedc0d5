"""Headless FreeCAD tests: a document saved by the workbench on FreeCAD 0.20 (data/, the demo's
filleted box with its parametric Fill) opens and recomputes in the FreeCAD running the test (0.20 on
Debian 12, 1.0 on Debian 13): the Fill's proxy comes back, its edge names still resolve on the source,
and a recompute after the source changes gives the same sewable face."""
import json
import os

import FreeCAD

import fcharness

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


def test_a_fill_saved_by_0_20_opens_and_recomputes():
    path = os.path.join(DATA, "fill_saved_by_freecad_0.20.FCStd")
    doc = FreeCAD.openDocument(path)
    try:
        fill, model = doc.getObject("Fill"), doc.getObject("Model")
        assert fill is not None and model is not None, [o.Name for o in doc.Objects]
        assert fill.Proxy is not None and type(fill.Proxy).__name__ == "FillFeature", fill.Proxy
        src, edges = fill.Source
        assert src is model and edges, (src, edges)
        for name in edges:  # sub-element names as 0.20 wrote them still name edges of the source
            assert model.Shape.getElement(name).ShapeType == "Edge", name
        saved = fill.Shape.copy()
        assert len(saved.Faces) == 1 and saved.isValid()
        # The source changes (moved, as a user would): the Fill follows it.
        model.Placement.Base = FreeCAD.Vector(10, 0, 0)
        doc.recompute()
        assert not fill.State or "Invalid" not in fill.State, fill.State
        report = json.loads(fill.Report)
        assert report["status"] == "ok" and report["achieved"] in ("G1", "G2"), (report["status"], report["achieved"])
        face = fill.Shape.Faces[0]
        assert face.isValid() and abs(face.Area - saved.Faces[0].Area) <= 1e-6 * saved.Faces[0].Area, (face.Area, saved.Faces[0].Area)
        moved = face.BoundBox.XMin - saved.Faces[0].BoundBox.XMin
        assert abs(moved - 10) <= 1e-6, moved
    finally:
        FreeCAD.closeDocument(doc.Name)


fcharness.run(globals())
