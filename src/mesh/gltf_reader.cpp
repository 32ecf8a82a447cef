#include "lbmshape/mesh/gltf_reader.hpp"

#include <cmath>

#include <cstring>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "lbmshape/core/checked_arithmetic.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/mesh/gltf_accessors.hpp"
#include "lbmshape/mesh/gltf_file_access.hpp"
#include "lbmshape/mesh/gltf_json_check.hpp"
#include "lbmshape/mesh/colour_space.hpp"
#include "lbmshape/mesh/glb_container.hpp"
#include "lbmshape/mesh/gltf_meshopt_decoding.hpp"
#include "lbmshape/mesh/gltf_scene_walk.hpp"
#include "lbmshape/mesh/gltf_skinning.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// The geometry a scene may instance, in bytes of TriangleMesh: a file may
// place one mesh many times, but never so often that a small file fills
// the machine's memory.
uint64_t geometryBudget(uint64_t inputBytes) { return std::max<uint64_t>(uint64_t(256) << 20, 16 * inputBytes); }

// Images are never needed; this skips their decoding.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
  return true;
}

// The JSON of a .gltf file, or of a GLB container, whose chunks are checked
// here: tinygltf reads a binary chunk that claims more bytes than follow it.
std::string_view jsonOf(const MeshSource& source, MeshFormat format)
{
  if (format == MeshFormat::Gltf) return source.bytes;
  // GLB: magic, version, length; chunk 0: length, "JSON", bytes; then
  // optionally chunk 1: length, "BIN\0", bytes.
  const std::string_view bytes = source.bytes;
  if (bytes.size() < 12 || bytes.substr(0, 4) != "glTF") source.refuse("not a GLB file (no 'glTF' magic)");
  if (glbWord(bytes, 4) != 2)
    source.refuse("it is a GLB file of version " + std::to_string(glbWord(bytes, 4)) +
                  "; lbmshape reads version 2 (glTF 2.0)");
  if (glbWord(bytes, 8) > bytes.size()) source.refuse("its GLB header claims more bytes than the file has");
  if (glbWord(bytes, 8) < bytes.size())
    source.refuse("its GLB header says the file has " + std::to_string(glbWord(bytes, 8)) + " bytes, but it has " +
                  std::to_string(bytes.size()) + " (bytes appended, or a damaged header)");
  if (bytes.size() < 20) source.refuse("it ends after its GLB header, before any JSON chunk");
  const uint64_t jsonLength = glbWord(bytes, 12);
  if (bytes.substr(16, 4) != "JSON" || jsonLength > bytes.size() - 20)
    source.refuse("its first GLB chunk is not JSON that fits in the file");
  // The chunks after the JSON: the binary chunk, then any others, which a
  // reader skips; fewer than a chunk header's 8 bytes at the end are padding.
  uint64_t at = 20 + jsonLength;
  for (int chunk = 2; bytes.size() - at >= 8; ++chunk) {
    const uint64_t rest = bytes.size() - at - 8, length = glbWord(bytes, at);
    if (length > rest)
      source.refuse("its GLB chunk " + std::to_string(chunk) + " claims " + std::to_string(length) + " bytes, but " +
                    std::to_string(rest) + " follow it");
    if (chunk == 2 && bytes.substr(at + 4, 4) != std::string_view("BIN\0", 4))
      source.refuse("its GLB chunk 2 is not a binary chunk (BIN)");
    at += 8 + length;
  }
  return glbChunks(bytes).json;
}

