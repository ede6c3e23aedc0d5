"""Leaving a FreeCAD test run reliably: write the JSON result to $HF_RESULT (the runners read it,
FreeCAD's own exit status is not reliable), close the documents (their transient folders go with
them), flush, and os._exit (FreeCAD's teardown after sys.exit can crash)."""
import json
import os
import sys


def write_result_and_exit(info, code):
    path = os.environ.get("HF_RESULT")
    if path:
        with open(path, "w") as f:
            json.dump(info, f, default=str)
    try:
        import FreeCAD
        for d in list(FreeCAD.listDocuments()):
            FreeCAD.closeDocument(d)
    except Exception:
        pass
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
