"""Minimal runner for headless FreeCAD tests: runs every test_* function of a module,
prints one line per test and 'N passed, N failed', writes {"ok": ...} to $HF_RESULT
and leaves with os._exit (freecadcmd's own exit status is not reliable)."""
import json
import os
import sys
import time
import traceback


def run(namespace):
    tests = sorted((n, f) for n, f in namespace.items() if n.startswith("test_") and callable(f))
    passed, failed = 0, []
    for name, fn in tests:
        t0 = time.time()
        try:
            fn()
            passed += 1
            print("ok   %s (%.2f s)" % (name, time.time() - t0))
        except Exception:
            failed.append(name)
            print("FAIL %s\n%s" % (name, traceback.format_exc()))
    print("%d passed, %d failed" % (passed, len(failed)))
    sys.stdout.flush()
    path = os.environ.get("HF_RESULT")
    if path:
        with open(path, "w") as f:
            json.dump({"ok": not failed and passed > 0, "passed": passed, "failed": failed}, f)
    try:
        import FreeCAD
        for d in list(FreeCAD.listDocuments()):
            FreeCAD.closeDocument(d)
    except Exception:
        pass
    sys.stdout.flush()
    os._exit(0 if not failed else 1)
