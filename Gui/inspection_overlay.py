"""View-only inspection overlays (curvature colours, zebra stripes, continuity-coloured
boundaries) on Part objects. Each overlay is one named SoSeparator in the active view's
scene graph, drawn with a polygon offset over the object's own faces: nothing in the
document changes, and removing the node restores the original display. Overlays follow
their object: a recompute that changes its Shape rebuilds them, deleting it removes them.

Geometry and numbers come from the core (HoleFill.inspectionMesh/curvatureMap: exact
normals and curvatures at an adaptive tessellation). Zebra stripes are computed per pixel
by a GLSL shader from the interpolated exact normals, so they follow the camera with no
per-frame work in Python; it repeats the core's stripe formula (App/inspect/inspection_values.h).
"""
import FreeCAD
import FreeCADGui
from pivy import coin

import HoleFill
from HoleFillGui import SelectionError
from HoleFillGui.scene_overlay import TIER_COLORS

translate = FreeCAD.Qt.translate

PREFIX = "HoleFillInspect"
KINDS = ("Curvature", "Zebra", "Continuity", "Combs")
# The curvature combs: the face measured (the fill) and the face it is measured against.
COMB_COLORS = {"face": (0.1, 0.35, 0.95), "support": (0.85, 0.1, 0.65)}


def scene_targets():
    """[(object, None)] for every visible object of the active document with B-rep faces: the
    whole scene, as CurvesWB's zebra judges a fill with its neighbours without re-selecting.
    SelectionError when there is none."""
    doc = FreeCADGui.ActiveDocument
    out = []
    for obj in (doc.Document.Objects if doc is not None else []):
        shape = getattr(obj, "Shape", None)
        if obj.isDerivedFrom("Mesh::Feature") or shape is None or shape.isNull() or not shape.Faces:
            continue
        if obj.ViewObject is not None and obj.ViewObject.Visibility:
            out.append((obj, None))
    if not out:
        raise SelectionError(translate("HoleFill", "No visible object has faces to draw stripes on: show one, or select faces."))
    return out


def targets_from_selection(allow_whole_objects=True, whole_scene=False):
    """[(object, [face indices] or None for all faces)] from the selection; with nothing selected,
    the visible objects (whole_scene) or SelectionError."""
    sel = FreeCADGui.Selection.getSelectionEx()
    if not sel and whole_scene:
        return scene_targets()
    if not sel:
        raise SelectionError(translate("HoleFill", "Select faces or Part objects first (e.g. a Fill result)."))
    out = []
    for s in sel:
        obj = s.Object
        if obj.isDerivedFrom("Mesh::Feature"):
            raise SelectionError(translate("HoleFill", "%s is a mesh: curvature maps and zebra stripes here work on B-rep faces. "
                                 "For meshes use Mesh > Curvature plot.") % obj.Label)
        shape = getattr(obj, "Shape", None)
        if shape is None or shape.isNull() or not shape.Faces:
            raise SelectionError(translate("HoleFill", "%s has no faces to inspect.") % obj.Label)
        subs = list(s.SubElementNames)
        faces = [int(n[4:]) for n in subs if n.startswith("Face")]
        if subs and not faces:
            raise SelectionError(translate("HoleFill", "Only edges or vertices of %s are selected: select faces or the whole object.") % obj.Label)
        if not faces and not allow_whole_objects:
            raise SelectionError(translate("HoleFill", "Select faces of %s.") % obj.Label)
        out.append((obj, faces or None))
    return out


def _view():
    gdoc = FreeCADGui.ActiveDocument
    if gdoc is None or not hasattr(gdoc.ActiveView, "getSceneGraph"):
        raise SelectionError(translate("HoleFill", "No 3D view is open."))
    return gdoc.ActiveView


# An overlay is interactive work: its tessellation stops before about two vertices per pixel of
# the view (more shows nothing more) or INTERACTIVE_SECONDS by its measured rate, shows its
# progress after half a second and can be cancelled (issue 22: zebra on a fill gone wrong once
# built 3 million vertices in 73 s with no way out).
INTERACTIVE_SECONDS = 10.0


