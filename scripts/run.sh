#!/usr/bin/env bash
# The main job on the embedded default: install hlacore (with matplotlib, for the trajectory plot) into
# .venv and run the demo federation on an in-process gateway. Arguments go to the demo (./scripts/run.sh --help).
source "$(dirname "$0")/env.sh"
install_hlacore plot
exec .venv/bin/python -m hlacore.experiments.robot_in_the_loop "$@"
