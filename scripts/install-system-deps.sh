#!/usr/bin/env bash
# Install the Debian packages wmr-mujoco needs, only if they are missing:
# python3-venv (virtual environment) and Mesa's EGL/OSMesa for headless rendering.
set -euo pipefail
missing=()
python3 -c "import venv, ensurepip" 2>/dev/null || missing+=(python3-venv)
ldconfig -p | grep -q "libEGL.so.1 " || missing+=(libegl1)
ldconfig -p | grep -q "libEGL_mesa.so.0 " || missing+=(libegl-mesa0)
ldconfig -p | grep -q "libGL.so.1 " || missing+=(libgl1)
[ -e /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so ] || [ -e /usr/lib/x86_64-linux-gnu/dri/llvmpipe_dri.so ] \
  || missing+=(libgl1-mesa-dri)
ldconfig -p | grep -q "libOSMesa.so" || missing+=(libosmesa6)
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "installing system packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
