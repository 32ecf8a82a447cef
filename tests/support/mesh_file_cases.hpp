// Mesh files made byte by byte, for the reader tests and the fuzzers' seed
// corpus (fuzz/make_fuzz_seeds.cpp): well-formed files in every variant each
// format has, and one file of each kind of malformed or hostile input the
// readers must refuse. Everything is generated here, the big ones too (a
// node chain 100,000 deep, JSON nested 50,000 deep), so nothing large is
// committed. This file needs only the standard library, glm and nlohmann's
// json: the fuzz build, which has no GoogleTest, compiles it too.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace lbmshape::testing {

struct MeshFileCase {
  std::string name;       // unique, usable as a file name stem
  std::string extension;  // ".obj", ".ply", ...
  std::string bytes;
  // Empty for a well-formed file; otherwise a phrase the error message must hold.
  std::string refusal;
  bool large = false;  // over 64 KB: too big to seed a fuzzer with
};

// Names the case in test listings (GoogleTest finds it by its argument's namespace).
inline void PrintTo(const MeshFileCase& c, std::ostream* out) { *out << c.name; }

// Well-formed files: each reads as a closed, outward tetrahedron or cube
// (volume 1/6 or 1), whatever the format's variant.
std::vector<MeshFileCase> wellFormedMeshFiles();

// Malformed and hostile files, each refused with its `refusal` phrase.
std::vector<MeshFileCase> hostileMeshFiles();

}  // namespace lbmshape::testing
