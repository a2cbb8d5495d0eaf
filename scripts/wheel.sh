#!/usr/bin/env bash
# A binary wheel of hlacore: ./scripts/wheel.sh [OUTDIR] (default dist/ in the checkout; a relative OUTDIR is
# taken from where it is called). It installs into a fresh environment with `pip install WHEEL` and needs no
# compiler there: hlacore._core and the `rtig` executable are in it, built and stripped (Release).
#
# It builds with the project venv's scikit-build-core in the CMake build directory the scripts' installs use
# (build/wheel, scripts/env.sh), so after ./scripts/run.sh or ./scripts/test.sh a wheel costs seconds: CMake
# recompiles only what changed since. The wheel's tag (cp311-cp311-linux_x86_64, say) means this CPython on a
# Linux like this one: the binaries load the system's glibc, libstdc++ and OpenSSL 3's libssl and libcrypto,
# at the versions they were built against (Debian 12: glibc >= 2.34, GCC 12's libstdc++, libssl.so.3 and
# libcrypto.so.3), and PyPI refuses the tag. A wheel for any Linux (manylinux) needs a build in a manylinux
# image and auditwheel repair. The last line printed is the wheel's path; the build log is build/wheel.log.
caller=$PWD
source "$(dirname "$0")/env.sh"
outdir=${1:-$PWD/dist}
[[ $outdir = /* ]] || outdir="$caller/$outdir"

# The build requirements of pyproject.toml, installed into .venv once (as install_hlacore does).
if ! .venv/bin/python -c "import scikit_build_core, pybind11" 2>/dev/null || [ ! -x .venv/bin/cmake ] \
        || [ ! -x .venv/bin/ninja ]; then
    pip_install scikit-build-core pybind11 cmake ninja
fi

require_build_headers
mkdir -p "$outdir"
lock_build_dir lock || exit 1  # held until this script exits: one build at a time in build/wheel
staging=$(mktemp -d build/wheel-out.XXXXXX)
trap 'rm -rf "$staging"' EXIT
echo "Building the hlacore wheel (build/wheel: seconds when the scripts have built these sources) ..." >&2
if ! .venv/bin/python -m pip wheel --disable-pip-version-check --no-build-isolation --no-deps -v \
        -C build-dir=build/wheel -w "$staging" . 2>&1 | tee build/wheel.log \
        | { grep --line-buffered -E '^ *\[[0-9]+/[0-9]+\] (Building|Linking)' || true; } | cut -c1-110 >&2; then
    tail -n 40 build/wheel.log >&2
    echo "wheel.sh: the build failed; the whole log is build/wheel.log" >&2
    exit 1
fi
built=("$staging"/hlacore-*.whl)
[ -f "${built[0]}" ] || { echo "wheel.sh: pip wheel made no hlacore wheel; see build/wheel.log" >&2; exit 1; }
wheel="$outdir/$(basename "${built[0]}")"
mv -f "${built[0]}" "$wheel"

# What makes it a binary wheel that runs without a compiler: the extension, the executable, the type marker.
.venv/bin/python - "$wheel" <<'EOF'
import re, sys, zipfile
path = sys.argv[1]
with zipfile.ZipFile(path) as wheel:
    infos = {info.filename: info for info in wheel.infolist()}
needed = {"the extension": r"hlacore/_core\..*\.so", "the rtig executable": r"hlacore-[^/]*\.data/scripts/rtig",
          "py.typed": r"hlacore/py\.typed", "the robot FOM": r"hlacore/.*\.fed"}
missing = [what for what, pattern in needed.items() if not any(re.fullmatch(pattern, name) for name in infos)]
rtig = [info for name, info in infos.items() if re.fullmatch(needed["the rtig executable"], name)]
if rtig and not (rtig[0].external_attr >> 16) & 0o111:
    missing.append("rtig's executable bit")
if missing:
    sys.exit(f"wheel.sh: {path} lacks " + ", ".join(missing))
tag = path.rsplit("/", 1)[-1][:-len(".whl")].split("-", 2)[2]
print(f"{len(infos)} files, {sum(i.file_size for i in infos.values()) / 1e6:.1f} MB unpacked; tag {tag}",
      file=sys.stderr)
EOF
echo "$(du -k "$wheel" | cut -f1) KiB:" >&2
echo "$wheel"
