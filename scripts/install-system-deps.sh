#!/usr/bin/env bash
# Offer the Debian packages that only offscreen rendering needs (Mesa's EGL), never
# failing the set-up: everything but drawing (validation, the API, the tests that draw
# nothing) works without them.
#
# - Nothing is asked for when an offscreen backend's libraries are there: Mesa's or
#   NVIDIA's EGL, or else OSMesa. OSMesa is never required where EGL is present.
# - Nothing is pinned: a package comes in the version the archive serves. The install
#   is first simulated (`apt-get -s`); if it would upgrade or remove an installed package
#   the script installs nothing and says so.
# - Without apt, without root and without password-less sudo, or when apt refuses, the
#   script prints one line naming what to install and exits 0.
# The Python environment itself is made by scripts/make-venv.sh.
set -uo pipefail
DRI_DIR="${WMR_DRI_DIR:-/usr/lib/x86_64-linux-gnu/dri}"
PACKAGES="libegl1 libegl-mesa0 libgl1 libgl1-mesa-dri"

note() { echo "note: $*; rendering (wmr render, the clips and pictures) needs it," \
              "everything else works without it" >&2; }

# ldconfig lives in /sbin, off an ordinary user's PATH.
libraries=$( { command -v ldconfig >/dev/null 2>&1 && ldconfig -p; } 2>/dev/null \
             || /sbin/ldconfig -p 2>/dev/null || true)
has_lib() { grep -qF -- "$1" <<< "$libraries"; }
has_dri() { [ -e "$DRI_DIR/swrast_dri.so" ] || [ -e "$DRI_DIR/llvmpipe_dri.so" ]; }
# A usable offscreen stack: EGL with a vendor (Mesa with its software driver, or
# NVIDIA's), or OSMesa.
if has_lib "libEGL.so.1 " && { { has_lib "libEGL_mesa.so.0 " && has_dri; } \
                               || has_lib "libEGL_nvidia.so.0 "; }; then
  exit 0
fi
has_lib "libOSMesa.so" && exit 0

missing=()
has_lib "libEGL.so.1 " || missing+=(libegl1)
has_lib "libEGL_mesa.so.0 " || missing+=(libegl-mesa0)
has_lib "libGL.so.1 " || missing+=(libgl1)
has_dri || missing+=(libgl1-mesa-dri)
want="apt-get install ${missing[*]}"

if ! command -v apt-get >/dev/null 2>&1; then
  note "no offscreen OpenGL found and no apt-get here: install Mesa's EGL ($PACKAGES)"
  exit 0
fi
SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    SUDO=(sudo -n)
  else
    note "no offscreen OpenGL found and no root here: ask for '$want'"
    exit 0
  fi
fi
echo "installing system packages: ${missing[*]}"
"${SUDO[@]}" apt-get update -qq >/dev/null 2>&1 || true
options=(--no-upgrade --no-install-recommends)
if ! plan=$(apt-get -s install "${options[@]}" "${missing[@]}" 2>&1); then
  note "apt cannot install ${missing[*]} here ($(echo "$plan" | grep -m1 '^E:' || echo "$plan" | tail -n 1))"
  exit 0
fi
# "Inst pkg [installed version] (new version ...)" is an upgrade; "Remv pkg" a removal.
changed=$(echo "$plan" | awk '/^Inst / && $3 ~ /^\[/ {print $2} /^Remv / {print $2}' | sort -u | tr '\n' ' ')
if [ -n "$changed" ]; then
  note "installing ${missing[*]} would upgrade or remove ${changed% }; not done (run '$want' if that is wanted)"
  exit 0
fi
if ! DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y -qq "${options[@]}" \
     "${missing[@]}" >/dev/null 2>&1; then
  note "apt-get install ${missing[*]} failed"
fi
exit 0
