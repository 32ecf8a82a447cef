// Mesh files made byte by byte, for the reader tests and the fuzzers' seed
// corpus (fuzz/make_fuzz_seeds.cpp): well-formed files in every variant each
// format has, and one file of each kind of malformed or hostile input the
// readers must refuse. Everything is generated here, the big ones too (a
// node chain 100,000 deep, JSON nested 50,000 deep), so nothing large is
// committed. This file needs only the standard library, glm and nlohmann's
// json: the fuzz build, which has no GoogleTest, compiles it too.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace lbmshape::testing {

class MeshFileCase {
public:
  // The large files are given as a function that makes them: every test
  // process lists every case, and making them all up front cost 0.4 s per
  // process (2.4 s under AddressSanitizer) before any test ran.
  using Maker = std::function<std::string()>;
  MeshFileCase(std::string name, std::string extension, std::string bytes, std::string refusal = "",
               bool large = false);
  MeshFileCase(std::string name, std::string extension, Maker makeBytes, std::string refusal = "", bool large = false);

  std::string name;       // unique, usable as a file name stem
  std::string extension;  // ".obj", ".ply", ...
  // Empty for a well-formed file; otherwise a phrase the error message must hold.
  std::string refusal;
  bool large = false;  // over 64 KB: too big to seed a fuzzer with

  // The file's bytes, made on first use (and shared by copies of the case).
  const std::string& bytes() const;

private:
  struct Bytes {
    Maker make;
    std::string made;
    bool done = false;
  };
  std::shared_ptr<Bytes> bytes_;
};

// Names the case in test listings (GoogleTest finds it by its argument's namespace).
inline void PrintTo(const MeshFileCase& c, std::ostream* out) { *out << c.name; }

// Well-formed files: each reads as a closed, outward tetrahedron or cube
// (volume 1/6 or 1), whatever the format's variant.
std::vector<MeshFileCase> wellFormedMeshFiles();

// Malformed and hostile files, each refused with its `refusal` phrase.
std::vector<MeshFileCase> hostileMeshFiles();

}  // namespace lbmshape::testing
