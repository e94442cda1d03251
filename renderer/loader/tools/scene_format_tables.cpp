// Rewrites the generated key tables of docs/scene-format.md from the registries:
//   scene_format_tables docs/scene-format.md
// The text outside the <!-- keys ... --> blocks is left as written. The CTest
// SceneFormatDocument.GeneratedTablesMatchTheRegistries fails until this has been run after a
// change to a type's keys.
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/error.h"
#include "loader/scene_format.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: scene_format_tables docs/scene-format.md\n";
    return 2;
  }
  const std::string path = argv[1];
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << path << ": cannot open the file\n";
    return 2;
  }
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  try {
    const std::string regenerated = verity::regenerateSceneFormat(text.str(), path);
    if (regenerated == text.str()) {
      std::cout << path << ": the key tables are up to date\n";
      return 0;
    }
    std::ofstream(path, std::ios::binary) << regenerated;
    std::cout << path << ": key tables rewritten from the registries\n";
  } catch (const verity::VerityError& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
