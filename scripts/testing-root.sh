#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# The current stack beside Debian 12's: makes once, and then reuses, a Debian testing root with
# VTK 9.6, OpenImageIO 3, ParaView 6.1 and PyVista, and runs a command in it with this source
# tree mounted at /src. There is no X server in the root: VTK renders through EGL (Mesa's
# llvmpipe), and DISPLAY is unset.
#   scripts/testing-root.sh [COMMAND [ARGUMENTS...]]   (no command: only make or update the root)
# With MLAA_TESTING_ROOT_X11=1 and DISPLAY set (an X server of the host's, such as
# scripts/with-xvfb.sh starts), the command gets that display (/tmp/.X11-unix and DISPLAY): for
# comparing VTK 9.6's GLX renders with its EGL ones (scripts/baseline-portability.sh). The tests
# never use it.
# The root lies at $MLAA_TESTING_ROOT (default /var/lib/vtkmlaa/testing-root), outside the source
# tree, so that later clones and CI runs on the same machine reuse it. Making it takes
# debootstrap (installed here if missing), about a minute, and then its packages, 3 to 6
# minutes and about 1.2 GB; a root that has them all is used as it is, with no network. Needs
# root rights (chroot, mounts). The mounts live in a mount namespace of their own (unshare), so
# they go away with the command, however it ends, and nothing on the host is left mounted.
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="${MLAA_TESTING_ROOT:-/var/lib/vtkmlaa/testing-root}"
suite=forky
mirror=http://deb.debian.org/debian

# What the root has: the main project's needs, then the ParaView plugin's and PyVista.
packages=(
  cmake g++ ninja-build pkg-config
  libvtk9-dev python3-vtk9 python3-numpy python3-dev
  libopenimageio-dev openimageio-tools
  libheif-plugin-x265   # HEIF output (recommended by libheif, so not installed without it)
  libegl-mesa0 libgl1-mesa-dri
  paraview paraview-dev python3-paraview openmpi-bin
  python3-pyvista
)

if [ "$(id -u)" -ne 0 ]; then
  # Root rights for debootstrap, chroot and the mounts: through sudo, as install-deps.sh does
  # for apt (the build in the root then belongs to root as well).
  if command -v sudo >/dev/null; then
    exec sudo env MLAA_TESTING_ROOT="$root" MLAA_TESTING_ROOT_X11="${MLAA_TESTING_ROOT_X11:-}" \
      DISPLAY="${DISPLAY:-}" "$0" "$@"
  fi
  echo "testing-root: needs root rights (debootstrap, chroot, mounts): run it as root" >&2
  exit 1
fi

make_root() {
  if ! command -v debootstrap >/dev/null; then
    echo "testing-root: installing debootstrap"
    apt-get update
    DEBIAN_FRONTEND=noninteractive apt-get install -y debootstrap
  fi
  # Debian 12's debootstrap has no script for forky; sid's serves any later suite.
  echo "testing-root: making a Debian $suite root in $root"
  rm -rf "$root.partial"
  mkdir -p "$(dirname "$root")"
  debootstrap --variant=minbase "$suite" "$root.partial" "$mirror" \
    /usr/share/debootstrap/scripts/sid
  # The mirror may be a snapshot whose Release files have expired.
  printf 'Acquire::Check-Valid-Until "false";\nAcquire::Check-Date "false";\n' \
    >"$root.partial/etc/apt/apt.conf.d/99snapshot"
  # Only a whole root is ever used: a debootstrap cut short leaves root.partial behind.
  mv "$root.partial" "$root"
}

# Runs "$@" chrooted in the root, with /proc, /sys, /dev, /dev/pts (the pseudo-terminal tests)
# and the source tree at /src, in a mount namespace of its own.
in_root() {
  unshare --mount --propagation private -- /bin/bash -euo pipefail -c '
    root="$1" source_dir="$2"
    shift 2
    mount -t proc proc "$root/proc"
    mount --rbind /sys "$root/sys"
    mount --rbind /dev "$root/dev"
    mkdir -p "$root/src"
    mount --bind "$source_dir" "$root/src"
    display=()
    if [ "${MLAA_TESTING_ROOT_X11:-}" = 1 ] && [ -n "${DISPLAY:-}" ]; then
      mkdir -p "$root/tmp/.X11-unix"
      mount --bind /tmp/.X11-unix "$root/tmp/.X11-unix"
      display=(DISPLAY="$DISPLAY" LIBGL_ALWAYS_SOFTWARE=1)
    fi
    # The host names as the machine has them: ParaView'"'"'s client-server tests connect to the
    # server by this machine'"'"'s name.
    cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
    cp -L /etc/hosts "$root/etc/hosts" 2>/dev/null || true
    hostname >"$root/etc/hostname" 2>/dev/null || true
    exec chroot "$root" /usr/bin/env -i PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin \
      HOME=/root LANG=C.UTF-8 TERM="${TERM:-dumb}" CI="${CI:-}" \
      MLAA_FUZZ_SECONDS="${MLAA_FUZZ_SECONDS:-}" "${display[@]}" "$@"
  ' in_root "$root" "$source_dir" "$@"
}

main() {
  [ -x "$root/usr/bin/apt-get" ] || make_root

  # The packages, installed once: a stamp holds the list last installed.
  stamp="$root/var/lib/vtkmlaa-packages"
  if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "${packages[*]}" ]; then
    echo "testing-root: installing ${packages[*]}"
    in_root apt-get update
    in_root /usr/bin/env DEBIAN_FRONTEND=noninteractive \
      apt-get install -y --no-install-recommends "${packages[@]}"
    in_root apt-get clean
    echo "${packages[*]}" >"$stamp"
  fi

  (($# > 0)) || return 0
  in_root "$@"
}

# The whole script is read before it runs (a script edited while it runs would go on from the
# old offset).
main "$@"
exit $?
