"""Refuses, with a clear error, to load the compiled core into a FreeCAD it was not built for.
The core links OCCT and is a module of one Python version: loaded into a FreeCAD built on another
OCCT it would put two OCCTs in one process (their handles and type registries clash), and under
another Python it does not load at all, with a message that does not say why. The build writes
build_info.py (OCCT and Python versions) next to this file; FreeCAD's own OCCT is Part's."""
import sys


def check():
    try:
        from HoleFill import build_info
    except ImportError:  # a source tree run without a build: nothing to compare
        return
    python = "%d.%d" % sys.version_info[:2]
    if python != build_info.PYTHON:
        raise ImportError("HoleFill was built for Python %s, but this FreeCAD runs Python %s: rebuild HoleFill on this system "
                          "(./scripts/build.sh) and install it again (./scripts/install.sh)" % (build_info.PYTHON, python))
    try:
        import Part
        occt = Part.OCC_VERSION
    except Exception:  # outside FreeCAD: no other OCCT to clash with
        return
    if occt.split(".")[:2] != build_info.OCCT.split(".")[:2]:
        raise ImportError("HoleFill was built against OCCT %s, but this FreeCAD uses OCCT %s; two OCCTs in one process must "
                          "not happen: rebuild HoleFill on this system (./scripts/build.sh) and install it again "
                          "(./scripts/install.sh)" % (build_info.OCCT, occt))
