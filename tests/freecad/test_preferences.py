"""Headless FreeCAD tests of the workbench's preferences (HoleFill/preferences.py): defaults equal to
the macro API's own, values kept in FreeCAD's parameters, bad values refused on storing and ignored
on reading, and the macro API unmoved by them."""
import inspect
import json

import FreeCAD

import fcharness
import HoleFill
from HoleFill import preferences


def test_defaults_are_the_macro_apis():
    preferences.reset()
    sig = inspect.signature(HoleFill.makeFill).parameters
    assert preferences.get("FillMethod") == sig["method"].default == "auto"
    assert preferences.get("FillContinuity") == sig["continuity"].default == "G1"
    assert preferences.get("FillTolerance") == sig["tolerance"].default == 0.0
    assert preferences.get("FillAngularTolerance") == sig["angularTolerance"].default == 1e-3
    assert preferences.get("FillOutput") == "Face"
    assert preferences.get("UvtranWeights") == sig["weights"].default == ""
    assert preferences.get("BidgcnWeights") == inspect.signature(HoleFill.fitPoints).parameters["weights"].default == ""
    assert preferences.get("ZebraRenderer") == "shader"
    assert preferences.get("FitTolerance") == inspect.signature(HoleFill.fitLabeled).parameters["relativeTolerance"].default == 1e-3


def test_values_live_in_freecads_parameters():
    preferences.reset()
    preferences.put("FillMethod", "mvc")
    preferences.put("FillContinuity", "G2")
    preferences.put("FillTolerance", 0.01)
    group = FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/HoleFill")
    assert group.GetString("FillMethod") == "mvc" and group.GetString("FillContinuity") == "G2"
    assert group.GetFloat("FillTolerance") == 0.01
    assert (preferences.get("FillMethod"), preferences.get("FillContinuity"), preferences.get("FillTolerance")) == ("mvc", "G2", 0.01)
    preferences.reset()
    assert preferences.get("FillMethod") == "auto" and group.GetString("FillMethod", "") == ""


def test_bad_values_are_refused_and_stale_ones_read_as_defaults():
    preferences.reset()
    for name, value in (("FillMethod", "support"), ("FillContinuity", "G3"), ("FillOutput", "Solid"), ("FillTolerance", -1.0), ("FitTolerance", 0.0),
                        ("ZebraRenderer", "opengl"), ("UvtranWeights", "/nonexistent/uvtran.pt"), ("BidgcnWeights", "/nonexistent")):
        try:
            preferences.put(name, value)
        except ValueError as e:
            assert name in str(e), e
        else:
            raise AssertionError("%s=%r was stored" % (name, value))
    # A value written by an older version or by hand, no longer valid: the default is read.
    group = FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/HoleFill")
    group.SetString("FillMethod", "nearest-plane")
    group.SetFloat("FillAngularTolerance", -5.0)
    assert preferences.get("FillMethod") == "auto" and preferences.get("FillAngularTolerance") == 1e-3
    preferences.reset()


def test_uvtran_weights_reach_the_fill():
    """The weights file a Fill names is the one its uvtran fill loads: the shipped file under
    another name gives the shipped result, a file that is no torch archive makes the fill fall
    back to mvc and say why, naming the file."""
    import shutil
    import tempfile
    doc = FreeCAD.newDocument("PrefWeights")
    try:
        import os
        import Part
        src = doc.addObject("Part::Feature", "Panel")
        src.Shape = Part.read(os.path.join(os.path.dirname(HoleFill.__file__), "..", "Resources", "samples", "panel_6_sided.brep"))
        doc.recompute()
        shipped = HoleFill.makeFill(src, None, method="uvtran")
        tmp = tempfile.mkdtemp()
        copy = os.path.join(tmp, "my_uvtran.pt")
        shutil.copy(os.path.join(os.path.dirname(HoleFill.__file__), "..", "Resources", "models", "uvtran.pt"), copy)
        named = HoleFill.makeFill(src, None, method="uvtran", weights=copy)
        assert named.Weights == copy
        a, b = json.loads(shipped.Report), json.loads(named.Report)
        assert a["method"] == b["method"] == "uvtran", (a["method"], b["method"], b["warnings"])
        assert abs(shipped.Shape.Area - named.Shape.Area) < 1e-9 * shipped.Shape.Area
        garbage = os.path.join(tmp, "garbage.pt")
        with open(garbage, "w") as f:
            f.write("not a torch archive\n")
        preferences.put("UvtranWeights", garbage)  # stored: it exists; what it holds the fill judges
        named.Weights = garbage
        doc.recompute()
        c = json.loads(named.Report)
        assert c["method"] == "uvtran:mvc" and any("garbage.pt" in w for w in c["warnings"]), (c["method"], c["warnings"])
        shutil.rmtree(tmp)
    finally:
        preferences.reset()
        FreeCAD.closeDocument(doc.Name)


fcharness.run(globals())
