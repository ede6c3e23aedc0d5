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
