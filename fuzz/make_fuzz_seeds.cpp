// Writes the fuzzers' seed corpus: every file of support/mesh_file_cases.hpp
// (well-formed variants of each format, and one of each hostile kind) that
// is small enough to mutate, into FOLDER/<format>/, one folder per fuzz
// target; and a meshopt-compressed GLB, as --compress writes it, so that
// the fuzzer reaches the decoding of EXT_meshopt_compression.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "lbmshape/mesh/mesh_writer.hpp"
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
  lbmshape::TriangleMesh octahedron;
  octahedron.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  octahedron.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  fs::create_directories(folder / "glb");
  lbmshape::writeMesh(octahedron, folder / "glb" / "compressed.glb", lbmshape::EmptyMesh::Refused,
                      lbmshape::GltfCompression::Meshopt);
  ++written;
  std::cout << "wrote " << written << " seed files into " << folder << "\n";
  return 0;
}
