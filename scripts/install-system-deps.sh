#!/usr/bin/env bash
# Install the Debian packages wmr-mujoco needs, only those missing, upgrading nothing:
# python3-venv (virtual environment) and Mesa's EGL/OSMesa for headless rendering.
#
# A missing Mesa package is pinned to the version of the Mesa already installed (all of
# Mesa's packages must carry one version, so an unpinned one would drag the installed ones
# up to the newest); the install is first simulated (`apt-get -s`), and if it would still
# upgrade or remove any installed package the script stops and says which, changing nothing.
set -euo pipefail
DRI_DIR="${WMR_DRI_DIR:-/usr/lib/x86_64-linux-gnu/dri}"
# Binary packages built from the mesa source, which share its version.
MESA_PACKAGES="libegl-mesa0 libgl1-mesa-dri libglapi-mesa libgbm1 libosmesa6 mesa-libgallium"

missing=()
# The library cache is read once (`ldconfig -p | grep -q` under pipefail fails whenever
# grep stops reading before ldconfig has written everything).
libraries=$(ldconfig -p)
has_lib() { grep -qF -- "$1" <<< "$libraries"; }
python3 -c "import venv, ensurepip" 2>/dev/null || missing+=(python3-venv)
has_lib "libEGL.so.1 " || missing+=(libegl1)
has_lib "libEGL_mesa.so.0 " || missing+=(libegl-mesa0)
has_lib "libGL.so.1 " || missing+=(libgl1)
[ -e "$DRI_DIR/swrast_dri.so" ] || [ -e "$DRI_DIR/llvmpipe_dri.so" ] || missing+=(libgl1-mesa-dri)
has_lib "libOSMesa.so" || missing+=(libosmesa6)
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

# The installed Mesa version, from the first Mesa package installed (empty: none yet).
mesa_version=""
for pkg in $MESA_PACKAGES; do
  status=$(dpkg-query -W -f='${Status} ${Version}' "$pkg" 2>/dev/null || true)
  if [[ "$status" == "install ok installed "* ]]; then
    mesa_version="${status#install ok installed }"
    break
  fi
done
request=()
for pkg in "${missing[@]}"; do
  if [ -n "$mesa_version" ] && [[ " $MESA_PACKAGES " == *" $pkg "* ]]; then
    request+=("$pkg=$mesa_version")
  else
    request+=("$pkg")
  fi
done

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "installing system packages: ${request[*]}"
$SUDO apt-get update -qq
options=(--no-upgrade --no-install-recommends)
if ! plan=$(apt-get -s install "${options[@]}" "${request[@]}" 2>&1); then
  echo "error: apt cannot install ${request[*]} without changing installed packages:" >&2
  echo "$plan" | tail -n 5 >&2
  exit 1
fi
# "Inst pkg [installed version] (new version ...)" is an upgrade; "Remv pkg" a removal.
changed=$(echo "$plan" | awk '/^Inst / && $3 ~ /^\[/ {print $2} /^Remv / {print $2}' | sort -u | tr '\n' ' ')
if [ -n "$changed" ]; then
  echo "error: installing ${request[*]} would upgrade or remove installed packages: " \
       "${changed% }; install them by hand if that is wanted" >&2
  exit 1
fi
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${options[@]}" "${request[@]}"
