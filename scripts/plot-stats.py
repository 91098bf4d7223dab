#!/usr/bin/env python3
"""The paper's Fig. 6 and Fig. 7 from a run's per-scan statistics (stats.csv).

Usage: python3 scripts/plot-stats.py RUN_DIR/stats.csv OUT_DIR [--x time|scan]

  OUT_DIR/fig6.png  execution time of each thread per scan [ms]: matching, tracking, graph
                    optimization, map construction (the last two only at the scans that
                    gave their thread work)
  OUT_DIR/fig7.png  sum of active squared residuals of the latest graph optimization (eq. 11;
                    above, log scale, with the scan matches' own sum, the full optimizations
                    as red stars labelled with their value and the scans with accepted loop
                    edges as purple lines) and the number of valid rays (below)

stats.csv has a header line and one comma-separated row per input scan:
  scan,timestamp,source,valid_rays,correspondences,match_sq_residuals,active_sq_residuals,
  match_ms,tracking_ms,graph_ms,map_ms,keyframe,new_node,loops,full_optimization,switched_off,
  ambiguous,prior_decided
(doc/system.md describes each column; a file written before prior_decided existed, without
that last column, is read too).
A missing or malformed value is an error naming its line and column. Each figure is written
under a temporary name in OUT_DIR (created if missing) and renamed. Needs matplotlib
(Debian: python3-matplotlib, installed by scripts/install-deps.sh).
"""

import argparse
import math
import os
import re
import sys
import tempfile

COLUMNS = ["scan", "timestamp", "source", "valid_rays", "correspondences", "match_sq_residuals",
           "active_sq_residuals", "match_ms", "tracking_ms", "graph_ms", "map_ms", "keyframe",
           "new_node", "loops", "full_optimization", "switched_off", "ambiguous", "prior_decided"]
SOURCES = ("first", "match", "searched", "odometry", "constant_motion")
INT_RE = re.compile(r"[0-9]+")
FLOAT_RE = re.compile(r"[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?")


class StatsError(Exception):
    pass


def count(text):
    """A non-negative integer."""
    if not INT_RE.fullmatch(text):
        raise ValueError("is not a non-negative integer")
    return int(text)


def flag(text):
    if text not in ("0", "1"):
        raise ValueError("is not 0 or 1")
    return int(text)


def number(text):
    if not FLOAT_RE.fullmatch(text) or not math.isfinite(float(text)):
        raise ValueError("is not a finite number")
    return float(text)


def duration(text):
    """A non-negative number (times, sums of squares)."""
    x = number(text)
    if x < 0:
        raise ValueError("is negative")
    return x


def source(text):
    if text not in SOURCES:
        raise ValueError("is not one of " + "|".join(SOURCES))
    return text


PARSERS = {"scan": count, "timestamp": number, "source": source, "valid_rays": count,
           "correspondences": count, "match_sq_residuals": duration,
           "active_sq_residuals": duration, "match_ms": duration,
           "tracking_ms": duration, "graph_ms": duration, "map_ms": duration,
           "keyframe": count, "new_node": flag, "loops": count, "full_optimization": flag,
           "switched_off": count, "ambiguous": count, "prior_decided": count}


def read_stats(path):
    """Columns of `path` as lists, checked; raises StatsError naming the line."""
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
    except (OSError, UnicodeDecodeError) as e:
        raise StatsError(f"{path}: cannot read: {e}")
    if not lines:
        raise StatsError(f"{path}: empty file (expected the header {','.join(COLUMNS)})")
    header = [h.strip() for h in lines[0].split(",")]
    if header not in (COLUMNS, COLUMNS[:-1]):  # the second: written before prior_decided
        raise StatsError(f"{path}:1: header is '{lines[0]}', expected '{','.join(COLUMNS)}'")
    cols = {c: [] for c in header}
    for lineno, line in enumerate(lines[1:], start=2):
        if not line.strip():
            continue
        fields = [v.strip() for v in line.split(",")]
        if len(fields) != len(header):
            raise StatsError(f"{path}:{lineno}: {len(fields)} values, expected {len(header)}")
        for name, text in zip(header, fields):
            if text == "":
                raise StatsError(f"{path}:{lineno}: column '{name}': missing value")
            try:
                cols[name].append(PARSERS[name](text))
            except ValueError as e:
                raise StatsError(f"{path}:{lineno}: column '{name}': '{text}' {e}")
        if len(cols["scan"]) > 1 and cols["scan"][-1] <= cols["scan"][-2]:
            raise StatsError(f"{path}:{lineno}: scan {cols['scan'][-1]} does not follow "
                             f"scan {cols['scan'][-2]}")
    if not cols["scan"]:
        raise StatsError(f"{path}: no scan rows after the header")
    return cols


def only_where(values, keep):
    """`values` where `keep` holds, NaN elsewhere (a gap in the plotted line)."""
    return [v if k else math.nan for v, k in zip(values, keep)]


