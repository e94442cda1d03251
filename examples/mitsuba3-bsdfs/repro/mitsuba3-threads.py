# A GGX roughconductor (alpha 0.3, eta 0.2, k 3.5) at 30 degrees, checked with threads=1 and
# no Dr.Jit scope of its own in the callables: on which threads are they called, and does
# Dr.Jit accept it?
import sys, threading, numpy as np
import mitsuba as mi, drjit as dr, verity
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error); dr.set_thread_count(1)
b = mi.load_dict({'type': 'roughconductor', 'distribution': 'ggx', 'alpha': 0.3,
                  'eta': {'type': 'rgb', 'value': [0.2] * 3}, 'k': {'type': 'rgb', 'value': [3.5] * 3}})
ctx = mi.BSDFContext()
callers = set()

def vec(a):
    a = np.ascontiguousarray(a, dtype=np.float32)
    return mi.Vector3f(*[mi.Float(a[:, i]) for i in range(3)])

def si_of(wi, n):
    si = dr.zeros(mi.SurfaceInteraction3f, n)
    si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
    si.wi = vec(np.broadcast_to(np.asarray(wi, dtype=np.float64), (n, 3)))
    return si

def col(v, n):
    return np.broadcast_to(np.asarray(v, dtype=np.float64).reshape(-1), (n,))

def sample(wi, u):
    callers.add(threading.get_ident()); n = len(u)
    u = np.minimum(u.astype(np.float32), np.float32(1 - 2.0**-24))
    bs, w = b.sample(ctx, si_of(wi, n), mi.Float(u[:, 0]), mi.Point2f(mi.Float(u[:, 1]), mi.Float(u[:, 2])))
    wo = np.stack([col(bs.wo[i], n) for i in range(3)], -1)
    w = np.stack([col(w[i], n) for i in range(3)], -1)
    pdf = np.where(np.all(w == 0, axis=1), 0.0, col(bs.pdf, n))
    return wo, w, pdf

def ev(wi, wo):
    callers.add(threading.get_ident()); n = len(wo)
    f = b.eval(ctx, si_of(wi, n), vec(wo))
    f = np.stack([col(f[i], n) for i in range(3)], -1)
    c = np.abs(wo[:, 2].astype(np.float32)).astype(np.float64)[:, None]
    with np.errstate(divide='ignore', invalid='ignore'):
        return np.where(c > 0, f / c, 0.0)

def pdf(wi, wo):
    callers.add(threading.get_ident()); n = len(wo)
    return col(b.pdf(ctx, si_of(wi, n), vec(wo)), n).copy()

wi = (0.5, 0.0, 0.8660254037844386)
r = verity.check_bsdf(sample, ev, pdf, wi=wi, alpha=0.01, samples=200_000, threads=1, name='ggx 0.3 30')
print(f"threads=1, no new scope: {r.verdict}, {r.samples} samples; callables called on "
      f"{len(callers)} thread(s), the calling thread: {callers == {threading.get_ident()}}")

