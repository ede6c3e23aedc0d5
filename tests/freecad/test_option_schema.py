"""Headless FreeCAD test that every door offers the fill's, labeled fitting's and the mesh fill's
options as the core's schemas declare them (HoleFillApp.optionSchema): the macro API's signatures carry their
defaults, the Fill and LabeledFit objects' properties their defaults, choices and tooltips, the
preferences start from them, and a value a schema refuses is refused by each door with the option
named. (The CLI's side: tests/cli/options.sh.)"""
import inspect

import FreeCAD
import Part

import fcharness
import HoleFill
import HoleFillApp
from HoleFill import fill_feature, labeled, preferences


def schema():
    return HoleFill.optionSchema("fill")


def test_the_macro_apis_defaults_are_the_schemas():
    fields = schema()
    assert list(fields) == [f["name"] for f in __import__("json").loads(HoleFillApp.optionSchema("fill"))]
    doors = {"fillHole": HoleFill.fillHole, "fillHoles": HoleFill.fillHoles, "PreparedHole.fill": HoleFill.PreparedHole.fill,
             "fillAdjacentHoles": HoleFill.fillAdjacentHoles, "makeFill": HoleFill.makeFill,
             "fill_feature.makeFill": fill_feature.makeFill}
    seen = set()
    for door, fn in doors.items():
        for name, p in inspect.signature(fn).parameters.items():
            if name in ("edgeContinuity", "points"):  # a dict / a list in the macro API: none, as the core's empty text
                assert p.default is None and fields[name]["default"] == "", (door, p.default)
                seen.add(name)
            elif name in fields:
                seen.add(name)
                assert p.default == fields[name]["default"], (door, name, p.default, fields[name]["default"])
    # Every option reaches the macro API but the two whole-model extras, the CLI's alone: a macro
    # measures the result with FreeCAD's own tools.
    assert set(fields) - seen == {"computeVolume", "checkModel"}, set(fields) - seen
    assert HoleFill.METHODS == tuple(fields["method"]["choices"]) and "support" not in HoleFill.METHODS
    assert HoleFill.CONTINUITIES == tuple(fields["continuity"]["choices"])


def test_the_fill_objects_properties_and_the_preferences_follow_the_schema():
    fields = schema()
    doc = FreeCAD.newDocument("schema")
    try:
        src = doc.addObject("Part::Feature", "Src")
        shape = Part.Shape()
        shape.importBrepFromString(HoleFillApp.sampleModel("bezier_patch_with_hole").decode())
        src.Shape = shape
        doc.recompute()
        fill = HoleFill.makeFill(src)
        for prop, name in (("Method", "method"), ("Continuity", "continuity"), ("Tolerance", "tolerance"),
                           ("AngularTolerance", "angularTolerance"), ("Weights", "weights"), ("EdgeContinuity", "edgeContinuity")):
            assert fill.getDocumentationOfProperty(prop) == HoleFill.optionTip(fields[name]), (prop, fill.getDocumentationOfProperty(prop))
            if name != "edgeContinuity":
                value = getattr(fill, prop)
                value = float(value) if name == "tolerance" else value
                assert value == fields[name]["default"], (prop, value)
        assert list(fill.getEnumerationsOfProperty("Method")) == fields["method"]["choices"]
        assert list(fill.getEnumerationsOfProperty("Continuity")) == fields["continuity"]["choices"]
        assert fill.Status == "ok", fill.Status
    finally:
        FreeCAD.closeDocument(doc.Name)
    preferences.reset()
    for pref, name in (("FillMethod", "method"), ("FillContinuity", "continuity"), ("FillTolerance", "tolerance"),
                       ("FillAngularTolerance", "angularTolerance"), ("UvtranWeights", "weights")):
        assert preferences.get(pref) == fields[name]["default"], (pref, preferences.get(pref))
    assert preferences.CHOICES["FillMethod"] == HoleFill.METHODS


def test_values_the_schema_refuses_are_refused_by_every_door_by_name():
    shape = Part.Shape()
    shape.importBrepFromString(HoleFillApp.sampleModel("bezier_patch_with_hole").decode())
    hole = HoleFill.prepareHole(shape, 1)
    for kwargs, word in ((dict(method="support"), "method must be one of"), (dict(continuity="G3"), "continuity must be one of"),
                         (dict(tolerance=-1.0), "tolerance must be zero or positive"),
                         (dict(angularTolerance=0.0), "angularTolerance must be positive"),
                         (dict(maxControlPoints=8), "maxControlPoints must be a whole number at least 16"),
                         (dict(edgeContinuity={"Edge1": "G7"}), "G7")):
        fcharness.expect_error(lambda: HoleFill.fillHole(shape, 1, **kwargs), word)
        fcharness.expect_error(lambda: hole.fill(**kwargs), word)
    # The core's dictionary door names an option it does not know, and the ones it does.
    fcharness.expect_error(lambda: hole._prepared.fill({"angularTolerence": 1e-3}), "unknown option 'angularTolerence'")
    fcharness.expect_error(lambda: hole._prepared.fill({"tolerance": [1]}), "tolerance must be a number, a bool or a string")


