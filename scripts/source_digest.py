"""Print a digest of every file that building hlacore reads (scripts/env.sh's install_hlacore compares it).

Usage: source_digest.py [ROOT] (default: this checkout).
"""

import hashlib
import pathlib
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
INPUTS = ["CMakeLists.txt", "pyproject.toml", "README.md", "cpp", "python"]
SKIP_SUFFIXES = {".pyc", ".so"}

digest = hashlib.sha256()
for name in INPUTS:
    top = ROOT / name
    files = [top] if top.is_file() else sorted(p for p in top.rglob("*") if p.is_file())  # absent: none
    for path in files:
        if path.suffix in SKIP_SUFFIXES or "__pycache__" in path.parts:
            continue
        digest.update(str(path.relative_to(ROOT)).encode() + b"\0" + path.read_bytes() + b"\0")
print(digest.hexdigest())
