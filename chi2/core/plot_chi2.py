#!/usr/bin/python3
"""The figure of one chi-square sampling test, drawn from the JSON written by
<verity/chi2/figure_data.h> (`verity chi2 -o PREFIX`, the suite for every failing
configuration, or a check outside Verity with writeFigureData):

    python3 share/verity/plot_chi2.py PREFIX.json PREFIX.png

Three panels: observed and expected counts per cell on ONE logarithmic colour scale (a
peaked lobe such as GGX with alpha 0.1 spans five decades, which a linear scale shows as a
few bright cells on black), and the standardised difference (O - E)/sqrt(E), linear within
three standard deviations and logarithmic beyond, so that both the noise of a correct
sampler and the gross error of a broken one are readable. Grey cells lie outside the
domain's support (nothing expected, nothing observed). Every cell is drawn as the rectangle
it is: strip i spans x_edges[i] to x_edges[i + 1] and is cut at its own y_edges[i]
(equal-probability cells crowd where the density's mass lies).
"""
import json
import math
import sys
import textwrap

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.colors import LogNorm, SymLogNorm
except ImportError as e:
    sys.exit(f"plot_chi2.py: {e} (Debian: apt-get install python3-matplotlib)")

LINEAR_SIGMAS = 3.0  # the difference's scale is linear within this many standard deviations
DECADES = 6  # the counts' scale spans at most this many decades below the largest count


def verdict(passed):
    return "pass" if passed else "FAIL"


def title(d):
    chi = d["chi_square"]
    integral = d["integral"]
    if chi["degenerate"]:
        p = "degenerate (fewer than two cells)"
    elif chi["p_value"] > 0:
        p = f"p = {chi['p_value']:.3g}"
    else:
        p = "p < 1e-308 (underflow)"
    lines = [part for line in d["subject"].splitlines() for part in textwrap.wrap(line, 110)]
    lines[0] = f"{d['verdict']}: {lines[0]}"
    lines.append(
        f"chi-square {p} against the level {d['significance']:.3g} "
        f"(X² = {chi['statistic']:.1f}, {chi['dof']} dof): {verdict(chi['passed'])}"
    )
    lines.append(
        f"pdf integral {integral['integral']:.6f} against the valid fraction "
        f"[{integral['lower']:.6f}, {integral['upper']:.6f}] ± {integral['tolerance']:.0e}: "
        f"{verdict(integral['passed'])}    per-sample audit: {verdict(d['audit']['passed'])}"
    )
    if d["inconclusive_reason"]:
        lines += textwrap.wrap(f"inconclusive: {d['inconclusive_reason']}", 110)
    extra = [f"{d['valid']:,} of {d['samples']:,} samples valid"]
    if chi["pooled_cells"]:
        extra.append(f"{chi['pooled_cells']} cells expecting < 5 pooled")
    if chi["outright_samples"]:
        extra.append(f"{chi['outright_samples']} samples where the pdf is zero (marked ×)")
    if d["outside"]:
        extra.append(f"{d['outside']} valid samples outside the domain")
    lines.append(", ".join(extra))
    return "\n".join(lines)


def difference_ticks(limit):
    """0, ±3 and ±10^k up to the limit (which is also a tick)."""
    ticks = [LINEAR_SIGMAS]
    k = 1
    while 10**k < 0.5 * limit:
        ticks.append(10**k)
        k += 1
    ticks.append(limit)
    return sorted([-t for t in ticks] + [0.0] + ticks)


def label_axes(ax, domain):
    ax.set_xlabel(domain["x_label"])
    ax.set_ylabel(domain["y_label"])
    if domain["kind"] == "sphere":
        ax.set_xticks([k * math.pi / 2 for k in range(5)])
        ax.set_xticklabels(["0", "π/2", "π", "3π/2", "2π"])
    else:
        ax.set_aspect("equal")


def draw_cells(ax, domain, values, **style):
    """values (ny, nx) drawn strip by strip on each strip's own edges; the last mesh."""
    x = domain["x_edges"]
    for i, y in enumerate(domain["y_edges"]):
        mesh = ax.pcolormesh(
            np.array(x[i : i + 2]), np.array(y), values[:, i : i + 1], **style
        )
    return mesh


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_chi2.py DATA.json OUT.png")
    with open(sys.argv[1]) as f:
        d = json.load(f)
    domain = d["domain"]
    x, y = domain["x_edges"], domain["y_edges"]
    observed = np.array(d["observed"], dtype=float)
    expected = np.array(d["expected"], dtype=float)
    outside = (expected <= 0) & (observed <= 0)

    # Counts: one log scale for both; an empty cell is drawn in the scale's lowest colour.
    top = max(observed.max(), expected.max(), 1.0)
    counts = LogNorm(vmin=max(0.5, top * 10.0**-DECADES), vmax=top)
    count_map = plt.get_cmap("magma").copy()
    count_map.set_under(count_map(0.0))
    count_map.set_bad("0.8")

    # Difference in standard deviations; a sample where nothing is expected saturates.
    with np.errstate(divide="ignore", invalid="ignore"):
        z = np.where(expected > 0, (observed - expected) / np.sqrt(expected), np.inf)
    z[outside] = np.nan
    finite = np.abs(z[np.isfinite(z)])
    limit = round(max(2 * LINEAR_SIGMAS, finite.max() if finite.size else 0.0), 1)
    z = np.clip(z, -limit, limit)
    diff_map = plt.get_cmap("RdBu_r").copy()
    diff_map.set_bad("0.8")
    diff_norm = SymLogNorm(linthresh=LINEAR_SIGMAS, vmin=-limit, vmax=limit, base=10)

    wide = domain["kind"] == "sphere"
    fig, axes = plt.subplots(1, 3, figsize=(18, 5.6) if wide else (16, 6.2), layout="constrained")
    for ax, values, name in ((axes[0], observed, "observed"), (axes[1], expected, "expected")):
        shown = np.where(outside, np.nan, np.maximum(values, counts.vmin / 2))
        image = draw_cells(ax, domain, shown, cmap=count_map, norm=counts)
        ax.set_title(f"{name} counts ({values.sum():,.0f})")
        label_axes(ax, domain)
    bar = fig.colorbar(image, ax=axes[:2], shrink=0.9, extend="min")
    bar.set_label("samples per cell (log scale)")

    image = draw_cells(axes[2], domain, z, cmap=diff_map, norm=diff_norm)
    axes[2].set_title("(O − E)/√E: red where too many samples")
    label_axes(axes[2], domain)
    cell = d["chi_square"]["outright_cell"]
    if d["chi_square"]["outright_samples"] and cell >= 0:
        i, j = cell % domain["nx"], cell // domain["nx"]
        axes[2].plot((x[i] + x[i + 1]) / 2, (y[i][j] + y[i][j + 1]) / 2, "kx", markersize=10)
    bar = fig.colorbar(image, ax=axes[2], shrink=0.9, ticks=difference_ticks(limit))
    bar.ax.set_yticklabels([f"{t:g}" for t in difference_ticks(limit)])
    bar.set_label(f"standard deviations (linear within ±{LINEAR_SIGMAS:g}, log beyond)")

    colour = {"PASSED": "black", "FAILED": "darkred", "INCONCLUSIVE": "darkorange"}[d["verdict"]]
    fig.suptitle(title(d), fontsize=10, color=colour)
    fig.savefig(sys.argv[2], dpi=100)


if __name__ == "__main__":
    main()
