#!/usr/bin/env bash
# Build the libFuzzer targets of cpp/fuzz with clang (installed from Debian's packages when missing) into
# build/fuzz/, then run each for SECONDS (default 60) from the committed seed corpus:
#   fuzz_wire  next_frame + decode of arbitrary bytes (seeds: cpp/fuzz/corpus/wire/ from make_wire_seeds.py,
#              and a sample frame of every message written by wire_seeds into build/fuzz/seeds-wire/)
#   fuzz_fed   fom::parse_fed of arbitrary text (seeds: tests/data/fed/good and bad, dictionary fed.dict)
#   fuzz_omt   fom::parse_omt of arbitrary bytes as an OMT XML FOM module, alone and after a valid one (seeds:
#              cpp/fuzz/corpus/omt/)
#   fuzz_gateway  a joined federate's arbitrary bytes to a real in-process Gateway (seeds: the wire corpus)
#   fuzz_datagram  a joined federate's arbitrary datagrams to the Gateway's UDP port (seeds: the wire corpus)
#   fuzz_certi  hlacore-rtia's decoder of CERTI's federate protocol (seeds: cpp/fuzz/corpus/certi/, frames of
#              both byte orders written by tests/support/certi.py's encoder)
#   fuzz_fedpro  the Federate Protocol's session layer: headers, numbering, resumes (seeds: cpp/fuzz/corpus/fedpro/)
#   fuzz_websocket  the Federate Protocol's WebSocket handshake and frame headers (seeds: cpp/fuzz/corpus/websocket/)
#   fuzz_zip   the Federate Protocol's compressed FOM modules, zip archives (seeds: cpp/fuzz/corpus/zip/)
# and replay the committed regression inputs (cpp/fuzz/regressions/). A crash leaves its input in
# build/fuzz/artifacts/ and makes the script fail; it then belongs in cpp/fuzz/regressions/TARGET/.
#
#   scripts/fuzz.sh [SECONDS]      build, replay the regressions, run each target SECONDS
#   scripts/fuzz.sh --build-only   install clang if needed and build (scripts/test.sh does this)
source "$(dirname "$0")/env.sh"

build_only=0
seconds=60
case "${1:-}" in
    --build-only) build_only=1 ;;
    "") ;;
    *[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS | --build-only]" >&2; exit 2 ;;
    *) seconds=$1 ;;
esac

# clang and its libFuzzer runtime (Debian 12: clang-14 and libclang-rt-14-dev).
fuzzer_runtime_works() {
    command -v clang++ >/dev/null 2>&1 || return 1
    local probe
    probe=$(mktemp -d)
    printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' >"$probe/p.cpp"
    clang++ -fsanitize=fuzzer,address,undefined "$probe/p.cpp" -o "$probe/p" >/dev/null 2>&1
    local rc=$?
    rm -rf "$probe"
    return $rc
}
if ! fuzzer_runtime_works; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo -n"; fi
    echo "fuzz.sh: installing clang and its libFuzzer runtime from Debian's packages (apt-get, about a minute)" \
         "to build the fuzz targets that tests/system/test_fuzz.py runs" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt_install() { $sudo apt-get install -y -q --no-install-recommends "$@" >build-apt.log 2>&1; }
    if ! apt_install clang libclang-rt-14-dev && ! apt_install clang; then
        $sudo apt-get update -q >build-apt.log 2>&1 || true
        apt_install clang libclang-rt-14-dev || apt_install clang || { cat build-apt.log >&2; exit 1; }
    fi
    rm -f build-apt.log
    fuzzer_runtime_works || { echo "fuzz.sh: clang is installed but cannot link -fsanitize=fuzzer" >&2; exit 1; }
fi

[ -x .venv/bin/cmake ] && [ -x .venv/bin/ninja ] || pip_install cmake ninja
mkdir -p build/fuzz
.venv/bin/cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
    -DHLACORE_FUZZ=ON -DHLACORE_PYTHON=OFF -DCMAKE_MAKE_PROGRAM="$PWD/.venv/bin/ninja" \
    >build/fuzz-configure.log 2>&1 || { cat build/fuzz-configure.log; exit 1; }
cmake_build build/fuzz "the libFuzzer targets" fuzz_wire fuzz_fed fuzz_omt fuzz_json fuzz_gateway fuzz_datagram fuzz_certi fuzz_fedpro fuzz_websocket fuzz_zip wire_seeds
# A sample frame of every message (the committed seeds are hand-written and may lag the message list).
rm -rf build/fuzz/seeds-wire && mkdir -p build/fuzz/seeds-wire && build/fuzz/wire_seeds build/fuzz/seeds-wire
[ "$build_only" = 1 ] && exit 0

status=0
for target in wire fed omt gateway datagram certi; do
    bin=build/fuzz/fuzz_$target
    # Replay the inputs that once failed (each file run once).
    regressions=(cpp/fuzz/regressions/$target/*)
    if [ -e "${regressions[0]}" ]; then
        "$bin" "${regressions[@]}" >build/fuzz/replay-$target.log 2>&1 \
            || { echo "fuzz_$target: a regression input fails again:"; tail -40 build/fuzz/replay-$target.log; status=1; }
    fi
    # New inputs go to a scratch corpus under build/, the committed seeds are read only.
    mkdir -p build/fuzz/corpus-$target build/fuzz/artifacts
    case $target in
        wire | gateway | datagram) inputs=(cpp/fuzz/corpus/wire build/fuzz/seeds-wire) ;;
        fed) inputs=(-dict=cpp/fuzz/fed.dict tests/data/fed/good tests/data/fed/bad) ;;
        certi) inputs=(cpp/fuzz/corpus/certi) ;;
        omt) inputs=(cpp/fuzz/corpus/omt) ;;
    esac
    log=build/fuzz/run-$target.log
    if "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix=build/fuzz/artifacts/$target- \
        build/fuzz/corpus-$target "${inputs[@]}" >"$log" 2>&1; then
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
        secs=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
        cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1)
        corpus=$(ls build/fuzz/corpus-$target | wc -l)
        echo "fuzz_$target: $runs executions in $seconds s ($secs/s), $cov, scratch corpus $corpus inputs, no failure"
    else
        echo "fuzz_$target: FAILED (log $log, input in build/fuzz/artifacts/):"
        grep -E 'ERROR|SUMMARY|runtime error|Test unit written|fuzz_' "$log" | head -20
        status=1
    fi
done
exit $status