tinygltf::Model load(const MeshSource& source, MeshFormat format, GltfFileAccess& files)
{
  if (source.bytes.size() > UINT32_MAX) source.refuse("it is larger than the 4 GiB a glTF file can be");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skipImage, nullptr);
  loader.SetFsCallbacks(files.callbacks());
  tinygltf::Model model;
  std::string error, warning;
  const auto* bytes = reinterpret_cast<const unsigned char*>(source.bytes.data());
  const auto size = static_cast<unsigned int>(source.bytes.size());
  bool ok = false;
  try {
    ok = format == MeshFormat::Glb
             ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes, size, files.baseDirectory())
             : loader.LoadASCIIFromString(&model, &error, &warning, source.bytes.data(), size, files.baseDirectory());
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    // What tinygltf throws (std::out_of_range on some malformed buffers) is
    // the file's fault like any other parse failure.
    source.refuse("not a readable " + formatName(format) + " file (" + text::printable(e.what()) + ")");
  }
  if (!warning.empty()) log::verbose("reading " + source.name + ": tinygltf: " + text::printable(warning));
  if (files.refusal()) source.refuse(*files.refusal());
  if (!ok)
    source.refuse("not a readable " + formatName(format) + " file (" +
                  (error.empty() ? std::string("no details") : text::printable(error)) + ")");
  return model;
}

class SoupBuilder {
public:
  SoupBuilder(const tinygltf::Model& model, const MeshSource& source, const GltfAccessors& accessors)
      : model_(model), source_(source), accessors_(accessors), skins_(model, source, accessors)
  {}

  // Counts what the instances would add, and refuses it beyond the budget
  // before anything is read or reserved. Each mesh is counted once: a file
  // may place a mesh of many primitives many times.
  void requireWithinBudget(const std::vector<GltfInstance>& instances, uint64_t budget, uint64_t inputBytes) const
  {
    struct Totals {
      uint64_t vertices = 0, triangles = 0;
      bool counted = false;
    };
    std::vector<Totals> perMesh(model_.meshes.size());
    uint64_t vertices = 0, triangles = 0, placedPrimitives = 0;
    for (const GltfInstance& instance : instances) {
      const auto& primitives = model_.meshes[size_t(instance.mesh)].primitives;
      Totals& t = perMesh[size_t(instance.mesh)];
      if (!t.counted) {
        for (size_t p = 0; p < primitives.size(); ++p) {
          const auto& primitive = primitives[p];
          const int mode = primitive.mode;  // one of glTF's (gltf_json_element.hpp); triangles when absent
          auto position = primitive.attributes.find("POSITION");
          if (!isTriangles(mode) || position == primitive.attributes.end()) continue;
          const std::string name = primitiveName(instance.mesh, p);
          const uint64_t v = accessors_.count(position->second, TINYGLTF_TYPE_VEC3, name + " POSITION");
          const uint64_t corners =
              primitive.indices >= 0 ? accessors_.count(primitive.indices, TINYGLTF_TYPE_SCALAR, name + " indices") : v;
          // Each morph target with positions is read too, where its weight
          // is not 0 (applyMorphTargets): counted as if every one were.
          uint64_t targets = 0;
          for (const auto& target : primitive.targets) targets += target.count("POSITION");
          // Saturated far beyond any budget, so that no sum below wraps.
          constexpr uint64_t beyondAnyBudget = uint64_t(1) << 56;
          const auto reads = checkedMultiply(v, 1 + targets);
          t.vertices =
              std::min(beyondAnyBudget, t.vertices + std::min(beyondAnyBudget, reads.value_or(beyondAnyBudget)));
          t.triangles += mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : corners >= 2 ? corners - 2 : 0;
        }
        t.counted = true;
      }
      // Every placement of every primitive costs a pass, even one that adds nothing.
      placedPrimitives += primitives.size();
      vertices += t.vertices;
      triangles += t.triangles;
      if (placedPrimitives > std::max<uint64_t>(uint64_t(1) << 20, inputBytes) ||
          vertices * sizeof(glm::dvec3) + triangles * sizeof(glm::uvec3) > budget)
        source_.refuse("its scene places its meshes " + std::to_string(instances.size()) +
                       " times, more geometry than lbmshape reads from a file of this size (" +
                       std::to_string(budget >> 20) + " MiB)");
    }
    if (vertices > UINT32_MAX) source_.refuse("more vertices than lbmshape can index (2^32 - 1)");
  }

