# HoleFill addon, console part. FreeCAD exec's this file with the addon folder on
# sys.path, so `import HoleFill` (the Python API) and `import HoleFillApp` (the
# compiled core next to this file) work in macros and in freecadcmd.