def view_vertex_budget():
    """Two vertices per pixel of the active 3D view (a full-HD view: about 4 million), at least 200,000."""
    try:
        w, h = _view().getSize()
    except Exception:
        w, h = 1920, 1080
    return max(200000, 2 * int(w) * int(h))


def bounded_mesh(obj, faces, maxNormalAngle=2.0, what="Tessellating", maxVertices=None):
    """HoleFill.inspectionMesh bounded by the view (or maxVertices) and INTERACTIVE_SECONDS, with a
    cancellable progress dialog; cancelling raises HoleFillError. A mesh that stopped at a bound
    carries stoppedByBudget and its warnings, which go to the report view."""
    from HoleFillGui import task_dialog
    with task_dialog.progress_dialog("%s %s..." % (what, obj.Label), FreeCADGui.getMainWindow()) as progress:
        mesh = HoleFill.inspectionMesh(obj.Shape, faces, maxNormalAngle, maxVertices=maxVertices or view_vertex_budget(),
                                       timeLimit=INTERACTIVE_SECONDS, progress=progress)
    for w in mesh["warnings"]:
        FreeCAD.Console.PrintWarning("HoleFill: %s: %s\n" % (obj.Label, w))
    return mesh


def _name(kind, obj):
    return "%s_%s_%s" % (PREFIX, kind, obj.Name)


def nodes(kind=None):
    """Overlay nodes now in the active view (all kinds, or one)."""
    try:
        root = _view().getSceneGraph()
    except SelectionError:
        return []
    want = PREFIX + ("_" + kind + "_" if kind else "")
    return [root.getChild(i) for i in range(root.getNumChildren()) if root.getChild(i).getName().getString().startswith(want)]


def remove(kind=None, obj=None):
    """Removes overlays (of a kind, of an object); returns how many were removed."""
    try:
        root = _view().getSceneGraph()
    except SelectionError:
        return 0
    n = 0
    for node in nodes(kind):
        name = node.getName().getString()
        if obj is None or name.endswith("_" + obj.Name):
            _drop(root, node)
            n += 1
    _WATCH.forget(kind, obj)
    if not nodes():
        _WATCH.detach()
    return n


def _surface_nodes(mesh, material_nodes):
    sep = coin.SoSeparator()
    pick = coin.SoPickStyle()
    pick.style = coin.SoPickStyle.UNPICKABLE
    offset = coin.SoPolygonOffset()  # wins the depth test over the object's own faces
    offset.factor = -1.0
    offset.units = -1.0
    hints = coin.SoShapeHints()
    hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
    hints.shapeType = coin.SoShapeHints.UNKNOWN_SHAPE_TYPE
    coords = coin.SoCoordinate3()
    pts = mesh["points"]
    coords.point.setValues(0, len(pts), pts.astype("float32"))
    normals = coin.SoNormal()
    normals.vector.setValues(0, len(pts), mesh["normals"].astype("float32"))
    nbind = coin.SoNormalBinding()
    nbind.value = coin.SoNormalBinding.PER_VERTEX_INDEXED
    faces = coin.SoIndexedFaceSet()
    tris = mesh["triangles"]
    import numpy
    idx = numpy.hstack([tris.astype("int32"), -numpy.ones((len(tris), 1), dtype="int32")]).ravel()
    faces.coordIndex.setValues(0, len(idx), idx)
    for n in [pick, offset, hints, coords, normals, nbind] + list(material_nodes) + [faces]:
        sep.addChild(n)
    return sep


def _drop(root, node):
    name = node.getName().getString()  # before the removal: it may free the node
    root.removeChild(node)
    zebra = _VERTEX_ZEBRAS.pop(name, None)
    if zebra is not None:
        zebra.detach()


def _add(kind, obj, node):
    root = _view().getSceneGraph()
    for old in nodes(kind):
        if old.getName().getString() == _name(kind, obj):
            _drop(root, old)
    node.setName(_name(kind, obj))
    root.addChild(node)
    _WATCH.attach()
    return node


