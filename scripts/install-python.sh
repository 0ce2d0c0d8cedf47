#!/usr/bin/env bash
# Builds the Python package thyrix (Release) and installs it into the user's site-packages of
# Debian's /usr/bin/python3, after which `/usr/bin/python3 -c "import thyrix"` works from any
# folder. Needs scripts/install-deps.sh first. Usage: scripts/install-python.sh [BUILD_DIR]
# (default build/python). Set THYRIX_PYTHON_INSTALL_DIR to install elsewhere (then put that
# folder on PYTHONPATH).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/python}
site=${THYRIX_PYTHON_INSTALL_DIR:-$(/usr/bin/python3 -c "import site; print(site.getusersitepackages())")}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DTHYRIX_BUILD_PYTHON=ON \
  -DTHYRIX_BUILD_TESTS=OFF -DTHYRIX_BUILD_EXAMPLES=OFF -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DTHYRIX_PYTHON_INSTALL_DIR="$site" >/dev/null
cmake --build "$build" -j"$(nproc)" --target thyrix_python
cmake --install "$build" --component python
# The check: from another folder, with the custom folder on PYTHONPATH if one was given.
check_path=${PYTHONPATH:-}
if [ -n "${THYRIX_PYTHON_INSTALL_DIR:-}" ]; then check_path="$site${check_path:+:$check_path}"; fi
cd / && PYTHONPATH="$check_path" /usr/bin/python3 -c "import thyrix; print('thyrix installed in', thyrix.__path__[0])"
