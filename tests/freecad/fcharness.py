"""Minimal runner for headless FreeCAD tests: runs every test_* function of a module,
prints one line per test and 'N passed, N failed', writes {"ok": ...} to $HF_RESULT
and leaves with os._exit (freecadcmd's own exit status is not reliable)."""
import os
import sys
import time
import traceback

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/: fc_exit
import fc_exit  # noqa: E402


def expect_error(fn, *words):
    """Calls fn, which must raise HoleFill.HoleFillError whose message holds every word; returns it."""
    import HoleFill
    try:
        fn()
    except HoleFill.HoleFillError as e:
        for w in words:
            assert w in str(e), "message %r lacks %r" % (str(e), w)
        return str(e)
    raise AssertionError("no HoleFillError raised")


# Set by the HoleFillTests package (FreeCAD's own test runner), which gathers the test functions
# itself: run() then leaves them to it.
COLLECTING = False


def run(namespace):
    if COLLECTING:
        return
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
    fc_exit.write_result_and_exit({"ok": not failed and passed > 0, "passed": passed, "failed": failed},
                                  0 if not failed else 1)
