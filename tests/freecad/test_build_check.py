"""Headless FreeCAD tests of HoleFill/build_check.py: the installed build says what it was built
for, matching the running FreeCAD; a build for another OCCT or Python is refused, before the core
is loaded, with an error that says what to do."""
import sys

import Part

import fcharness
from HoleFill import build_check, build_info


def test_the_build_matches_the_running_freecad():
    assert build_info.OCCT.split(".")[:2] == Part.OCC_VERSION.split(".")[:2], (build_info.OCCT, Part.OCC_VERSION)
    assert build_info.PYTHON == "%d.%d" % sys.version_info[:2], build_info.PYTHON
    build_check.check()


def refused(**wrong):
    saved = {k: getattr(build_info, k) for k in wrong}
    try:
        for k, v in wrong.items():
            setattr(build_info, k, v)
        build_check.check()
    except ImportError as e:
        return str(e)
    finally:
        for k, v in saved.items():
            setattr(build_info, k, v)
    raise AssertionError("a build for %s was not refused" % wrong)


def test_a_build_for_another_occt_or_python_is_refused():
    msg = refused(OCCT="6.9.1")
    assert "OCCT 6.9.1" in msg and Part.OCC_VERSION in msg and "two OCCTs" in msg and "./scripts/build.sh" in msg, msg
    msg = refused(PYTHON="2.7")
    assert "Python 2.7" in msg and "rebuild" in msg, msg


fcharness.run(globals())
