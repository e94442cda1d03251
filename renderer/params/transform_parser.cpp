#include "params/transform_parser.h"

namespace verity {

namespace {
Matrix4f lookAt(const Vector3f& from, const Vector3f& at, const Vector3f& up,
                const JsonNode& node) {
  // Stable norms: a far-away camera must reach the extent check, not overflow to a zero axis.
  const Vector3f dir = at - from;
  if (!(dir.stableNorm() > 0)) node.fail("\"from\" and \"at\" are the same point");
  const Vector3f z = -dir.stableNormalized();  // the camera looks down −z
  if (!(up.stableNorm() > 0)) node[{"up"}].fail("\"up\" must not be the zero vector");
  const Vector3f xRaw = up.stableNormalized().cross(z);
  if (!(xRaw.norm() > 1e-12f)) node.fail("\"up\" is parallel to the viewing direction");
  const Vector3f x = xRaw.normalized();
  const Vector3f y = z.cross(x);
  Matrix4f m = Matrix4f::Identity();
  m.block<3, 1>(0, 0) = x;
  m.block<3, 1>(0, 1) = y;
  m.block<3, 1>(0, 2) = z;
  m.block<3, 1>(0, 3) = from;
  return m;
}

Matrix4f parseOne(const JsonNode& node) {
  if (!node.isObject()) node.fail("expected a transform object");
  node.declare({"a transform", {&transformKeys()}});
  Matrix4f m = Matrix4f::Identity();
  int forms = 0;
  if (node.has({"from"}) || node.has({"at", "to"}) || node.has({"up"})) {
    ++forms;
    m = lookAt(node.getVector3({"from"}, Vector3f(0, 0, 1)),
               node.getVector3({"at", "to"}, Vector3f::Zero()),
               node.getVector3({"up"}, Vector3f::UnitY()), node);
  }
  if (node.has({"o"}) || node.has({"x"}) || node.has({"y"}) || node.has({"z"})) {
    ++forms;
    // Missing axes default to the identity's.
    m.block<3, 1>(0, 0) = node.getVector3({"x"}, Vector3f::UnitX());
    m.block<3, 1>(0, 1) = node.getVector3({"y"}, Vector3f::UnitY());
    m.block<3, 1>(0, 2) = node.getVector3({"z"}, Vector3f::UnitZ());
    m.block<3, 1>(0, 3) = node.getVector3({"o"}, Vector3f::Zero());
  }
  if (node.has({"translate"})) {
    ++forms;
    m.block<3, 1>(0, 3) = node.getVector3({"translate"}, Vector3f::Zero());
  }
  if (node.has({"scale"})) {
    ++forms;
    const Vector3f s = node.getVector3({"scale"}, Vector3f::Ones());
    if ((s.array() == 0).any())
      node[{"scale"}].fail("a scale of zero makes the transform singular");
    m.topLeftCorner<3, 3>() = s.asDiagonal();
  }
  if (node.has({"axis"}) || node.has({"angle"})) {
    ++forms;
    const Vector3f axis = node[{"axis"}].asVector3();
    const float angle = node[{"angle"}].asFloat();
    if (!(axis.norm() > 0)) node[{"axis"}].fail("the rotation axis must not be zero");
    m.topLeftCorner<3, 3>() =
        Eigen::AngleAxisf(degToRad(angle), axis.normalized()).toRotationMatrix();
  }
  if (node.has({"matrix"})) {
    ++forms;
    const JsonNode mat = node[{"matrix"}];
    if (!mat.isArray() || mat.size() != 16) mat.fail("expected an array of 16 numbers (row-major)");
    for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = mat[i].asFloat();
    // Points, directions and normals are transformed affinely; a projective row would be
    // applied to some of them and not to others.
    if (m.row(3) != Eigen::RowVector4f(0, 0, 0, 1))
      mat.fail("the last row must be [0, 0, 0, 1] (an affine transform)");
  }
  if (forms == 0)
    node.fail(
        "a transform needs one of from/at/up, o/x/y/z, translate, scale, axis/angle or matrix");
  if (forms > 1)
    node.fail("a transform object must have exactly one form; use an array to combine them");
  node.rejectUnknownKeys();
  return m;
}
}  // namespace

const KeyList& transformKeys() {
  static const KeyList keys = {
      {"from", {}, ValueType::Vector3, "", "[0, 0, 1]", "look-at: the eye point"},
      {"at",
       {"to"},
       ValueType::Vector3,
       "not \"from\"",
       "[0, 0, 0]",
       "look-at: the point the local -z axis is turned towards"},
      {"up",
       {},
       ValueType::Vector3,
       "not zero, not along at - from",
       "[0, 1, 0]",
       "look-at: the direction that local +y leans towards"},
      {"o", {}, ValueType::Vector3, "", "[0, 0, 0]", "frame: where the local origin goes"},
      {"x", {}, ValueType::Vector3, "", "[1, 0, 0]", "frame: where local x goes"},
      {"y", {}, ValueType::Vector3, "", "[0, 1, 0]", "frame: where local y goes"},
      {"z", {}, ValueType::Vector3, "", "[0, 0, 1]", "frame: where local z goes"},
      {"translate", {}, ValueType::Vector3, "", "—", "a translation"},
      {"scale",
       {},
       ValueType::Vector3,
       "no component 0",
       "—",
       "a scale along the axes (one number: uniform)"},
      {"axis",
       {},
       ValueType::Vector3,
       "not zero",
       "required with angle",
       "rotation: the axis (through the origin)"},
      {"angle",
       {},
       ValueType::Number,
       "",
       "required with axis",
       "rotation: the angle in degrees, right-handed (counter-clockwise seen from the axis's tip)"},
      {"matrix",
       {},
       ValueType::Array,
       "16 numbers, row-major, last row [0, 0, 0, 1]",
       "—",
       "an affine matrix"}};
  return keys;
}

Transform parseTransform(const JsonNode& node) {
  Matrix4f m = Matrix4f::Identity();
  if (node.isArray()) {
    for (size_t i = 0; i < node.size(); ++i) m = parseOne(node[i]) * m;
  } else {
    m = parseOne(node);
  }
  Transform t(m);
  if (!t.isInvertible()) node.fail("the transform is singular (not invertible)");
  return t;
}

Transform parseOptionalTransform(const JsonNode& parent) {
  auto node = parent.find({"transform"});
  return node ? parseTransform(*node) : Transform();
}

}  // namespace verity
