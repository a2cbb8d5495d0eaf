#!/usr/bin/env bash
# Build the API reference (docs/api: Sphinx autodoc of hlacore.rti, hlacore.omt, hlacore.Gateway and
# hlacore.aio from their docstrings) into build/docs, after installing hlacore with the docs extra into .venv.
# Nitpicky and warnings as errors: a broken cross-reference or broken reST in a docstring fails the build.
# tests/system/test_api_docs.py runs the same build. Arguments go to sphinx-build.
source "$(dirname "$0")/env.sh"
install_hlacore docs
# -E: read every page again. Autodoc cannot see that the compiled module changed, and a page Sphinx does
# not read again would not repeat its warnings; the whole build takes seconds.
.venv/bin/sphinx-build -n -W --keep-going -E -b html "$@" docs/api build/docs
echo "the API reference: $PWD/build/docs/index.html"
