// libFuzzer target: any bytes, read as a mesh file of one format (chosen at
// build time), must give a mesh or an InputError; a crash, a sanitizer
// report, another exception, a hang or an allocation beyond libFuzzer's
// limit is a finding.
#include <cstddef>
#include <cstdint>
#include <iostream>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // Readers warn on std::cerr (skipped faces); millions of inputs would
  // bury libFuzzer's own report. Sanitizer reports go to the file
  // descriptor directly and still appear.
  lbmshape::log::setLevel(lbmshape::log::Level::Quiet);
  std::cerr.rdbuf(nullptr);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace lbmshape;
  static const MeshFormat format = *meshFormatOf("input." LBMSHAPE_FUZZ_FORMAT);
  // No folder: a glTF file's external buffers are refused, never opened.
  const MeshSource source{std::string_view(reinterpret_cast<const char*>(data), size), "fuzz input", std::nullopt};
  try {
    readMesh(source, format);
  } catch (const InputError&) {}
  return 0;
}
