"""HoleFill's headless tests for FreeCAD's own test runner: `freecadcmd -t HoleFillTests`, or the
Test workbench's "Self-test" with HoleFillTests typed in. The same test functions as the project's
ctest runs one file at a time (tests/freecad/test_*.py), gathered as one unittest TestCase per file
and one test per function. The addon ships them in its HoleFillTests folder, laid out as in the
source tree (freecad/, fuzz/corpus/, fc_exit.py) so that their relative paths hold."""
import glob
import importlib
import os
import sys
import unittest

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(_HERE, "freecad"))
import fcharness  # noqa: E402

fcharness.COLLECTING = True  # each file's fcharness.run(globals()) returns instead of running and leaving


def _case(module):
    def method(fn):
        return lambda self: fn()

    attrs = {name: method(fn) for name, fn in vars(module).items() if name.startswith("test_") and callable(fn)}
    attrs["__doc__"] = (module.__doc__ or "").strip().split("\n")[0]
    return type("HoleFill_" + module.__name__[len("test_"):], (unittest.TestCase,), attrs)


for _path in sorted(glob.glob(os.path.join(_HERE, "freecad", "test_*.py"))):
    _module = importlib.import_module(os.path.basename(_path)[:-3])
    _cls = _case(_module)
    globals()[_cls.__name__] = _cls

del _path, _module, _cls
