#!/usr/bin/env python3
"""The largest source files and functions of renderer/ and exporters/.

Prints the N largest files (lines) and the N longest functions (lines from
their definition to their closing brace, as Universal Ctags reports them
with --fields=+ne). Used for the before/after sizes of a restructuring:
run it on two commits (git worktree) and compare.

Usage: scripts/code-sizes.py [--top N] [ROOT]   (ROOT: the repository, default .)
"""
import argparse
import json
import os
import subprocess
import sys


def source_files(root):
    for top in ("renderer", "exporters"):
        for dirpath, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if name.endswith((".cpp", ".h", ".py")):
                    yield os.path.join(dirpath, name)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("root", nargs="?", default=".")
    ap.add_argument("--top", type=int, default=10)
    args = ap.parse_args()
    files = list(source_files(args.root))
    if not files:
        sys.exit(f"code-sizes: no sources under {args.root}/renderer or {args.root}/exporters")
    sizes = []
    for f in files:
        with open(f, encoding="utf-8", errors="replace") as fh:
            sizes.append((sum(1 for _ in fh), os.path.relpath(f, args.root)))
    print(f"files: {len(files)}, lines: {sum(n for n, _ in sizes)}")
    print(f"largest files (lines):")
    for n, f in sorted(sizes, reverse=True)[: args.top]:
        print(f"  {n:6d}  {f}")
    try:
        out = subprocess.run(["ctags", "--output-format=json", "--fields=+ne", "--kinds-C++=f", "--kinds-Python=f",
                              "-f", "-"] + files, capture_output=True, text=True, check=True, timeout=120).stdout
    except (OSError, subprocess.SubprocessError) as e:
        sys.exit(f"code-sizes: ctags (Universal Ctags) failed: {e}")
    funcs = []
    for line in out.splitlines():
        tag = json.loads(line)
        if "end" in tag and "line" in tag:
            funcs.append((tag["end"] - tag["line"] + 1, f"{os.path.relpath(tag['path'], args.root)}:{tag['line']} {tag['name']}"))
    print(f"longest functions (lines):")
    for n, f in sorted(funcs, reverse=True)[: args.top]:
        print(f"  {n:6d}  {f}")


if __name__ == "__main__":
    main()
