# plastic's diffuse-lobe probability, as its sample() forms it (1 - p_s/(p_s+p_d)) and as its
# pdf() forms it (p_d/(p_s+p_d)), in float32, against double: R 0.01, eta 3, 89.9 degrees.
import numpy as np, mitsuba as mi
mi.set_variant('scalar_rgb')
f32 = np.float32
c = f32(0.001745329)
F = f32(mi.fresnel(float(c), 3.0)[0])
w = f32(1) / (f32(0.01) + f32(1))          # specular_sampling_weight = s_mean / (d_mean + s_mean)
ps, pd = F * w, (f32(1) - F) * (f32(1) - w)
a = f32(1) - ps / (ps + pd)                 # sample()
b = pd / (ps + pd)                          # pdf()
Fd = float(F); wd = 1 / 1.01
exact = (1 - Fd) * (1 - wd) / (Fd * wd + (1 - Fd) * (1 - wd))
print(f"F {F}, prob_diffuse: sample() {a:.7g}, pdf() {b:.7g}, double {exact:.7g}; "
      f"sample()/pdf() = {a/b:.6f}")
