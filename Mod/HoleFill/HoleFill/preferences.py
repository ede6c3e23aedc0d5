"""The workbench's preferences (Edit → Preferences → HoleFill), kept in FreeCAD's parameters under
User parameter:BaseApp/Preferences/Mod/HoleFill. The task panels start from them; the macro API
(fillHole, makeFill, ...) takes its own arguments and reads none of them, so that a macro gives
the same result on every machine whatever its user chose. A weights file that has gone since it
was stored is passed on as it is: the fill then says so in its report (and falls back to mvc)."""
import inspect
import os

import FreeCAD

import HoleFill
from HoleFill import fill_feature, inspection, labeled, pointcloud

PATH = "User parameter:BaseApp/Preferences/Mod/HoleFill"

# name: (default, what it sets). The defaults are makeFill's own, read from it.
_MAKE_FILL = inspect.signature(fill_feature.makeFill).parameters
SETTINGS = {
    "FillMethod": (_MAKE_FILL["method"].default, "Fill hole: the parameterization (%s)" % ", ".join(HoleFill.METHODS)),
    "FillContinuity": (_MAKE_FILL["continuity"].default, "Fill hole: the continuity asked of the hole's edges (%s)" % ", ".join(HoleFill.CONTINUITIES)),
    "FillTolerance": (float(_MAKE_FILL["tolerance"].default), "Fill hole: the G0 tolerance in model units; 0: 1e-6 of the hole's size"),
    "FillAngularTolerance": (float(_MAKE_FILL["angularTolerance"].default), "Fill hole: the G1 tolerance in radians"),
    "FillOutput": (_MAKE_FILL["output"].default, "Fill hole: the new object holds the face alone (Face) or the source with it sewn in (Sewn)"),
    "UvtranWeights": (_MAKE_FILL["weights"].default, "Fill hole: UVTran's weights file (.pt, from holefill train uvtran); empty: the shipped one"),
    "BidgcnWeights": (inspect.signature(pointcloud.fitPoints).parameters["weights"].default,
                      "Fit point cloud: BIDGCN's weights file (.pt, from holefill train bidgcn); empty: the shipped one"),
    "FitTolerance": (float(inspect.signature(labeled.fitLabeled).parameters["relativeTolerance"].default),
                     "Fit labeled surface and Fit point cloud: the data max that ends the refinement, as a fraction of the region's diagonal"),
    "ZebraRenderer": (inspection.ZEBRA_RENDERERS[0], "Zebra stripes: shader draws them per pixel (GLSL); vertex per vertex of the inspection mesh, "
                                "for OpenGL without shaders (remote X, old drivers), where the shader draws nothing"),
}
CHOICES = {"FillMethod": HoleFill.METHODS, "FillContinuity": HoleFill.CONTINUITIES, "FillOutput": fill_feature.OUTPUTS,
           "ZebraRenderer": inspection.ZEBRA_RENDERERS}

FILES = ("UvtranWeights", "BidgcnWeights")  # paths: empty, or a file that exists when stored
POSITIVE = ("FillAngularTolerance", "FitTolerance")  # tolerances that 0 would make unreachable


def _group():
    return FreeCAD.ParamGet(PATH)


def get(name):
    """The user's value of `name`, or its default; a stored value that is no longer valid (a
    method renamed, a negative tolerance) reads as the default."""
    default = SETTINGS[name][0]
    g = _group()
    if isinstance(default, float):
        value = g.GetFloat(name, default)
        return value if value > 0 or (value == 0 and name not in POSITIVE) else default
    value = g.GetString(name, default)
    if name in CHOICES and value not in CHOICES[name]:
        return default
    return value


def put(name, value):
    """Stores `value` for `name` (checked as get() reads it)."""
    default = SETTINGS[name][0]
    if isinstance(default, float):
        value = float(value)
        if name in POSITIVE and not value > 0:
            raise ValueError("%s must be positive" % name)
        if not value >= 0:
            raise ValueError("%s must be zero or positive" % name)
        _group().SetFloat(name, value)
        return
    value = str(value)
    if name in CHOICES and value not in CHOICES[name]:
        raise ValueError("%s must be one of %s" % (name, ", ".join(CHOICES[name])))
    if name in FILES and value and not os.path.isfile(value):
        raise ValueError("%s: no such file: %s" % (name, value))
    _group().SetString(name, value)


def reset():
    """Every setting back to its default."""
    g = _group()
    for name, (default, _) in SETTINGS.items():
        if isinstance(default, float):
            g.RemFloat(name)
        else:
            g.RemString(name)
