"""Headless FreeCAD tests of the workbench's preferences (HoleFill/preferences.py): defaults equal to
the macro API's own, values kept in FreeCAD's parameters, bad values refused on storing and ignored
on reading, and the macro API unmoved by them."""
import inspect

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
    for name, value in (("FillMethod", "support"), ("FillContinuity", "G3"), ("FillOutput", "Solid"), ("FillTolerance", -1.0)):
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


fcharness.run(globals())
