#!/usr/bin/env bash
# Installs what vap_bt needs on a fresh Debian machine, and nothing twice:
# Debian packages (libusb-1.0-0 for open3d, libgomp1 for the solvers, chromium for the browser
# test of the rerun web viewer, which Playwright drives but cannot download here; tesseract-ocr, with
# which that test reads what the viewer's panels say), a virtual
# environment in .venv, and the project with its test extras (editable, so `vap-bt` runs this checkout).
set -euo pipefail
cd "$(dirname "$0")/.."

need_apt=()
ldconfig -p | grep -q 'libusb-1.0.so.0' || need_apt+=(libusb-1.0-0)
ldconfig -p | grep -q 'libgomp.so.1' || need_apt+=(libgomp1)
[ -x /usr/bin/chromium ] || need_apt+=(chromium)
[ -x /usr/bin/tesseract ] || need_apt+=(tesseract-ocr)
if [ ${#need_apt[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${need_apt[*]}" >&2
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need_apt[@]}" >/dev/null
fi

PY=${PYTHON:-python3.11}
command -v "$PY" >/dev/null || PY=python3
if [ ! -x .venv/bin/python ]; then
  echo "setup: creating .venv with $("$PY" --version)" >&2
  "$PY" -m venv .venv
fi
stamp=.venv/.vap_bt-installed
if [ ! -f "$stamp" ] || [ pyproject.toml -nt "$stamp" ]; then
  echo "setup: installing the project and its dependencies into .venv (first time takes a few minutes)" >&2
  .venv/bin/python -m pip install -q --upgrade pip 2>&1 | grep -v '^WARNING: Location' || true
  .venv/bin/python -m pip install -q -e '.[test]' 2>&1 | grep -vE '^WARNING: Location|^\s*$' || true
  .venv/bin/python -c "import vap_bt, skills, robots, py_trees, zenoh, unified_planning, vap_bt.sim.pb, pinocchio" \
    || { echo "setup: the installation is incomplete" >&2; exit 1; }
  touch "$stamp"
fi
