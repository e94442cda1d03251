#!/usr/bin/python3
"""The figure of one chi-square sampling test, drawn from the JSON written by
<verity/chi2/figure_data.h> (`verity chi2 -o PREFIX`, the suite for every failing
configuration, or a check outside Verity with writeFigureData):

    python3 share/verity/plot_chi2.py PREFIX.json PREFIX.png

Six panels. Above: observed and expected counts per cell on ONE logarithmic colour scale (a
peaked lobe such as GGX with alpha 0.1 spans five decades, which a linear scale shows as a
few bright cells on black), and the standardised difference (O - E)/sqrt(E), linear within
three standard deviations and logarithmic beyond, so that both the noise of a correct
sampler and the gross error of a broken one are readable. Below: the same as densities,
counts over the cell's area (solid angle on the sphere) and the number of samples: the
sampled density and the claimed one on one logarithmic scale, and their ratio O/E on a
logarithmic scale about 1 (grey where a cell expects fewer than 5 samples). On cells of equal probability the counts are flat by design; the
densities show the lobe, and the ratio where and by how much the sampler departs from it.
Grey cells lie outside the domain's support (nothing expected, nothing observed). Every cell is drawn as the rectangle
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
RATIO_SPAN = 2.0  # the ratio's scale spans at least 1/RATIO_SPAN to RATIO_SPAN


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


def draw_pair(fig, axes, domain, outside, cmap, norm, panels, label):
    """Two panels of (values, title) on one logarithmic scale and one colour bar; a cell below
    the scale is drawn in its lowest colour, one outside the support in grey."""
    for ax, (values, name) in zip(axes, panels):
        shown = np.where(outside, np.nan, np.maximum(values, norm.vmin / 2))
        image = draw_cells(ax, domain, shown, cmap=cmap, norm=norm)
        ax.set_title(name)
        label_axes(ax, domain)
    fig.colorbar(image, ax=axes, shrink=0.9, extend="min").set_label(label)


def cell_areas(domain):
    """(ny, nx): strip i's cell j spans x_edges[i:i+2] by y_edges[i][j:j+2]; on the sphere
    (phi, cos theta) that product is the cell's solid angle."""
    x = np.array(domain["x_edges"])
    y = np.array(domain["y_edges"])  # (nx, ny + 1)
    return (np.diff(y, axis=1) * np.diff(x)[:, None]).T


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

    # Densities: counts over the cell's area and the number of samples.
    scale = cell_areas(domain) * max(d["samples"], 1)
    sampled, claimed = observed / scale, expected / scale
    top_density = max(sampled.max(), claimed.max(), np.finfo(float).tiny)
    densities = LogNorm(vmin=top_density * 10.0**-DECADES, vmax=top_density)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(expected > 0, observed / expected, np.inf)
    # A cell expecting fewer than 5 samples (pooled by the test) has no ratio worth a colour,
    # unless it holds samples where nothing is claimed.
    ratio[outside | ((expected > 0) & (expected < 5))] = np.nan
    shown_ratio = ratio[np.isfinite(ratio) & (ratio > 0)]
    span = max(RATIO_SPAN, np.exp(np.abs(np.log(shown_ratio)).max()) if shown_ratio.size else 0)
    ratio_norm = LogNorm(vmin=1 / span, vmax=span)

    wide = domain["kind"] == "sphere"
    fig, axes = plt.subplots(2, 3, figsize=(18, 10.4) if wide else (16, 11.6), layout="constrained")
    draw_pair(fig, axes[0, :2], domain, outside, count_map, counts,
              [(observed, f"observed counts ({observed.sum():,.0f})"),
               (expected, f"expected counts ({expected.sum():,.0f})")],
              "samples per cell (log scale)")

    image = draw_cells(axes[0, 2], domain, z, cmap=diff_map, norm=diff_norm)
    axes[0, 2].set_title("(O − E)/√E: red where too many samples")
    label_axes(axes[0, 2], domain)
    cell = d["chi_square"]["outright_cell"]
    if d["chi_square"]["outright_samples"] and cell >= 0:
        i, j = cell % domain["nx"], cell // domain["nx"]
        axes[0, 2].plot((x[i] + x[i + 1]) / 2, (y[i][j] + y[i][j + 1]) / 2, "kx", markersize=10)
    bar = fig.colorbar(image, ax=axes[0, 2], shrink=0.9, ticks=difference_ticks(limit))
    bar.ax.set_yticklabels([f"{t:g}" for t in difference_ticks(limit)])
    bar.set_label(f"standard deviations (linear within ±{LINEAR_SIGMAS:g}, log beyond)")

    unit = "per steradian" if wide else "per unit area"
    draw_pair(fig, axes[1, :2], domain, outside, count_map, densities,
              [(sampled, "sampled density (counts / (N · cell area))"),
               (claimed, "claimed density (counts / (N · cell area))")],
              f"density {unit} (log scale)")

    ratio_map = plt.get_cmap("RdBu_r").copy()
    ratio_map.set_bad("0.8")
    ratio_map.set_over("black")  # samples where nothing is expected
    ratio_map.set_under(ratio_map(0.0))  # nothing where samples are expected
    shown = np.clip(ratio, 1 / span, span)
    shown[ratio == np.inf] = 2 * span
    shown[ratio == 0] = 1 / (2 * span)
    image = draw_cells(axes[1, 2], domain, shown, cmap=ratio_map, norm=ratio_norm)
    axes[1, 2].set_title("sampled / claimed density: red where too dense")
    label_axes(axes[1, 2], domain)
    bar = fig.colorbar(image, ax=axes[1, 2], shrink=0.9, extend="both")
    bar.set_label("O / E (log scale; black: samples where nothing is claimed)")

    colour = {"PASSED": "black", "FAILED": "darkred", "INCONCLUSIVE": "darkorange"}[d["verdict"]]
    fig.suptitle(title(d), fontsize=10, color=colour)
    fig.savefig(sys.argv[2], dpi=100)


if __name__ == "__main__":
    main()
