"""Benchmark on the B-rep hole corpus (tests/corpus/brep_holes.py, issue 20): HoleFill's whole
`holefill fill` CLI call (methods auto, np, mvc, uvtran) against FreeCAD's Surface Filling (OCCT
GeomPlate, neighbours as supports, default settings), side by side in one run on the same real holes.

A hole is judged per edge against its truth (the face the corpus removed): on the edges where the
original model was tangent (truth G1 <= 1e-2 rad) the fill must reach G1 <= 1e-3 rad; on creases
G1 is not asked. Strict = G0 <= 1e-6 x scale everywhere and G1 <= 1e-3 rad on the tangent edges.
G2 <= 0.1 is judged on the edges where the truth is G2, on the holes whose every edge that is not a
crease is G2 (a "G2 surround"). "fail" = no face (the CLI exited 2,
crashed or timed out; GeomPlate's recompute gave no valid face).

  BENCH_CORPUS=DIR (corpus-out/brep)  BENCH_CORPUS_EVERY=k (every k-th hole, 1) from BENCH_CORPUS_OFFSET (0)
  BENCH_FILL_ARGS="--no-crease-detection": extra `holefill fill` arguments for every fill
  BENCH_CORPUS_MERGE="a.json b.json": no run, the tables of earlier runs' results together (shards)
  BENCH_CORPUS_ONLY=g2 (the G2 surrounds only)  BENCH_CORPUS_METHODS=auto,np,mvc,uvtran  BENCH_CORPUS_CONTINUITY=G1  BENCH_GEOMPLATE=1
Run by scripts/bench.sh (BENCH_ONLY=corpus) inside freecadcmd; writes $BENCH_OUT/bench_corpus.json/.md."""
import collections
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import FreeCAD
import Part

import HoleFill

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else "tests/bench")
from geomplate import surface_filling  # noqa: E402

OUT = os.environ.get("BENCH_OUT", "/tmp")
CORPUS = os.environ.get("BENCH_CORPUS", "corpus-out/brep")
EVERY = int(os.environ.get("BENCH_CORPUS_EVERY", "1"))
OFFSET = int(os.environ.get("BENCH_CORPUS_OFFSET", "0"))
MERGE = os.environ.get("BENCH_CORPUS_MERGE", "").split()
METHODS = os.environ.get("BENCH_CORPUS_METHODS", "auto,np,mvc,uvtran").split(",")
CONTINUITY = os.environ.get("BENCH_CORPUS_CONTINUITY", "G1")
GEOMPLATE = os.environ.get("BENCH_GEOMPLATE", "1") == "1"
CLI = os.environ.get("HOLEFILL_CLI", "holefill")
EXTRA = os.environ.get("BENCH_FILL_ARGS", "").split()  # e.g. --no-crease-detection, for a row without it
TIMEOUT = 120


def judge(per_edge, truth, g0r, scale):
    cls = {e["edge"]: e["class"] for e in truth["per_edge"]}
    g1 = max([e["g1"] for e in per_edge if cls.get(e["edge"]) != "crease"] or [0.0])
    g2 = max([e["g2"] for e in per_edge if cls.get(e["edge"]) == "g2"] or [0.0])
    # Strict, or no worse than the input model is at each edge: G0 within the edge's own tolerance
    # (as the model had it) where that is larger, G1 within 1e-3 rad beyond the angle at which the
    # neighbour meets the edge's curve (the report's g1_floor; no surface through the curve does better).
    model = all(e["g0"] <= max(1e-6 * scale, e.get("tolerance_before", 0.0)) and
                (cls.get(e["edge"]) == "crease" or e["g1"] <= 1e-3 + e.get("g1_floor", 0.0)) for e in per_edge)
    return {"g0r": g0r, "g1_tangent": g1, "g2": g2, "strict": g0r <= 1e-6 and g1 <= 1e-3,
            "model": model, "loose": g0r <= 1e-4 and g1 <= 1e-2, "g2_ok": g2 <= 0.1}


