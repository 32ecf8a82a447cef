#include "support/mesh_file_cases.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <utility>

#include <nlohmann/json.hpp>

namespace lbmshape::testing {
namespace {

// The unit tetrahedron: corners (0,0,0), (1,0,0), (0,1,0), (0,0,1), faces outward.
constexpr std::array<std::array<float, 3>, 4> corners{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
constexpr std::array<std::array<uint32_t, 3>, 4> faces{{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};

const std::string tetraObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

template <typename T>
std::string little(T value)
{
  std::string bytes(sizeof(T), '\0');
  std::memcpy(bytes.data(), &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  return bytes;
}

template <typename T>
std::string big(T value)
{
  std::string bytes = little(value);
  std::reverse(bytes.begin(), bytes.end());
  return bytes;
}

std::string repeat(const std::string& text, size_t times)
{
  std::string out;
  out.reserve(text.size() * times);
  for (size_t i = 0; i < times; ++i) out += text;
  return out;
}

// ---- PLY -------------------------------------------------------------------

std::string plyAsciiTetra(const std::string& faceLines)
{
  return "ply\nformat ascii 1.0\ncomment made by the tests\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n1 0 0\n0 1 0\n0 0 1\n" +
         faceLines;
}

const std::string tetraPlyFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// Binary, with x as double, y as float and z as uint (all legal PLY), a
// colour per vertex and an extra element with a list, all to be read past.
std::string plyBinaryTetra(bool bigEndian)
{
  std::string text = std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                     " 1.0\nelement vertex 4\nproperty double x\nproperty float y\nproperty uint z\n"
                     "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                     "element face 4\nproperty list uchar uint vertex_indices\nproperty float quality\n"
                     "element edge 1\nproperty list ushort int vertices\nend_header\n";
  auto put = [&](auto value) { text += bigEndian ? big(value) : little(value); };
  for (const auto& c : corners) {
    put(double(c[0]));
    put(float(c[1]));
    put(uint32_t(c[2]));
    put(uint8_t(200)), put(uint8_t(100)), put(uint8_t(50));
  }
  for (const auto& f : faces) {
    put(uint8_t(3));
    for (uint32_t i : f) put(i);
    put(1.5f);
  }
  put(uint16_t(2)), put(int32_t(0)), put(int32_t(1));
  return text;
}

// ---- OFF and STL -----------------------------------------------------------

std::string offBinaryTetra()
{
  std::string text = "OFF BINARY\n";
  text += big(int32_t(4)) + big(int32_t(4)) + big(int32_t(6));
  for (const auto& c : corners)
    for (float v : c) text += big(v);
  for (const auto& f : faces) {
    text += big(int32_t(3));
    for (uint32_t i : f) text += big(int32_t(i));
    text += big(int32_t(0));  // no colour
  }
  return text;
}

std::string stlAscii(const std::string& facetBody, const std::string& end = "endsolid tetra\n")
{
  return "solid tetra\n facet normal 0 0 -1\n  outer loop\n" + facetBody + "  endloop\n endfacet\n" + end;
}

std::string stlAsciiTetra(bool upperCase)
{
  std::string text = upperCase ? "SOLID tetra\n" : "solid tetra\n";
  for (const auto& f : faces) {
    text += upperCase ? " FACET NORMAL 0 0 0\n  OUTER LOOP\n" : " facet normal 0 0 0\n  outer loop\n";
    for (uint32_t i : f)
      text += std::string(upperCase ? "   VERTEX " : "   vertex ") + std::to_string(corners[i][0]) + " " +
              std::to_string(corners[i][1]) + " " + std::to_string(corners[i][2]) + "\n";
    text += upperCase ? "  ENDLOOP\n ENDFACET\n" : "  endloop\n endfacet\n";
  }
  return text + (upperCase ? "ENDSOLID tetra\n" : "endsolid tetra\n");
}

std::string stlBinaryTetra(const std::string& headerStart)
{
  std::string text = headerStart;
  text.resize(80, ' ');
  text += little(uint32_t(faces.size()));
  for (const auto& f : faces) {
    for (int k = 0; k < 3; ++k) text += little(0.f);  // normal
    for (uint32_t i : f)
      for (float v : corners[i]) text += little(v);
    text += little(uint16_t(0));
  }
  return text;
}

// ---- glTF ------------------------------------------------------------------

std::string base64(const std::string& bytes)
{
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 2]));
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[n & 63] : '=';
  }
  return out;
}

// A glTF file put together in code: one buffer, embedded as a data: URI in
// a .gltf or as the binary chunk of a .glb.
struct Gltf {
  nlohmann::json json = {{"asset", {{"version", "2.0"}}}};
  std::string buffer;

