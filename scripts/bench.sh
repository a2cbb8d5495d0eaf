#!/usr/bin/env bash
# Install hlacore (Release, with rtig into .venv/bin) and the bench extras into .venv, build the C++ TCP
# floor program, then run the benchmarks in bench/. Arguments go to pytest (./scripts/bench.sh -k grant).
# Writes build/bench/ (results.json, results.md, grant-latency.png) and, after a full run, the figures of
# docs/performance.md and docs/grant-latency.png; the three-RTI table of docs/performance.md after any run that
# measured all of it (-k three_rtis). OpenRTI and CERTI 3.5.1 join the three-RTI group only when given as
# existing installs, HLACORE_BENCH_OPENRTI=PREFIX and HLACORE_BENCH_CERTI=PREFIX (bench/three_rtis.py says what
# each prefix must hold); without them hlacore's rows run alone and one skip line says so.
source "$(dirname "$0")/env.sh"
install_hlacore bench
./scripts/install-ros2.sh   # ROS 2's pinned wheels for bench/test_ros_bridge.py's ROS 2 row (ROS 1: scripts/install-ros.sh)
command -v nft >/dev/null 2>&1 \
    || debian_install "nft drops packets in the namespace of the best-effort loss bench (bench/lossy_stream.py)" nftables
[ -x .venv/bin/cmake ] && [ -x .venv/bin/ninja ] || pip_install cmake ninja
mkdir -p build
.venv/bin/cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DHLACORE_BENCH=ON -DHLACORE_PYTHON=OFF \
    -DCMAKE_MAKE_PROGRAM="$PWD/.venv/bin/ninja" >build/bench-configure.log 2>&1 \
    || { cat build/bench-configure.log; exit 1; }
.venv/bin/cmake --build build/bench --target tcp_floor >build/bench-build.log 2>&1 || { cat build/bench-build.log; exit 1; }
export HLACORE_TCP_FLOOR="$PWD/build/bench/tcp_floor"
export HLACORE_BENCH_COMMAND="./scripts/bench.sh${*:+ $*}"
exec .venv/bin/python -m pytest bench --benchmark-columns=min,median,mean,max,rounds "$@"
