# Fresnel of a conductor with k = 0 and eta 0.0381849 across its critical angle, one float step of cos at a time:
# Mitsuba's fresnel_conductor (float) beside the double formula of check_mitsuba_bsdfs.py.
import numpy as np, mitsuba as mi, drjit as dr
mi.set_variant('scalar_rgb')
import sys; import os; sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
from check_mitsuba_bsdfs import fresnel
eta = np.float32(0.0381849)
# cos of the half vector at the critical angle sin = eta
c0 = np.float32(np.sqrt(1 - float(eta)**2))
print('critical cos', float(c0))
cs = [c0]
for i in range(6): cs.append(np.nextafter(cs[-1], np.float32(1)))
cl = [c0]
for i in range(6): cl.insert(0, np.nextafter(cl[0], np.float32(0)))
for c in cl[:-1] + cs:
    fm = mi.fresnel_conductor(float(c), dr.scalar.Complex2f(float(eta), 0.0)) if hasattr(mi,'fresnel_conductor') else None
    print(f'{float(c):.9f}', fm, fresnel(float(c), complex(float(eta), 0)))
