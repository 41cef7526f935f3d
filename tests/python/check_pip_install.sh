#!/usr/bin/env bash
# `pip install --no-build-isolation .` into a fresh virtual environment with Debian's build tools
# only (no package index), reusing the configured build folder; then `import upf` from it.
# Usage: check_pip_install.sh SOURCE_DIR BUILD_DIR PYTHON
set -euo pipefail
source_dir=$1 build_dir=$2 python=$3
venv=$build_dir/pip-install-check
rm -rf "$venv"
"$python" -m venv --system-site-packages "$venv"
cd "$source_dir"
UPF_BUILD_DIR=$build_dir "$venv/bin/pip" install --quiet --no-build-isolation --no-index \
  --no-cache-dir . 
cd /
"$venv/bin/python" - <<'PY'
import upf
assert "/pip-install-check/" in upf.__file__, upf.__file__
assert any(s["name"] == "pcisph" for s in upf.solvers())
print("installed:", upf.__file__)
PY