  int view(const std::string& bytes)
  {
    buffer.resize((buffer.size() + 3) / 4 * 4, '\0');
    json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", bytes.size()}});
    buffer += bytes;
    return int(json["bufferViews"].size() - 1);
  }
  int accessor(nlohmann::json a)
  {
    json["accessors"].push_back(std::move(a));
    return int(json["accessors"].size() - 1);
  }
  int positions()
  {
    std::string bytes;
    for (const auto& c : corners)
      for (float v : c) bytes += little(v);
    return accessor({{"bufferView", view(bytes)},
                     {"componentType", 5126},
                     {"count", 4},
                     {"type", "VEC3"},
                     {"min", {0, 0, 0}},
                     {"max", {1, 1, 1}}});
  }
  int indices()
  {
    std::string bytes;
    for (const auto& f : faces)
      for (uint32_t i : f) bytes += little(i);
    return accessor({{"bufferView", view(bytes)}, {"componentType", 5125}, {"count", 12}, {"type", "SCALAR"}});
  }
  void mesh(int positionAccessor, int indexAccessor)
  {
    json["meshes"].push_back(
        {{"primitives", {{{"attributes", {{"POSITION", positionAccessor}}}, {"indices", indexAccessor}}}}});
  }
  // A tetrahedron as mesh 0, shown by node 0 in scene 0.
  static Gltf tetra()
  {
    Gltf g;
    const int p = g.positions(), i = g.indices();
    g.mesh(p, i);
    g.json["nodes"] = {{{"mesh", 0}}};
    g.json["scenes"] = {{{"nodes", {0}}}};
    g.json["scene"] = 0;
    return g;
  }

  std::string gltf() const
  {
    nlohmann::json out = json;
    out["buffers"] = {
        {{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}};
    return out.dump();
  }
  // `change` edits the final JSON (buffers included) before it is written.
  std::string glb(const std::function<void(nlohmann::json&)>& change = {}) const
  {
    nlohmann::json out = json;
    out["buffers"] = {{{"byteLength", buffer.size()}}};
    if (change) change(out);
    std::string text = out.dump();
    text.resize((text.size() + 3) / 4 * 4, ' ');
    std::string binary = buffer;
    binary.resize((binary.size() + 3) / 4 * 4, '\0');
    return "glTF" + little(uint32_t(2)) + little(uint32_t(28 + text.size() + binary.size())) +
           little(uint32_t(text.size())) + "JSON" + text + little(uint32_t(binary.size())) + std::string("BIN\0", 4) +
           binary;
  }
  // With an external buffer file instead of embedded data.
  std::string gltfWithUri(const std::string& uri) const
  {
    nlohmann::json out = json;
    out["buffers"] = {{{"byteLength", buffer.size()}, {"uri", uri}}};
    return out.dump();
  }
};

// `glb` with `more` appended, its header's length made the new one (a GLB
// whose length differs from its file's is refused).
std::string glbWithMore(std::string glb, const std::string& more)
{
  glb += more;
  return glb.replace(8, 4, little(uint32_t(glb.size())));
}

Gltf tetraWith(const std::function<void(Gltf&)>& change)
{
  Gltf g = Gltf::tetra();
  change(g);
  return g;
}

// A chain of nodes `depth` long, the last one holding the tetrahedron.
Gltf nodeChain(size_t depth)
{
  Gltf g = Gltf::tetra();
  nlohmann::json nodes = nlohmann::json::array();
  for (size_t i = 0; i + 1 < depth; ++i) nodes.push_back({{"children", {i + 1}}});
  nodes.push_back({{"mesh", 0}});
  g.json["nodes"] = nodes;
  return g;
}

}  // namespace

std::vector<MeshFileCase> wellFormedMeshFiles()
{
  std::vector<MeshFileCase> cases = {
      {"obj_tetra", ".obj", tetraObj, "", false},
      {"obj_cube_of_quads_in_every_corner_form", ".obj",
       "# a cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvt 0 0\nvn 0 0 1\n"
       "g cube\no cube\ns off\nusemtl none\nf 1 4 3 2\nf 5/1 6/1 7/1 8/1\nf 1//1 2//1 6//1 5//1\nf 2/1/1 3/1/1 7/1/1 "
       "6/1/1\n"
       "f -5 -1 -2 -6\nf -8 -4 -1 -5\nl 1 2\n",
       "", false},
      {"obj_windows_line_ends_colours_and_w", ".obj",
       "v 0 0 0 1\r\nv 1 0 0 1 0 0\r\nv 0 1 0 0 1 0\r\nv 0 0 1 0.5 0.5 0.5\r\nf 1 3 2\r\nf 1 2 4\r\nf 1 4 3\r\nf 2 3 4",
       "", false},
      {"obj_face_of_no_corners_skipped", ".obj", tetraObj + "f\n", "", false},
      {"obj_with_byte_order_mark", ".obj", "\xEF\xBB\xBF" + tetraObj, "", false},
      {"obj_line_continuations_and_comments", ".obj",
       "# a tetrahedron\nv 0 0 0 # the origin\nv 1 0 \\\n  0\nv 0 1 0\nv 0 0 1\nf 1 3 2 # base\nf 1 2 \\\n4\nf 1 4 "
       "3\nf 2 3 4\n",
       "", false},
      {"obj_fan_of_one_repeated_vertex", ".obj", [] { return tetraObj + "f 1" + repeat(" 1", 200000) + "\n"; }, "",
       true},
      {"ply_ascii_tetra", ".ply", plyAsciiTetra(tetraPlyFaces), "", false},
      {"ply_binary_little_endian_mixed_types", ".ply", plyBinaryTetra(false), "", false},
      {"ply_binary_big_endian_mixed_types", ".ply", plyBinaryTetra(true), "", false},
      {"ply_faces_before_vertices", ".ply",
       "ply\nformat ascii 1.0\nelement face 4\nproperty list uchar int vertex_index\nelement vertex 4\n"
       "property float x\nproperty float y\nproperty float z\nend_header\n" +
           tetraPlyFaces + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
       "", false},
      {"off_tetra", ".off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", "", false},
      {"off_counts_on_the_keyword_line_comments_and_colours", ".off",
       "COFF 4 4 6 # counts here\n# a comment\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n\n0 1 0 0 0 1 1\n0 0 1 1 1 1 1\n"
       "3 0 2 1 255 0 0\n3 0 1 3\n3 0 3 2 0.5 0.5 0.5 1\n3 1 2 3\n",
       "", false},
      {"off_without_keyword", ".off", "4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", "",
       false},
      {"off_binary", ".off", offBinaryTetra(), "", false},
      {"stl_ascii", ".stl", stlAsciiTetra(false), "", false},
      {"stl_ascii_upper_case", ".stl", stlAsciiTetra(true), "", false},
      {"stl_binary", ".stl", stlBinaryTetra("made by the tests"), "", false},
      {"stl_binary_whose_header_says_solid", ".stl", stlBinaryTetra("solid but binary"), "", false},
      {"gltf_tetra", ".gltf", Gltf::tetra().gltf(), "", false},
      {"glb_tetra", ".glb", Gltf::tetra().glb(), "", false},
      {"gltf_sparse_positions_over_zeros", ".gltf",
       tetraWith([](Gltf& g) {
         // Corner 0 is (0,0,0) already; the three others come from the sparse part.
         std::string idx = little(uint16_t(1)) + little(uint16_t(2)) + little(uint16_t(3));
         std::string values;
         for (int c = 1; c < 4; ++c)
           for (float v : corners[size_t(c)]) values += little(v);
         const int iv = g.view(idx), vv = g.view(values);
         g.json["accessors"][0] = {{"componentType", 5126},
                                   {"count", 4},
                                   {"type", "VEC3"},
                                   {"sparse",
                                    {{"count", 3},
                                     {"indices", {{"bufferView", iv}, {"componentType", 5123}}},
                                     {"values", {{"bufferView", vv}}}}}};
       }).gltf(),
       "", false},
      {"glb_nodes_translated_and_short_indices", ".glb",
       tetraWith([](Gltf& g) {
         std::string idx;
         for (const auto& f : faces)
           for (uint32_t i : f) idx += little(uint16_t(i));
         g.json["accessors"][1] = {
             {"bufferView", g.view(idx)}, {"componentType", 5123}, {"count", 12}, {"type", "SCALAR"}};
         g.json["nodes"] = {{{"translation", {5, 0, 0}}, {"children", {1}}}, {{"mesh", 0}, {"translation", {0, 2, 0}}}};
       }).glb(),
       "", false},
      {"glb_with_a_chunk_of_an_unknown_type", ".glb",
       glbWithMore(Gltf::tetra().glb(), little(uint32_t(4)) + "XTRA" + "data"), "", false},
      // A base shape with vertex 1 at x = 0.5 and a morph target that moves
      // it by 1, weighted 0.5 by the mesh: the unit tetrahedron, as a
      // viewer shows it (the base shape alone is half its volume).
      {"gltf_weighted_morph_target", ".gltf",
       [] {
         Gltf g = Gltf::tetra();
         std::string base, move;
         for (size_t c = 0; c < corners.size(); ++c)
           for (int k = 0; k < 3; ++k) {
             base += little(c == 1 && k == 0 ? 0.5f : corners[c][size_t(k)]);
             move += little(c == 1 && k == 0 ? 1.0f : 0.0f);
           }
         g.json["accessors"][0]["bufferView"] = g.view(base);
         const int target = g.accessor({{"bufferView", g.view(move)},
                                        {"componentType", 5126},
                                        {"count", 4},
                                        {"type", "VEC3"},
                                        {"min", {0, 0, 0}},
                                        {"max", {1, 0, 0}}});
         g.json["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", target}}};
         g.json["meshes"][0]["weights"] = {0.5};
         return g.gltf();
       }(),
       "", false},
      {"gltf_rotation_a_little_off_unit_length", ".gltf", tetraWith([](Gltf& g) {
                                                            g.json["nodes"][0]["rotation"] = {0, 0, 0, 1.001};
                                                          }).gltf(),
       "", false},
      {"gltf_node_chain_100000_deep", ".gltf", [] { return nodeChain(100000).gltf(); }, "", true},
  };
  return cases;
}

