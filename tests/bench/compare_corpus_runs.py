#!/usr/bin/env python3
"""Two runs of the B-rep hole corpus benchmark (tests/bench/bench_corpus.py's bench_corpus.json),
e.g. Debian 12 against Debian 13, compared hole by hole on the holes both ran: per method, the
holes each run filled and held strict, the holes whose verdict differs (named), how far the
measured G0 and G1 moved (largest ratio, either way, among holes both filled) and the median
times. A hole only one run has (the corpora differ where the two systems ship different models)
is counted, not compared.

  python3 tests/bench/compare_corpus_runs.py A.json B.json [--names NAME_A NAME_B]
"""
import argparse
import json
import math
import statistics


def load(path):
    with open(path) as f:
        d = json.load(f)
    return {r["id"]: r for r in d["results"]}, d["labels"]


def ratio(a, b):
    """How many times apart two nonnegative measures are; values at round-off (below 1e-12) count as equal."""
    a, b = max(a, 1e-12), max(b, 1e-12)
    return max(a / b, b / a)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--names", nargs=2, default=("A", "B"))
    args = ap.parse_args()
    (ra, methods), (rb, _) = load(args.a), load(args.b)
    na, nb = args.names
    common = sorted(set(ra) & set(rb))
    print("holes: %d in both, %d only in %s, %d only in %s" % (len(common), len(set(ra) - set(rb)), na,
                                                               len(set(rb) - set(ra)), nb))
    print()
    print("| method | %s faces | %s faces | %s strict | %s strict | verdicts that differ | G0 apart (max x) | G1 apart (max x) "
          "| %s median s | %s median s |" % (na, nb, na, nb, na, nb))
    print("|---|---|---|---|---|---|---|---|---|---|")
    differing = {}
    for m in methods:
        rows = [(ra[h][m], rb[h][m], h) for h in common if m in ra[h] and m in rb[h]]
        both = [(x, y, h) for x, y, h in rows if x.get("ok") and y.get("ok")]
        diff = [h for x, y, h in rows if bool(x.get("ok")) != bool(y.get("ok")) or x.get("strict") != y.get("strict")]
        differing[m] = diff
        g0 = max([ratio(x["g0r"], y["g0r"]) for x, y, _ in both] or [1.0])
        g1 = max([ratio(x["g1_tangent"], y["g1_tangent"]) for x, y, _ in both] or [1.0])
        ta = statistics.median([x["time"] for x, _, _ in rows]) if rows else math.nan
        tb = statistics.median([y["time"] for _, y, _ in rows]) if rows else math.nan
        print("| %s | %d | %d | %d | %d | %d | %.3g | %.3g | %.3f | %.3f |" % (
            m, sum(bool(x.get("ok")) for x, _, _ in rows), sum(bool(y.get("ok")) for _, y, _ in rows),
            sum(bool(x.get("strict")) for x, _, _ in rows), sum(bool(y.get("strict")) for _, y, _ in rows),
            len(diff), g0, g1, ta, tb))
    for m, hs in differing.items():
        for h in hs:
            x, y = ra[h][m], rb[h][m]
            print("- %s %s: %s %s, %s %s" % (m, h, na, describe(x), nb, describe(y)))


def describe(r):
    if not r.get("ok"):
        return "failed (%s)" % str(r.get("error", r.get("rc", "")))[:80]
    return "%s G0 %.2e G1 %.2e" % ("strict" if r.get("strict") else "not strict", r["g0r"], r["g1_tangent"])


if __name__ == "__main__":
    main()
