#!/bin/sh
# install-deps.sh -- install the Debian 12 packages radiosity needs to build,
# test and run.  Idempotent; uses sudo when not run as root.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -e
pkgs="build-essential autoconf automake libtool autoconf-archive pkg-config
  libcgal-dev libgmp-dev libmpfr-dev liblapack-dev libopenblas-dev
  libcairo2-dev help2man python3 python3-mpmath python3-dev python3-numpy valgrind
  assimp-testmodels libmicrohttpd-dev chromium
  libscalapack-openmpi-dev libopenmpi-dev openmpi-bin"
missing=
for p in $pkgs; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
SUDO=
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends $missing