std::vector<MeshFileCase> hostileMeshFiles()
{
  const std::string finite = "three finite coordinates";
  std::vector<MeshFileCase> cases = {
      // OBJ
      {"obj_corner_without_vertex_number", ".obj", tetraObj + "f /1\n", "has no vertex number"},
      {"obj_vertex_with_two_coordinates", ".obj", "v 1 2\n" + tetraObj, finite},
      {"obj_vertex_nan", ".obj", "v nan 0 0\n" + tetraObj, finite},
      {"obj_vertex_infinite", ".obj", "v 0 inf 0\n" + tetraObj, finite},
      {"obj_vertex_beyond_float", ".obj", "v 0 0 1e39\n" + tetraObj, "magnitude at most 3.4e38"},
      {"obj_vertex_word", ".obj", "v abc 0 0\n" + tetraObj, finite},
      {"obj_corner_of_three_slashes", ".obj", tetraObj + "f 1///1 2 3\n", "is not of the form v, v/vt, v/vt/vn or v//vn"},
      {"obj_corner_with_a_word_for_its_normal", ".obj", tetraObj + "f 1 2 3//n\n", "'3//n' is not of the form"},
      {"obj_bare_v_before_the_vertices", ".obj", "v\n" + tetraObj, "line 1: 'v' is not a vertex"},
      {"obj_two_vertices_on_one_line", ".obj", "v 0 0 0\nv 1 0 0\rv 9 9 9\nv 0 1 0\nv 0 0 1\n" + tetraObj,
       "a carriage return inside the line"},
      {"obj_vertex_with_a_word_after_it", ".obj", "v 0 0 1 foo\n" + tetraObj, "and nothing else"},
      {"obj_vertex_of_five_numbers", ".obj", "v 0 0 1 1 1\n" + tetraObj, "and nothing else"},
      {"obj_index_zero", ".obj", tetraObj + "f 0 1 2\n", "start at 1"},
      {"obj_index_beyond_the_vertices", ".obj", tetraObj + "f 1 2 99\n", "vertex number 99"},
      {"obj_index_beyond_64_bits", ".obj", tetraObj + "f 1 2 99999999999999999999999\n", "has no vertex number"},
      {"obj_relative_index_before_the_first_vertex", ".obj", tetraObj + "f -1 -2 -9\n", "only 4 vertices come before"},
      {"obj_no_faces", ".obj", "v 0 0 0\nv 1 0 0\n", "no triangles"},
      {"obj_nul_before_a_vertex", ".obj", std::string("\0v 0 0 0\n", 9) + tetraObj, "holds the byte 0x00"},
      {"obj_no_break_space_after_v", ".obj",
       "v\xc2\xa0"
       "0 0 0\n" +
           tetraObj,
       "holds the byte 0xc2"},
      {"obj_empty", ".obj", "", "empty"},
      {"obj_two_tetrahedra_a_million_apart", ".obj",
       tetraObj + "v 1e6 0 0\nv 1000001 0 0\nv 1e6 1 0\nv 1e6 0 1\nf 5 7 6\nf 5 6 8\nf 5 8 7\nf 6 7 8\n",
       "its bounding box is 1e+06 along x but 1 along y: flat on any grid"},
      // Compressed files, whichever name they were given.
      {"obj_gzip_compressed", ".obj", std::string("\x1f\x8b\x08\x00", 4) + repeat("x", 200), "gzip-compressed"},
      {"ply_zip_compressed", ".ply", std::string("PK\x03\x04", 4) + repeat("x", 200), "zip-compressed"},
      {"stl_gzip_compressed", ".stl", std::string("\x1f\x8b\x08\x00", 4) + repeat("x", 200), "gzip-compressed"},
      {"glb_xz_compressed", ".glb", std::string("\xfd" "7zXZ\x00", 6) + repeat("x", 200), "xz-compressed"},
      // PLY
      {"ply_property_before_any_element", ".ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n",
       "property before any element"},
      {"ply_header_without_end", ".ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n" + repeat("0 0 0\n", 50),
       "unknown header line '0 0 0'"},
      {"ply_header_cut_short", ".ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n",
       "no 'end_header'"},
      {"ply_not_ply", ".ply", "plx\n" + tetraObj, "not a PLY file"},
      {"ply_unknown_format", ".ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown format"},
      {"ply_unknown_type", ".ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n",
       "unknown property type"},
      // ASCII PLY keeps an entry to a line: values one too few or too many
      // (a vertex count one too high, a vertex of two coordinates) shift
      // every later value onto the wrong property if read as one stream.
      {"ply_vertex_line_of_two_values", ".ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 4\nproperty list uchar int vertex_indices\nend_header\n0 0\n0 1 0 0\n0 1 0\n0 0 1\n" +
           tetraPlyFaces,
       "line 10: vertex 1 of 4: its line ends after 2 values"},
      {"ply_vertex_line_of_five_values", ".ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0 7 7\n1 0 0\n0 1 0\n0 0 1\n" +
           tetraPlyFaces,
       "more values than the header's properties"},
      {"ply_vertex_count_one_too_high", ".ply",
       "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" +
           tetraPlyFaces,
       "more values than the header's properties"},
      {"ply_face_count_one_too_low", ".ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 3\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" +
           tetraPlyFaces,
       "values follow line 16, the last entry the header counts"},
      {"ply_property_named_twice", ".ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
       "property float x\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
       "0 0 0 0\n1 0 0 3\n0 1 0 0\n0 0 1 0\n" +
           tetraPlyFaces,
       "element 'vertex' already has a property 'x'"},
      {"ply_list_of_minus_one", ".ply", plyAsciiTetra("3 0 2 1\n-1 0 1 3\n3 0 3 2\n3 1 2 3\n"), "a list of -1 items"},
      {"ply_list_of_two_billion", ".ply", plyAsciiTetra("3 0 2 1\n2000000000 0 1 3\n3 0 3 2\n3 1 2 3\n"),
       "longer than the rest of the file"},
      {"ply_vertex_count_two_to_the_62", ".ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 4611686018427387904\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n" +
           repeat(little(0.f), 12),
       "more than the 2^32 - 1 lbmshape can index"},
      {"ply_face_count_beyond_the_file", ".ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1000000\nproperty list uchar int vertex_indices\nend_header\n" +
           repeat(little(0.f), 12),
       "more than the rest of the file can hold"},
      {"ply_binary_cut_short", ".ply", plyBinaryTetra(false).substr(0, plyBinaryTetra(false).size() - 40),
       "longer than the rest of the file"},
      {"ply_binary_cut_inside_a_vertex", ".ply",
       plyBinaryTetra(false).substr(0, plyBinaryTetra(false).find("end_header") + 11 + 30),
       "more than the rest of the file can hold"},
      {"ply_ascii_cut_short", ".ply", plyAsciiTetra("3 0 2 1\n3 0 1 3\n3 0 3"), "ends in the middle"},
      {"ply_index_beyond_the_vertices", ".ply", plyAsciiTetra("3 0 2 1\n3 0 1 7\n3 0 3 2\n3 1 2 3\n"),
       "refers to vertex 7"},
      {"ply_without_vertices", ".ply",
       "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n3 0 1 2\n",
       "no 'vertex' element"},
      {"ply_vertex_without_z", ".ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
       "no 'z' property"},
      {"ply_float_indices", ".ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
       "property list uchar float vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
       "not a list of integers"},
      {"ply_word_in_the_body", ".ply", plyAsciiTetra(tetraPlyFaces).replace(plyAsciiTetra("").size() - 6, 1, "abc"),
       "is not a number"},
      {"ply_a_thousand_and_one_elements", ".ply",
       [] {
         std::string text = "ply\nformat ascii 1.0\n";
         for (int e = 0; e < 1001; ++e) text += "element e" + std::to_string(e) + " 0\n";
         return text + "end_header\n";
       }(),
       "more than 1000 elements"},
      {"ply_element_named_with_control_bytes", ".ply",
       "ply\nformat ascii 1.0\nelement \x1b]0;x\x07\xff -1\nend_header\n", "negative count"},
      // OFF
      {"off_keyword_alone", ".off", "OFF\n", "before the vertex and face counts"},
      {"off_negative_vertex_count", ".off", "OFF\n-1 12 0\n0 0 0\n", "negative counts"},
      {"off_counts_beyond_the_file", ".off", "OFF\n4294967295 1 0\n0 0 0\n", "more than the rest of the file can hold"},
      {"off_ends_before_its_vertices", ".off", "OFF\n8 6 0\n" + repeat("0.0000000000 0.0000000000 0.0000000000\n", 4),
       "ends after 4 of 8 vertices"},
      {"off_binary_followed_by_text", ".off", "OFF BINARY\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n",
       "more than the rest of the file can hold"},
      {"off_face_with_fewer_indices_than_announced", ".off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1\n",
       "announces 3 corners but gives 2"},
      {"off_index_beyond_the_vertices", ".off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 4\n",
       "refers to vertex '4'"},
      {"off_four_dimensional", ".off", "4OFF\n4 4 6\n0 0 0 0\n", "only three-dimensional"},
      {"off_face_beyond_the_count", ".off",
       "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 1 2\n",
       "follows the last of the 4 faces the header counts"},
      // STL
      {"stl_vertex_nan", ".stl", stlAscii("   vertex nan 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"), finite},
      {"stl_vertex_word", ".stl", stlAscii("   vertex abc 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"), finite},
      {"stl_vertex_with_two_coordinates", ".stl", stlAscii("   vertex 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"),
       finite},
      {"stl_vertex_beyond_float", ".stl", stlAscii("   vertex 1e39 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"), finite},
      {"stl_facet_with_four_vertices", ".stl",
       stlAscii("   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n   vertex 0 0 1\n"), "more than 3 vertices"},
      {"stl_facet_with_two_vertices", ".stl", stlAscii("   vertex 0 0 0\n   vertex 1 0 0\n"), "with 2 vertices"},
      {"stl_without_endsolid", ".stl", stlAscii("   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n", ""),
       "before 'endsolid'"},
      {"stl_binary_of_the_wrong_size", ".stl", stlBinaryTetra("binary").substr(0, 84 + 50 * 3 + 10),
       "header counts 4 triangles"},
      {"stl_too_short_for_anything", ".stl", "abc", "not an STL file"},
      {"stl_ascii_without_solid", ".stl", stlAsciiTetra(false).substr(stlAsciiTetra(false).find('\n') + 1),
       "does not begin with 'solid' (it begins with 'facet')"},
      {"stl_binary_with_nan_corners", ".stl",
       "binary" + std::string(74, ' ') + little(uint32_t(1000)) + std::string(50000, '\xff'), "not finite numbers"},
      {"stl_vertex_outside_a_facet", ".stl", "solid x\nvertex 0 0 0\nendsolid x\n", "expected 'facet' or 'endsolid'"},
      // glTF
      {"gltf_count_whose_size_wraps", ".gltf",
       tetraWith([](Gltf& g) { g.json["accessors"][0]["count"] = uint64_t(6148914691236517206ull); }).gltf(),
       "reads past the end of buffer view"},
      {"gltf_accessor_offset_near_2_to_the_64", ".gltf",
       tetraWith([](Gltf& g) { g.json["accessors"][0]["byteOffset"] = uint64_t(18446744073709551612ull); }).gltf(),
       "past the end of buffer view"},
      {"gltf_view_offset_near_2_to_the_64", ".gltf",
       tetraWith([](Gltf& g) { g.json["bufferViews"][0]["byteOffset"] = uint64_t(18446744073709551612ull); }).gltf(),
       "reaches past the end of its buffer"},
      {"gltf_count_two_to_the_62", ".gltf",
       tetraWith([](Gltf& g) { g.json["accessors"][0]["count"] = uint64_t(1) << 62; }).gltf(),
       "reads past the end of buffer view"},
      {"gltf_count_two_to_the_28_without_data", ".gltf",
       tetraWith([](Gltf& g) {
         g.json["accessors"][0] = {{"componentType", 5126}, {"count", uint64_t(1) << 28}, {"type", "VEC3"}};
       }).gltf(),
       "no data, more than a file of this size"},
      {"gltf_negative_sparse_offset", ".gltf",
       tetraWith([](Gltf& g) {
         g.json["accessors"][0]["sparse"] = {
             {"count", 1},
             {"indices", {{"bufferView", 1}, {"byteOffset", -8}, {"componentType", 5125}}},
             {"values", {{"bufferView", 0}}}};
       }).gltf(),
       "accessor 0's sparse indices: \"byteOffset\" must be a whole number of 0 or more; it is -8"},
      {"gltf_sparse_index_out_of_range", ".gltf", tetraWith([](Gltf& g) {
                                                    const int view = g.view(little(uint32_t(4000)));
                                                    g.json["accessors"][0]["sparse"] = {
                                                        {"count", 1},
                                                        {"indices", {{"bufferView", view}, {"componentType", 5125}}},
                                                        {"values", {{"bufferView", 0}}}};
                                                  }).gltf(),
       "sparse index out of range"},
      {"gltf_stride_shorter_than_an_element", ".gltf",
       tetraWith([](Gltf& g) { g.json["bufferViews"][0]["byteStride"] = 4; }).gltf(), "less than an element"},
      {"gltf_index_beyond_the_vertices", ".gltf",
       tetraWith([](Gltf& g) {
         std::string idx;
         for (uint32_t i : {0u, 1u, 2u, 0u, 1u, 9u}) idx += little(i);
         g.json["accessors"][1] = {
             {"bufferView", g.view(idx)}, {"componentType", 5125}, {"count", 6}, {"type", "SCALAR"}};
       }).gltf(),
       "has index 9 but only 4 vertices"},
      {"gltf_nodes_sharing_children_20_levels", ".gltf", tetraWith([](Gltf& g) {
                                                           nlohmann::json nodes = nlohmann::json::array();
                                                           for (int i = 0; i < 20; ++i)
                                                             nodes.push_back({{"children", {i + 1, i + 1}}});
                                                           nodes.push_back({{"mesh", 0}});
                                                           g.json["nodes"] = nodes;
                                                         }).gltf(),
       "glTF nodes form trees"},
      {"gltf_node_with_two_parents", ".gltf",
       tetraWith([](Gltf& g) {
         g.json["nodes"] = {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}};
         g.json["scenes"] = {{{"nodes", {0, 1}}}};
       }).gltf(),
       "glTF nodes form trees"},
      {"gltf_node_cycle", ".gltf", tetraWith([](Gltf& g) {
                                     g.json["nodes"] = {{{"children", {1}}, {"mesh", 0}}, {{"children", {0}}}};
                                   }).gltf(),
       "is its own ancestor"},
      {"gltf_node_its_own_child", ".gltf", tetraWith([](Gltf& g) {
                                             g.json["nodes"] = {{{"children", {0}}, {"mesh", 0}}};
                                           }).gltf(),
       "is its own ancestor"},
      {"gltf_scene_lists_a_child", ".gltf", tetraWith([](Gltf& g) {
                                              g.json["nodes"] = {{{"children", {1}}}, {{"mesh", 0}}};
                                              g.json["scenes"] = {{{"nodes", {1}}}};
                                            }).gltf(),
       "a scene lists root nodes"},
      {"gltf_extras_nested_50000_deep", ".gltf",
       [] {
         std::string text = Gltf::tetra().gltf();
         text.insert(1, "\"extras\":" + repeat("[", 50000) + repeat("]", 50000) + ",");
         return text;
       },
       "nests more than 64 levels", true},
      {"gltf_buffer_uri_leaving_the_folder", ".gltf", Gltf::tetra().gltfWithUri("../../../../etc/passwd"),
       "leaves the glTF file's folder"},
      {"gltf_buffer_uri_percent_encoded_parent", ".gltf", Gltf::tetra().gltfWithUri("sub/%2e%2e/%2E%2E/etc/passwd"),
       "leaves the glTF file's folder"},
      {"gltf_buffer_uri_absolute", ".gltf", Gltf::tetra().gltfWithUri("/etc/passwd"), "is an absolute path"},
      {"gltf_buffer_uri_with_a_scheme", ".gltf", Gltf::tetra().gltfWithUri("https://example.com/tetra.bin"),
       "names a scheme other than data:"},
      {"gltf_instanced_beyond_any_sensible_size", ".gltf",
       [] {
         // 3,000 vertices placed 4,000 times: 12 million vertices from 100 KB.
         Gltf g;
         std::string positions;
         for (int v = 0; v < 3000; ++v)
           for (float c : {float(v % 10), float(v / 10 % 10), float(v / 100)}) positions += little(c);
         const int p = g.accessor(
             {{"bufferView", g.view(positions)}, {"componentType", 5126}, {"count", 3000}, {"type", "VEC3"}});
         g.json["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}}}}}}}};
         nlohmann::json nodes = nlohmann::json::array();
         for (int n = 0; n < 4000; ++n) nodes.push_back({{"mesh", 0}});
         g.json["nodes"] = nodes;
         return g.gltf();
       },
       "more geometry than lbmshape reads", true},
      {"gltf_many_primitives_placed_many_times", ".gltf",
       [] {
         Gltf g = Gltf::tetra();
         nlohmann::json primitives = nlohmann::json::array();
         for (int p = 0; p < 2000; ++p) primitives.push_back({{"attributes", nlohmann::json::object()}});
         g.json["meshes"] = {{{"primitives", primitives}}};
         nlohmann::json nodes = nlohmann::json::array();
         for (int n = 0; n < 2000; ++n) nodes.push_back({{"mesh", 0}});
         g.json["nodes"] = nodes;
         g.json.erase("scenes");
         g.json.erase("scene");
         return g.gltf();
       },
       "places its meshes 2000 times", true},
      {"gltf_two_buffers_on_one_file", ".gltf",
       [] {
         nlohmann::json json = nlohmann::json::parse(Gltf::tetra().gltfWithUri("tetra.bin"));
         json["buffers"].push_back(json["buffers"][0]);
         return json.dump();
       }(),
       "that another buffer already names"},
      {"glb_second_buffer_without_uri", ".glb",
       Gltf::tetra().glb([](nlohmann::json& json) { json["buffers"].push_back(json["buffers"][0]); }),
       "only buffer 0 may refer to the GLB"},
      {"glb_buffer_of_zero_bytes", ".glb",
       Gltf::tetra().glb([](nlohmann::json& json) { json["buffers"][0]["byteLength"] = 0; }),
       "no byteLength of at least 1"},
      {"glb_binary_chunk_longer_than_the_file", ".glb",
       [] {
         std::string bytes = Gltf::tetra().glb();
         const size_t jsonLength = size_t(bytes[12] & 0xff) | size_t(bytes[13] & 0xff) << 8;
         bytes.replace(20 + jsonLength, 4, little(uint32_t(1) << 20));
         return bytes;
       }(),
       "GLB chunk 2 claims 1048576 bytes"},
      {"gltf_accessor_of_no_elements_past_its_view", ".gltf", tetraWith([](Gltf& g) {
                                                                g.json["accessors"][0]["count"] = 0;
                                                                g.json["accessors"][0]["byteOffset"] =
                                                                    uint64_t(18446744073709551615ull);
                                                              }).gltf(),
       "begins past the end of buffer view"},
      {"gltf_image_view_past_its_buffer", ".gltf",
       tetraWith([](Gltf& g) {
         g.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 1000000000}, {"byteLength", 16}});
         g.json["images"] = {{{"bufferView", g.json["bufferViews"].size() - 1}, {"mimeType", "image/png"}}};
       }).gltf(),
       "reaches past the end of its buffer"},
      {"gltf_extras_of_three_million_values", ".gltf",
       [] {
         std::string text = Gltf::tetra().gltf();
         text.insert(1, "\"extras\":[" + repeat("0,", 3000000) + "0],");
         return text;
       },
       "more than a glTF file of this size needs", true},
      {"gltf_malformed_json", ".gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [", "JSON is malformed"},
      {"gltf_empty", ".gltf", "", "empty"},
      {"glb_without_magic", ".glb", "glTX" + Gltf::tetra().glb().substr(4), "no 'glTF' magic"},
      {"glb_json_chunk_longer_than_the_file", ".glb",
       [] {
         std::string bytes = Gltf::tetra().glb();
         const std::string length = little(uint32_t(1) << 30);
         bytes.replace(12, 4, length);
         return bytes;
       }(),
       "first GLB chunk"},
      // Properties of the wrong type or length, which tinygltf reads as
      // absent: each gave another shape and exit 0.
      {"gltf_default_scene_that_does_not_exist", ".gltf", tetraWith([](Gltf& g) { g.json["scene"] = 5; }).gltf(),
       "default scene is scene 5, but it has 1 scene"},
      {"gltf_node_mesh_as_a_string", ".gltf", tetraWith([](Gltf& g) { g.json["nodes"][0]["mesh"] = "0"; }).gltf(),
       "node 0's \"mesh\" must be a whole number"},
      {"gltf_negative_accessor_offset", ".gltf",
       tetraWith([](Gltf& g) { g.json["accessors"][1]["byteOffset"] = -4; }).gltf(),
       "accessor 1's \"byteOffset\" must be a whole number of 0 or more; it is -4"},
      {"gltf_translation_not_all_numbers", ".gltf",
       tetraWith([](Gltf& g) { g.json["nodes"][0]["translation"] = {"a", 0, 0}; }).gltf(),
       "\"translation\" must be an array of 3 numbers; it is an array of 3 values, not all numbers"},
      {"gltf_matrix_of_12_numbers", ".gltf",
       tetraWith([](Gltf& g) { g.json["nodes"][0]["matrix"] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0}; }).gltf(),
       "must be an array of 16 numbers; it is an array of 12 numbers"},
      {"gltf_matrix_beside_a_translation", ".gltf", tetraWith([](Gltf& g) {
                                                      g.json["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0,
                                                                                      0, 0, 1, 0, 0, 0, 0, 1};
                                                      g.json["nodes"][0]["translation"] = {1, 0, 0};
                                                    }).gltf(),
       "both a matrix and a translation"},
      {"gltf_projective_matrix", ".gltf", tetraWith([](Gltf& g) {
                                            g.json["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0,
                                                                            0, 0, 1, 1, 0, 0, 0, 1};
                                          }).gltf(),
       "matrix is not affine"},
      {"gltf_rotation_of_zeros", ".gltf",
       tetraWith([](Gltf& g) { g.json["nodes"][0]["rotation"] = {0, 0, 0, 0}; }).gltf(), "not a unit quaternion"},
      {"gltf_mode_minus_one", ".gltf",
       tetraWith([](Gltf& g) { g.json["meshes"][0]["primitives"][0]["mode"] = -1; }).gltf(),
       "mesh 0 primitive 0's \"mode\" must be a whole number"},
      {"gltf_mode_nine", ".gltf", tetraWith([](Gltf& g) { g.json["meshes"][0]["primitives"][0]["mode"] = 9; }).gltf(),
       "mode 9 is not a glTF primitive mode"},
      {"gltf_a_key_twice_in_a_node", ".gltf",
       [] {
         std::string text = Gltf::tetra().gltf();
         const size_t node = text.find("{\"mesh\":0}");
         return text.replace(node, 10, "{\"mesh\":0,\"translation\":[5,0,0],\"translation\":\"x\"}");
       }(),
       "gives the key 'translation' twice in one object of node 0"},
      {"gltf_attribute_that_is_no_index", ".gltf",
       tetraWith([](Gltf& g) { g.json["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 0.5; }).gltf(),
       "mesh 0 primitive 0's attributes: \"NORMAL\" must be an accessor's index; it is 0.5"},
      {"gltf_scenes_as_an_object", ".gltf",
       tetraWith([](Gltf& g) {
         g.json.erase("scene");
         g.json["scenes"] = {{"s", {{"nodes", {0}}}}};
       }).gltf(),
       "its \"scenes\" must be an array of objects; it is an object"},
      {"gltf_normalized_as_a_string", ".gltf",
       tetraWith([](Gltf& g) { g.json["accessors"][0]["normalized"] = "true"; }).gltf(),
       "accessor 0's \"normalized\" must be true or false; it is 'true'"},
      {"gltf_sparse_offset_as_a_string", ".gltf",
       tetraWith([](Gltf& g) {
         g.json["accessors"][0]["sparse"] = {{"count", 1},
                                             {"indices", {{"bufferView", 1}, {"byteOffset", "2"}, {"componentType", 5125}}},
                                             {"values", {{"bufferView", 0}}}};
       }).gltf(),
       "accessor 0's sparse indices: \"byteOffset\" must be a whole number"},
      {"gltf_required_extensions_as_a_string", ".gltf",
       tetraWith([](Gltf& g) { g.json["extensionsRequired"] = "EXT_mesh_gpu_instancing"; }).gltf(),
       "its \"extensionsRequired\" must be an array of strings"},
      {"gltf_morph_target_of_other_length", ".gltf",
       tetraWith([](Gltf& g) {
         const int three = g.accessor({{"bufferView", g.view(repeat(little(0.0f), 9))},
                                       {"componentType", 5126},
                                       {"count", 3},
                                       {"type", "VEC3"}});
         g.json["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", three}}};
         g.json["meshes"][0]["weights"] = {1.0};
       }).gltf(),
       "morph target 0 POSITION"},
      {"glb_of_version_1", ".glb",
       [] {
         std::string bytes = Gltf::tetra().glb();
         return bytes.replace(4, 4, little(uint32_t(1)));
       }(),
       "GLB file of version 1"},
      {"glb_header_alone", ".glb", "glTF" + little(uint32_t(2)) + little(uint32_t(12)), "before any JSON chunk"},
      {"glb_third_chunk_longer_than_the_file", ".glb",
       glbWithMore(Gltf::tetra().glb(), little(uint32_t(1) << 31) + "XTRA"),
       "chunk 3 claims 2147483648 bytes, but 0 follow"},
      {"glb_with_bytes_beyond_its_length", ".glb", Gltf::tetra().glb() + "junk", "(bytes appended, or a damaged header)"},
      {"glb_count_whose_size_wraps", ".glb",
       tetraWith([](Gltf& g) { g.json["accessors"][0]["count"] = uint64_t(6148914691236517206ull); }).glb(),
       "reads past the end of buffer view"},
  };
  return cases;
}

MeshFileCase::MeshFileCase(std::string name, std::string extension, std::string bytes, std::string refusal, bool large)
    : name(std::move(name)), extension(std::move(extension)), refusal(std::move(refusal)), large(large),
      bytes_(std::make_shared<Bytes>(Bytes{nullptr, std::move(bytes), true}))
{}

MeshFileCase::MeshFileCase(std::string name, std::string extension, Maker makeBytes, std::string refusal, bool large)
    : name(std::move(name)), extension(std::move(extension)), refusal(std::move(refusal)), large(large),
      bytes_(std::make_shared<Bytes>(Bytes{std::move(makeBytes), {}, false}))
{}

const std::string& MeshFileCase::bytes() const
{
  if (!bytes_->done) {
    bytes_->made = bytes_->make();
    bytes_->done = true;
  }
  return bytes_->made;
}

}  // namespace lbmshape::testing
