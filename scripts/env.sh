# Sourced by the scripts: enter the checkout and make sure the project venv exists.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if [ ! -x .venv/bin/python ]; then
    "${PYTHON:-python3}" -m venv .venv
fi
pip_install() { .venv/bin/python -m pip install --quiet --disable-pip-version-check "$@"; }

# Installs hlacore with the given extras (e.g. "test", or "" for none) into .venv, unless those very
# sources are installed with those extras already (.venv/hlacore-installed holds a hash of every file the
# build reads). A rebuild reuses build/wheel, so CMake compiles only what changed.
install_hlacore() {
    local extras=$1 stamp=.venv/hlacore-installed digest
    digest=$(.venv/bin/python scripts/source_digest.py)
    if [ -f "$stamp" ] && grep -qxF "$digest [$extras]" "$stamp" && .venv/bin/python -c "import hlacore._core" 2>/dev/null; then
        return 0
    fi
    echo "Building hlacore into .venv (the C++ core: a few minutes the first time, seconds after a change) ..." >&2
    pip_install scikit-build-core pybind11 cmake ninja
    pip_install --no-build-isolation -C build-dir=build/wheel ".${extras:+[$extras]}"
    # The stamp lists the extras installed with these sources, so run.sh and test.sh do not undo each other.
    { [ -f "$stamp" ] && grep "^$digest " "$stamp" || true; echo "$digest [$extras]"; } >"$stamp.new"
    mv "$stamp.new" "$stamp"
}