  void add(const GltfInstance& instance)
  {
    const auto& primitives = model_.meshes[size_t(instance.mesh)].primitives;
    for (size_t p = 0; p < primitives.size(); ++p)
      addPrimitive(primitives[p], primitiveName(instance.mesh, p), instance.world, *instance.weights, instance.skin);
  }

  // One warning for each kind of primitive passed over, however many: a
  // CAD export with an edge-line primitive per part gave a line each.
  TriangleMesh take()
  {
    for (const Skipped* skipped : {&notTriangles_, &withoutPositions_})
      if (skipped->count > 0)
        log::warning("reading " + source_.name + ": skipped " +
                     (skipped->count == 1
                          ? skipped->first
                          : std::to_string(skipped->count) + " primitives (" + skipped->first + " the first)") +
                     ": " + skipped->why);
    return std::move(mesh_);
  }

private:
  static std::string primitiveName(int mesh, size_t primitive)
  {
    return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
  }
  static bool isTriangles(int mode)
  {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
  }

  // COLOR_0 is linear RGB; the mesh keeps colours as shown on a screen
  // (sRGB). Where some primitives have colours and others not, the others
  // are white, as glTF draws a primitive without COLOR_0.
  void addColours(const tinygltf::Primitive& primitive, const std::string& name, uint32_t base, size_t count)
  {
    auto colour = primitive.attributes.find("COLOR_0");
    std::vector<glm::vec3> colours;
    if (colour != primitive.attributes.end()) {
      colours = accessors_.colours(colour->second, name + " COLOR_0");
      if (colours.size() != count)
        source_.refuse(name + " has " + std::to_string(colours.size()) + " COLOR_0 values for " +
                       std::to_string(count) + " positions");
      for (glm::vec3& c : colours) c = glm::vec3(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b));
    }
    if (colours.empty() && mesh_.colours.empty()) return;
    mesh_.colours.resize(base, glm::vec3(1.0f));
    if (colours.empty()) colours.assign(count, glm::vec3(1.0f));
    mesh_.colours.insert(mesh_.colours.end(), colours.begin(), colours.end());
  }

  // The morph targets' POSITION displacements, each times its weight: the
  // shape the file shows (a viewer draws the weighted targets; the base
  // shape alone was another shape).
  void applyMorphTargets(const tinygltf::Primitive& primitive, const std::string& name,
                         const std::vector<double>& weights, std::vector<glm::dvec3>& positions) const
  {
    for (size_t t = 0; t < primitive.targets.size() && t < weights.size(); ++t) {
      auto displacement = primitive.targets[t].find("POSITION");
      if (weights[t] == 0.0 || displacement == primitive.targets[t].end()) continue;
      const std::string what = name + " morph target " + std::to_string(t) + " POSITION";
      const std::vector<glm::dvec3> moves = accessors_.vectors(displacement->second, what);
      if (moves.size() != positions.size())
        source_.refuse(what + " has " + std::to_string(moves.size()) + " values for " +
                       std::to_string(positions.size()) + " positions");
      for (size_t i = 0; i < positions.size(); ++i) positions[i] += weights[t] * moves[i];
    }
  }

  void addPrimitive(const tinygltf::Primitive& primitive, const std::string& name, glm::dmat4 world,
                    const std::vector<double>& weights, int skin)
  {
    const int mode = primitive.mode;  // one of glTF's (gltf_json_element.hpp); triangles when absent
    if (!isTriangles(mode)) return notTriangles_.add(name);
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) return withoutPositions_.add(name);
    std::vector<glm::dvec3> positions = accessors_.vectors(position->second, name + " POSITION");
    applyMorphTargets(primitive, name, weights, positions);  // before skinning, as glTF orders them
    // A skinned mesh is placed by its joints alone (gltf_skinning.hpp).
    const std::vector<uint8_t> skinMirrors =
        skin >= 0 ? skins_.pose(primitive, name, skin, positions) : std::vector<uint8_t>();
    if (skin >= 0) world = glm::dmat4(1.0);
    std::vector<uint32_t> order;
    if (primitive.indices >= 0) {
      order = accessors_.indices(primitive.indices, positions.size(), name + " indices");
    } else {
      order.resize(positions.size());
      for (size_t i = 0; i < positions.size(); ++i) order[i] = uint32_t(i);
    }

    const auto base = uint32_t(mesh_.positions.size());
    for (const glm::dvec3& p : positions) mesh_.positions.emplace_back(world * glm::dvec4(p, 1.0));
    addColours(primitive, name, base, positions.size());
    // A mirroring transform turns counter-clockwise faces clockwise (glTF
    // spec, 3.7.4); swapping two corners keeps them facing outwards.
    const bool mirrored = glm::determinant(world) < 0;
    auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
      const bool turned = skinMirrors.empty() ? mirrored : skinMirrors[a] + skinMirrors[b] + skinMirrors[c] >= 2;
      if (turned) std::swap(b, c);
      mesh_.triangles.emplace_back(base + a, base + b, base + c);
    };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (size_t i = 0; i + 2 < order.size(); i += 3) add(order[i], order[i + 1], order[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (size_t i = 0; i + 2 < order.size(); ++i)  // every other triangle reversed to keep one winding
        i % 2 == 0 ? add(order[i], order[i + 1], order[i + 2]) : add(order[i + 1], order[i], order[i + 2]);
    } else {
      for (size_t i = 1; i + 1 < order.size(); ++i) add(order[i], order[i + 1], order[0]);
    }
  }

  struct Skipped {
    std::string why;
    size_t count = 0;
    std::string first;
    void add(const std::string& name)
    {
      if (count++ == 0) first = name;
    }
  };

  const tinygltf::Model& model_;
  const MeshSource& source_;
  const GltfAccessors& accessors_;
  GltfSkins skins_;
  TriangleMesh mesh_;
  Skipped notTriangles_{"points or lines, not triangles", 0, {}}, withoutPositions_{"no POSITION attribute", 0, {}};
};

}  // namespace

