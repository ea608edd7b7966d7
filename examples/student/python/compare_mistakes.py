#!/usr/bin/env python3
"""Render a scene with single (or combined) mistakes and ask RasterLab's
`compare` what it sees in each image.

    python3 compare_mistakes.py --cli build/bin/rasterlab-cli \\
        --camera C.cfg --lighting L.txt --object O.byu [--size 800x600] \\
        [--outdir DIR] [--only --flip-y ...]

Prints one line a case: the switches, the differing pixels, the
mistakes compare lists (name, share of the difference it removes, in the
order compare applied them) and the share left unexplained.  Runs one
render at a time, to keep the machine free.
"""

import argparse
import json
import os
import subprocess
import sys

import rasterizer

HERE = os.path.dirname(os.path.abspath(__file__))

CASES = [[]] + [[flag] for flag, _ in rasterizer.MISTAKES] + [
    ["--color-offset", "1"], ["--color-offset", "-8"],
    ["--color-scale", "0.8"], ["--flat-color", "0,200,0"]]


def run_case(args, switches, index):
    name = "plain" if not switches else \
        "_".join(s[2:] if s.startswith("--") else s
                 for s in switches).replace(",", "-")
    image = os.path.join(args.outdir, f"{index:02d}_{name}.png")
    scene = ["--camera", args.camera, "--lighting", args.lighting,
             "--object", args.object, "--size", args.size]
    subprocess.run([sys.executable, os.path.join(HERE, "rasterizer.py"),
                    *scene, "--output", image, *switches], check=True)
    done = subprocess.run([args.cli, "compare", *scene, "--image", image,
                           "--format", "json"], capture_output=True,
                          text=True)
    if done.returncode != 0:
        return name, f"exit {done.returncode}: {done.stderr.strip()}"
    report = json.loads(done.stdout)
    found = ", ".join(f"{d['mistake']} {100 * d['share']:.0f}%"
                      for d in report.get("diagnosis", [])) or "-"
    largest = max(report["largestDifference"][:3])
    unexplained = 100 * report["unexplained"]["share"]
    unlit = "unlit, coverage: " if "unlit" in report else ""
    return name, (f"{report['differing']} differ (largest {largest}): "
                  f"{unlit}{found}; unexplained {unexplained:.0f}%")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for name in ("--cli", "--camera", "--lighting", "--object"):
        p.add_argument(name, required=True)
    p.add_argument("--size", default="800x600")
    p.add_argument("--outdir", default="mistakes")
    p.add_argument("--only", nargs=argparse.REMAINDER,
                   help="one case with these switches instead of all")
    args = p.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    cases = [args.only] if args.only is not None else CASES
    for index, switches in enumerate(cases):
        name, text = run_case(args, switches, index)
        print(f"{name}: {text}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
