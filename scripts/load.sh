#!/usr/bin/env bash
# The load test at full size: FEDERATES federate processes (default 32) x UPDATES timestamped updates
# each (default 10000) in lockstep over the optimized rtig, every delivery checked by per-sender sequence
# numbers; then the same with 2 federates killed midway. Prints the figures. The suite runs it at 8 x 200.
#   scripts/load.sh [FEDERATES [UPDATES]]
# Extra pytest arguments after `--`. Needs the project installed in .venv (./scripts/test.sh or
# ./scripts/run.sh did it).
source "$(dirname "$0")/env.sh"
federates=${1:-32}
updates=${2:-10000}
shift $(( $# > 2 ? 2 : $# ))
[ "${1:-}" = "--" ] && shift
install_hlacore test
unset HLACORE_TEST_RTIG  # the rtig installed in .venv (optimized), not the sanitizer build
export HLACORE_LOAD_FEDERATES=$federates HLACORE_LOAD_UPDATES=$updates
# pytest-timeout: a bound proportional to the size (the tests bound each wait themselves too)
exec .venv/bin/python -m pytest tests/system/test_load.py -s -q --timeout=$(( 600 + federates * updates / 20 )) "$@"
