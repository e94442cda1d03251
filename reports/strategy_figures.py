"""The strategies study's figures and table for the report (called by make_report.py).

Records of `verity study strategies` with budgets carry, per BDPT strategy (s, t) of k = s + t − 2
bounces, the relative variance of its unweighted image (its estimate of the length-k image on
its own) and of its MIS-weighted contribution, and per length k BDPT's and a path tracer's;
all against r_k, BDPT's length-k image (validation/studies/strategies.h). This module draws:

- strategy_convergence.png: per k a log-log panel of relative variance against wall time;
- strategy_pyramid.png: the weighted strategy images, one row per k, as in Veach 1997,
  "Robust Monte Carlo Methods for Light Transport Simulation", ch. 10, fig. 10.3;
- the table of what MIS gains over the best single strategy, per k, at the largest budget.
"""
import math
import os
import sys
import statistics

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def _groups(records):
    """Strategies records with budgets, by scene, size, max bounces, budget kind, path tracer."""
    groups = {}
    for r in records:
        if r.get("study") != "strategies" or "lengths" not in r:
            continue
        key = (r["scene"], r["width"], r["height"], r["max_bounces"], r["budget_type"],
               r["path_tracer"]["integrator"])
        groups.setdefault(key, []).append(r)
    return [(k, groups[k]) for k in sorted(groups)]


def _suffix(i):
    return "" if i == 0 else f"_{i + 1}"


def _medians(rs, value):
    """(median wall seconds, median value) per budget; value(r) returns (seconds, y) or None."""
    pts = []
    for b in sorted({r["budget"] for r in rs}):
        vals = [value(r) for r in rs if r["budget"] == b]
        vals = [v for v in vals if v is not None and v[1] > 0]
        if vals:
            pts.append((statistics.median(v[0] for v in vals),
                        statistics.median(v[1] for v in vals)))
    return np.array(pts, float).reshape(-1, 2)


def _strategy(r, s, t):
    for st in r["strategies"]:
        if st["s"] == s and st["t"] == t:
            return st
    return None


def plot_convergence(key, rs, out_dir, name):
    scene, _, _, max_bounces, _, tracer = key
    ks = list(range(1, max_bounces + 1))
    if not ks:
        return None
    cols = min(3, len(ks))
    rows = math.ceil(len(ks) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.8 * cols, 4.0 * rows), squeeze=False)
    for ax in axes.flat[len(ks):]:
        ax.axis("off")
    for ax, k in zip(axes.flat, ks):
        for s in range(k + 2):
            t = k + 2 - s
            for weighted in (False, True):
                field = "rel_variance_weighted" if weighted else "rel_variance_unweighted"

                def value(r, s=s, t=t, field=field):
                    st = _strategy(r, s, t)
                    return None if st is None else (r["wall_seconds"], st[field])
                pts = _medians(rs, value)
                if len(pts):
                    ax.loglog(pts[:, 0], pts[:, 1], color=f"C{s}", marker="o", ms=3,
                              ls="-" if weighted else "--", lw=1,
                              label=f"({s}, {t})" if weighted else None)
        mis = _medians(rs, lambda r: (r["bdpt_lengths"]["wall_seconds"],
                                      r["lengths"][k]["rel_variance"]))
        pt = _medians(rs, lambda r: (r["path_tracer"]["wall_seconds"],
                                     r["lengths"][k]["path_tracer_rel_variance"]))
        if len(mis):
            ax.loglog(mis[:, 0], mis[:, 1], color="black", lw=2.5, marker="s", ms=4,
                      label="MIS sum (BDPT)")
        if len(pt):
            ax.loglog(pt[:, 0], pt[:, 1], color="0.55", lw=2.5, marker="^", ms=4, label=tracer)
        ax.set_title(f"{scene}: k = {k} bounce{'s' if k > 1 else ''}"
                     f"{' (direct light)' if k == 1 else ''}", fontsize=10)
        ax.set_xlabel("wall time (s)")
        ax.set_ylabel("relative variance")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6.5, ncol=2, title="solid: weighted, dashed: unweighted",
                  title_fontsize=6.5)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, name), dpi=110)
    plt.close(fig)
    return name


