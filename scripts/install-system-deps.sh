#!/usr/bin/env bash
# Offer the Debian packages the set-up can use, never failing it:
# - python3-venv, where the interpreter lacks ensurepip (scripts/make-venv.sh has a way
#   round it through pip, and says what to install when there is none);
# - Mesa's EGL, which only offscreen rendering needs: everything but drawing (validation,
#   the API, the tests that draw nothing) works without it. Nothing is asked for when an
#   offscreen backend's libraries are there: Mesa's or NVIDIA's EGL, or else OSMesa.
#   OSMesa is never required where EGL is present.
# Nothing is pinned: a package comes in the version the archive serves. The install is
# first simulated (`apt-get -s`); if it would upgrade or remove an installed package the
# script installs nothing and says so. Without apt, without root and without password-less
# sudo, or when apt refuses, the script prints one line naming what to install and exits 0.
set -uo pipefail
DRI_DIR="${WMR_DRI_DIR:-/usr/lib/x86_64-linux-gnu/dri}"
PYTHON="${PYTHON:-python3}"

note() { echo "note: $*" >&2; }

# ldconfig lives in /sbin, off an ordinary user's PATH.
libraries=$( { command -v ldconfig >/dev/null 2>&1 && ldconfig -p; } 2>/dev/null \
             || /sbin/ldconfig -p 2>/dev/null || true)
has_lib() { grep -qF -- "$1" <<< "$libraries"; }
has_dri() { [ -e "$DRI_DIR/swrast_dri.so" ] || [ -e "$DRI_DIR/llvmpipe_dri.so" ]; }

missing=()
why=()
if ! "$PYTHON" -c "import venv, ensurepip" >/dev/null 2>&1; then
  missing+=(python3-venv)
  why+=("$PYTHON has no ensurepip")
fi
# A usable offscreen stack: EGL with a vendor (Mesa with its software driver, or
# NVIDIA's), or OSMesa.
if ! { has_lib "libEGL.so.1 " && { { has_lib "libEGL_mesa.so.0 " && has_dri; } \
                                   || has_lib "libEGL_nvidia.so.0 "; }; } \
   && ! has_lib "libOSMesa.so"; then
  has_lib "libEGL.so.1 " || missing+=(libegl1)
  has_lib "libEGL_mesa.so.0 " || missing+=(libegl-mesa0)
  has_lib "libGL.so.1 " || missing+=(libgl1)
  has_dri || missing+=(libgl1-mesa-dri)
  why+=("no offscreen OpenGL (rendering needs it; everything else works without it)")
fi
[ ${#missing[@]} -eq 0 ] && exit 0
reason=$(IFS=';'; echo "${why[*]}" | sed 's/;/; /g')
want="apt-get install ${missing[*]}"

if ! command -v apt-get >/dev/null 2>&1; then
  note "$reason, and no apt-get here: install the equivalent of '$want'"
  exit 0
fi
SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    SUDO=(sudo -n)
  else
    note "$reason, and no root here: ask for '$want'"
    exit 0
  fi
fi
echo "installing system packages: ${missing[*]}"
"${SUDO[@]}" apt-get update -qq >/dev/null 2>&1 || true
options=(--no-upgrade --no-install-recommends)
if ! plan=$(apt-get -s install "${options[@]}" "${missing[@]}" 2>&1); then
  note "$reason; apt cannot install ${missing[*]} here ($(echo "$plan" | grep -m1 '^E:' || echo "$plan" | tail -n 1))"
  exit 0
fi
# "Inst pkg [installed version] (new version ...)" is an upgrade; "Remv pkg" a removal.
changed=$(echo "$plan" | awk '/^Inst / && $3 ~ /^\[/ {print $2} /^Remv / {print $2}' | sort -u | tr '\n' ' ')
if [ -n "$changed" ]; then
  note "$reason; installing ${missing[*]} would upgrade or remove ${changed% }; not done (run '$want' if that is wanted)"
  exit 0
fi
if ! DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y -qq "${options[@]}" \
     "${missing[@]}" >/dev/null 2>&1; then
  note "$reason; apt-get install ${missing[*]} failed"
fi
exit 0
