#!/usr/bin/python3
"""Study report for Verity: plots (matplotlib) and an HTML page and Markdown summary.

Run by `verity report`, which first writes summary.json (fits, efficiencies, speed-ups,
computed in C++: validation/studies/summary.cpp). This script only draws and formats:

    /usr/bin/python3 reports/make_report.py --summary OUT/summary.json --out OUT results.jsonl...

Relative-error images are NumPy arrays (.npy) saved by `verity study convergence` at the
largest budget; their paths in the records are relative to the results file's folder.
"""
import argparse
import collections
import html
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

import strategy_figures  # noqa: E402  (this folder: the strategies study's figures)


def read_records(paths):
    records = []
    for path in paths:
        with open(path) as f:
            for line in f:
                line = line.strip()
                if not line:
                    continue
                try:
                    r = json.loads(line)
                except json.JSONDecodeError:
                    continue  # a line cut off by an interrupted study
                r["_dir"] = os.path.dirname(os.path.abspath(path))
                records.append(r)
    return records


def fmt_fit(f):
    if f is None or f.get("slope") is None:
        return "n/a"
    if f.get("slope_low") is None:
        return f"{f['slope']:.3f}"
    return f"{f['slope']:.3f} [{f['slope_low']:.3f}, {f['slope_high']:.3f}]"


def covers(f, value=-1.0):
    if f is None or f.get("slope_low") is None:
        return "n/a"
    return "yes" if f["slope_low"] <= value <= f["slope_high"] else "**no**"


def scenes_of(records, study):
    return sorted({r["scene"] for r in records if r.get("study") == study})


def standard_error(values):
    """The standard error of the mean (0 for fewer than two values)."""
    if len(values) < 2:
        return 0.0
    return float(np.std(values, ddof=1) / math.sqrt(len(values)))


def fmt_seconds(a):
    """A time-to-accuracy entry of summary.json as table text."""
    if a["status"] == "reached":
        return f"{a['seconds']:.3g} s [{a['seconds_low']:.3g}, {a['seconds_high']:.3g}]"
    if a["status"] == "not reached" and a.get("seconds") is not None:
        return f"not reached (line: {a['seconds']:.3g} s)"
    return a["status"]


def accuracy_table(summary):
    """The table the report opens with: wall time to each relative MSE target."""
    conv = [g for g in summary.get("convergence", []) if g.get("time_to_accuracy")]
    if not conv:
        return None
    conf = int(round(100 * summary.get("confidence", 0.95)))
    targets = [a["target_rel_mse"] for a in conv[0]["time_to_accuracy"]]
    rows = []
    for g in sorted(conv, key=lambda g: (g["scene"], g["threads"], g["integrator"])):
        rows.append([g["scene"], f"{g['width']}×{g['height']}", g["integrator"], g["threads"],
                     g["runs"], len(g["budgets"])]
                    + [fmt_seconds(a) for a in g["time_to_accuracy"]])
    header = ["scene", "size", "integrator", "threads", "runs", "budgets"] + [
        f"time to relMSE {t:g} [{conf}% CI]" for t in targets]
    note = (f"Wall seconds at which the line fitted to log mean relMSE against log mean wall "
            f"time (one point per budget, the mean over its runs) reaches the target; the "
            f"interval is the inverse-prediction (calibration) interval of that time at {conf}% "
            f"(Draper & Smith, section 3.2). \"not reached\": the target lies below every "
            f"mean measured, so the line would be extrapolated (its value is shown); \"before "
            f"the smallest budget\": every budget already reached it.")
    return ("Time to accuracy", header, rows, note)


def equal_time_table(summary):
    """Every integrator's relative MSE at the same wall-clock budget."""
    entries = summary.get("equal_time", [])
    if not entries:
        return None
    names = sorted({n for e in entries for n in e["integrators"]})
    rows = []
    for e in entries:
        cells = []
        for n in names:
            v = e["integrators"].get(n)
            if v is None:
                cells.append("—")
                continue
            se = v.get("rel_mse_std_error")
            cells.append(f"{v['mean_rel_mse']:.3g} ± {se:.2g}" if se is not None
                         else f"{v['mean_rel_mse']:.3g}")
        best = min(e["integrators"].items(), key=lambda kv: kv[1]["mean_rel_mse"])[0]
        rows.append([e["scene"], e["threads"], f"{e['seconds']:g} s"] + cells + [best])
    return ("Equal time", ["scene", "threads", "budget"] + [f"relMSE {n}" for n in names]
            + ["lowest"], rows,
            "Mean relative MSE over the runs at each time budget ± its standard error; the "
            "same seconds for every integrator.")


