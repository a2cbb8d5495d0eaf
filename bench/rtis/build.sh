#!/usr/bin/env bash
# Builds the two reference RTIs of the three-RTI benchmark (bench/test_three_rtis.py) from their source
# archives: OpenRTI (openrti-*.tar.gz) and CERTI 3.5.1 (certi-*.tar.gz) found in ARCHIVES (for example
# ../shared/anchors), each installed into OUT/<rti> (default build/rtis). A build whose archive has not
# changed is kept (OUT/<rti>/.archive holds the archive's checksum). The build notes are
# ../shared/anchors/README.md's: CMake 4 needs a policy minimum, CERTI needs C++14 (its headers keep
# exception specifications), flex, bison, libxml2 and SunRPC, and two of its generated files print with
# `out << x.show(out)`, which C++11 rejects.
#
# Then compiles bench/rtis/hla13_bench.cpp against each of the three (hlacore's from this checkout's .venv)
# into OUT/bench/hla13_bench-<rti>.
#
# usage: bench/rtis/build.sh ARCHIVES [OUT]
set -euo pipefail
cd "$(dirname "$0")/../.."
source scripts/env.sh
archives=$(realpath "${1:?usage: bench/rtis/build.sh ARCHIVES [OUT]}")
out=$(realpath -m "${2:-build/rtis}")
cmake=$PWD/.venv/bin/cmake
[ -x "$cmake" ] || pip_install cmake ninja
mkdir -p "$out"

the_archive() {  # the one archive matching $1 in $archives
    local found=("$archives"/$1)
    [ -f "${found[0]}" ] || { echo "build.sh: no $1 in $archives" >&2; exit 1; }
    echo "${found[0]}"
}

# Unpacks archive $2 into $out/$1-src unless $out/$1 was built from it; returns 1 when up to date.
unpack() {
    local name=$1 archive=$2 sum
    sum=$(sha256sum "$archive" | cut -d' ' -f1)
    if [ -f "$out/$name/.archive" ] && [ "$(cat "$out/$name/.archive")" = "$sum" ]; then
        return 1
    fi
    rm -rf "$out/$name-src" "$out/$name-build" "$out/$name"
    mkdir -p "$out/$name-src"
    tar xzf "$archive" -C "$out/$name-src" --strip-components=1
    echo "$sum" >"$out/$name-src/.archive"
}

openrti=$(the_archive 'openrti-*.tar.gz')
if unpack openrti "$openrti"; then
    echo "Building OpenRTI from $(basename "$openrti") into $out/openrti (about 1.5 min) ..." >&2
    "$cmake" -S "$out/openrti-src" -B "$out/openrti-build" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_POLICY_VERSION_MINIMUM=3.5 -DCMAKE_INSTALL_PREFIX="$out/openrti" >"$out/openrti-build.log" 2>&1
    make -C "$out/openrti-build" -j"$(nproc)" OpenRTI RTI-NG FedTime rtinode >>"$out/openrti-build.log" 2>&1 \
        || { tail -30 "$out/openrti-build.log"; exit 1; }
    # Installs the HLA 1.3 headers, libraries and rtinode, then stops at the unbuilt libfedtime1516 (not needed).
    make -C "$out/openrti-build" install/fast >>"$out/openrti-build.log" 2>&1 || true
    [ -f "$out/openrti/include/RTI13/RTI.hh" ] && [ -x "$out/openrti/bin/rtinode" ] \
        || { tail -30 "$out/openrti-build.log"; echo "build.sh: OpenRTI's install is incomplete" >&2; exit 1; }
    cp "$out/openrti-src/.archive" "$out/openrti/.archive"
fi

certi=$(the_archive 'certi-*.tar.gz')
missing=()
command -v flex >/dev/null 2>&1 || missing+=(flex)
command -v bison >/dev/null 2>&1 || missing+=(bison)
[ -e /usr/include/libxml2/libxml/parser.h ] || missing+=(libxml2-dev)
[ -e /usr/include/tirpc/rpc/rpc.h ] || missing+=(libtirpc-dev)
if [ ${#missing[@]} -gt 0 ]; then
    debian_install "CERTI 3.5.1's build needs flex and bison (its FED parser), libxml2 (XML FOMs) and SunRPC (a test tool)" "${missing[@]}"
fi
if unpack certi "$certi"; then
    echo "Building CERTI from $(basename "$certi") into $out/certi (about 2 min) ..." >&2
    # `out << x.show(out)` prints a stream into itself, which C++11 rejects: one statement each.
    sed -i -E 's/out << (.*) << ([A-Za-z_.]+)\.show\(out\) *<< std::endl;/out << \1; \2.show(out); out << std::endl;/;
               s/out << ([A-Za-z_]+\[i\])\.show\(out\);/\1.show(out);/' \
        "$out/certi-src/libCERTI/M_Classes.cc" "$out/certi-src/libCERTI/NM_Classes.cc"
    "$cmake" -S "$out/certi-src" -B "$out/certi-build" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_POLICY_VERSION_MINIMUM=3.5 -DFORCE_NO_X11=ON -DCMAKE_INSTALL_PREFIX="$out/certi" \
        "-DCMAKE_CXX_FLAGS_RELEASE=-O3 -DNDEBUG -std=gnu++14" "-DCMAKE_C_FLAGS=-I/usr/include/tirpc" \
        -DCMAKE_C_STANDARD_LIBRARIES=-ltirpc >"$out/certi-build.log" 2>&1 \
        || { tail -30 "$out/certi-build.log"; exit 1; }
    # -k: only the unit test TestFedTime fails to link, which the install does not need.
    make -C "$out/certi-build" -j"$(nproc)" -k >>"$out/certi-build.log" 2>&1 || true
    make -C "$out/certi-build" install/fast >>"$out/certi-build.log" 2>&1 || true
    [ -f "$out/certi/include/hla13/RTI.hh" ] && [ -x "$out/certi/bin/rtig" ] && [ -x "$out/certi/bin/rtia" ] \
        || { tail -30 "$out/certi-build.log"; echo "build.sh: CERTI's install is incomplete" >&2; exit 1; }
    cp "$out/certi-src/.archive" "$out/certi/.archive"
fi

# The benchmark program, unchanged, against each RTI (C++14: CERTI's headers keep exception specifications);
# again when the program or the RTI's library is newer than the binary.
mkdir -p "$out/bench"
compile() {  # RTI INCLUDE_DIR LIB_DIR
    local target=$out/bench/hla13_bench-$1
    if [ -x "$target" ] && [ "$target" -nt bench/rtis/hla13_bench.cpp ] && [ "$target" -nt "$3/libRTI-NG.so" ]; then
        return 0
    fi
    echo "Compiling bench/rtis/hla13_bench.cpp against $1 ..." >&2
    g++ -std=gnu++14 -O2 -Wno-deprecated -DRTI_USES_STD_FSTREAM bench/rtis/hla13_bench.cpp -I"$2" \
        -L"$3" -Wl,-rpath,"$3" -Wl,-rpath-link,"$3" -lRTI-NG -lFedTime -o "$target"
}
compile openrti "$out/openrti/include/RTI13" "$out/openrti/lib"
compile certi "$out/certi/include/hla13" "$out/certi/lib"
compile hlacore "$(.venv/bin/python -m hlacore.config --include-dir)" "$(.venv/bin/python -m hlacore.config --lib-dir)"
echo "$out"
