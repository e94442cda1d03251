#include "params/key.h"

namespace verity {

std::string KeyValue<float>::allowedText(const Range& r) {
  return r == Range::any() ? "" : r.interval();
}

std::string KeyValue<float>::text(float v) {
  return numberText(v);
}

std::string KeyValue<Vector3f>::allowedText(const Range& r) {
  return r == Range::any() ? "" : "each component " + r.interval();
}

std::string KeyValue<Vector3f>::text(const Vector3f& v) {
  return fmt::format("[{}, {}, {}]", numberText(v.x()), numberText(v.y()), numberText(v.z()));
}

Vector2f KeyValue<Vector2f>::read(const JsonNode& node, const Range& r) {
  if (node.isNumber()) return Vector2f::Constant(node.asFloat(r));
  if (!node.isArray() || node.size() != 2) node.fail("expected a number or [width, height]");
  return {node[0].asFloat(r), node[1].asFloat(r)};
}

std::string KeyValue<Vector2f>::text(const Vector2f& v) {
  if (v.x() == v.y()) return numberText(v.x());
  return fmt::format("[{}, {}]", numberText(v.x()), numberText(v.y()));
}

std::string KeyValue<Color3>::allowedText(const Range& r) {
  return r == Range::any() ? "" : "each channel " + r.interval();
}

std::string KeyValue<Color3>::text(const Color3& v) {
  if (v.x() == v.y() && v.y() == v.z()) return numberText(v.x());
  return KeyValue<Vector3f>::text(v.matrix());
}

}  // namespace verity
