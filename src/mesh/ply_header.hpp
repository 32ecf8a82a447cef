// The header of a PLY file: its encoding and the elements and properties its
// body holds, in order. Checked line by line, so that the body reader can
// trust every name, type and count it finds here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

size_t byteSize(PlyType type);
bool isInteger(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // of the value, or of each item of a list
  bool isList = false;
  PlyType countType = PlyType::UInt8;  // of a list's length
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;

  // The least number of bytes one entry takes in the body (a list counted as
  // empty): what a count is checked against before anything is reserved.
  size_t leastBytesPerEntry(PlyEncoding encoding) const;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  size_t bodyOffset = 0;     // of the first byte after "end_header\n"
  size_t bodyFirstLine = 0;  // the line number the body starts on (for ASCII messages)
};

// Throws InputError naming the line for anything but a well-formed header:
// "ply", one "format ascii|binary_little_endian|binary_big_endian 1.0",
// "comment" and "obj_info" lines, "element NAME COUNT", "property TYPE NAME",
// "property list COUNT_TYPE ITEM_TYPE NAME" (only after an element), and
// "end_header".
PlyHeader parsePlyHeader(const MeshSource& source);

}  // namespace lbmshape
