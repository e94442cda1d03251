# Dr.Jit (Mitsuba 3 v3.8.0, llvm_rgb) reads past the end of a NumPy array it was given: mi.Float
# maps a contiguous float32 array without copying, and the LLVM kernels load whole vectors of
# 16 floats. Each case puts the array's last float just before a page that may not be read
# (mprotect PROT_NONE) and evaluates f * 2 + 1 in a child process: n not a multiple of 16
# crashes (SIGSEGV, exit -11); the same n given as the head of a copy padded by 16 floats, as
# check_mitsuba_bsdfs.py's adapter now does, does not. The family runs' crashes (the report's
# limit 6) had this signature: an unmasked 16-wide load 32 bytes before the end of the heap,
# in a JIT kernel called from the adapter's pdf.
import subprocess, sys

CHILD = r'''
import ctypes, mmap, sys
import numpy as np
import mitsuba as mi, drjit as dr
mi.set_variant("llvm_rgb"); dr.set_thread_count(1)
n, pad = int(sys.argv[1]), int(sys.argv[2])
page = mmap.PAGESIZE
size = (n + pad) * 4
pages = (size + page - 1) // page + 1
buf = mmap.mmap(-1, (pages + 1) * page)
addr = ctypes.addressof(ctypes.c_char.from_buffer(buf))
libc = ctypes.CDLL(None)
libc.mprotect.argtypes = [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int]
assert libc.mprotect(addr + pages * page, page, 0) == 0
a = np.frombuffer(buf, dtype=np.float32, count=n + pad, offset=pages * page - size)
a[:n] = np.arange(n, dtype=np.float32)
f = mi.Float(a[:n])
a[0] = -1.0
shared = f[0] == -1.0
g = f * 2 + 1
dr.eval(g)
print(f"shared {shared}, g[n - 1] = {g[n - 1]}")
'''

for n in (16, 17, 100, 16384, 16385, 16552):
    for pad in (0, 16):
        r = subprocess.run([sys.executable, "-c", CHILD, str(n), str(pad)],
                           capture_output=True, text=True)
        out = r.stdout.strip() or "(nothing)"
        print(f"n {n:6d}, padding {pad:2d}: exit {r.returncode:4d}  {out}")
