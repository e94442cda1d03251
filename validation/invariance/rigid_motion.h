// Rigid motions of a whole scene, camera included: radiance does not depend on where the
// scene is or how it is turned, so every motion must leave the image unchanged in
// expectation, and a mirror image must give the image mirrored. A test that no integrator
// can pass by sharing a bug with another.
#pragma once

#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace verity::validation {

struct RigidMotion {
  std::string name;
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();  // world to moved world
  // A mirror image: the camera keeps its handedness (its local x is mirrored too), so the
  // image is the original mirrored left to right.
  bool mirrors = false;
};

// The motions every scene is put through:
//   planes      translation by −bounds.lo: the scene's bounding planes (a box's floor and
//               walls) on the coordinate planes x = 0, y = 0 and z = 0;
//   far         a translation by up to 100 times the scene's extent;
//   turn90      90° about y then 90° about x (an exact permutation of the axes);
//   turn        37° about the axis (1, 2, 3);
//   mirror      x → −x.
// "planes", "far" and "turn" round every coordinate, so they are kept only as far as floats
// can still place the smallest surface to a thousandth of its size: "far" goes no further than
// that allows, and none is applied to a scene whose own extent does not allow it (small objects
// on a floor two million units wide: turned, the floor's corners round by 0.1; moved onto the
// planes, the objects sit a million units from the origin, where floats are 1/16 apart, which
// moves a sphere of radius 0.4 by 6% of its radius and changes the image measurably).
std::vector<RigidMotion> standardMotions(const Scene& scene);

// The scene (DIRT JSON) moved by `motion`: its surfaces wrapped in a group with the motion as
// transform, the motion appended to the camera's transform and to every solid texture's
// (checker, marble), which are evaluated in world space. The background must be constant: a
// lat-long image would have to turn with the scene, which the format cannot state.
nlohmann::json moveScene(nlohmann::json scene, const RigidMotion& motion);

}  // namespace verity::validation
