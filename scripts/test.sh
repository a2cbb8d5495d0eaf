#!/usr/bin/env bash
# Install hlacore and its test dependencies into .venv, build an ASan+UBSan rtig for the tests that run
# against the real executable (and the bench's C++ TCP floor program, for its smoke test), then run the
# whole test suite. Arguments go to pytest. It also builds the libFuzzer targets (scripts/fuzz.sh --build-only,
# which installs clang from Debian's packages when missing) for tests/system/test_fuzz.py's short fuzz runs; outside
# CI (CI=true) a machine where clang cannot be installed only skips those.
source "$(dirname "$0")/env.sh"
./scripts/install-ros.sh   # ROS 1 from Debian for the ROS bridge tests (docs/ros-bridge.md)
command -v ip >/dev/null 2>&1 \
    || debian_install "the ip command makes the test hosts (network namespaces) of tests/transport/test_link.py" iproute2
command -v nft >/dev/null 2>&1 \
    || debian_install "nft drops packets in the namespace of the best-effort loss bench (bench/lossy_stream.py)" nftables
command -v openssl >/dev/null 2>&1 \
    || debian_install "the openssl command makes the test certificates of tests/transport/test_tls.py" openssl
{ command -v chromium && command -v chromedriver; } >/dev/null 2>&1 \
    || debian_install "tests/system/test_monitor.py opens the monitor's page in headless chromium, driven by Selenium through chromedriver" chromium chromium-driver
command -v pkg-config >/dev/null 2>&1 \
    || debian_install "pkg-config reads the installed hlacore.pc in tests/system/test_cpp_api.py (the HLA 1.3 C++ API)" pkgconf
install_hlacore test
./scripts/install-ros2.sh   # ROS 2's pinned wheels from PyPI for the ROS 2 bridge tests (after hlacore: numpy comes with it)
[ -x .venv/bin/cmake ] && [ -x .venv/bin/ninja ] || pip_install cmake ninja
mkdir -p build
# The gateway, and hlacore-rtia over the federate side (it decodes what CERTI federates send: sanitized too), and
# the IEEE 1516-2010 C++ API's test programs against the tree's libraries, sanitized.
.venv/bin/cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DHLACORE_SANITIZE=ON -DHLACORE_PYTHON=OFF -DHLACORE_BENCH=ON \
    -DCMAKE_MAKE_PROGRAM="$PWD/.venv/bin/ninja" >build/asan-configure.log 2>&1 \
    || { cat build/asan-configure.log; exit 1; }
cmake_build build/asan "the ASan+UBSan rtig, hlacore-rtia and 1516-2010 test programs the tests run" rtig \
    hlacore-rtia tcp_floor state_types_test rti1516e_federate rti1516e_encoding rti1516e_services rti1516e_bench
# The C++ test federates of the HLA 1.3 API (tests/cpp/hla13), against the installed package's CMake config ...
api_dir=$(.venv/bin/python -m hlacore.config --cmake-dir) || exit 1
.venv/bin/cmake -S tests/cpp/hla13 -B build/hla13-tests -G Ninja -Dhlacore_DIR="$api_dir" \
    -DCMAKE_MAKE_PROGRAM="$PWD/.venv/bin/ninja" >build/hla13-tests-configure.log 2>&1 \
    || { cat build/hla13-tests-configure.log; exit 1; }
cmake_build build/hla13-tests "the C++ test federates of the HLA 1.3 API" all
# ... and the C++ test programs of the IEEE 1516-2010 API (tests/cpp/rti1516e), the same way.
.venv/bin/cmake -S tests/cpp/rti1516e -B build/rti1516e-tests -G Ninja -Dhlacore_DIR="$api_dir" \
    -DCMAKE_MAKE_PROGRAM="$PWD/.venv/bin/ninja" >build/rti1516e-tests-configure.log 2>&1 \
    || { cat build/rti1516e-tests-configure.log; exit 1; }
cmake_build build/rti1516e-tests "the C++ test programs of the IEEE 1516-2010 API" all
if ./scripts/fuzz.sh --build-only; then
    export HLACORE_TEST_FUZZERS="$PWD/build/fuzz"
elif [ "${CI:-}" = true ]; then
    exit 1
else
    echo "test.sh: the fuzz targets could not be built; tests/system/test_fuzz.py will skip" >&2
fi
export HLACORE_TEST_RTIG="$PWD/build/asan/rtig" HLACORE_TEST_RTIA="$PWD/build/asan/hlacore-rtia" \
    HLACORE_TEST_TCP_FLOOR="$PWD/build/asan/tcp_floor" \
    HLACORE_TEST_STATE_TYPES="$PWD/build/asan/state_types_test" HLACORE_TEST_HLA13="$PWD/build/hla13-tests"
# The tests run in parallel processes (pytest-xdist), one more than the cores: most of a test's time is waiting
# (on a gateway, a child process, a timeout), and in one process the whole suite took two and a half times as long.
# `-n 0` (or HLACORE_TEST_WORKERS=0) runs it in this process, for a debugger.
exec .venv/bin/python -m pytest -n "${HLACORE_TEST_WORKERS:-$(( $(nproc) + 1 ))}" "$@"
