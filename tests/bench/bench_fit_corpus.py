#!/usr/bin/env python3
"""Labeled fitting on the labeled-region corpus (issue 21): every region of corpus-out/fit (made by
tests/corpus/labeled_regions.py) through `holefill fit`, with the extension at G2 and G1 and without
it (plain least squares over the region, the anchor), side by side in one run.

Per method: regions, crashes (a signal or exit 4), refusals (exit 1), faces written (exit 0 or 3),
maps that keep folded triangles, the share meeting the data goal (data max <= 1e-3 of the diagonal
noise-free, <= 3 sigma with noise), with no weak control points, with log10 condition < 8, and the
median data max and time; then per shape and per noise class for the first method.

  HOLEFILL_CLI=build/App/holefill python3 tests/bench/bench_fit_corpus.py [CORPUS (corpus-out/fit)]
Env: BENCH_FIT_METHODS (G2,G1,none), BENCH_FIT_TIMEOUT (120 s), BENCH_OUT (bench-out): JSON rows there.
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(cli, region, ext, timeout, tmp):
    out = os.path.join(tmp, "fit.brep")
    cmd = [cli, "fit", os.path.join(region, "region.obj"), "--labels", os.path.join(region, "labels.json"),
           "--extension", ext, "--out", out, "--json"]
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"rc": "timeout", "time": timeout}
    row = {"rc": p.returncode, "time": time.monotonic() - t0, "err": p.stderr.strip().splitlines()[-1:] }
    if p.returncode in (0, 3):
        try:
            row.update(json.loads(p.stdout))
        except ValueError:
            row["rc"] = "bad json"
    if os.path.exists(out):
        os.remove(out)
    return row


def main():
    corpus = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "corpus-out", "fit")
    cli = os.environ.get("HOLEFILL_CLI", os.path.join(ROOT, "build", "App", "holefill"))
    methods = os.environ.get("BENCH_FIT_METHODS", "G2,G1,none").split(",")
    timeout = float(os.environ.get("BENCH_FIT_TIMEOUT", "120"))
    index = json.load(open(os.path.join(ROOT, "tests", "corpus", "labeled_regions_index.json")))["regions"]
    index = [r for r in index if os.path.isdir(os.path.join(corpus, r["id"]))]
    if not index:
        print("no regions in %s: run tests/corpus/labeled_regions.py %s first" % (corpus, corpus))
        return 2
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for r in index:
            row = {"id": r["id"], "shape": r["shape"], "surface": r["surface"], "noise": r["noise"], "clockwise": r["clockwise"],
                   "labels": r.get("labels", "bbox")}
            for m in methods:
                row[m] = run(cli, os.path.join(corpus, r["id"]), m, timeout, tmp)
            rows.append(row)
    out_dir = os.environ.get("BENCH_OUT", os.path.join(ROOT, "bench-out"))
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "bench_fit_corpus.json"), "w") as f:
        json.dump(rows, f, indent=1)

    def goal(row, m):
        x = row[m]
        limit = 1e-3 if row["noise"] == 0 else 3 * row["noise"]
        return x.get("rc") in (0, 3) and x.get("data_max", 1e9) <= limit

    def summary(sel, m):
        xs = [r[m] for r in sel]
        written = [x for x in xs if x.get("rc") in (0, 3)]
        crash = sum(1 for x in xs if x.get("rc") == 4 or (isinstance(x.get("rc"), int) and x["rc"] < 0) or x.get("rc") == "timeout")
        pct = lambda k: "%.0f%%" % (100.0 * k / max(1, len(sel)))
        med = lambda v: "%.2e" % statistics.median(v) if v else "-"
        return [str(len(sel)), str(crash), str(sum(1 for x in xs if x.get("rc") == 1)), pct(len(written)),
                str(sum(1 for x in written if x.get("flipped_triangles", 0) > 0)),
                pct(sum(1 for r in sel if goal(r, m))), pct(sum(1 for x in written if x.get("weak_control_points", 1) == 0)),
                pct(sum(1 for x in written if x.get("log10_condition", 99) < 8)),
                med([x["data_max"] for x in written if "data_max" in x]), "%.2f" % statistics.median([x["time"] for x in xs])]

    head = "| %s | regions | crash | refused | face written | folded maps | data goal | no weak ctrl pts | cond < 1e8 | data max median | time median s |"
    print("Labeled fitting on %d regions (%s), %s" % (len(rows), corpus, time.strftime("%Y-%m-%d")))
    print()
    print(head % "extension")
    print("|---" * 11 + "|")
    for m in methods:
        print("| %s | %s |" % (m, " | ".join(summary(rows, m))))
    for key in ("labels", "shape", "noise"):
        print()
        print(head % key + "  (extension %s)" % methods[0])
        print("|---" * 11 + "|")
        for v in sorted({r[key] for r in rows}):
            print("| %s | %s |" % (v, " | ".join(summary([r for r in rows if r[key] == v], methods[0]))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