def run_ours(path, truth, method):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.brep")
        t = time.time()
        try:
            p = subprocess.run([CLI, "fill", path, "--out", out, "--method", method, "--continuity", CONTINUITY, "--json"] + EXTRA,
                               capture_output=True, text=True, timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            return {"ok": False, "time": TIMEOUT, "error": "timeout"}
        dt = time.time() - t
        if p.returncode not in (0, 3) or not os.path.exists(out):
            return {"ok": False, "time": dt, "rc": p.returncode, "error": (p.stderr.strip().splitlines() or ["?"])[-1][:200]}
        rep = json.loads(p.stdout)[0]
    r = {"ok": rep["face_valid"], "time": dt, "core": rep["timings"]["total"], "solve": rep["timings"]["solve"],
         "status": rep["status"], "method": rep["method"], "achieved": rep["achieved"], "shape_valid": rep["shape_valid"]}
    r.update(judge(rep["per_edge"], truth, rep["g0_relative"], rep["scale"]))
    return r


def run_geomplate(doc, shape, hole, truth, order):
    f, dt = surface_filling(doc, shape, hole, order)
    try:
        produced = f.isValid() and not f.Shape.isNull() and len(f.Shape.Faces) == 1
        if not produced or not f.Shape.Faces[0].isValid():
            return {"ok": False, "time": dt, "produced": produced,
                    "error": "face produced but not valid (BRepCheck)" if produced else f.getStatusString()}
        rep = HoleFill.continuityReport(f.Shape.Faces[0], shape, hole)
        r = {"ok": True, "time": dt, "core": dt, "produced": True}
        r.update(judge(rep["per_edge"], truth, rep["g0_relative"], rep["scale"]))
        return r
    except Exception as e:
        return {"ok": False, "time": dt, "error": str(e)[:200]}
    finally:
        for o in list(doc.Objects):
            doc.removeObject(o.Name)


def row(label, rs):
    n = len(rs)
    ok = [r for r in rs if r["ok"]]
    g2set = [r for r in rs if r["surround"] == "g2"]
    ts = [r["time"] for r in rs]
    cores = [r.get("core", r["time"]) for r in ok] or [float("nan")]
    return "| %s | %d | %d | %.1f%% | %.1f%% | %.1f%% | %s | %.3f | %.3f | %.3f |" % (
        label, n, n - len(ok), 100.0 * sum(r["strict"] for r in ok) / n, 100.0 * sum(r.get("model", r["strict"]) for r in ok) / n,
        100.0 * sum(r["loose"] for r in ok) / n,
        ("%.0f%% of %d" % (100.0 * sum(r["ok"] and r["g2_ok"] for r in g2set) / len(g2set), len(g2set))) if g2set else "-",
        statistics.median(ts), max(ts), statistics.median(cores))


HEADER = ["| method | holes | fail | strict G0+G1 | strict at the model's accuracy | loose | G2 <= 0.1 (G2 surround) | "
          "CLI/recompute median s | max s | algorithm median s |", "|---|---|---|---|---|---|---|---|---|---|"]


def main():
    index = json.load(open(os.path.join(CORPUS, "index.json")))
    t0 = time.time()
    if MERGE:
        results, labels = [], None
        for path in MERGE:
            d = json.load(open(path))
            results += d["results"]
            labels = labels or d["labels"]
        holes = results
        scope = "%d holes from %d runs (%s) of the %d-hole corpus" % (len(results), len(MERGE), " ".join(MERGE),
                                                                   len(index["holes"]))
    else:
        holes = index["holes"][OFFSET::EVERY]
        if os.environ.get("BENCH_CORPUS_ONLY") == "g2":  # the G2 surrounds alone (with BENCH_CORPUS_CONTINUITY=G2)
            holes = [h for h in holes if surround(h) == "g2"]
        scope = "%d holes (every %d-th from %d of %d)" % (len(holes), EVERY, OFFSET, len(index["holes"]))
        results = run(holes)
        labels = list(METHODS) + (["geomplate"] if GEOMPLATE else [])
    summarize(results, labels, "Corpus: %s, continuity %s, %s, %.0f s." % (scope, CONTINUITY, platform.node(),
                                                                         time.time() - t0))


def surround(truth):
    """ "g2" when every edge that is not a crease is curvature continuous in the original (and one is)."""
    cls = [e["class"] for e in truth["per_edge"]]
    return "g2" if "g2" in cls and all(c in ("g2", "crease") for c in cls) else truth["surround"]


def run(holes):
    doc = FreeCAD.newDocument("BenchCorpus")
    labels = list(METHODS) + (["geomplate"] if GEOMPLATE else [])
    results = []
    for k, truth in enumerate(holes):
        path = os.path.join(CORPUS, truth["id"], "hole.brep")
        res = {"id": truth["id"], "kind": truth["kind"], "N": truth["N"], "surround": surround(truth),
               "valid_part": truth["part_valid"]}
        for m in METHODS:
            res[m] = run_ours(path, truth, m)
        if GEOMPLATE:
            shape = Part.Shape()
            shape.read(path)
            hole = HoleFill.findHoles(shape)[0]
            res["geomplate"] = run_geomplate(doc, shape, hole, truth, 2 if CONTINUITY == "G2" else 1)
        results.append(res)
        print("%4d/%d %-34s %-9s N=%d %s" % (k + 1, len(holes), truth["id"], truth["kind"], truth["N"], "  ".join(
            "%s %s" % (m, ("%.0e/%.0e" % (res[m]["g0r"], res[m]["g1_tangent"])) if res[m]["ok"] else "FAIL")
            for m in labels)))
        sys.stdout.flush()
    with open(os.path.join(OUT, "bench_corpus.json"), "w") as f:
        json.dump({"results": results, "continuity": CONTINUITY, "labels": labels}, f, indent=1)
    return results


def summarize(results, labels, title):
    for res in results:
        for m in labels:
            res[m]["surround"] = res["surround"]
    lines = [title, ""] + HEADER
    for m in labels:
        lines.append(row(m, [r[m] for r in results]))
    for key, title in (("kind", "surface kind"), ("N", "N")):
        lines += ["", "Strict share by %s (holes): " % title + ", ".join(labels), "",
                  "| %s | holes | %s |" % (title, " | ".join(labels)), "|---|---|" + "---|" * len(labels)]
        groups = collections.defaultdict(list)
        for r in results:
            groups[r[key]].append(r)
        for g in sorted(groups, key=str):
            rs = groups[g]
            lines.append("| %s | %d | %s |" % (g, len(rs), " | ".join(
                "%.0f%%" % (100.0 * sum(r[m]["ok"] and r[m]["strict"] for r in rs) / len(rs)) for m in labels)))
    fails = collections.Counter()
    for r in results:
        for m in labels:
            if not r[m]["ok"]:
                fails[(m, r[m].get("error", "invalid face")[:90])] += 1
    if "geomplate" in labels:
        lines += ["", "Holes where GeomPlate produced a face (valid or not) and ours failed: " + ", ".join(
            "%s %d" % (m, sum(1 for r in results if r["geomplate"].get("produced") and not r[m]["ok"]))
            for m in labels if m != "geomplate")]
    lines += ["", "Failures by message:", ""] + ["- %s: %d x %s" % (m, n, e) for (m, e), n in fails.most_common(30)]
    md = "\n".join(lines)
    print()
    print(md)
    with open(os.path.join(OUT, "bench_corpus.md"), "w") as f:
        f.write(md + "\n")


main()
os._exit(0)
