#!/usr/bin/env python3
"""Memory and graph size of a long run against the distance travelled (scripts/bench-long.sh).

Usage: python3 scripts/plot-long.py STATS_CSV GROUND_TRUTH_TUM RSS_TXT LAPS OUT_PNG

  STATS_CSV         the run's stats.csv (doc/system.md): one row per scan
  GROUND_TRUTH_TUM  the reference poses of the scans (distance travelled)
  RSS_TXT           lines "SECONDS KB": the run's resident memory sampled by the wall clock
  LAPS              how many times the path was driven (the laps are equal)

A sample's time is placed at the scan whose share of the run's processing time (tracking,
graph and map, from stats.csv) equals the sample's share of the run. Prints one row per lap:
distance at its end, graph nodes, peak memory, the slowest tracked scan and the slowest full
optimization during it, then the end of the run (final optimization and refinement); and
draws OUT_PNG: memory, graph nodes and full optimization times against distance, the first
lap (new shore) shaded apart from the revisits. Needs matplotlib (python3-matplotlib).
Graph nodes are the keyframes made less those merged into earlier nodes: the run folder's
graph.graph names them ("# kind=merged") and its keyframes.tum gives their stamps.
"""

import bisect
import csv
import math
import os
import sys
import tempfile


def fail(message):
    sys.exit("plot-long: " + message)


def read_stats(path):
    rows = []
    with open(path, newline="") as f:
        for n, row in enumerate(csv.DictReader(f), start=2):
            try:
                rows.append({
                    "t": float(row["timestamp"]),
                    "work": float(row["tracking_ms"]) + float(row["graph_ms"]) + float(row["map_ms"]),
                    "tracking": float(row["tracking_ms"]),
                    "graph": float(row["graph_ms"]),
                    "node": int(row["new_node"]),
                    "full": int(row["full_optimization"]),
                })
            except (KeyError, TypeError, ValueError) as e:
                fail(f"{path} line {n}: {e}")
    if not rows:
        fail(f"{path} has no scan")
    return rows


def read_columns(path, columns):
    out = []
    with open(path) as f:
        for n, line in enumerate(f, start=1):
            if not line.strip() or line.startswith("#"):
                continue
            parts = line.split()
            try:
                out.append(tuple(float(parts[c]) for c in columns))
            except (IndexError, ValueError):
                fail(f"{path} line {n}: expected numbers in columns {columns}")
    if not out:
        fail(f"{path} has no line")
    return out


def merged_stamps(run_dir):
    """Stamps of the keyframes merged into earlier nodes (none without the run's files)."""
    graph, keyframes = os.path.join(run_dir, "graph.graph"), os.path.join(run_dir, "keyframes.tum")
    if not (os.path.isfile(graph) and os.path.isfile(keyframes)):
        return []
    ids = []
    with open(graph) as f:
        for line in f:
            if line.startswith("EDGE_SE2 ") and "kind=merged" in line:
                ids.append(int(line.split()[2]))
    stamps = [t for (t,) in read_columns(keyframes, (0,))]
    try:
        return sorted(stamps[i] for i in ids)
    except IndexError:
        fail(f"{graph} merges a node that {keyframes} does not list")


def main():
    if len(sys.argv) != 6:
        fail("usage: plot-long.py STATS_CSV GROUND_TRUTH_TUM RSS_TXT LAPS OUT_PNG")
    stats_path, gt_path, rss_path, laps_text, png = sys.argv[1:]
    laps = int(laps_text)
    rows = read_stats(stats_path)
    gt = read_columns(gt_path, (0, 1, 2))
    rss = read_columns(rss_path, (0, 1))

    # Distance travelled at each scan, from the reference poses at or before its stamp.
    gt_t = [p[0] for p in gt]
    gt_d = [0.0]
    for a, b in zip(gt, gt[1:]):
        gt_d.append(gt_d[-1] + math.hypot(b[1] - a[1], b[2] - a[2]))
    dist = [gt_d[max(0, bisect.bisect_right(gt_t, r["t"] + 1e-6) - 1)] for r in rows]
    lap_length = gt_d[-1] / laps

    # Each memory sample at the scan of the same share of the work.
    work = []
    total = 0.0
    for r in rows:
        total += r["work"]
        work.append(total)
    t_end = rss[-1][0] if rss[-1][0] > 0 else 1.0
    rss_d = [dist[min(len(rows) - 1, bisect.bisect_left(work, t / t_end * total))] for t, _ in rss]
    rss_mb = [kb / 1024.0 for _, kb in rss]

    merged = merged_stamps(os.path.dirname(os.path.abspath(stats_path)))
    nodes, count = [], 0
    for r in rows:
        count += r["node"]
        nodes.append(count - bisect.bisect_right(merged, r["t"] + 1e-6))
    body = rows[:-1]  # the last row is the end of the run: final optimization and refinement

    print("| lap | distance at its end [m] | graph nodes | nodes added | peak memory [MB] | slowest tracked scan [ms] | full optimizations | slowest [ms] |")
    print("|---|---|---|---|---|---|---|---|")
    for k in range(laps):
        lo, hi = k * lap_length, (k + 1) * lap_length
        idx = [i for i, d in enumerate(dist[:-1]) if lo <= d < hi or (k == laps - 1 and d >= hi)]
        if not idx:
            continue
        mem = [m for d, m in zip(rss_d, rss_mb) if lo <= d < hi]
        full = [body[i]["graph"] for i in idx if body[i]["full"]]
        before = nodes[idx[0] - 1] if idx[0] > 0 else 0
        print(f"| {k + 1} | {dist[idx[-1]]:.0f} | {nodes[idx[-1]]} | {nodes[idx[-1]] - before} | "
              f"{max(mem) if mem else float('nan'):.0f} | {max(body[i]['tracking'] for i in idx):.1f} | "
              f"{len(full)} | {max(full) if full else 0:.0f} |")
    print(f"end of run (final optimization and refinement): {rows[-1]['graph']:.0f} ms; "
          f"peak memory sampled {max(rss_mb):.0f} MB")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 1, figsize=(9, 9), sharex=True)
    for ax in axes:
        ax.axvspan(0, lap_length, color="#e8f4e8", label="first lap: new shore")
        for k in range(1, laps):
            ax.axvline(k * lap_length, color="#cccccc", linewidth=0.8)
        ax.grid(alpha=0.3)
    axes[0].plot(rss_d, rss_mb, color="#c04000")
    axes[0].set_ylabel("resident memory [MB]")
    axes[0].legend(loc="upper left")
    axes[1].plot(dist, nodes, color="#2060a0")
    axes[1].set_ylabel("graph nodes")
    fx = [dist[i] for i, r in enumerate(body) if r["full"]]
    fy = [r["graph"] for r in body if r["full"]]
    axes[2].plot(fx, fy, "o", color="#8020a0", markersize=4)
    axes[2].set_ylabel("full optimization [ms]")
    axes[2].set_xlabel("distance travelled [m] (grey lines: the laps)")
    fig.suptitle(f"valley path driven {laps} times: memory and graph against distance")
    fig.tight_layout()
    out_dir = os.path.dirname(os.path.abspath(png))
    os.makedirs(out_dir, exist_ok=True)
    fd, tmp = tempfile.mkstemp(suffix=".png", dir=out_dir)
    os.close(fd)
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, png)
    print(f"plot: {png}")


if __name__ == "__main__":
    main()
