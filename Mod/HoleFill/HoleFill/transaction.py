"""Adding a parametric object in one undo step, or not at all: the document is left exactly as
it was when building it fails or the object does not compute (with or without undo enabled);
and giving a parametric object the properties it lacks (new ones, or a document saved by an
older version)."""
import HoleFillApp


def addParametric(doc, title, name, setup, what):
    """New Part::FeaturePython `name` in `doc` under the undo title `title`; setup(obj) attaches
    the proxy and sets the properties. `what` names the object in the error raised when its
    recompute fails."""
    doc.openTransaction(title)
    obj = None
    try:
        obj = doc.addObject("Part::FeaturePython", name)
        setup(obj)
        doc.recompute()
        if not obj.isValid():
            raise HoleFillApp.HoleFillError("%s failed: %s" % (what, obj.getStatusString() or "see the report view"))
    except Exception:
        if obj is not None and doc.getObject(obj.Name) is not None:
            doc.removeObject(obj.Name)
        doc.abortTransaction()
        raise
    doc.commitTransaction()
    return obj


def changeParametric(obj, title, change, what):
    """change(obj) under the undo title `title`, then a recompute; when the recompute fails the
    change is undone (the object keeps its properties and shape) and HoleFillError raised."""
    doc = obj.Document
    doc.openTransaction(title)
    try:
        change(obj)
        obj.touch()
        doc.recompute()
        if not obj.isValid():
            raise HoleFillApp.HoleFillError("%s failed: %s" % (what, obj.getStatusString() or "see the report view"))
    except Exception:
        doc.abortTransaction()
        doc.recompute()
        raise
    doc.commitTransaction()
    return obj


def ensureProperty(obj, kind, name, group, doc, default=None):
    """Adds property `name` to obj unless it has it, set to `default` when one is given."""
    if name not in obj.PropertiesList:
        obj.addProperty(kind, name, group, doc)
        if default is not None:
            setattr(obj, name, default)


class ParametricFeature:
    """What the proxy of every HoleFill document object shares: its properties are set up when it
    is made and again when a saved document is restored (so properties added since appear in old
    documents), and nothing of it is pickled (its state is in the properties; caches are rebuilt).
    `viewProvider` names the view provider HoleFillGui gives it (view_provider.py; None: FreeCAD's
    own), attached from the Gui side when the object is made (HoleFillGui/view_attach.py): the App
    never imports the Gui."""

    viewProvider = None
    # The properties its result is computed from. Set, the object records them when it computes
    # (markComputed) and an undo or redo that brings back a result with the inputs it was computed
    # from leaves it untouched (FreeCAD marks every object whose properties an undo restored as
    # needing a recompute, and an edit undone left the Fill "Touched" with nothing to do).
    computedFrom = ()

    def __init__(self, obj):
        obj.Proxy = self
        self.setupProperties(obj)
        _watchUndo()

    def inputsKey(self, obj):
        """The values of computedFrom as text, to compare with what the result was computed from."""
        return repr([(name, str(getattr(obj, name, None))) for name in self.computedFrom])

    def markComputed(self, obj):
        if not self.computedFrom:
            return
        ensureProperty(obj, "App::PropertyString", "ComputedFor", "Base", "The inputs the shape was computed from (internal)")
        obj.setEditorMode("ComputedFor", 2)
        obj.ComputedFor = self.inputsKey(obj)

    def setupProperties(self, obj):
        raise NotImplementedError

    def onDocumentRestored(self, obj):
        self.setupProperties(obj)
        _watchUndo()

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None


class _UndoObserver:
    """After an undo or redo: a HoleFill object whose restored result was computed from its
    restored inputs, and whose inputs are not themselves waiting for a recompute, is not touched."""

    def slotUndoDocument(self, doc):
        self._settle(doc)

    def slotRedoDocument(self, doc):
        self._settle(doc)

    @staticmethod
    def _settle(doc):
        for obj in doc.Objects:
            proxy = getattr(obj, "Proxy", None)
            if not isinstance(proxy, ParametricFeature) or not proxy.computedFrom or "Touched" not in obj.State:
                continue
            if getattr(obj, "ComputedFor", None) != proxy.inputsKey(obj):
                continue
            if any("Touched" in o.State for o in obj.OutList):
                continue
            obj.purgeTouched()


_OBSERVER = None


def _watchUndo():
    global _OBSERVER
    if _OBSERVER is None:
        import FreeCAD
        _OBSERVER = _UndoObserver()
        FreeCAD.addDocumentObserver(_OBSERVER)
