#!/usr/bin/env python3
"""Draws libslam's modules in their layers, with an arrow from each module to the modules it
links that it does not already reach through another one (the transitive reduction: every other
link follows the arrows).

Reads the table CMake writes when it configures (BUILD_DIR/swslam_modules.txt, from
libslam/CMakeLists.txt: module, layer, linked modules) and the number of files and lines of each
module folder, and writes a PNG (doc/architecture.png is made by this script).

Usage: python3 scripts/plot-modules.py [BUILD_DIR] [OUT.png]   (default: build doc/architecture.png)
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import FancyArrowPatch, FancyBboxPatch  # noqa: E402

LAYER_NAMES = {
    1: "foundations",
    2: "input, simulation, matching, graph, map",
    3: "correlative search",
    4: "tracking, loops, benchmarks",
    5: "evaluation, the three threads",
    6: "the programs' logic",
    7: "programs",
}


def read_table(path):
    modules = {}
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words or words[0].startswith("#"):
                continue
            modules[words[0]] = (int(words[1]), words[2:])
    return modules


def module_size(src, name):
    folder = os.path.join(src, "libslam", "swslam", name)
    files = [f for f in os.listdir(folder) if f.endswith((".h", ".cpp"))]
    lines = sum(sum(1 for _ in open(os.path.join(folder, f))) for f in files)
    return len(files), lines


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    out = sys.argv[2] if len(sys.argv) > 2 else "doc/architecture.png"
    src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    modules = read_table(os.path.join(build, "swslam_modules.txt"))
    top = max(layer for layer, _ in modules.values()) + 1
    modules["apps/"] = (top, ["app"])

    def reaches(a, b, skip):  # b reachable from a without the direct link a -> skip
        stack = [d for d in modules[a][1] if d != skip]
        seen = set()
        while stack:
            n = stack.pop()
            if n == b:
                return True
            if n not in seen:
                seen.add(n)
                stack.extend(modules[n][1])
        return False

    drawn = {n: [d for d in deps if not reaches(n, d, d)] for n, (_, deps) in modules.items()}

    by_layer = {}
    for name, (layer, _) in modules.items():
        by_layer.setdefault(layer, []).append(name)
    # Keep a module above the middle of what it links, so that arrows stay short.
    position = {}
    for layer in sorted(by_layer):
        names = by_layer[layer]

        def centre(n):
            xs = [position[d][0] for d in modules[n][1] if d in position]
            return sum(xs) / len(xs) if xs else 0.0

        names.sort(key=lambda n: (centre(n), n))
        width = 2.6
        if layer == 1:
            xs = [(i - (len(names) - 1) / 2) * width for i in range(len(names))]
        else:  # each near the middle of what it links, at least a box apart
            wanted = [centre(n) for n in names]
            xs = []
            for w in wanted:
                xs.append(max(w, xs[-1] + width) if xs else w)
            shift = sum(wanted) / len(wanted) - sum(xs) / len(xs)
            xs = [x + shift for x in xs]
        for n, x in zip(names, xs):
            position[n] = (x, (layer - 1) * 1.6)

    fig, ax = plt.subplots(figsize=(12, 8.5))
    box_w, box_h = 2.0, 0.7
    for name in modules:
        x, y = position[name]
        for d in drawn[name]:
            dx, dy = position[d]
            ax.add_patch(FancyArrowPatch((x, y - box_h / 2), (dx, dy + box_h / 2), arrowstyle="-|>",
                                         mutation_scale=10, color="0.55", lw=0.8,
                                         connectionstyle="arc3,rad=0.05", zorder=1))
    for name, (layer, deps) in modules.items():
        x, y = position[name]
        colour = "#dfe9f5" if name != "apps/" else "#f3e3c8"
        ax.add_patch(FancyBboxPatch((x - box_w / 2, y - box_h / 2), box_w, box_h,
                                    boxstyle="round,pad=0.02", fc=colour, ec="0.25", zorder=2))
        if name == "apps/":
            label, detail = "apps/", "thin programs"
        else:
            files, lines = module_size(src, name)
            label, detail = name, f"{files} files, {lines} lines"
        ax.text(x, y + 0.1, label, ha="center", va="center", fontsize=11, weight="bold", zorder=3)
        ax.text(x, y - 0.17, detail, ha="center", va="center", fontsize=7.5, color="0.3", zorder=3)
    xmin = min(p[0] for p in position.values()) - 1.5
    for layer in sorted(by_layer):
        y = (layer - 1) * 1.6
        ax.text(xmin - 0.3, y, f"{layer}  {LAYER_NAMES.get(layer, '')}", ha="right", va="center",
                fontsize=9, color="0.2")
        ax.axhline(y - 0.8, color="0.9", lw=0.6, zorder=0)
    ax.set_xlim(xmin - 4.6, max(p[0] for p in position.values()) + 1.5)
    ax.set_ylim(-0.9, (top - 1) * 1.6 + 0.9)
    ax.set_axis_off()
    ax.set_title("libslam's modules by layer: each links only modules of lower layers\n"
                 "(an arrow for each link not implied by the others)", fontsize=12)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"plot-modules: {len(modules) - 1} modules in {top - 1} layers -> {out}")


if __name__ == "__main__":
    main()
