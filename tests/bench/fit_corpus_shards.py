#!/usr/bin/env python3
"""The labeled-fitting corpus bench in shards, and their per-region rows summed up (issue 21).

holefill_bench_fitting --corpus takes an index of regions and prints one row per region on
stderr ("region ID SHAPE LABELS NOISE | failed truthMax band weak log10cond seconds valid | ..."
per method). On a machine with few cores the corpus runs as shards side by side:

  fit_corpus_shards.py split INDEX N OUTDIR     N index files, regions dealt round-robin
  fit_corpus_shards.py sum [--method K] [--tsv F] ERR...
                                                the rows of every shard's stderr: per class
                                                (all, labels, shape, noise) the share meeting
                                                the data goal, the band median, no weak control
                                                points, condition < 1e8, valid faces, time; then
                                                the regions that miss the data goal
Goals as in the bench: data max vs truth <= 1e-3 of the diagonal noise-free, <= 3 x noise noisy.
"""
import argparse
import json
import os
import statistics
import sys


def split(index, n, outdir):
    data = json.load(open(index))
    os.makedirs(outdir, exist_ok=True)
    for k in range(n):
        part = dict(data, regions=data["regions"][k::n])
        path = os.path.join(outdir, "shard%d.json" % k)
        json.dump(part, open(path, "w"), indent=1)
        print(path, len(part["regions"]))


def rows(paths, method):
    out = {}
    for p in paths:
        for line in open(p):
            if not line.startswith("region "):
                continue
            head, *ms = line.split("|")
            _, rid, shape, labels, noise = head.split()
            f = ms[method].split()
            out[rid] = dict(id=rid, shape=shape, labels=labels, noise=float(noise), failed=f[0] == "1", truth=float(f[1]),
                            band=float(f[2]), weak=int(f[3]), cond=float(f[4]), sec=float(f[5]), valid=int(f[6]))
    return list(out.values())


def summary(rs):
    n = len(rs)
    ok = [r for r in rs if not r["failed"]]
    goal = sum(r["truth"] <= (3 * r["noise"] if r["noise"] > 0 else 1e-3) for r in ok)
    pct = lambda k: "%d%% (%d/%d)" % (round(100.0 * k / max(1, n)), k, n)
    med = lambda v: statistics.median(v) if v else float("nan")
    return "goal %s | band median %.3f | no weak %s | cond<1e8 %s | valid %s | failed %d | time median %.2f s" % (
        pct(goal), med([r["band"] for r in ok]), pct(sum(r["weak"] == 0 for r in ok)), pct(sum(r["cond"] < 8 for r in ok)),
        pct(sum(r["valid"] == 1 for r in ok)), n - len(ok), med([r["sec"] for r in ok]))


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("split")
    s.add_argument("index"), s.add_argument("n", type=int), s.add_argument("outdir")
    m = sub.add_parser("sum")
    m.add_argument("--method", type=int, default=0, help="the method's column among those run (0: the first)")
    m.add_argument("--tsv")
    m.add_argument("err", nargs="+")
    a = ap.parse_args()
    if a.cmd == "split":
        return split(a.index, a.n, a.outdir)
    rs = rows(a.err, a.method)
    if not rs:
        print("no region rows in", a.err)
        return 2
    print("all:", summary(rs))
    for key in ("labels", "shape", "noise"):
        for v in sorted({r[key] for r in rs}):
            print("%s %s: %s" % (key, v, summary([r for r in rs if r[key] == v])))
    miss = sorted((r for r in rs if r["failed"] or r["truth"] > (3 * r["noise"] if r["noise"] > 0 else 1e-3)), key=lambda r: -r["truth"])
    print("\nmissing the data goal (%d):" % len(miss))
    for r in miss:
        print("  %-40s truth %.2e band %.3f weak %d cond %.1f valid %d %.1f s%s" % (
            r["id"], r["truth"], r["band"], r["weak"], r["cond"], r["valid"], r["sec"], " FAILED" if r["failed"] else ""))
    if a.tsv:
        with open(a.tsv, "w") as f:
            cols = ["id", "shape", "labels", "noise", "failed", "truth", "band", "weak", "cond", "sec", "valid"]
            f.write("\t".join(cols) + "\n")
            for r in rs:
                f.write("\t".join(str(r[c]) for c in cols) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
