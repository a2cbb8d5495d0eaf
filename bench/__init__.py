"""hlacore's benchmarks (pytest-benchmark), run by ./scripts/bench.sh; the bodies are importable so that
tests/system/test_bench_smoke.py can run each of them at a tiny size."""
