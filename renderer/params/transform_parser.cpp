#include "params/transform_parser.h"

#include "params/key.h"

namespace verity {

namespace {

// Each key is declared once: parseOne reads it by this object, and transformKeys() lists it.
const Key<Vector3f> kFrom{
    .name = "from", .defaultValue = Vector3f(0, 0, 1), .meaning = "look-at: the eye point"};
const Key<Vector3f> kAt{.name = "at",
                        .aliases = {"to"},
                        .defaultValue = Vector3f::Zero(),
                        .meaning = "look-at: the point the local -z axis is turned towards",
                        .alsoAllowed = "not \"from\""};
const Key<Vector3f> kUp{.name = "up",
                        .defaultValue = Vector3f::UnitY(),
                        .meaning = "look-at: the direction that local +y leans towards",
                        .alsoAllowed = "not zero, not along at - from"};
const Key<Vector3f> kOrigin{
    .name = "o", .defaultValue = Vector3f::Zero(), .meaning = "frame: where the local origin goes"};
const Key<Vector3f> kAxisX{
    .name = "x", .defaultValue = Vector3f::UnitX(), .meaning = "frame: where local x goes"};
const Key<Vector3f> kAxisY{
    .name = "y", .defaultValue = Vector3f::UnitY(), .meaning = "frame: where local y goes"};
const Key<Vector3f> kAxisZ{
    .name = "z", .defaultValue = Vector3f::UnitZ(), .meaning = "frame: where local z goes"};
// The keys below are read only when given: "—" or "required with ..." is their default.
const Key<Vector3f> kTranslate{.name = "translate", .meaning = "a translation", .defaultText = "—"};
const Key<Vector3f> kScale{.name = "scale",
                           .meaning = "a scale along the axes (one number: uniform)",
                           .defaultText = "—",
                           .alsoAllowed = "no component 0"};
const Key<Vector3f> kAxis{.name = "axis",
                          .meaning = "rotation: the axis (through the origin)",
                          .defaultText = "required with angle",
                          .alsoAllowed = "not zero"};
const Key<float> kAngle{.name = "angle",
                        .meaning =
                            "rotation: the angle in degrees, right-handed "
                            "(counter-clockwise seen from the axis's tip)",
                        .defaultText = "required with axis"};
const KeyDeclaration kMatrix{
    "matrix",          {}, ValueType::Array, "16 numbers, row-major, last row [0, 0, 0, 1]", "—",
    "an affine matrix"};

Matrix4f lookAt(const Vector3f& from, const Vector3f& at, const Vector3f& up,
                const JsonNode& node) {
  // Stable norms: a far-away camera must reach the extent check, not overflow to a zero axis.
  const Vector3f dir = at - from;
  if (!(dir.stableNorm() > 0)) node.fail("\"from\" and \"at\" are the same point");
  const Vector3f z = -dir.stableNormalized();  // the camera looks down −z
  if (!(up.stableNorm() > 0)) node[kUp].fail("\"up\" must not be the zero vector");
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
  if (node.find(kFrom) || node.find(kAt) || node.find(kUp)) {
    ++forms;
    m = lookAt(node.get(kFrom), node.get(kAt), node.get(kUp), node);
  }
  if (node.find(kOrigin) || node.find(kAxisX) || node.find(kAxisY) || node.find(kAxisZ)) {
    ++forms;
    // Missing axes default to the identity's.
    m.block<3, 1>(0, 0) = node.get(kAxisX);
    m.block<3, 1>(0, 1) = node.get(kAxisY);
    m.block<3, 1>(0, 2) = node.get(kAxisZ);
    m.block<3, 1>(0, 3) = node.get(kOrigin);
  }
  if (node.find(kTranslate)) {
    ++forms;
    m.block<3, 1>(0, 3) = node.get(kTranslate);
  }
  if (node.find(kScale)) {
    ++forms;
    const Vector3f s = node.get(kScale);
    if ((s.array() == 0).any()) node[kScale].fail("a scale of zero makes the transform singular");
    m.topLeftCorner<3, 3>() = s.asDiagonal();
  }
  if (node.find(kAxis) || node.find(kAngle)) {
    ++forms;
    const Vector3f axis = node.get(kAxis);
    const float angle = node.get(kAngle);
    if (!(axis.norm() > 0)) node[kAxis].fail("the rotation axis must not be zero");
    m.topLeftCorner<3, 3>() =
        Eigen::AngleAxisf(degToRad(angle), axis.normalized()).toRotationMatrix();
  }
  if (node.find(kMatrix)) {
    ++forms;
    const JsonNode mat = node[kMatrix];
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
  static const KeyList keys = declarations(kFrom, kAt, kUp, kOrigin, kAxisX, kAxisY, kAxisZ,
                                           kTranslate, kScale, kAxis, kAngle, kMatrix);
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