def expect_properties_follow(feature, properties, fields):
    """A new object of `feature` has each of `properties` ({property: option}) with the option's
    tooltip, default and choices."""
    doc = FreeCAD.newDocument("schema_object")
    try:
        obj = doc.addObject("Part::FeaturePython", "Object")
        feature(obj)
        for prop, name in properties.items():
            assert obj.getDocumentationOfProperty(prop) == HoleFill.optionTip(fields[name]), prop
            assert getattr(obj, prop) == fields[name]["default"], (prop, getattr(obj, prop), fields[name]["default"])
            if fields[name]["kind"] == "choice":
                assert list(obj.getEnumerationsOfProperty(prop)) == fields[name]["choices"], prop
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_labeled_fitting_follows_its_schema_in_every_door():
    fields = HoleFill.optionSchema("labeled_fit")
    assert list(fields) == [f["name"] for f in __import__("json").loads(HoleFillApp.optionSchema("labeled_fit"))]
    for fn in (HoleFill.fitLabeled, HoleFill.makeLabeledFit):
        params = inspect.signature(fn).parameters
        assert params["controlPoints"].default == (fields["controlU"]["default"], fields["controlV"]["default"]), fn
        for name, f in fields.items():
            if name in ("controlU", "controlV"):
                continue
            assert params[name].default == f["default"], (fn.__name__, name, params[name].default, f["default"])
    assert set(labeled.FIT_PROPERTIES.values()) == set(fields), set(fields) ^ set(labeled.FIT_PROPERTIES.values())
    expect_properties_follow(labeled.LabeledFitFeature, labeled.FIT_PROPERTIES, fields)
    import Mesh
    tri = Mesh.Mesh([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(0, 1, 0)])
    for kwargs, word in ((dict(extension="G7"), "extension must be one of fit, G2, G1, none"),
                         (dict(isocurves="wavy"), "isocurves must be one of grid, paper"),
                         (dict(reach=11.0), "reach must be between 0 and 10"),
                         (dict(controlPoints=(3, 12)), "controlU must be a whole number between 4 and 200"),
                         (dict(tolerance=-1.0), "tolerance must be zero or positive"),
                         (dict(relativeTolerance=0.0), "relativeTolerance must be")):
        fcharness.expect_error(lambda: HoleFill.fitLabeled(tri, [("N", [0, 1])], **kwargs), word)


def test_mesh_fill_follows_its_schema():
    fields = HoleFill.optionSchema("mesh_fill")
    params = inspect.signature(HoleFill.fillMeshHoles).parameters
    for name, f in fields.items():
        assert params[name].default == f["default"], (name, params[name].default, f["default"])
    assert inspect.signature(HoleFill.makeMeshFill).parameters["maxBoundary"].default == fields["maxBoundary"]["default"]
    assert HoleFill.defaultMaxBoundary() == fields["maxBoundary"]["default"]
    import Mesh
    tri = Mesh.Mesh([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(0, 1, 0)])
    for kwargs, word in ((dict(triangulation="delaunay"), "triangulation must be one of angle, dihedral, auto"),
                         (dict(shapeOrder=4), "shapeOrder must be a whole number between 0 and 3"),
                         (dict(densityFactor=0.0), "densityFactor must be positive"),
                         (dict(maxBoundary=-1), "maxBoundary must be a whole number")):
        fcharness.expect_error(lambda: HoleFill.fillMeshHoles(tri, **kwargs), word)


def test_gnurbs_follows_its_schema():
    fields = HoleFill.optionSchema("gnurbs")
    params = inspect.signature(HoleFill.gnurbsSurface).parameters
    for name, f in fields.items():
        assert params[name].default == f["default"], (name, params[name].default, f["default"])
    cage = HoleFill.sampleCage("cage_valence5")
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(cage["vertices"], cage["quads"], solve="greedy"),
                           "solve must be one of fair, stepwise")
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(cage["vertices"], cage["quads"], maxValence=4), "valence")


def test_point_cloud_fit_follows_its_schema_in_every_door():
    from HoleFill import pointcloud
    fields = HoleFill.optionSchema("point_fit")
    params = inspect.signature(HoleFill.fitPoints).parameters
    for name, f in fields.items():
        if name == "cellFaces":  # the CLI's shape choice; fitPoints returns the finest-level face
            continue
        assert params[name].default == f["default"], (name, params[name].default, f["default"])
    made = inspect.signature(HoleFill.makePointCloudFit).parameters
    for name in pointcloud.POINT_FIT_PROPERTIES.values():
        assert made[name].default == fields[name]["default"], name
    expect_properties_follow(pointcloud.PointCloudFitFeature, pointcloud.POINT_FIT_PROPERTIES, fields)
    pts = [FreeCAD.Vector(i, j, 0.1 * i * j) for i in range(6) for j in range(6)]
    for kwargs, word in ((dict(method="support"), "method must be one of shape, bidgcn, invdist, uniform"),
                         (dict(degree=8), "degree must be a whole number between 1 and 7"),
                         (dict(tolerance=-1.0), "tolerance must be zero or positive"),
                         (dict(relativeTolerance=0.0), "relativeTolerance must be")):
        fcharness.expect_error(lambda: HoleFill.fitPoints(pts, **kwargs), word)


fcharness.run(globals())
