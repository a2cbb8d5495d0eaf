#!/usr/bin/env bash
# Install hlacore and its test dependencies into .venv, build an ASan+UBSan rtig for the tests that run
# against the real executable, then run the whole test suite. Arguments go to pytest.
source "$(dirname "$0")/env.sh"
pip_install ".[test]" cmake ninja
mkdir -p build
.venv/bin/cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DHLACORE_SANITIZE=ON -DHLACORE_PYTHON=OFF \
    -DCMAKE_MAKE_PROGRAM="$PWD/.venv/bin/ninja" >build/asan-configure.log 2>&1 \
    || { cat build/asan-configure.log; exit 1; }
.venv/bin/cmake --build build/asan --target rtig >build/asan-build.log 2>&1 || { cat build/asan-build.log; exit 1; }
export HLACORE_TEST_RTIG="$PWD/build/asan/rtig"
exec .venv/bin/python -m pytest "$@"
