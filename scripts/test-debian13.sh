#!/usr/bin/env bash
# The README's two commands on Debian 13 (trixie: FreeCAD 1.0, OCCT 7.8, Python 3.13, libtorch
# 2.6), from a fresh clone of this checkout's HEAD, inside a Debian 13 root made with debootstrap
# from Debian's own archive. The root is made once and reused (.cache/debian13, or
# $HOLEFILL_DEB13_ROOT); what setup.sh installs into it stays there for the next run.
#   ./scripts/test-debian13.sh            demo.sh, then test.sh (GUI tests under Xvfb included)
#   ./scripts/test-debian13.sh -- ARGS    test.sh ARGS only (e.g. -- -L freecad)
#   ./scripts/test-debian13.sh --shell    a shell in the root, at the clone
#   ./scripts/test-debian13.sh --run 'CMD'   one command line in the root, at the clone (e.g.
#                                         'BENCH_ONLY=corpus ./scripts/bench.sh', for docs/platforms.md)
#   ./scripts/test-debian13.sh --keep-build [ARGS]   as above, the last run's build folder kept
#                                         (incremental: for working on a failure, not for a verdict)
# Needs root (debootstrap, unshare, chroot) and the archive at $HOLEFILL_DEB13_MIRROR (default
# http://deb.debian.org/debian). Exit status 3, and a line that says why, when this machine cannot
# make the Debian 13 root (not root, no mount namespaces, debootstrap failed); otherwise test.sh's.
# /proc, /sys and /dev are bound into the root inside a private mount namespace only: they vanish
# with the run, however it ends, and nothing that walks the project's tree (grep -r, git clean,
# rm -rf .cache) ever meets the host's /dev through them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
chroot_dir=${HOLEFILL_DEB13_ROOT:-$root/.cache/debian13}
mirror=${HOLEFILL_DEB13_MIRROR:-http://deb.debian.org/debian}
clone=/work/holefill

if [ "${HOLEFILL_DEB13_INSIDE:-}" != 1 ]; then
  cannot() { echo "[debian13] cannot make a Debian 13 root here: $*" >&2; exit 3; }
  [ "$(id -u)" = 0 ] || cannot "needs root (debootstrap, unshare and chroot)"
  unshare --mount --propagation private true 2>/dev/null || cannot "no private mount namespace (unshare --mount)"
  command -v debootstrap >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap ||
    cannot "debootstrap could not be installed"
  # A root whose debootstrap was cut short has no marker and is made again.
  if [ ! -f "$chroot_dir/.holefill-root-complete" ]; then
    if findmnt -rn -o TARGET | grep -q "^$chroot_dir/"; then
      echo "[debian13] $chroot_dir has file systems mounted in it; unmount them first" >&2; exit 2
    fi
    echo "[debian13] making a Debian 13 root in $chroot_dir (debootstrap, a few minutes)"
    rm -rf --one-file-system "$chroot_dir"
    mkdir -p "$chroot_dir"
    debootstrap --variant=minbase --include=ca-certificates,git,sudo,procps trixie "$chroot_dir" "$mirror" ||
      { rm -rf --one-file-system "$chroot_dir"; cannot "debootstrap of trixie from $mirror failed"; }
    touch "$chroot_dir/.holefill-root-complete"
  fi
  cp /etc/resolv.conf "$chroot_dir/etc/resolv.conf"
  # A fresh clone of HEAD, as CI sees it: nothing of this checkout's build or outputs. With
  # --keep-build the last clone is moved to HEAD in place instead (changed files only get new
  # times, so the build is incremental) and its build folder kept.
  if [ "${1:-}" = "--keep-build" ] && [ -d "$chroot_dir$clone/.git" ]; then
    shift
    git -C "$chroot_dir$clone" fetch -q "$root" HEAD
    git -C "$chroot_dir$clone" reset -q --hard FETCH_HEAD
    git -C "$chroot_dir$clone" clean -q -fdx -e build
    echo "[debian13] the last clone moved to $(git -C "$root" rev-parse --short HEAD), its build kept"
  else
    [ "${1:-}" != "--keep-build" ] || shift
    rm -rf --one-file-system "$chroot_dir$clone"
    mkdir -p "$(dirname "$chroot_dir$clone")"
    git clone -q --no-hardlinks "$root" "$chroot_dir$clone"
    echo "[debian13] clone of $(git -C "$root" rev-parse --short HEAD) at $clone in the root"
  fi
  exec unshare --mount --propagation private /usr/bin/env HOLEFILL_DEB13_INSIDE=1 HOLEFILL_DEB13_ROOT="$chroot_dir" "$0" "$@"
fi

for m in proc sys dev dev/pts dev/shm; do
  mkdir -p "$chroot_dir/$m"
  mount --bind "/$m" "$chroot_dir/$m"
done
inside() {
  chroot "$chroot_dir" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 TERM=dumb \
    /bin/bash -c "cd $clone && $1"
}
case "${1:-}" in
  --shell) inside "exec bash -i" ;;
  --run) inside "$2" ;;
  --) shift; inside "./scripts/test.sh $(printf '%q ' "$@")" ;;
  *) inside "./scripts/demo.sh && ./scripts/test.sh" ;;
esac