def show_curvature(obj, faces, quantity="mean", percentiles=(2.0, 98.0), valueRange=None, maxNormalAngle=2.0,
                   mesh=None):
    """Curvature-coloured overlay of `obj` (its `faces`, or all); returns the curvatureMap dict."""
    mesh = mesh or bounded_mesh(obj, faces, maxNormalAngle, "Curvature of")
    cmap = HoleFill.curvatureMap(obj.Shape, quantity=quantity, faces=faces, percentiles=percentiles,
                                 valueRange=valueRange, maxNormalAngle=maxNormalAngle, mesh=mesh)
    mat = coin.SoMaterial()
    mat.diffuseColor.setValues(0, len(cmap["colors"]), cmap["colors"])
    mat.specularColor = (0.15, 0.15, 0.15)
    mat.shininess = 0.3
    mbind = coin.SoMaterialBinding()
    mbind.value = coin.SoMaterialBinding.PER_VERTEX_INDEXED
    _add("Curvature", obj, _surface_nodes(cmap, [mat, mbind]))
    _WATCH.remember("Curvature", obj, dict(faces=faces, quantity=quantity, percentiles=percentiles,
                                           valueRange=valueRange, maxNormalAngle=maxNormalAngle))
    return cmap


_VERTEX = """
varying vec3 nEye;
varying vec3 nWorld;
varying vec3 pEye;
void main() {
  nEye = normalize(gl_NormalMatrix * gl_Normal);
  nWorld = gl_Normal;  // the overlay sits at the scene root: object space is world space
  pEye = vec3(gl_ModelViewMatrix * gl_Vertex);
  gl_Position = ftransform();
}
"""

# stripe parameter s = angle(a, d) / pi; a = view ray mirrored at n (reflection) or n (isophote).
_FRAGMENT = """
varying vec3 nEye;
varying vec3 nWorld;
varying vec3 pEye;
uniform float count;
uniform float width;
uniform float angle;
uniform float isophote;
uniform vec3 isoDirection;
void main() {
  vec3 n = normalize(nEye);
  bool ortho = gl_ProjectionMatrix[3][3] > 0.5;
  vec3 v = ortho ? vec3(0.0, 0.0, -1.0) : normalize(pEye);
  vec3 a = isophote > 0.5 ? normalize(nWorld) : reflect(v, n);
  vec3 d = isophote > 0.5 ? normalize(isoDirection) : vec3(cos(angle), sin(angle), 0.0);
  float s = acos(clamp(dot(a, d), -1.0, 1.0)) / 3.14159265 * count;
  float f = fract(s);
  float e = max(fwidth(s), 1e-4);
  float white = smoothstep(width - e, width + e, f) * (1.0 - smoothstep(1.0 - e, 1.0, f));
  float c = mix(0.06, 0.97, white) * (0.8 + 0.2 * abs(n.z));
  gl_FragColor = vec4(c, c, c, 1.0);
}
"""


def zebra_shader(count=16, width=0.5, angleDeg=0.0, isophote=False, isoDirection=(0.0, 0.0, 1.0)):
    import math
    prog = coin.SoShaderProgram()
    vs = coin.SoVertexShader()
    vs.sourceType = coin.SoShaderObject.GLSL_PROGRAM
    vs.sourceProgram = _VERTEX
    fs = coin.SoFragmentShader()
    fs.sourceType = coin.SoShaderObject.GLSL_PROGRAM
    fs.sourceProgram = _FRAGMENT
    params = []
    for name, value in (("count", float(count)), ("width", float(width)), ("angle", math.radians(angleDeg)),
                        ("isophote", 1.0 if isophote else 0.0)):
        p = coin.SoShaderParameter1f()
        p.name = name
        p.value = value
        params.append(p)
    d = coin.SoShaderParameter3f()
    d.name = "isoDirection"
    d.value = coin.SbVec3f(*[float(x) for x in isoDirection])
    params.append(d)
    fs.parameter.setValues(0, len(params), params)
    prog.shaderObject.setValues(0, 2, [vs, fs])
    return prog


