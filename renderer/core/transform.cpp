#include "core/transform.h"

namespace verity {

bool Transform::isSimilarity(float* scale) const {
  const Matrix3f a = m_.topLeftCorner<3, 3>();
  const Matrix3f ata = a.transpose() * a;
  const float s2 = ata.trace() / 3;
  if (!(s2 > 0)) return false;
  if ((ata - s2 * Matrix3f::Identity()).cwiseAbs().maxCoeff() > 1e-4f * s2) return false;
  if (scale) *scale = std::sqrt(s2);
  return true;
}

bool Transform::isInvertible() const {
  const float det = m_.topLeftCorner<3, 3>().determinant();
  return std::isfinite(det) && det != 0 && inv_.allFinite();
}

}  // namespace verity
