"""Gives HoleFill's document objects their view providers from the Gui side, so that the App side
(Mod/HoleFill/HoleFill) never imports the Gui. Each App feature class names its view provider in
`viewProvider` (a class of view_provider.py; None: FreeCAD's own, which Proxy 0 keeps); a document
observer attaches it when the object's Proxy is set, i.e. when the object is made — by a command,
a task panel or a macro. InitGui.py installs the observer when FreeCAD's GUI starts, before any
workbench is loaded, so a macro that makes a Fill first still gets the Fill's view provider.
Documents being restored keep the view providers they were saved with."""
import FreeCAD

_observer = None


def attach(obj):
    """Gives `obj` the view provider its feature class names, unless it has one already."""
    feature = getattr(obj, "Proxy", None)
    if feature is None or not hasattr(type(feature), "viewProvider"):
        return
    vobj = getattr(obj, "ViewObject", None)
    if vobj is None or getattr(vobj, "Proxy", None) is not None:
        return
    name = type(feature).viewProvider
    if name is None:
        vobj.Proxy = 0
        return
    from HoleFillGui import view_provider
    getattr(view_provider, name)(vobj)


class _Observer:
    def slotChangedObject(self, obj, prop):
        if prop == "Proxy" and not getattr(obj.Document, "Restoring", False):
            attach(obj)


def install():
    """Installs the observer once (InitGui.py)."""
    global _observer
    if _observer is None:
        _observer = _Observer()
        FreeCAD.addDocumentObserver(_observer)