def zebra_shades(points, normals, camera, count=16, width=0.5, angleDeg=0.0, isophote=False, isoDirection=(0.0, 0.0, 1.0)):
    """The fragment shader's grey per vertex (numpy arrays of points and unit normals in, one value
    in [0, 1] per vertex out), for `camera` (an SoCamera) as it is now; the stripe edges are hard,
    as the shader's are at a pixel, and are blended across each triangle by the vertex colours."""
    import math
    import numpy
    rot = camera.orientation.getValue()
    axes = numpy.array([rot.multVec(coin.SbVec3f(*e)).getValue() for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))])
    n = normals @ axes.T  # eye space: rows of axes are the camera's x, y, z in world space
    if isophote:
        a = normals
        d = numpy.asarray(isoDirection, float) / max(numpy.linalg.norm(isoDirection), 1e-300)
    else:
        if camera.isOfType(coin.SoOrthographicCamera.getClassTypeId()):
            v = numpy.tile([0.0, 0.0, -1.0], (len(points), 1))
        else:
            v = (points - numpy.array(camera.position.getValue().getValue())) @ axes.T
            v /= numpy.maximum(numpy.linalg.norm(v, axis=1), 1e-300)[:, None]
        a = v - 2.0 * numpy.sum(v * n, axis=1)[:, None] * n
        d = numpy.array([math.cos(math.radians(angleDeg)), math.sin(math.radians(angleDeg)), 0.0])
    s = numpy.arccos(numpy.clip(a @ d, -1.0, 1.0)) / math.pi * count
    white = (s - numpy.floor(s)) >= width
    return numpy.where(white, 0.97, 0.06) * (0.8 + 0.2 * numpy.abs(n[:, 2]))


# The per-vertex zebra recomputes every vertex's grey in Python at each camera change, so its mesh
# is bounded by what a turn of the view can afford, not by the view's pixels: measured on this
# project's VM (AMD EPYC, both cores busy with a build), shades plus upload to Coin took 0.09 s
# at 200,000 vertices, 0.96 s at 1 million and 3.6 s at 4 million (a full-HD view's budget).
VERTEX_ZEBRA_VERTICES = 200000


def zebra_vertex_budget(renderer):
    """The zebra mesh's vertex bound for `renderer`: VERTEX_ZEBRA_VERTICES for the per-vertex one,
    None (the view's) for the shader."""
    return VERTEX_ZEBRA_VERTICES if renderer == "vertex" else None


class _VertexZebra:
    """Per-vertex stripes that follow the view: the material's colours are recomputed whenever the
    camera changes (one sensor on the camera node: a turn that moves its orientation and position
    at once is one update, not two)."""

    def __init__(self, mesh, camera, params):
        import numpy
        self.points = numpy.asarray(mesh["points"], float)
        normals = numpy.asarray(mesh["normals"], float)
        # Unit once here, not at every camera move.
        self.normals = normals / numpy.maximum(numpy.linalg.norm(normals, axis=1), 1e-300)[:, None]
        self.camera, self.params = camera, params
        self.material = coin.SoMaterial()
        self.light = coin.SoLightModel()
        self.light.model = coin.SoLightModel.BASE_COLOR  # the grey already holds the shading
        self.binding = coin.SoMaterialBinding()
        self.binding.value = coin.SoMaterialBinding.PER_VERTEX_INDEXED
        self.sensor = coin.SoNodeSensor(self._changed, None)
        self.sensor.attach(camera)
        self.update()

    def _changed(self, data, sensor):
        self.update()

    def update(self):
        import numpy
        grey = zebra_shades(self.points, self.normals, self.camera, **self.params).astype("float32")
        rgb = numpy.repeat(grey[:, None], 3, axis=1)
        self.material.diffuseColor.setValues(0, len(rgb), rgb)

    def detach(self):
        self.sensor.detach()


_VERTEX_ZEBRAS = {}  # overlay node name -> its _VertexZebra, alive while the overlay is shown


