#!/usr/bin/env bash
# holefill options and the fill's flags, both made from the core's option schema: the schema is
# listed in full; every flag given at its default fills exactly as no flag; a flag given a value
# its option refuses exits 1 naming the flag and writes nothing.
. "$(dirname "$0")/checks.sh"
mkdir -p "$T/samples" && "$H" samples "$T/samples" >/dev/null || bad "samples"
M="$T/samples/bezier_patch_with_hole.brep"
if "$H" options fill --json >"$T/schema.json" && "$H" options >"$T/schema.txt"; then ok "options listed"; else bad "options: rc=$?"; fi
"$H" fill "$M" --out "$T/plain.brep" --json >"$T/plain.json" 2>/dev/null || bad "plain fill rc=$?"
# Every valued flag at the schema's default (a bool's bare flag sets the value that is not its default).
args=$("$PY" - "$T/schema.json" "$T/schema.txt" <<'PY'
import json, sys
fields = json.load(open(sys.argv[1]))
text = open(sys.argv[2]).read()
names = [f["name"] for f in fields]
assert len(names) == len(set(names)) and len(names) >= 10, names
out = []
for f in fields:
    assert f["doc"] and f["name"] in text and (not f["flag"] or f["flag"] in text), f
    if f["kind"] == "bool":
        assert f["flag_sets"] != f["default"], f  # a bare flag that set the default would do nothing
        continue
    if f["flag"] and f["default"] != "":
        out += [f["flag"], str(f["default"])]
print(" ".join(out))
PY
) || bad "schema: $args"
# shellcheck disable=SC2086
"$H" fill "$M" --out "$T/defaults.brep" --json $args >"$T/defaults.json" 2>"$T/defaults.err" || bad "fill with every default given: $(cat "$T/defaults.err")"
if "$PY" - "$T/plain.json" "$T/defaults.json" <<'PY'
import json, sys
a, b = (json.load(open(p))[0] for p in sys.argv[1:3])
keys = ("status", "method", "requested", "achieved", "g0", "g1", "g2", "poles_u", "poles_v")
assert all(a[k] == b[k] for k in keys), [(k, a[k], b[k]) for k in keys if a[k] != b[k]]
PY
then ok "every flag at its default fills as no flag ($args)"; else bad "defaults differ from no flags"; fi
# Refused values, one per option kind, each naming its flag.
for case in "--method support" "--continuity G3" "--tolerance -1" "--angular-tolerance 0" "--curvature-tolerance x" \
            "--max-control-points 12.5" "--max-control-points 8" "--edge-continuity Edge5:G0"; do
  set -- $case
  expect_refusal "refused $case" "$1" "$T/o.brep" fill "$M" --out "$T/o.brep" "$1" "$2"
done
expect_refusal "an unknown option set" "unknown option set 'fil'" "" options fil
finish
