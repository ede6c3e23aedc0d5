#!/usr/bin/env bash
# holefill param: a planar jittered grid gets its own parameters back (shape-preserving); a wavy
# sheet gets one "u v" line per point, inside the square, with every method; bad clouds and an
# unknown method exit 1 and write nothing.
. "$(dirname "$0")/checks.sh"
"$PY" - "$T" <<'PY'
import math, random, sys
t = sys.argv[1]; m = 20; random.seed(3)
for name, lift in (("flat", lambda u, v: 0.0), ("wavy", lambda u, v: 0.3 * math.sin(3 * u) * math.cos(2 * v))):
    with open(t + "/%s.txt" % name, "w") as f, open(t + "/%s_truth.txt" % name, "w") as g:
        f.write("# x y z flag u v\n\n")
        for j in range(m + 1):
            for i in range(m + 1):
                rim = i in (0, m) or j in (0, m)
                u = (i + (0 if rim else random.uniform(-.3, .3))) / m
                v = (j + (0 if rim else random.uniform(-.3, .3))) / m
                f.write("%r %r %r 1 %r %r\n" % (u, v, lift(u, v), u, v) if rim else "%r %r %r 0\n" % (u, v, lift(u, v)))
                g.write("%r %r\n" % (u, v))
with open(t + "/flat_nouv.txt", "w") as f:  # the same planar grid, boundary points without u v
    for line in open(t + "/flat.txt"):
        w = line.split()
        f.write(" ".join(w[:4]) + "\n" if len(w) == 6 else line)
open(t + "/mixed.txt", "w").write("0 0 0 1 0 0\n1 0 0 1\n" + "".join("%d %d 0 0\n" % (k % 4, k // 4) for k in range(10)))
open(t + "/badflag.txt", "w").write("".join("%d 0 0 2\n" % k for k in range(12)))
open(t + "/noboundary.txt", "w").write("".join("%d %d 0 0\n" % (k % 4, k // 4) for k in range(12)))
open(t + "/few.txt", "w").write("".join("%d 0 0 1 %d 0\n" % (k, k) for k in range(5)))
open(t + "/nan.txt", "w").write("".join("%d %d 0 1 0 0\n" % (k % 4, k // 4) for k in range(11)) + "nan 1 1 0\n")
PY
"$H" param "$T/flat.txt" --out "$T/flat_uv.txt" --json >"$T/flat.json" 2>"$T/err" && ok "planar grid parameterized" || bad "planar: $(cat "$T/err")"
"$PY" - "$T" <<'PY' && ok "planar grid: its own parameters back (shape-preserving)" || bad "planar parameters differ"
import sys
t = sys.argv[1]
got = [tuple(map(float, l.split())) for l in open(t + "/flat_uv.txt")]
want = [tuple(map(float, l.split())) for l in open(t + "/flat_truth.txt")]
assert len(got) == len(want) == 441, (len(got), len(want))
assert max(abs(a - b) for p, q in zip(got, want) for a, b in zip(p, q)) < 1e-9
PY
"$H" param "$T/flat_nouv.txt" --out "$T/nouv_uv.txt" 2>"$T/err" >/dev/null && ok "boundary without u v: chord length from found corners" || bad "no uv: $(cat "$T/err")"
"$PY" - "$T" <<'PY' && ok "boundary without u v: the planar grid's parameters back, up to the square's symmetry" || bad "no-uv parameters differ"
import sys
t = sys.argv[1]
got = [tuple(map(float, l.split())) for l in open(t + "/nouv_uv.txt")]
want = [tuple(map(float, l.split())) for l in open(t + "/flat_truth.txt")]
syms = [lambda u, v: (u, v), lambda u, v: (1 - u, v), lambda u, v: (u, 1 - v), lambda u, v: (1 - u, 1 - v),
        lambda u, v: (v, u), lambda u, v: (1 - v, u), lambda u, v: (v, 1 - u), lambda u, v: (1 - v, 1 - u)]
assert min(max(abs(a - b) for p, q in zip(got, want) for a, b in zip(p, s(*q))) for s in syms) < 1e-9
PY
expect_refusal "boundary u v mixed" "for every boundary point" "$T/o.txt" param "$T/mixed.txt" --out "$T/o.txt"
expect_refusal "corner not on the boundary" "not a boundary point" "$T/o.txt" param "$T/flat_nouv.txt" --corners 0,20,440,22 --out "$T/o.txt"
for m in shape invdist uniform; do
  "$H" param "$T/wavy.txt" --method $m --out "$T/wavy_$m.txt" 2>"$T/err" >/dev/null || bad "$m: $(cat "$T/err")"
  "$PY" -c 'import sys; uv=[tuple(map(float,l.split())) for l in open(sys.argv[1])]; assert len(uv)==441 and all(-1e-9<=x<=1+1e-9 for p in uv for x in p)' "$T/wavy_$m.txt" \
    && ok "wavy sheet, $m: 441 parameters inside the square" || bad "wavy $m parameters"
done
expect_refusal "unknown method" "unknown parameterization method" "$T/o.txt" param "$T/wavy.txt" --method bidgcnx --out "$T/o.txt"
expect_refusal "bad flag" "flag must be 0" "$T/o.txt" param "$T/badflag.txt" --out "$T/o.txt"
expect_refusal "no boundary" "boundary points" "$T/o.txt" param "$T/noboundary.txt" --out "$T/o.txt"
expect_refusal "fewer than 10 points" "at least 10" "$T/o.txt" param "$T/few.txt" --out "$T/o.txt"
expect_refusal "NaN" "not a finite number" "$T/o.txt" param "$T/nan.txt" --out "$T/o.txt"
expect_refusal "no --out" "--out" "$T/o.txt" param "$T/wavy.txt"
finish
