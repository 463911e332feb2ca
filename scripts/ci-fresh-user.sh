#!/usr/bin/env bash
# The quick start as a fresh machine's unprivileged user meets it: a new account (no
# root, no sudo, so apt cannot help), a fresh clone, the system's python3, and MUJOCO_GL
# naming OSMesa, which the CI image lacks. `make demo` must pass there as written, and
# the set-up and drawing tests must pass or skip with their one-line reason.
# Run by .ci/run as root; where no account can be made it says so in one line.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
if [ "$(id -u)" -ne 0 ] || ! command -v useradd >/dev/null 2>&1; then
  echo "fresh-user check not run: it needs root to make an account (useradd)"
  exit 0
fi
user=wmr-fresh
id "$user" >/dev/null 2>&1 || useradd --create-home --shell /bin/bash "$user"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"
git clone --quiet "$repo" "$work/wmr"
chown -R "$user" "$work"
# The set-up path is what is checked here: `make demo` judges 3 draws a family (labelled
# quick); the full families are CI's own `make demo`.
echo "fresh-user check: make demo (quick) and the set-up tests as '$user' (no root, MUJOCO_GL=osmesa)"
su "$user" -c "cd '$work/wmr' && export PATH=/usr/local/bin:/usr/bin:/bin MUJOCO_GL=osmesa \
  PYTHON=/usr/bin/python3 && make demo PYTHON=/usr/bin/python3 DEMO_ARGS=--quick \
  && .venv/bin/python -m pytest -q -p no:cacheprovider tests/scripts tests/test_gl_env.py \
     tests/render/test_gl_backend.py"