def plot_error(conv, out_dir, x_key, x_label, file_name, fits):
    """One panel per (scene, integrator); one curve per thread count."""
    panels = sorted({(r["scene"], r["integrator"]) for r in conv})
    if not panels:
        return None
    cols = min(3, len(panels))
    rows = math.ceil(len(panels) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.6 * cols, 3.8 * rows), squeeze=False)
    for ax, (scene, integ) in zip(axes.flat, panels):
        runs = [r for r in conv if r["scene"] == scene and r["integrator"] == integ]
        curves = sorted({(r["threads"], r["budget_type"]) for r in runs})
        kinds = {k for _, k in curves}
        for i, (threads, kind) in enumerate(curves):
            rs = [r for r in runs if r["threads"] == threads and r["budget_type"] == kind
                  and r["rel_mse"] > 0]
            color = f"C{i}"
            xs = np.array([r[x_key] for r in rs], float)
            ys = np.array([r["rel_mse"] for r in rs], float)
            ax.scatter(xs, ys, s=9, alpha=0.45, color=color,
                       marker="o" if kind == "spp" else "^")
            by_budget = collections.defaultdict(list)
            for r in rs:
                by_budget[r["budget"]].append(r)
            groups = [v for _, v in sorted(by_budget.items())]
            mx = [np.mean([r[x_key] for r in v]) for v in groups]
            my = [np.mean([r["rel_mse"] for r in v]) for v in groups]
            sx = [standard_error([r[x_key] for r in v]) for v in groups]
            sy = [standard_error([r["rel_mse"] for r in v]) for v in groups]
            fit = fits.get((scene, integ, threads, kind))
            label = f"{threads} thread{'s' if threads != 1 else ''}"
            if len(kinds) > 1:
                label += f" ({'spp' if kind == 'spp' else 'time'} budgets)"
            if fit and fit.get("slope") is not None:
                label += f", slope {fmt_fit(fit)}"
            ax.errorbar(mx, my, xerr=sx, yerr=sy, fmt="-o", color=color, ms=3, capsize=2,
                        lw=1, label=label)
        # A slope −1 guide through the first curve's smallest budget.
        if runs:
            x0 = min(r[x_key] for r in runs if r[x_key] > 0)
            x1 = max(r[x_key] for r in runs)
            y0 = np.median([r["rel_mse"] for r in runs if r[x_key] <= x0 * 1.5])
            ax.plot([x0, x1], [y0, y0 * x0 / x1], "k--", lw=0.8, label="slope −1")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(x_label)
        ax.set_ylabel("relative MSE")
        ax.set_title(f"{scene}: {integ}", fontsize=10)
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(panels):]:
        ax.set_visible(False)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, file_name), dpi=110)
    plt.close(fig)
    return file_name


def plot_efficiency(summary, out_dir):
    groups = summary.get("convergence", [])
    if not groups:
        return None
    scenes = sorted({g["scene"] for g in groups})
    n_integ = len({g["integrator"] for g in groups})
    fig, axes = plt.subplots(1, len(scenes), figsize=((1.4 * n_integ + 2.5) * len(scenes), 4),
                             squeeze=False)
    for ax, scene in zip(axes.flat, scenes):
        gs = [g for g in groups if g["scene"] == scene]
        integs = sorted({g["integrator"] for g in gs})
        series = sorted({(g["threads"], g["budget_type"]) for g in gs})
        kinds = {k for _, k in series}
        width = 0.8 / len(series)
        for j, (t, kind) in enumerate(series):
            vals = []
            for integ in integs:
                g = [g for g in gs if g["integrator"] == integ and g["threads"] == t
                     and g["budget_type"] == kind]
                vals.append(g[0]["efficiency"] if g else 0)
            label = f"{t} thread{'s' if t != 1 else ''}"
            if len(kinds) > 1:
                label += f" ({'spp' if kind == 'spp' else 'time'} budgets)"
            bars = ax.bar(np.arange(len(integs)) + (j - (len(series) - 1) / 2) * width, vals,
                          width, label=label, color=f"C{j}")
            # The value on each bar, so that one far below the best still reads.
            ax.bar_label(bars, fmt="%.3g", fontsize=6)
        ax.set_xticks(np.arange(len(integs)))
        ax.set_xticklabels(integs, rotation=20, ha="right", fontsize=8)
        # Bars on a linear axis from zero: their heights compare as the efficiencies do (a log
        # axis with a cut baseline makes a 1.9× gap look several times larger).
        ax.set_ylim(bottom=0)
        ax.set_ylabel("efficiency 1 / (relMSE · seconds)")
        ax.set_title(f"{scene}: efficiency at the largest budget\n(median over runs)", fontsize=10)
        ax.grid(True, axis="y", alpha=0.25)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "efficiency.png"), dpi=110)
    plt.close(fig)
    return "efficiency.png"


