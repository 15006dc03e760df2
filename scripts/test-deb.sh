#!/usr/bin/env bash
# test-deb.sh: the Debian package as a user on a clean Debian 12 gets it (docs/install.md).
#
#   sudo scripts/test-deb.sh BUILD_DIR [ROOT]
#
# 1. packs BUILD_DIR (cpack -G DEB) and lists the package's control fields and contents;
# 2. makes a minimal Debian 12 root in ROOT (default /srv/deb12; debootstrap --variant=minbase,
#    skipped when ROOT already holds one) and installs the package there with apt-get, which
#    fetches its Depends from Debian's mirror;
# 3. in the root: swarf --version, the man page present, `swarf run --check` of the built-in
#    default case and of every installed example, and the default case's first 20 us
#    (`--set integrator.end_time=2e-5`, one thread) with its pictures, which must complete.
# Needs root, network and debootstrap. Prints "test-deb: PASSED" at the end; exit 1 on the
# first failure, naming it.
set -euo pipefail
build=${1:?usage: test-deb.sh BUILD_DIR [ROOT]}
root=${2:-/srv/deb12}
fail() { echo "test-deb: FAILED: $1" >&2; exit 1; }
[ "$(id -u)" = 0 ] || fail "must run as root (debootstrap, chroot)"
command -v debootstrap >/dev/null || fail "debootstrap not installed (apt-get install debootstrap)"

echo "== test-deb: cpack -G DEB in $build"
(cd "$build" && cpack -G DEB >cpack.log 2>&1) || fail "cpack (see $build/cpack.log)"
deb=$(ls -t "$build"/swarf_*.deb | head -1)
[ -f "$deb" ] || fail "no swarf_*.deb in $build"
echo "== test-deb: $deb ($(du -h "$deb" | cut -f1))"
dpkg-deb -f "$deb" Package Version Architecture Depends Suggests
dpkg-deb -c "$deb" | awk '{print $6}' | grep -E 'bin/swarf$|man1|copyright$|examples/|postprocess/[a-z_]+\.(py|json)$' || true

if [ ! -x "$root/usr/bin/apt-get" ]; then
  echo "== test-deb: debootstrap --variant=minbase bookworm $root"
  debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >"$root.debootstrap.log" 2>&1 ||
    fail "debootstrap (see $root.debootstrap.log)"
fi
cp /etc/resolv.conf "$root/etc/"
mountpoint -q "$root/proc" || mount -t proc proc "$root/proc"
trap 'umount "$root/proc" 2>/dev/null || true' EXIT
cp "$deb" "$root/tmp/swarf.deb"

echo "== test-deb: apt-get install ./swarf.deb in the root"
chroot "$root" sh -c 'apt-get update -q >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -q /tmp/swarf.deb' \
  >"$root.install.log" 2>&1 || fail "apt-get install (see $root.install.log)"
echo "== test-deb: in the root"
chroot "$root" sh -ec '
  swarf --version
  test -f /usr/share/man/man1/swarf.1.gz
  test -f /usr/share/doc/swarf/copyright
  swarf run --check >/tmp/check.txt && tail -n 3 /tmp/check.txt
  for c in /usr/share/swarf/examples/*.toml; do swarf run "$c" --check >/dev/null && echo "--check $c: ok"; done
  rm -rf /tmp/short
  swarf run --out /tmp/short --threads 1 --set integrator.end_time=2e-5 --set output.steady_from=1e-5 >/tmp/short.log 2>&1
  tail -n 4 /tmp/short.log
  test -f /tmp/short/summary.json && ls /tmp/short/*.png
' || fail "a command in the root"
echo "test-deb: PASSED"