def show_zebra(obj, faces, count=16, width=0.5, angleDeg=0.0, isophote=False, isoDirection=(0.0, 0.0, 1.0),
               maxNormalAngle=2.0, mesh=None, renderer="shader"):
    """Zebra overlay (reflection lines, or isophotes when isophote=True); returns the mesh dict.
    renderer: one of HoleFill.inspection.ZEBRA_RENDERERS (the Preferences' choice in the panel)."""
    from HoleFill.inspection import ZEBRA_RENDERERS
    if renderer not in ZEBRA_RENDERERS:
        raise HoleFill.HoleFillError("unknown zebra renderer '%s': use %s" % (renderer, ", ".join(ZEBRA_RENDERERS)))
    mesh = mesh or bounded_mesh(obj, faces, maxNormalAngle, "Zebra stripes of", zebra_vertex_budget(renderer))
    if renderer == "shader":
        node = _add("Zebra", obj, _surface_nodes(mesh, [zebra_shader(count, width, angleDeg, isophote, isoDirection)]))
    else:
        zebra = _VertexZebra(mesh, _view().getCameraNode(), dict(count=count, width=width, angleDeg=angleDeg,
                                                                  isophote=isophote, isoDirection=isoDirection))
        node = _add("Zebra", obj, _surface_nodes(mesh, [zebra.light, zebra.material, zebra.binding]))
        _VERTEX_ZEBRAS[node.getName().getString()] = zebra
    _WATCH.remember("Zebra", obj, dict(faces=faces, count=count, width=width, angleDeg=angleDeg, isophote=isophote,
                                       isoDirection=isoDirection, maxNormalAngle=maxNormalAngle, renderer=renderer))
    return mesh


def continuity_color(g0rel, g1, g2):
    """The colour of the tier met (scene_overlay.TIER_COLORS): G2 blue, G1 strict cyan, G0 strict
    orange, not even G0 red."""
    return TIER_COLORS["none" if g0rel > 1e-6 else "G0" if g1 > 1e-3 else "G1" if g2 > 0.1 else "G2"]


def edge_runs(report):
    """The report's boundary samples cut where their edge changes: [samples of one edge, ...]
    (stretches of one sample left out: nothing to draw along)."""
    samples, edges = report["samples_along"], report["sample_edges"]
    runs, start = [], 0
    for i in range(1, len(samples) + 1):
        if i == len(samples) or edges[i] != edges[start]:
            if i - start >= 2:
                runs.append(samples[start:i])
            start = i
    return runs


def show_continuity(obj, report):
    """Draws the measured boundary samples as thick lines coloured by their continuity tier."""
    scale = max(report["scale"], 1e-300)
    sep = coin.SoSeparator()
    pick = coin.SoPickStyle()
    pick.style = coin.SoPickStyle.UNPICKABLE
    depth = coin.SoDepthBuffer()
    depth.test = False  # always visible, also behind the faces it separates
    style = coin.SoDrawStyle()
    style.lineWidth = 5
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    mat = coin.SoMaterial()
    mbind = coin.SoMaterialBinding()
    mbind.value = coin.SoMaterialBinding.PER_VERTEX
    coords = coin.SoCoordinate3()
    lines = coin.SoLineSet()
    pts, cols, counts = [], [], []
    for run in edge_runs(report):
        counts.append(len(run))
        for x, y, z, g0, g1, g2 in (r[:6] for r in run):
            pts.append((x, y, z))
            cols.append(continuity_color(g0 / scale, g1, g2))
    coords.point.setValues(0, len(pts), pts)
    mat.diffuseColor.setValues(0, len(cols), cols)
    lines.numVertices.setValues(0, len(counts), counts)
    for n in (pick, depth, style, light, mat, mbind, coords, lines):
        sep.addChild(n)
    _add("Continuity", obj, sep)
    return sep


