#!/usr/bin/env bash
# Idempotent set-up for building and testing cadlod on Debian 12:
#  - installs the Debian packages the build, tests, demo and benchmarks need;
#  - adds a bookworm deb-src entry if the machine has none;
#  - unpacks MeshLab's source package (headers + bundled vcglib) of exactly the
#    installed meshlab version into .cache/meshlab-src (git-ignored).
# A second run only checks and returns quickly.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CACHE="${CADLOD_CACHE:-$ROOT/.cache}"
SRC_DIR="$CACHE/meshlab-src"

PACKAGES=(
  build-essential cmake ninja-build pkg-config dpkg-dev
  meshlab qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libeigen3-dev libglew-dev
  zlib1g-dev libgtest-dev
  xvfb xauth x11-apps xdotool imagemagick
  openscenegraph libopenscenegraph-dev
  libcoin-dev
  libcli11-dev nlohmann-json3-dev libtbb-dev parallel
  python3  # scripts/paper: the paper reproduction
)
# Fuzzing (tests/fuzz, CADLOD_BUILD_FUZZERS=ON): clang with libFuzzer.
if [ "${CADLOD_FUZZ_DEPS:-0}" = 1 ]; then
  PACKAGES+=(clang libclang-rt-14-dev)
fi
if [ "${CADLOD_BENCH_DEPS:-0}" = 1 ]; then
  PACKAGES+=(libmeshoptimizer-dev libcgal-dev libgmp-dev libmpfr-dev time gnuplot-nox)
fi

say() { printf '[bootstrap] %s\n' "$*"; }
die() { printf '[bootstrap] ERROR: %s\n' "$*" >&2; exit 1; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null 2>&1; then sudo "$@"
  else die "need root to run: $* (run this script as root or install sudo)"
  fi
}

missing_packages() {
  local p
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

has_deb_src() {
  grep -rqsE '^(deb-src|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/
}

add_deb_src() {
  has_deb_src && return 0
  say "adding a bookworm deb-src entry (/etc/apt/sources.list.d/cadlod-deb-src.sources)"
  as_root tee /etc/apt/sources.list.d/cadlod-deb-src.sources >/dev/null <<'SRC'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  APT_UPDATED=0
}

APT_UPDATED=0
apt_update_once() {
  [ "$APT_UPDATED" = 1 ] && return 0
  say "apt-get update"
  as_root apt-get update -qq
  APT_UPDATED=1
}

install_packages() {
  local missing
  missing=$(missing_packages | tr '\n' ' ')
  [ -z "${missing// }" ] && { say "Debian packages present"; return 0; }
  apt_update_once
  say "installing: $missing"
  # shellcheck disable=SC2086
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
}

installed_meshlab_version() {
  dpkg-query -W -f='${Version}' meshlab 2>/dev/null
}

fetch_meshlab_source() {
  local want have
  want=$(installed_meshlab_version) || die "meshlab is not installed"
  if [ -f "$SRC_DIR/.cadlod-version" ] && [ "$(cat "$SRC_DIR/.cadlod-version")" = "$want" ]; then
    say "MeshLab source $want present in $SRC_DIR"
    return 0
  fi
  add_deb_src
  apt_update_once
  have=$(apt-cache showsrc meshlab 2>/dev/null | awk '/^Version:/{print $2}' | sort -V | tail -n 1)
  [ -n "$have" ] || die "no MeshLab source package found; check the deb-src entry and run apt-get update"
  if ! apt-cache showsrc meshlab | grep -qx "Version: $want"; then
    die "installed meshlab is $want but the source package offers $have; install meshlab=$have or pin a matching source"
  fi
  say "fetching MeshLab source package $want"
  rm -rf "$CACHE/meshlab-fetch" "$SRC_DIR"
  mkdir -p "$CACHE/meshlab-fetch"
  (cd "$CACHE/meshlab-fetch" && apt-get source -qq "meshlab=$want" >/dev/null)
  local dir
  dir=$(find "$CACHE/meshlab-fetch" -maxdepth 1 -mindepth 1 -type d -name 'meshlab-*' | head -n 1)
  [ -n "$dir" ] || die "apt-get source meshlab unpacked nothing"
  mv "$dir" "$SRC_DIR"
  rm -rf "$CACHE/meshlab-fetch"
  echo "$want" > "$SRC_DIR/.cadlod-version"
  say "MeshLab source unpacked in $SRC_DIR"
}

main() {
  install_packages
  fetch_meshlab_source
}
main "$@"
