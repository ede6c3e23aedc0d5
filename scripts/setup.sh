#!/usr/bin/env bash
# Installs (from Debian's packages only) whatever HoleFill needs that is missing.
# Idempotent: does nothing (and needs no network) when everything is present.
set -euo pipefail
PKGS=(
  build-essential cmake g++ pkg-config
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-ocaf-dev occt-misc
  # OCCT 7.8 (Debian 13): TKDESTEP's link interface reaches TKService, which names -lfontconfig.
  libfontconfig-dev
  libtbb-dev libeigen3-dev zlib1g-dev libtorch-dev libgtest-dev pybind11-dev python3-dev python3-numpy python3-scipy libcgal-dev
  freecad xvfb xauth xdotool imagemagick python3-pyside2.qttest x11-utils bc
  # libtorch calls the system BLAS: OpenBLAS instead of the reference BLAS makes UVTran 5-10x faster.
  libopenblas0-pthread python3-matplotlib
)
# scripts/bench.sh adds the peers' packages (CGAL's demo data, assimp's test models, OpenSubdiv).
read -r -a extra <<< "${HOLEFILL_EXTRA_PKGS:-}"
PKGS+=("${extra[@]}")
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "[setup] installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
  export DEBIAN_FRONTEND=noninteractive
  for i in 1 2 3 4 5; do   # dpkg lock may be busy right after boot
    if $SUDO apt-get update -qq && $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"; then
      break
    fi
    echo "[setup] apt-get failed (try $i), retrying in 15 s"; sleep 15
    [ $i = 5 ] && { echo "[setup] could not install: ${missing[*]}" >&2; exit 1; }
  done
fi
echo "[setup] dependencies present"
