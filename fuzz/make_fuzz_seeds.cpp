// Writes the fuzzers' seed corpus: every file of support/mesh_file_cases.hpp
// (well-formed variants of each format, and one of each hostile kind) that
// is small enough to mutate, into FOLDER/<format>/, one folder per fuzz
// target.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "support/mesh_file_cases.hpp"

int main(int argc, char** argv)
{
  if (argc != 2) {
    std::cerr << "usage: make_fuzz_seeds FOLDER\n";
    return 2;
  }
  namespace fs = std::filesystem;
  const fs::path folder = argv[1];
  size_t written = 0;
  for (const auto& cases : {lbmshape::testing::wellFormedMeshFiles(), lbmshape::testing::hostileMeshFiles()})
    for (const auto& c : cases) {
      if (c.large) continue;
      const fs::path target = folder / c.extension.substr(1);
      fs::create_directories(target);
      std::ofstream(target / (c.name + c.extension), std::ios::binary) << c.bytes();
      ++written;
    }
  std::cout << "wrote " << written << " seed files into " << folder << "\n";
  return 0;
}
