# Sourced by the scripts: enter the checkout and make sure the project venv exists.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if [ ! -x .venv/bin/python ]; then
    "${PYTHON:-python3}" -m venv .venv
fi
pip_install() { .venv/bin/python -m pip install --quiet --disable-pip-version-check "$@"; }

# Opens build/wheel.lock on a new descriptor (its number in the variable named $1) and waits (20 min at most)
# for the lock: one build at a time in build/wheel (install_hlacore, scripts/wheel.sh), since two ninjas
# writing the same objects break the link. Closing the descriptor releases it.
lock_build_dir() {
    local -n fd=$1
    mkdir -p build
    exec {fd}>build/wheel.lock
    flock -w 1200 "$fd" || { echo "another build holds build/wheel.lock (20 min)" >&2; exec {fd}>&-; return 1; }
}

# Installs hlacore with the given extras (e.g. "test", or "" for none) into .venv, unless those very
# sources are installed with those extras already (.venv/hlacore-installed holds a hash of every file the
# build reads). A rebuild reuses build/wheel, so CMake compiles only what changed.
install_hlacore() {
    local extras=$1 stamp=.venv/hlacore-installed digest
    digest=$(.venv/bin/python scripts/source_digest.py)
    if [ -f "$stamp" ] && grep -qxF "$digest [$extras]" "$stamp" && .venv/bin/python -c "import hlacore._core" 2>/dev/null; then
        return 0
    fi
    require_build_headers
    echo "Building hlacore into .venv (the C++ core: a few minutes the first time, seconds after a change) ..." >&2
    pip_install scikit-build-core pybind11 cmake ninja
    local lock status=0
    lock_build_dir lock || return 1
    # The compiler's progress lines as they come; the whole log in build/install.log, its end on failure.
    .venv/bin/python -m pip install --disable-pip-version-check --no-build-isolation -v \
            -C build-dir=build/wheel ".${extras:+[$extras]}" 2>&1 | tee build/install.log \
            | { grep --line-buffered -E '^ *\[[0-9]+/[0-9]+\] (Building|Linking)' || true; } | cut -c1-110 >&2 \
        || status=$?
    exec {lock}>&-
    if [ "$status" -ne 0 ]; then
        tail -n 40 build/install.log >&2
        echo "install_hlacore: the build failed; the whole log is build/install.log" >&2
        return 1
    fi
    # The stamp lists the extras installed with these sources, so run.sh and test.sh do not undo each other.
    { [ -f "$stamp" ] && grep "^$digest " "$stamp" || true; echo "$digest [$extras]"; } >"$stamp.new"
    mv "$stamp.new" "$stamp"
}

# The headers and link libraries of the C++ core's system libraries: OpenSSL (Debian's libssl-dev):
# libcrypto for the shared secret's HMAC (cpp/rti/auth.cpp), libssl for the optional TLS (cpp/rti/tls.cpp);
# zlib (zlib1g-dev) for the recordings' CRC (cpp/rti/record/mcap.cpp); expat (libexpat1-dev) for the XML of
# FOM modules (cpp/fed_parser/omt.cpp); protobuf (libprotobuf-dev, protobuf-compiler) for the Federate
# Protocol's messages (cpp/fedpro/proto), compiled by protoc into C++ and into hlacore.fedpro._proto.
require_build_headers() {
    [ -e /usr/include/openssl/ssl.h ] \
        || debian_install "hlacore's C++ core compiles against OpenSSL (libcrypto for the shared secret, libssl for TLS)" libssl-dev
    [ -e /usr/include/zlib.h ] \
        || debian_install "hlacore's C++ core computes the recordings' checksums with zlib" zlib1g-dev
    [ -e /usr/include/expat.h ] \
        || debian_install "hlacore's C++ core reads FOM modules in OMT XML with expat" libexpat1-dev
    { command -v protoc && [ -e /usr/include/google/protobuf/message.h ]; } >/dev/null 2>&1 \
        || debian_install "the HLA 4 Federate Protocol's messages are protobuf: protoc generates their C++ and Python" \
            libprotobuf-dev protobuf-compiler
}

# Builds TARGETS in the configured CMake build directory DIR, saying so (LABEL) and showing the compiler's
# progress only when there is something to build; the log goes to DIR.log, shown on failure.
cmake_build() {
    local dir=$1 label=$2
    shift 2
    if .venv/bin/ninja -C "$dir" -n "$@" 2>/dev/null | grep -qE '^\[[0-9]+/[0-9]+\] (Building|Linking)'; then
        echo "Building $label ($dir) ..." >&2
    fi
    if ! .venv/bin/cmake --build "$dir" --target "$@" 2>&1 | tee "$dir.log" \
            | { grep --line-buffered -E '^\[[0-9]+/[0-9]+\] (Building|Linking)' || true; } | sed -u 's/^/  /' | cut -c1-110 >&2; then
        tail -n 60 "$dir.log" >&2
        echo "the build failed; the whole log is $dir.log" >&2
        return 1
    fi
}

# Installs Debian's PACKAGES when a command is missing, saying first what and WHY; as root or through
# passwordless sudo; apt-get update only when the install fails without it. The log is build/apt.log.
debian_install() {
    local why=$1 sudo=()
    shift
    [ "$(id -u)" -eq 0 ] || sudo=(sudo -n)
    echo "installing $* from Debian's packages: $why" >&2
    mkdir -p build
    local apt=(${sudo[@]+"${sudo[@]}"} env DEBIAN_FRONTEND=noninteractive apt-get -y -q)
    "${apt[@]}" install --no-install-recommends "$@" </dev/null >build/apt.log 2>&1 \
        || { "${apt[@]}" update </dev/null >>build/apt.log 2>&1 \
             && "${apt[@]}" install --no-install-recommends "$@" </dev/null >>build/apt.log 2>&1; } \
        || { tail -n 30 build/apt.log >&2; return 1; }
}