def plot_speedup(summary, out_dir):
    rows = summary.get("speedup", [])
    if not rows:
        return None
    scenes = sorted({r["scene"] for r in rows})
    fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 4), squeeze=False)
    for ax, scene in zip(axes.flat, scenes):
        rs = [r for r in rows if r["scene"] == scene]
        all_threads = sorted({r["threads"] for r in rs})
        base = min(all_threads)
        ax.plot(all_threads, [t / base for t in all_threads], "k--", lw=0.8, label="ideal")
        for i, integ in enumerate(sorted({r["integrator"] for r in rs})):
            pts = sorted((r["threads"], r["speedup"]) for r in rs if r["integrator"] == integ)
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "-o", color=f"C{i}", ms=4,
                    label=integ)
        ax.set_xscale("log", base=2)
        ax.set_yscale("log", base=2)
        ax.set_xticks(all_threads)
        ax.set_xticklabels([str(t) for t in all_threads])
        ax.set_xlabel("threads")
        ax.set_ylabel(f"speed-up over {base} thread{'s' if base != 1 else ''} (median times)")
        ax.set_title(f"{scene}: speed-up", fontsize=10)
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "speedup.png"), dpi=110)
    plt.close(fig)
    return "speedup.png"


def plot_error_images(conv, out_dir):
    """False colour: per-pixel relative RMS error sqrt(mean_c (x − r)² / (r² + ε)), log scale."""
    items = []
    for r in conv:
        if "error_image" in r:
            path = os.path.join(r["_dir"], r["error_image"])
            if os.path.exists(path):
                items.append((r, np.load(path)))
    if not items:
        return None
    items.sort(key=lambda it: (it[0]["scene"], it[0]["integrator"]))
    positive = np.concatenate([img[img > 0].ravel() for _, img in items])
    if positive.size == 0:
        return None
    lo, hi = np.percentile(positive, 1), np.percentile(positive, 99.5)
    lo = max(lo, hi * 1e-4)
    cols = min(4, len(items))
    rows = math.ceil(len(items) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.6 * cols, 3.4 * rows), squeeze=False)
    im = None
    for ax, (r, img) in zip(axes.flat, items):
        im = ax.imshow(np.clip(img, lo, hi), cmap="inferno", norm=LogNorm(vmin=lo, vmax=hi),
                       interpolation="nearest")
        unit = "spp" if r["budget_type"] == "spp" else "s"
        ax.set_title(f"{r['integrator']}\n{r['scene']}, {r['budget']:g} {unit}, "
                     f"relMSE {r['rel_mse']:.3g}", fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
    for ax in list(axes.flat)[len(items):]:
        ax.set_visible(False)
    fig.colorbar(im, ax=list(axes.flat), shrink=0.85,
                 label="relative RMS error")
    fig.savefig(os.path.join(out_dir, "relative_error_images.png"), dpi=110, bbox_inches="tight")
    plt.close(fig)
    return "relative_error_images.png"


def tables(summary):
    """Returns a list of (title, header, rows, note) tables."""
    out = []
    equal = equal_time_table(summary)
    if equal:
        out.append(equal)
    conf = int(round(100 * summary.get("confidence", 0.95)))
    conv = summary.get("convergence", [])
    if conv:
        eps = conv[0].get("rel_mse_epsilon")
        rows = []
        for g in conv:
            rows.append([g["scene"], g["integrator"], g["threads"], g["budget_type"], g["runs"],
                         fmt_fit(g["fit_time"]), fmt_fit(g["fit_spp"]), covers(g["fit_spp"]),
                         fmt_fit(g.get("fit_spp_of_means")),
                         f"{g['efficiency']:.4g}", f"{g.get('reference_rel_mse', 0):.3g}"])
        out.append(("Convergence",
                    ["scene", "integrator", "threads", "budget", "runs",
                     f"slope vs time [{conf}% CI]",
                     f"slope vs spp [{conf}% CI]", "spp CI covers −1",
                     "slope of mean relMSE vs spp", "efficiency",
                     "reference's relMSE"],
                    rows,
                    f"Relative MSE = mean over pixels and channels of (x − r)² / (r² + ε), "
                    f"ε = {eps}. Slopes: ordinary least squares of log relMSE on log cost over "
                    f"all runs, Student-t interval; the slope of the mean relMSE over runs per "
                    f"budget is unbiased for heavy-tailed estimators, whose per-run slope can "
                    f"be flatter than −1 (rare large samples are missed more often at small "
                    f"budgets). Efficiency = 1 / (relMSE · wall seconds), "
                    f"median over the runs at the largest budget. An unbiased estimator "
                    f"has slope −1 until the reference's own error (last column) is reached."))
        detail = []
        for g in conv:
            for b in g["budgets"]:
                unit = " spp" if g["budget_type"] == "spp" else " s"
                detail.append([g["scene"], g["integrator"], g["threads"], f"{b['budget']:g}{unit}",
                               b["runs"], f"{b['median_spp']:g}",
                               f"{b['median_wall_seconds']:.4g}", f"{b['median_cpu_seconds']:.4g}",
                               f"{b['median_rel_mse']:.4g}", fmt_number(b["median_rel_variance"]),
                               f"{b['median_efficiency']:.4g}"])
        out.append(("Per budget (medians over runs)",
                    ["scene", "integrator", "threads", "budget", "runs", "spp", "wall s", "CPU s",
                     "relMSE", "rel. variance est.", "efficiency"], detail,
                    "rel. variance est.: the run's own estimate of its relative MSE from its "
                    "per-pixel variance (mean of Var[mean] / (r² + ε)); close to relMSE when "
                    "the estimator is unbiased and the reference is good; a dash for a sampler "
                    "that correlates a pixel's samples, whose spread would overstate it."))
    best = summary.get("best", [])
    if best:
        rows = []
        for b in best:
            others = ", ".join(f"{v:.2f}× {k}" for k, v in sorted(b["times_better_than"].items())
                               if k != b["integrator"])
            rows.append([b["scene"], b["threads"], b["budget_type"], b["integrator"],
                         f"{b['efficiency']:.4g}", others or "—"])
        out.append(("Most efficient integrator",
                    ["scene", "threads", "budget", "best integrator", "efficiency",
                     "times as efficient as"], rows, None))
    speed = summary.get("speedup", [])
    if speed:
        rows = [[s["scene"], s["integrator"], s["spp"], s["threads"], s["repeats"],
                 f"{s['median_wall_seconds']:.4g}", f"{s['speedup']:.3f}",
                 f"{s['parallel_efficiency']:.3f}", f"{s.get('cores_used', float('nan')):.2f}"]
                for s in speed]
        out.append(("Speed-up",
                    ["scene", "integrator", "spp", "threads", "repeats", "median wall s",
                     "speed-up", "parallel efficiency", "cores used"], rows,
                    "Thread counts alternate within each repeat; speed-up = median time at the "
                    "fewest threads / median time; parallel efficiency = speed-up × fewest "
                    "threads / threads; cores used = median CPU seconds / median wall seconds, "
                    "the cores the render actually got (under the thread count on a loaded "
                    "machine, which caps the speed-up)."))
    strat = summary.get("strategies", [])
    if strat:
        rows = []
        for g in strat:
            carrying = {(c["s"], c["t"]) for c in g["carrying"]}
            for st in g["ranked"]:
                if st["share"] < 1e-3 and (st["s"], st["t"]) not in carrying:
                    continue
                rows.append([g["scene"], g["spp"], g["max_bounces"], st["bounces"],
                             f"({st['s']}, {st['t']})", f"{100 * st['share']:.2f}%",
                             "yes" if (st["s"], st["t"]) in carrying else ""])
        out.append(("BDPT strategies",
                    ["scene", "spp", "max bounces", "bounces", "(s, t)", "share of the image",
                     f"carries ({100 * strat[0]['carried_share_target']:.0f}%)"], rows,
                    "s counts light subpath vertices (the emitter point included), t camera "
                    "subpath vertices (the lens point included); share = the strategy's "
                    "MIS-weighted image, mean over pixels and channels, over the image's. "
                    "Strategies under 0.1% are left out. The fewest strategies whose shares "
                    "reach the target carry the image."))
    return out


def findings(summary, records):
    """Sentences with the numbers the report is asked for, per scene."""
    conv = [r for r in records if r.get("study") == "convergence"]
    lines = []
    groups = [g for g in summary.get("convergence", []) if g.get("time_to_accuracy")]
    for scene, threads in sorted({(g["scene"], g["threads"]) for g in groups}):
        gs = [g for g in groups if g["scene"] == scene and g["threads"] == threads]
        for i, target in enumerate(a["target_rel_mse"] for a in gs[0]["time_to_accuracy"]):
            reached = sorted((g["time_to_accuracy"][i]["seconds"], g["integrator"]) for g in gs
                             if g["time_to_accuracy"][i]["status"] == "reached")
            if not reached:
                continue
            (t, best), rest = reached[0], reached[1:]
            a = next(g for g in gs if g["integrator"] == best)["time_to_accuracy"][i]
            text = (f"- **{scene}, relMSE {target:g}** ({threads} thread"
                    f"{'s' if threads != 1 else ''}): **{best}** reaches it in {t:.3g} s "
                    f"[{a['seconds_low']:.3g}, {a['seconds_high']:.3g}]")
            def versus(u, n):
                other = next(g for g in gs if g["integrator"] == n)["time_to_accuracy"][i]
                tie = other["seconds_low"] <= a["seconds_high"]
                return (f"{u / t:.1f}× faster than {n} ({u:.3g} s"
                        f"{'; the intervals overlap' if tie else ''})")

            if rest:
                text += ", " + ", ".join(versus(u, n) for u, n in rest)
            missing = [g["integrator"] for g in gs
                       if g["time_to_accuracy"][i]["status"] == "not reached"]
            if missing:
                text += f"; {', '.join(missing)} did not reach it in the budgets measured"
            lines.append(text + ".")
    for b in summary.get("best", []):
        ratios = sorted((v, k) for k, v in b["times_better_than"].items() if k != b["integrator"])
        if ratios:
            runner, worst = ratios[0], ratios[-1]

            def spread(integ):
                # The runs' own efficiencies at the largest budget, to judge a close call.
                rs = [r for r in conv if r["scene"] == b["scene"] and r["integrator"] == integ
                      and r["threads"] == b["threads"] and r["budget_type"] == b["budget_type"]]
                top = max(r["budget"] for r in rs)
                e = [1 / (r["rel_mse"] * r["wall_seconds"]) for r in rs if r["budget"] == top]
                return f"{min(e):.3g} to {max(e):.3g}"

            lines.append(
                f"- **Best efficiency on {b['scene']}** ({b['threads']} thread"
                f"{'s' if b['threads'] != 1 else ''}, {b['budget_type']} budgets): "
                f"**{b['integrator']}**, {runner[0]:.2f}× as efficient as the runner-up "
                f"{runner[1]} and {worst[0]:.2f}× as efficient as {worst[1]} (runs at the "
                f"largest budget: {spread(b['integrator'])} against {spread(runner[1])}).")
    for scene in sorted({r["scene"] for r in conv}):
        rs = [r for r in conv if r["scene"] == scene and r.get("rel_mse", 0) > 0]
        ref = max(r.get("reference_rel_mse", 0) for r in rs)
        low = min(rs, key=lambda r: r["rel_mse"])
        if ref > 0:
            lines.append(
                f"- **Reference of {scene}**: its own relative MSE is {ref:.3g}; the smallest "
                f"error any run reports is {low['rel_mse']:.3g} ({low['integrator']}, "
                f"{low['budget']:g} {low['budget_type']}), {low['rel_mse'] / ref:.1f}× the "
                f"reference's ({'at least' if low['rel_mse'] >= 10 * ref else '**under**'} "
                f"the 10× asked for).")
    for g in summary.get("strategies", []):
        carried = ", ".join(f"({c['s']}, {c['t']}) {100 * c['share']:.1f}%" for c in g["carrying"])
        text = (f"- **BDPT strategies on {g['scene']}** ({g['spp']} spp, max bounces "
                f"{g['max_bounces']}): {len(g['carrying'])} strategies carry "
                f"{100 * g['carried_share']:.1f}% of the image: {carried}.")
        bounced = [st for st in g["ranked"] if st["bounces"] > 0]
        rest = sum(st["share"] for st in bounced)
        if 0 < rest < 1:
            carried, picked = 0.0, []
            for st in bounced:
                if carried >= g["carried_share_target"] * rest:
                    break
                carried += st["share"]
                picked.append(f"({st['s']}, {st['t']}) {100 * st['share'] / rest:.1f}%")
            text += (f" Emitters seen directly (0 bounces) make {100 * (1 - rest):.1f}% of it; "
                     f"of the light with at least one bounce, {len(picked)} strategies carry "
                     f"{100 * carried / rest:.1f}%: {', '.join(picked)}.")
        if "share_beyond_max_bounces" in g:
            x = g["share_beyond_max_bounces"]
            text += (f" This render's mean is {100 * abs(x):.1f}% {'below' if x >= 0 else 'above'} "
                     f"the reference's (all path lengths): the paths of more than "
                     f"{g['max_bounces']} bounces, plus both images' noise.")
        lines.append(text)
    speed = summary.get("speedup", [])
    for scene in sorted({s["scene"] for s in speed}):
        for integ in sorted({s["integrator"] for s in speed if s["scene"] == scene}):
            rows = sorted((s for s in speed if s["scene"] == scene and s["integrator"] == integ),
                          key=lambda s: s["threads"])
            pts = ", ".join(f"{s['speedup']:.2f}× at {s['threads']} thread{'s' if s['threads'] != 1 else ''} (using "
                            f"{s.get('cores_used', float('nan')):.2f} cores)" for s in rows)
            lines.append(f"- **Speed-up on {scene}, {integ}** (over {rows[0]['baseline_threads']} "
                         f"thread{'s' if rows[0]['baseline_threads'] != 1 else ''}, "
                         f"{rows[0]['spp']} spp): {pts}.")
    cores = sorted({r.get("cores") for r in records if r.get("study") == "speedup"})
    threads = sorted({s["threads"] for s in speed})
    if cores:
        lines.append(f"- Thread counts timed: {', '.join(map(str, threads))}, on a machine with "
                     f"{', '.join(map(str, cores))} cores; no larger count was measured.")
    return lines


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for r in rows:
        lines.append("| " + " | ".join(str(c) for c in r) + " |")
    return "\n".join(lines)


def html_table(header, rows):
    h = "".join(f"<th>{html.escape(str(c))}</th>" for c in header)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c)).replace('**', '')}</td>"
                                    for c in r) + "</tr>" for r in rows)
    return f"<table><thead><tr>{h}</tr></thead><tbody>{body}</tbody></table>"


