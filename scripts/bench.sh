#!/usr/bin/env bash
# Peer benchmarks (not part of ctest): builds, then runs
#  1. holefill_bench_params: parameter error of UVTran vs MVC vs NP on the synthetic test split;
#     holefill_bench_inspect: exact curvature per sample vs OCCT SLProps (1M samples), tessellation and render times;
#  2. tests/bench/bench_fill.py in freecadcmd: HoleFill NP/MVC/UVTran/auto vs FreeCAD Surface
#     Filling (GeomPlate) on the same holes, asked for G1 and for G2, in one run.
#  3. tests/bench/bench_meshfill.py in freecadcmd: HoleFill mesh-hole filling vs CGAL PMP
#     triangulate_refine_and_fair_hole (holefill_bench_cgal_fill) vs FreeCAD Mesh fillupHoles,
#     on CGAL's demo meshes, assimp's sphereWithHole.stl and holes cut from closed meshes.
#  4. holefill_bench_gnurbs: G² G-NURBS vs OpenSubdiv's Catmull-Clark limit surface (Gregory end
#     caps) on the same quad cages: G1/G2 across every cage edge, curvature at EPs, time.
#     BENCH_ONLY=gnurbs runs part 4 alone.
#  5. holefill_bench_fitting: labeled fitting (labels + G2 extension, and without extension) vs
#     plain and thin-plate least squares and FreeCAD's ReverseEngineering.approxSurface (through
#     freecadcmd, tests/bench/approx_surface.py) on 12 trimmed regions cut from known surfaces:
#     data error, band deviation both ways, weak control points, condition, time; curvature
#     pictures in bench-out/fitting. BENCH_ONLY=fitting runs part 5 alone.
#  6. holefill_bench_cloud_params: point-cloud parameterization (shape-preserving, inverse
#     distance, uniform) and BIDGCN on the bidgcn paper's random Bézier clouds: fit MSE,
#     failures, time. BENCH_ONLY=cloud-params runs part 6 alone (BENCH_CLOUDS, default 100).
#  7. holefill_bench_thb: adaptive THB fitting vs uniform B-spline refinement on a region of the
#     Stanford bunny (CGAL's bunny00.off) as a bare cloud: error against degrees of freedom, with
#     a picture (bench-out/thb/thb_bunny.png). BENCH_ONLY=thb runs part 7 alone.
#  8. tests/bench/bench_corpus.py in freecadcmd: the whole `holefill fill` CLI (auto, np, mvc, uvtran)
#     vs FreeCAD Surface Filling on the B-rep hole corpus (scripts/make_corpus.sh: every eligible
#     face of the real models in occt-misc and freecad-common removed, judged per edge against the
#     removed face). BENCH_ONLY=corpus runs part 8 alone (BENCH_CORPUS_EVERY=k for every k-th hole).
#  9. tests/bench/bench_preview.py in freecadcmd: the Fill task panel's Preview (a Fill recomputed
#     after each continuity change) with the prepared hole kept, with a fresh fill each time, and
#     FreeCAD Surface Filling's recompute, on every 23rd corpus hole. BENCH_ONLY=preview runs part 9 alone.
# 10. tests/bench/bench_fit_corpus.py: labeled fitting (extension G2, G1, none) on the labeled-region
#     corpus (tests/corpus/labeled_regions.py, 131 regions cut from nine known surfaces and a real scan): crashes, refusals,
#     faces, folded maps, data goal, weak control points, condition, by shape and noise; then
#     tests/bench/bench_fitting.cpp --corpus: ours against the least-squares anchors on the same
#     regions, judged against the truth (data max, band deviation). BENCH_ONLY=fit-corpus runs part 10 alone.
# 11. tests/bench/bench_mesh_corpus.py in freecadcmd: mesh hole filling, ours vs CGAL PMP vs FreeCAD
#     fillupHoles on the mesh-hole corpus (tests/corpus/mesh_holes.py, 138 cases: CGAL's and assimp's
#     meshes with holes as they ship, and six cut classes with ground truth): valid (nothing
#     crossing, non-manifold, misoriented added), closed, quality, distance, time, by class.
#     BENCH_ONLY=mesh-corpus runs part 11 alone.
# 12. tests/bench/bench_fill_points.py in freecadcmd: a fill through a point of the removed face,
#     ours vs Surface Filling's Points, on every 23rd B-rep corpus hole. BENCH_ONLY=fill-points runs it alone.
# Prints the tables; results in bench-out/. Paste the printed tables into docs/benchmarks.md.
# BENCH_PARAM_HOLES (default 1000) sets the size of the synthetic test set used.
set -euo pipefail
export HOLEFILL_EXTRA_PKGS="libcgal-dev libcgal-demo assimp-testmodels libosd-dev"
. "$(dirname "$0")/prepare.sh"
export BENCH_OUT="$root/bench-out"
mkdir -p "$BENCH_OUT"
bench_fitting() {
  cmake -S "$root" -B "$build" >/dev/null
  cmake --build "$build" --target holefill_bench_fitting -j "$(nproc)"
  echo
  (
    . tests/fcenv.sh "$build/Mod/HoleFill"
    "$build/tests/holefill_bench_fitting" "$BENCH_OUT/fitting" tests/bench/approx_surface.py | tee "$BENCH_OUT/bench_fitting.md"
    rm -rf "$HOME"
  )
}
bench_cloud_params() {
  cmake -S "$root" -B "$build" >/dev/null
  cmake --build "$build" --target holefill_bench_cloud_params -j "$(nproc)"
  echo
  "$build/tests/holefill_bench_cloud_params" "${BENCH_CLOUDS:-100}" | tee "$BENCH_OUT/bench_cloud_params.md"
}
bench_thb() {
  cmake -S "$root" -B "$build" >/dev/null
  cmake --build "$build" --target holefill_bench_thb -j "$(nproc)"
  if [ ! -d "$BENCH_OUT/cgal-data/meshes" ]; then
    tar -xzf /usr/share/doc/libcgal-demo/data.tar.gz -C "$BENCH_OUT" && mv "$BENCH_OUT/data" "$BENCH_OUT/cgal-data"
  fi
  mkdir -p "$BENCH_OUT/thb"
  echo
  for method in shape bidgcn; do
    "$build/tests/holefill_bench_thb" "$BENCH_OUT/cgal-data/meshes/bunny00.off" "$BENCH_OUT/thb" "$method" | tee "$BENCH_OUT/bench_thb_$method.md"
    /usr/bin/python3 tests/bench/thb_pictures.py "$BENCH_OUT/thb" >/dev/null && mv "$BENCH_OUT/thb/thb_bunny.png" "$BENCH_OUT/thb/thb_bunny_$method.png"
    echo
  done
}
bench_corpus() {
  export CORPUS_OUT="$root/corpus-out/brep"
  [ -f "$CORPUS_OUT/index.json" ] || "$root/scripts/make_corpus.sh"
  (
    . tests/fcenv.sh "$build/Mod/HoleFill"
    BENCH_CORPUS="$CORPUS_OUT" HOLEFILL_CLI="$build/App/holefill" freecadcmd tests/bench/bench_corpus.py 2>&1 |
      grep -v '^ *#\|^$\|Juergen\|licensed\|wouldn.t be possible\|Libs:\|Recompute\|(100 %)\|(50 %)'
    rm -rf "$HOME"
  )
}
bench_preview() {
  export CORPUS_OUT="$root/corpus-out/brep"
  [ -f "$CORPUS_OUT/index.json" ] || "$root/scripts/make_corpus.sh"
  (
    . tests/fcenv.sh "$build/Mod/HoleFill"
    BENCH_CORPUS="$CORPUS_OUT" freecadcmd tests/bench/bench_preview.py 2>&1 |
      grep -v '^ *#\|^$\|Juergen\|licensed\|wouldn.t be possible\|Libs:\|Recompute\|(100 %)\|(50 %)\|^ *[0-9]*/[0-9]* '
    rm -rf "$HOME"
  )
}
bench_mesh_corpus() {
  cmake -S "$root" -B "$build" >/dev/null
  cmake --build "$build" --target holefill_bench_cgal_fill -j "$(nproc)" >/dev/null
  [ -f "$root/corpus-out/mesh/index.json" ] ||
    PYTHONPATH="$build/App" /usr/bin/python3 tests/corpus/mesh_holes.py "$root/corpus-out/mesh" >/dev/null
  (
    . tests/fcenv.sh "$build/Mod/HoleFill"
    HOLEFILL_BENCH_CGAL="$build/tests/holefill_bench_cgal_fill" BENCH_MESH_CORPUS="$root/corpus-out/mesh" \
      freecadcmd tests/bench/bench_mesh_corpus.py 2>"$BENCH_OUT/bench_mesh_corpus.log" | grep '^|'
    rm -rf "$HOME"
  )
}
bench_fit_corpus() {
  [ -f "$root/corpus-out/fit/plane_strip_clean/region.obj" ] ||
    /usr/bin/python3 tests/corpus/labeled_regions.py "$root/corpus-out/fit" >/dev/null
  HOLEFILL_CLI="$build/App/holefill" /usr/bin/python3 tests/bench/bench_fit_corpus.py "$root/corpus-out/fit"
  cmake --build "$build" --target holefill_bench_fitting -j "$(nproc)" >/dev/null
  "$build/tests/holefill_bench_fitting" --corpus "$root/corpus-out/fit" tests/corpus/labeled_regions_index.json 2>/dev/null |
    tee "$BENCH_OUT/bench_fit_corpus_anchors.md"
}
if [ "${BENCH_ONLY:-}" = fill-points ]; then  # BENCH_ONLY=fill-points runs part 12 alone
  export CORPUS_OUT="$root/corpus-out/brep"
  [ -f "$CORPUS_OUT/index.json" ] || "$root/scripts/make_corpus.sh"
  (
    . tests/fcenv.sh "$build/Mod/HoleFill"
    BENCH_CORPUS="$CORPUS_OUT" freecadcmd tests/bench/bench_fill_points.py 2>&1 | grep -a '^|\|corpus holes' | sed 's/.*\([0-9][0-9]* corpus holes\)/\1/'
    rm -rf "$HOME"
  )
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" = mesh-corpus ]; then  # BENCH_ONLY=mesh-corpus runs part 11 alone
  bench_mesh_corpus
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" = fit-corpus ]; then  # BENCH_ONLY=fit-corpus runs part 10 alone
  bench_fit_corpus
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" = preview ]; then  # BENCH_ONLY=preview runs part 9 alone
  bench_preview
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" = corpus ]; then  # BENCH_ONLY=corpus runs part 8 alone
  bench_corpus
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" = thb ]; then  # BENCH_ONLY=thb runs part 7 alone
  bench_thb
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" = cloud-params ]; then  # BENCH_ONLY=cloud-params runs part 6 alone
  bench_cloud_params
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" = fitting ]; then  # BENCH_ONLY=fitting runs part 5 alone
  bench_fitting
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" = gnurbs ]; then  # BENCH_ONLY=gnurbs runs part 4 alone
  cmake -S "$root" -B "$build" >/dev/null
  cmake --build "$build" --target holefill_bench_gnurbs -j "$(nproc)"
  "$build/tests/holefill_bench_gnurbs" 4 | tee "$BENCH_OUT/bench_gnurbs.md"
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
if [ "${BENCH_ONLY:-}" != meshfill ]; then  # BENCH_ONLY=meshfill runs part 3 alone
"$build/tests/holefill_bench_params" "${BENCH_PARAM_HOLES:-1000}" | tee "$BENCH_OUT/bench_params.md"
echo
"$build/tests/holefill_bench_inspect" "${BENCH_INSPECT_SAMPLES:-1000000}" | tee "$BENCH_OUT/bench_inspect.md"
echo
(
  . tests/fcenv.sh "$build/Mod/HoleFill"
  freecadcmd tests/bench/bench_fill.py 2>&1 | grep -v '^ *#\|^$\|Juergen\|licensed\|wouldn.t be possible\|Libs:\|Recompute\|(100 %)\|(50 %)'
  rm -rf "$HOME"
)
fi
# Configure again: a build tree made before CGAL was installed (test.sh first) has it cached as
# not found, and only a new configure looks for it again.
cmake -S "$root" -B "$build" >/dev/null
cmake --build "$build" --target holefill_bench_cgal_fill -j "$(nproc)"
if [ ! -d "$BENCH_OUT/cgal-data/meshes" ]; then
  tar -xzf /usr/share/doc/libcgal-demo/data.tar.gz -C "$BENCH_OUT" && mv "$BENCH_OUT/data" "$BENCH_OUT/cgal-data"
fi
echo
(
  . tests/fcenv.sh "$build/Mod/HoleFill"
  HOLEFILL_BENCH_CGAL="$build/tests/holefill_bench_cgal_fill" CGAL_DATA="$BENCH_OUT/cgal-data" \
    freecadcmd tests/bench/bench_meshfill.py 2>&1 | grep '^|'
  # Pictures of one hole per case, filled by each method (bench-out/meshfill/*.png).
  xvfb-run -a -s "-screen 0 1280x1024x24 -dpi 96 -nolisten tcp" timeout 300 freecad tests/bench/meshfill_pictures.py >/dev/null 2>&1 || true
  rm -rf "$HOME"
)
if [ "${BENCH_ONLY:-}" = meshfill ]; then  # part 3 alone, as the header says
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
  exit 0
fi
cmake --build "$build" --target holefill_bench_gnurbs -j "$(nproc)"
echo
"$build/tests/holefill_bench_gnurbs" 4 | tee "$BENCH_OUT/bench_gnurbs.md"
bench_fitting
bench_cloud_params
bench_thb
bench_corpus
bench_preview
bench_fit_corpus
bench_mesh_corpus
echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
