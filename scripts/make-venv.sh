#!/usr/bin/env bash
# Make the project's virtual environment: PYTHON's venv module where it works; where it
# lacks ensurepip (Debian without python3-venv) and there is no root to add it, a venv
# without pip that the interpreter's own pip fills (pip >= 22.3, `--python`); else one
# line naming what to install. Usage: make-venv.sh PYTHON VENV
set -uo pipefail
PY="${1:-python3}"
VENV="${2:-.venv}"

if "$PY" -m venv "$VENV" >/dev/null 2>&1 && [ -x "$VENV/bin/pip" ]; then
  exit 0
fi
rm -rf "$VENV"
if "$PY" -m pip --version >/dev/null 2>&1 && "$PY" -m venv --without-pip "$VENV" 2>/dev/null \
   && "$PY" -m pip --python "$VENV/bin/python" install --quiet pip 2>/dev/null; then
  echo "made $VENV without ensurepip (pip installed into it by $PY's pip)"
  exit 0
fi
rm -rf "$VENV"
echo "error: $PY can make no virtual environment here: install python3-venv" \
     "(Debian/Ubuntu: apt-get install python3-venv) or pip, then rerun" >&2
exit 1
