// The fake renderer (test support): writes one EXR of fake_images.h, for the referee's tests
// through command templates.
//   fake_renderer --seed S --out FILE [--bias B] [--biased-tiles N] [--biased-channels N]
//                 [--heavy] [--noise SD]
//                 [--size W H] [--no-rgb] [--fail] [--crash] [--half]
// --no-rgb writes a channel Y only; --fail prints to stderr and exits with status 7; --crash
// aborts (SIGABRT) after a line on stderr; --half leaves the EXR cut to half its length, as a
// render killed while writing would.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "validation/referee/tests/fake_images.h"

int main(int argc, char** argv) {
  verity::validation::testing::FakeScene scene;
  unsigned long long seed = 0;
  std::string out;
  bool rgb = true, half = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto next = [&] { return i + 1 < argc ? argv[++i] : ""; };
    if (arg == "--seed")
      seed = std::strtoull(next(), nullptr, 10);
    else if (arg == "--out")
      out = next();
    else if (arg == "--bias")
      scene.bias = std::atof(next());
    else if (arg == "--biased-tiles")
      scene.biasedTiles = std::atoi(next());
    else if (arg == "--biased-channels")
      scene.biasedChannels = std::atoi(next());
    else if (arg == "--heavy")
      scene.heavyTails = true;
    else if (arg == "--noise")
      scene.noise = std::atof(next());
    else if (arg == "--size") {
      scene.width = std::atoi(next());
      scene.height = std::atoi(next());
    } else if (arg == "--no-rgb")
      rgb = false;
    else if (arg == "--half")
      half = true;
    else if (arg == "--crash") {
      std::fprintf(stderr, "fake renderer: crashing as asked\n");
      std::abort();
    } else if (arg == "--fail") {
      std::fprintf(stderr, "fake renderer: failing as asked\n");
      return 7;
    } else {
      std::fprintf(stderr, "fake renderer: unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  if (out.empty()) {
    std::fprintf(stderr, "fake renderer: no --out\n");
    return 2;
  }
  verity::ImageChannels image = verity::validation::testing::fakeRender(scene, seed);
  if (!rgb) {
    image.planes["Y"] = image.planes["R"];
    image.planes.erase("R");
    image.planes.erase("G");
    image.planes.erase("B");
  }
  verity::writeExr(out, image);
  if (half) std::filesystem::resize_file(out, std::filesystem::file_size(out) / 2);
  return 0;
}
