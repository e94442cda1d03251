# The GGX all-normals sampler's elevation in float32, as microfacet.h:278-288 forms it
# (cos = rsqrt(1 + tan^2), then sin = sqrt(1 - cos^2)), against the exact sin = tan * cos.
import numpy as np
f = np.float32
rng = np.random.default_rng(0)
u = rng.random(1_000_000).astype(f)
for alpha in (1e-4, 2.06893e-3, 0.0398):
    a2 = f(alpha) * f(alpha)
    t2 = a2 * u / (f(1) - u)
    c = f(1) / np.sqrt(f(1) + t2)
    s_float = np.sqrt(np.maximum(f(0), f(1) - c * c))
    s_exact = np.sqrt(t2.astype(np.float64)) / np.sqrt(1 + t2.astype(np.float64))
    r = s_float / s_exact
    print(f"alpha {alpha:g}: sin(theta_m) exactly 0 for {np.mean(s_float == 0):.1%} of draws; "
          f"float/exact sin quantiles 1%/50%/99%: {np.round(np.quantile(r[s_exact > 0], [0.01, 0.5, 0.99]), 3)}; "
          f"distinct sin values among 10^6 draws: {len(np.unique(s_float))}")
