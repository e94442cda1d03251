import mitsuba as mi, drjit as dr
mi.set_variant('scalar_rgb')
mi.set_log_level(mi.LogLevel.Warn)
ctx = mi.BSDFContext()
for t in ['conductor', 'roughconductor']:
    b = mi.load_dict({'type': t, 'material': 'AlSb'})
    si = dr.zeros(mi.SurfaceInteraction3f); si.wi = mi.Vector3f(0, 0, 1)
    bs, w = b.sample(ctx, si, 0.5, mi.Point2f(0.5, 0.5))
    print(t, 'AlSb wi=(0,0,1): weight', w, 'wo', bs.wo)
# the same through eta = k = 0 given directly, and Mitsuba's Fresnel term itself:
print('fresnel_conductor(1, 0+0i) =', mi.fresnel_conductor(1.0, dr.scalar.Complex2f(0.0, 0.0)))
print('fresnel_conductor(0.9999, 0+0i) =', mi.fresnel_conductor(0.9999, dr.scalar.Complex2f(0.0, 0.0)))
print('AlSb in scalar_rgb: eta', mi.traverse(mi.load_dict({'type': 'conductor', 'material': 'AlSb'}))['eta.value'],
      'k', mi.traverse(mi.load_dict({'type': 'conductor', 'material': 'AlSb'}))['k.value'])