def comb_teeth(report, length=0.2):
    """Per edge of the continuity report, the two curvature combs along it (CurvesWB's): for the
    face and for its support, the samples and the tips of the teeth p − s·κ·n, κ the normal
    curvature across the boundary, n the face's normal, s one scale for all (the largest |κ|
    gives length × the report's scale). Returns ({"face": [(points, tips), ...], "support": [...]}, s);
    s is 0 where every κ is 0 (flat on both sides: teeth of zero length)."""
    import math
    finite = [abs(r[c]) for r in report["samples_along"] for c in (9, 10) if math.isfinite(r[c])]
    top = max(finite, default=0.0)
    s = length * report["scale"] / top if top > 1e-12 / max(report["scale"], 1e-300) else 0.0
    combs = {"face": [], "support": []}
    for run in edge_runs(report):
        run = [r for r in run if all(math.isfinite(x) for x in r[6:11])]
        if len(run) < 2:
            continue
        for side, c in (("face", 9), ("support", 10)):
            pts = [tuple(r[:3]) for r in run]
            tips = [tuple(r[k] - s * r[c] * r[6 + k] for k in range(3)) for r in run]
            combs[side].append((pts, tips))
    return combs, s


def show_combs(obj, report, length=0.2, teeth=24):
    """Draws the curvature combs of comb_teeth over the boundary: the face's in blue, its
    support's in magenta (COMB_COLORS), about `teeth` teeth per edge (the report samples 200,
    which drawn all read as a filled band) and the line through every sample's tip.
    Where the face is G2 the two combs coincide. Returns the scale s."""
    combs, s = comb_teeth(report, length)
    sep = coin.SoSeparator()
    pick = coin.SoPickStyle()
    pick.style = coin.SoPickStyle.UNPICKABLE
    depth = coin.SoDepthBuffer()
    depth.test = False  # teeth on the far side of a face stay visible
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    for n in (pick, depth, light):
        sep.addChild(n)
    for side in ("face", "support"):
        part = coin.SoSeparator()
        part.setName("%s_Combs_%s" % (PREFIX, side))
        col = coin.SoBaseColor()
        col.rgb.setValue(*COMB_COLORS[side])
        style = coin.SoDrawStyle()
        style.lineWidth = 2 if side == "face" else 1.5
        pts, counts = [], []
        for base, tips in combs[side]:
            step = max(1, len(base) // teeth)
            for k in list(range(0, len(base), step)) + ([len(base) - 1] if (len(base) - 1) % step else []):
                pts += [base[k], tips[k]]
                counts.append(2)
            pts += tips
            counts.append(len(tips))
        coords = coin.SoCoordinate3()
        coords.point.setValues(0, len(pts), pts)
        lines = coin.SoLineSet()
        lines.numVertices.setValues(0, len(counts), counts)
        for n in (col, style, coords, lines):
            part.addChild(n)
        sep.addChild(part)
    _add("Combs", obj, sep)
    return s


class _Watcher:
    """Rebuilds overlays when their object's Shape changes; removes them when it is deleted."""

    def __init__(self):
        self.attached = False
        self.settings = {}  # (kind, object name) -> keyword arguments of show_*

    def remember(self, kind, obj, kwargs):
        self.settings[(kind, obj.Name)] = (obj, kwargs)

    def forget(self, kind, obj):
        for key in list(self.settings):
            if (kind is None or key[0] == kind) and (obj is None or key[1] == obj.Name):
                del self.settings[key]

    def attach(self):
        if not self.attached:
            FreeCAD.addDocumentObserver(self)
            self.attached = True

    def detach(self):
        if self.attached:
            FreeCAD.removeDocumentObserver(self)
            self.attached = False

    def slotChangedObject(self, obj, prop):
        # A Placement change moves the Shape without announcing a Shape change.
        if prop not in ("Shape", "Placement") or not any(k[1] == obj.Name for k in self.settings):
            return
        from PySide2 import QtCore
        QtCore.QTimer.singleShot(0, lambda: self.refresh(obj))

    def slotDeletedObject(self, obj):
        if any(k[1] == obj.Name for k in self.settings):
            remove(None, obj)

    def refresh(self, obj):
        for (kind, name), (o, kw) in list(self.settings.items()):
            if name != obj.Name:
                continue
            try:
                if kind == "Curvature":
                    show_curvature(o, **kw)
                elif kind == "Zebra":
                    show_zebra(o, **kw)
            except Exception as e:  # e.g. the new shape lost the inspected faces
                FreeCAD.Console.PrintWarning("HoleFill: %s overlay of %s removed: %s\n" % (kind, o.Label, e))
                remove(kind, o)


_WATCH = _Watcher()