def name_samplers(summary, conv):
    """Names each integrator with its sampler where that is not the independent one
    ("path_tracer_nee + sobol"): the tables and plots below group by integrator, and so tell
    the samplers of a `study convergence --sampler` apart."""
    def label(integrator, sampler):
        return integrator if sampler in (None, "independent") else f"{integrator} + {sampler}"
    for r in conv + summary.get("convergence", []):
        r["integrator"] = label(r["integrator"], r.get("sampler"))
    for b in summary.get("best", []):
        b["integrator"] = label(b["integrator"], b.get("sampler"))
        b["times_better_than"] = {label(k, b.get("sampler")): v
                                  for k, v in b["times_better_than"].items()}
    for e in summary.get("equal_time", []):
        e["integrators"] = {label(k, e.get("sampler")): v for k, v in e["integrators"].items()}


def fmt_number(v):
    """A figure to four digits, or a dash where the summary has none (null)."""
    return "—" if v is None else f"{v:.4g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--summary", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("results", nargs="+")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with open(args.summary) as f:
        summary = json.load(f)
    records = read_records(args.results)
    conv = [r for r in records if r.get("study") == "convergence"]
    name_samplers(summary, conv)

    fits_time = {(g["scene"], g["integrator"], g["threads"], g["budget_type"]): g["fit_time"]
                 for g in summary.get("convergence", [])}
    fits_spp = {(g["scene"], g["integrator"], g["threads"], g["budget_type"]): g["fit_spp"]
                for g in summary.get("convergence", [])}
    figures = []
    f = plot_error(conv, args.out, "wall_seconds", "wall time (s)", "error_vs_time.png", fits_time)
    if f:
        figures.append((f, "Relative MSE against wall time (log-log), one panel per integrator, "
                           "one curve per thread count; dots are runs, points are means over the runs "
                           "at each budget with their standard errors."))
    f = plot_error(conv, args.out, "spp", "samples per pixel", "error_vs_spp.png", fits_spp)
    if f:
        figures.append((f, "Relative MSE against samples per pixel (log-log)."))
    f = plot_efficiency(summary, args.out)
    if f:
        figures.append((f, "Efficiency 1 / (relMSE · time), on a linear axis from zero: higher is better."))
    f = plot_speedup(summary, args.out)
    if f:
        figures.append((f, "Speed-up against threads, with the ideal line."))
    f = plot_error_images(conv, args.out)
    if f:
        figures.append((f, "Per-pixel relative RMS error against the reference at the largest "
                           "budget (run 0), false colour on a log scale."))

    machine = summary.get("machine", {})
    meta = (f"Generated {summary.get('created', '')} on {machine.get('hostname', '?')} "
            f"({machine.get('cpu_model', '?')}, {machine.get('cores', '?')} cores), source "
            f"revision {summary.get('revision', 'unknown')}. Results: "
            + ", ".join(os.path.basename(p) for p in args.results) + ".")
    hosts = sorted({r.get("hostname", "?") for r in records})
    revs = sorted({r.get("revision", "unknown") for r in records})
    meta_runs = f"Runs were made on {', '.join(hosts)} at revision(s) {', '.join(revs)}."

    tbls = tables(summary)
    more_figures, more_tables = strategy_figures.add(records, args.out)
    figures += more_figures
    tbls += more_tables
    # The report opens with what a reader acts on: the time to accuracy, then which BDPT
    # strategy carries which light (the pyramid); the other figures close it.
    leading = [fc for fc in figures if fc[0].startswith("strategy_pyramid")]
    figures = [fc for fc in figures if fc not in leading]
    accuracy = accuracy_table(summary)
    md = ["# Verity study report", "", meta, "", meta_runs, ""]
    if accuracy:
        title, header, rows, note = accuracy
        md += [f"## {title}", "", markdown_table(header, rows), "", note, ""]
    for name, caption in leading:
        md += ["## BDPT strategies, by path length", "", f"![{caption}]({name})", "", caption, ""]
    found = findings(summary, records)
    if found:
        md += ["## Findings", ""] + found + [""]
    for title, header, rows, note in tbls:
        md += [f"## {title}", "", markdown_table(header, rows), ""]
        if note:
            md += [note, ""]
    md += ["## Figures", ""]
    for name, caption in figures:
        md += [f"![{caption}]({name})", "", caption, ""]
    with open(os.path.join(args.out, "summary.md"), "w") as f:
        f.write("\n".join(md))

    css = ("body{font-family:sans-serif;max-width:1200px;margin:2em auto;color:#222}"
           "table{border-collapse:collapse;margin:1em 0;font-size:0.85em}"
           "td,th{border:1px solid #bbb;padding:3px 7px;text-align:right}"
           "th{background:#eee}img{max-width:100%}figcaption{font-size:0.9em;color:#555}")
    parts = [f"<!doctype html><html><head><meta charset='utf-8'><title>Verity study report"
             f"</title><style>{css}</style></head><body><h1>Verity study report</h1>",
             f"<p>{html.escape(meta)}</p><p>{html.escape(meta_runs)}</p>"]
    if accuracy:
        title, header, rows, note = accuracy
        parts.append(f"<h2>{html.escape(title)}</h2>" + html_table(header, rows)
                     + f"<p>{html.escape(note)}</p>")
    for name, caption in leading:
        parts.append(f"<h2>BDPT strategies, by path length</h2><figure><img src='{name}'>"
                     f"<figcaption>{html.escape(caption)}</figcaption></figure>")
    if found:
        parts.append("<h2>Findings</h2><ul>" + "".join(
            f"<li>{html.escape(f[2:]).replace('**', '')}</li>" for f in found) + "</ul>")
    for title, header, rows, note in tbls:
        parts.append(f"<h2>{html.escape(title)}</h2>" + html_table(header, rows))
        if note:
            parts.append(f"<p>{html.escape(note)}</p>")
    parts.append("<h2>Figures</h2>")
    for name, caption in figures:
        parts.append(f"<figure><img src='{name}'><figcaption>{html.escape(caption)}"
                     f"</figcaption></figure>")
    parts.append("</body></html>")
    with open(os.path.join(args.out, "index.html"), "w") as f:
        f.write("\n".join(parts))
    return 0


if __name__ == "__main__":
    sys.exit(main())