TriangleMesh readGltf(const MeshSource& given, MeshFormat format)
{
  // A GLB with meshopt-compressed views is read as the plain GLB it decodes to.
  std::optional<std::string> decoded;
  if (format == MeshFormat::Glb) {
    jsonOf(given, format);  // checks the chunks
    const GlbChunks chunks = glbChunks(given.bytes);
    decoded = decodeMeshoptGlb(given, chunks.json, chunks.binary);
  }
  MeshSource source = given;
  if (decoded) source.bytes = *decoded;
  // A GLB saved under a .gltf name (its JSON parse failed, "last read: 'g'"):
  // read as what it is.
  if (format == MeshFormat::Gltf && given.bytes.starts_with("glTF")) {
    log::warning("reading " + given.name + ": it is a GLB (binary glTF) file, though named .gltf; read as GLB");
    return readGltf(given, MeshFormat::Glb);
  }

  // Before tinygltf sees the file: nesting it could not survive, required
  // extensions lbmshape cannot read (gltf_json_check.hpp), and the buffer
  // files it would open.
  const std::vector<GltfBufferEntry> buffers = checkGltfJson(jsonOf(source, format), format == MeshFormat::Glb, source);
  GltfFileAccess files(source, buffers);
  const tinygltf::Model model = load(source, format, files);  // its required extensions checked above

  // What the file holds bounds what it may make: for a compressed file, its
  // own size, not what it decoded to.
  uint64_t inputBytes = decoded ? given.bytes.size() : source.bytes.size();
  if (!decoded)
    for (const auto& buffer : model.buffers) inputBytes += buffer.data.size();
  const GltfAccessors accessors(model, source, inputBytes);
  const std::vector<GltfInstance> instances = meshInstances(model, source);
  SoupBuilder builder(model, source, accessors);
  builder.requireWithinBudget(instances, geometryBudget(inputBytes), inputBytes);
  for (const GltfInstance& instance : instances) builder.add(instance);
  return builder.take();
}

}  // namespace lbmshape