def _srgb(x):
    x = np.clip(x, 0, 1)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def plot_pyramid(key, rs, out_dir, name):
    """Rows k = 0 … max bounces, row k holding its k + 2 weighted strategy images, centred."""
    with_images = [r for r in rs if "strategy_images" in r]
    if not with_images:
        return None
    r = max(with_images, key=lambda r: (r["budget"], -r["run"]))
    path = os.path.join(r["_dir"], r["strategy_images"])
    if not os.path.exists(path):
        # The images are large (11 MB per 256² scene) and not committed with the records.
        print(f"note: no strategy pyramid for {key[0]}: {path} is missing (rerun the "
              f"strategies study's largest budget to make it)", file=sys.stderr)
        return None
    images = np.load(path).astype(np.float32)  # (strategies, height, width, RGB)
    order = {(st["s"], st["t"]): i for i, st in enumerate(r["strategies"])}
    kmax = r["max_bounces"]
    cols = kmax + 2
    h, w = images.shape[1:3]
    cell = 1.5
    height = cell * (kmax + 1) * h / w * 1.2 + 0.4
    fig = plt.figure(figsize=(cell * cols, height))
    grid = fig.add_gridspec(kmax + 1, 2 * cols, hspace=0.3, wspace=0.05, left=0.05, right=0.99,
                            bottom=0.01, top=1 - 0.45 / height)
    for k in range(kmax + 1):
        row = [images[order[(s, k + 2 - s)]] for s in range(k + 2)]
        # One exposure per row: the row's sum (BDPT's length-k image) at the 99th percentile
        # of its lit pixels maps to white, so that the dim long paths are seen (and the light,
        # under 1% of the pixels at k = 0, is not clipped); the factor is printed.
        lit = np.sum(row, axis=0).max(axis=2)
        lit = lit[lit > 0]
        top = np.percentile(lit, 99) if lit.size else 0
        scale = 1 / top if top > 0 else 1
        offset = cols - (k + 2)
        for s, img in enumerate(row):
            t = k + 2 - s
            ax = fig.add_subplot(grid[k, offset + 2 * s: offset + 2 * s + 2])
            ax.imshow(_srgb(img * scale), interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            share = r["strategies"][order[(s, t)]]["share"]
            ax.set_title(f"({s}, {t}) {100 * share:.1f}%", fontsize=7, pad=2)
            if s == 0:
                ax.set_ylabel(f"k = {k}\n×{scale:.3g}", fontsize=7)
    fig.suptitle(f"{r['scene']}: MIS-weighted strategy images, {r['spp']} spp "
                 f"(row k: k bounces, (s, t) with s + t = k + 2)", fontsize=8,
                 y=1 - 0.1 / height)
    # Enough dots for one image pixel per dot up to 512 wide, so that noise is not aliased.
    fig.savefig(os.path.join(out_dir, name), dpi=max(130, min(w, 512) / cell),
                bbox_inches="tight")
    plt.close(fig)
    return name


def mis_gain_rows(key, rs):
    """Per k at the largest budget (medians over runs): the best unweighted strategy against
    BDPT's MIS combination and the path tracer."""
    scene, _, _, max_bounces, budget_type, tracer = key
    top = max(r["budget"] for r in rs)
    at = [r for r in rs if r["budget"] == top]
    rows = []
    for k in range(max_bounces + 1):
        singles = []
        for s in range(k + 2):
            v = [st["rel_variance_unweighted"] for r in at
                 for st in [_strategy(r, s, k + 2 - s)] if st and st["pixels"] > 0]
            if v:
                singles.append((statistics.median(v), s, k + 2 - s))
        if not singles:
            continue
        best, s, t = min(singles)
        mis = statistics.median(r["lengths"][k]["rel_variance"] for r in at)
        pt = statistics.median(r["lengths"][k]["path_tracer_rel_variance"] for r in at)
        rows.append([scene, f"{top:g} {budget_type}", k, f"({s}, {t})", f"{best:.3g}",
                     f"{mis:.3g}", f"{best / mis:.2f}×" if mis > 0 else "n/a",
                     f"{pt:.3g}", f"{pt / mis:.2f}×" if mis > 0 else "n/a"])
    return rows


def add(records, out_dir):
    """(figures, tables) for make_report.py: figures as (file, caption), tables as (title,
    header, rows, note)."""
    figures, rows = [], []
    for i, (key, rs) in enumerate(_groups(records)):
        scene, _, _, max_bounces, budget_type, tracer = key
        f = plot_convergence(key, rs, out_dir, f"strategy_convergence{_suffix(i)}.png")
        if f:
            figures.append((f, f"{scene}: relative variance against wall time (log-log, medians "
                               f"over runs) per path length k (bounces), against r_k = BDPT's "
                               f"length-k image: each strategy (s, t) unweighted (dashed: its "
                               f"own estimate of the length-k image) "
                               f"and MIS-weighted (solid: its part of the image), BDPT's MIS "
                               f"sum and {tracer}'s length-k image, each averaged over the pixels "
                               f"where r_k is non-zero. Strategy curves are timed "
                               f"by the whole BDPT render that records them all."))
        f = plot_pyramid(key, rs, out_dir, f"strategy_pyramid{_suffix(i)}.png")
        if f:
            figures.append((f, f"{scene}: the MIS-weighted image of every BDPT strategy (s, t), "
                               f"s light and t camera vertices, one row per path length k "
                               f"(bounces; Veach's length k + 1), as in Veach 1997, fig. 10.3; "
                               f"each with its share of the image. Each row is exposed on its "
                               f"own scale (×factor), so that its 99th percentile is white."))
        rows += mis_gain_rows(key, rs)
    tables = []
    if rows:
        tables.append(("What MIS gains over the best single strategy",
                       ["scene", "budget", "bounces k", "best strategy (s, t)",
                        "its rel. variance (unweighted)", "MIS (BDPT) rel. variance",
                        "MIS gain", "path tracer rel. variance", "path tracer / MIS"], rows,
                       "At the largest budget, medians over runs; relative variance = mean over "
                       "pixels and channels of the variance of the pixel mean / (r_k² + ε), "
                       "r_k = BDPT's length-k image, over the pixels where r_k is non-zero. The "
                       "best strategy is the unweighted one of least variance. At spp budgets "
                       "the gains are per sample."))
    return figures, tables