def fig6(plt, cols, x, xlabel):
    series = [("matching", cols["match_ms"], None), ("tracking", cols["tracking_ms"], None),
              ("graph optimization", cols["graph_ms"], [v > 0 for v in cols["graph_ms"]]),
              ("map construction", cols["map_ms"], [v > 0 for v in cols["map_ms"]])]
    fig, axes = plt.subplots(len(series), 1, sharex=True, figsize=(10, 9))
    for ax, (name, values, worked) in zip(axes, series):
        active = values if worked is None else [v for v, w in zip(values, worked) if w]
        if worked is None:
            ax.plot(x, values, lw=0.6)
        else:
            ax.plot(x, only_where(values, worked), ".", ms=2.5)
        if active:
            mean = sum(active) / len(active)
            ax.axhline(mean, color="k", lw=0.8, ls="--")
            ax.set_title(f"{name}: mean {mean:.2f} ms, max {max(active):.2f} ms "
                         f"over {len(active)} scans", fontsize=9)
        else:
            ax.set_title(f"{name}: no work", fontsize=9)
        ax.set_ylabel("ms")
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel(xlabel)
    fig.suptitle("Execution time of each thread per scan")
    fig.tight_layout()
    return fig


def fig7(plt, cols, x, xlabel):
    """Log scale above: the graph's sum (about 1e4 on lake-short) and the scan matches' (about
    0.3 m^2) differ by orders of magnitude, and a full optimization's sum (all edges active,
    1e5) would flatten a linear axis. Full optimizations are drawn apart, as labelled stars."""
    matched = [s in ("match", "searched") for s in cols["source"]]
    full = [f == 1 for f in cols["full_optimization"]]
    # The column carries the latest optimization's sum forward: the scans after a full
    # optimization repeat its sum until the next optimization changes it.
    from_full, last = [], None
    for v, f in zip(cols["active_sq_residuals"], full):
        last = v if f else (last if last is not None and v == last else None)
        from_full.append(last is not None)
    positive = lambda values, keep: [v if k and v > 0 else math.nan for v, k in zip(values, keep)]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(10, 6.5),
                                      gridspec_kw={"height_ratios": [3, 2]})
    top.set_yscale("log")
    top.plot(x, positive(cols["active_sq_residuals"], [not f for f in from_full]), lw=0.8,
             color="tab:blue", label="graph, sliding window: sum of w r^2 (eq. 11)")
    fx = [xi for xi, f in zip(x, full) if f]
    fy = [v for v, f in zip(cols["active_sq_residuals"], full) if f]
    if fx:
        top.plot(fx, [max(v, 1e-12) for v in fy], "*", ms=11, color="tab:red",
                 label="graph, full optimization (whole graph)")
        labelled = -math.inf  # one label where stars crowd (within 4% of the axis)
        for xi, v in zip(fx, fy):
            if xi - labelled < 0.04 * (max(x) - min(x)):
                continue
            labelled = xi
            top.annotate(f"{v:.3g}", (xi, max(v, 1e-12)), textcoords="offset points",
                         xytext=(-6, -4), ha="right", va="top", fontsize=8, color="tab:red")
    top.plot(x, positive(cols["match_sq_residuals"], matched), lw=0.5, alpha=0.8,
             color="tab:orange", label="scan match: sum of squared distances [m^2]")
    top.set_ylabel("sum of squared residuals (log)")
    loops = [xi for xi, n in zip(x, cols["loops"]) if n > 0]
    for i, xi in enumerate(loops):
        top.axvline(xi, color="tab:purple", lw=0.6, alpha=0.5,
                    label="scan with accepted loop edges" if i == 0 else None)
    top.legend(fontsize=8, loc="best", framealpha=0.9)
    top.set_title(f"{sum(matched)} of {len(matched)} scans matched; loop edges accepted: "
                  f"{sum(cols['loops'])}; full optimizations: {len(fx)}", fontsize=9)
    bottom.plot(x, cols["valid_rays"], lw=0.6, color="tab:green")
    bottom.set_ylabel("valid rays")
    bottom.set_xlabel(xlabel)
    for ax in (top, bottom):
        ax.grid(alpha=0.3, which="major")
    fig.suptitle("Sum of active squared residuals (above, log scale) vs. number of valid rays (below)")
    fig.tight_layout()
    return fig


def save_atomically(fig, path):
    fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", suffix=".tmp.png",
                               dir=os.path.dirname(path))
    try:
        with os.fdopen(fd, "wb") as f:
            fig.savefig(f, format="png", dpi=120)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def main():
    ap = argparse.ArgumentParser(description="Fig. 6 and Fig. 7 of the paper from stats.csv")
    ap.add_argument("stats", help="RUN_DIR/stats.csv")
    ap.add_argument("out_dir", help="folder for fig6.png and fig7.png (created if missing)")
    ap.add_argument("--x", choices=("time", "scan"), default="time",
                    help="horizontal axis: seconds since the first scan (default) or scan index")
    args = ap.parse_args()
    try:
        cols = read_stats(args.stats)
    except StatsError as e:
        sys.exit(f"plot-stats: {e}")
    if os.path.exists(args.out_dir) and not os.path.isdir(args.out_dir):
        sys.exit(f"plot-stats: output '{args.out_dir}' exists and is not a folder")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit(f"plot-stats: matplotlib is not installed for {sys.executable}: "
                 "install python3-matplotlib (scripts/install-deps.sh)")
    os.makedirs(args.out_dir, exist_ok=True)

    if args.x == "time":
        t0 = cols["timestamp"][0]
        x, xlabel = [t - t0 for t in cols["timestamp"]], "time since the first scan [s]"
    else:
        x, xlabel = cols["scan"], "scan"
    for name, make in (("fig6.png", fig6), ("fig7.png", fig7)):
        fig = make(plt, cols, x, xlabel)
        path = os.path.join(args.out_dir, name)
        save_atomically(fig, path)
        plt.close(fig)
        print(f"plot-stats: wrote {path}")


if __name__ == "__main__":
    main()
