// Multiple importance sampling weights of bidirectional path tracing (Veach 1997, §10.2-10.3,
// with the balance and power heuristics of Veach and Guibas 1995).
//
// A full path x_0 … x_{n−1} runs from the camera (x_0) to an emitter (x_{n−1}). Strategy t
// (t = 1 … n, s = n − t) takes x_0 … x_{t−1} from the camera subpath and x_t … x_{n−1} from the
// light subpath. Its density is
//   p_t = Π_{i=1}^{t−1} C_i · Π_{i=t}^{n−2} L_i · E_t,
// with C_i the area density of x_i by the camera walk, L_i that by the light walk, and E_t the
// density of the emitter endpoint: C_{n−1} for s = 0, the next-event density for s = 1 (t ≥ 2),
// the light subpath's origin density otherwise. The lens position is common to all
// strategies and cancels; the strategy t = 0 (a light path hitting the lens) is not used.
//
// Delta vertices: a vertex left through a delta lobe makes the density of each neighbour by
// a walk through it a Dirac delta. Every usable strategy contains exactly one of the two
// (the strategies that would connect at the delta vertex are the only ones that contain
// neither or both, and they cannot be used), so the deltas cancel in the ratios p_t / p_t*;
// they are stored as 0 and read as 1 there, and only there (other zero densities stay zero).
//
// The weight is 1 / Σ_t (p_t / p_t*)^β over the usable strategies, the ratios walked outward
// from the sampled strategy t* in double precision (the walk follows Veach 1997, §10.2.3).
#pragma once

#include <cstdint>
#include <vector>

namespace verity {

// Densities of one full path, filled by the integrator for each connection.
struct MisPath {
  int n = 0;                        // vertices
  std::vector<double> C, L;         // C[i], L[i] for i in [1, n − 1] (index 0 unused)
  std::vector<uint8_t> delta;       // delta[i]: x_i was left through a delta lobe
  double nextEventPdf = 0;          // E for s = 1, t ≥ 2
  double lightPathPdf = 0;          // E for s ≥ 2, and s = 1 with t = 1
  bool endpointAtInfinity = false;  // then t = 1 with s = 1 is impossible

  void reset(int vertices) {
    n = vertices;
    C.assign(n, 0.0);
    L.assign(n, 0.0);
    delta.assign(n, 0);
    nextEventPdf = lightPathPdf = 0;
    endpointAtInfinity = false;
  }
};

// The weight of strategy t (1 ≤ t ≤ n) for that path; power 1 is the balance heuristic, 2 the
// power heuristic. 0 when the sampled strategy's own density is zero.
float bdptMisWeight(const MisPath& path, int t, float power);

}  // namespace verity
