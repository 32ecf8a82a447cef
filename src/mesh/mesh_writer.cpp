#include "lbmshape/mesh/mesh_writer.hpp"

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/mesh/gltf_writer.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/obj_writer.hpp"
#include "lbmshape/mesh/openmesh_writer.hpp"
#include "lbmshape/mesh/writable_mesh.hpp"

namespace lbmshape {

namespace {
MeshFormat outputFormat(const std::filesystem::path& path)
{
  const auto format = meshFormatOf(path);
  if (!format)
    throw UsageError("cannot write " + path.string() + ": unknown mesh format '" + path.extension().string() +
                     "' (use one of " + supportedExtensions() + ")");
  return *format;
}

CoordinatePrecision coordinatePrecisionOf(MeshFormat format)
{
  switch (format) {
  case MeshFormat::Obj: return CoordinatePrecision::Double;  // text, every digit
  case MeshFormat::Gltf:
  case MeshFormat::Glb: return CoordinatePrecision::SingleAboutAnOrigin;
  case MeshFormat::Ply:
  case MeshFormat::Off:  // text, but of floats (OpenMesh's writer)
  case MeshFormat::Stl: break;
  }
  return CoordinatePrecision::Single;
}

void requireCompressible(MeshFormat format, const std::filesystem::path& path, GltfCompression compression)
{
  if (compression != GltfCompression::None && format != MeshFormat::Glb)
    throw UsageError(nameOf(Parameter::Compression) + " writes .glb files, not " + path.string());
}

}  // namespace

void checkMeshFormat(const std::filesystem::path& path, GltfCompression compression)
{
  requireCompressible(outputFormat(path), path, compression);
}

void checkMeshDestination(const std::filesystem::path& path, GltfCompression compression)
{
  checkMeshFormat(path, compression);
  AtomicFile probe(path);  // created and, uncommitted, removed again
}

void checkNotTheInput(const std::filesystem::path& output, const std::filesystem::path& input, bool replaceInput)
{
  std::error_code ec;
  if (replaceInput || !std::filesystem::equivalent(output, input, ec) || ec) return;
  throw UsageError("the output " + output.string() + " is the input mesh " + input.string() +
                   ": write the result elsewhere, or give " + nameOf(Parameter::ReplaceInput) +
                   " to replace the input");
}

std::unique_ptr<AtomicFile> writeMeshUncommitted(const TriangleMesh& mesh, const std::filesystem::path& path,
                                                 EmptyMesh empty, GltfCompression compression)
{
  const auto format = outputFormat(path);
  requireCompressible(format, path, compression);
  requireWritable(mesh, path, "the mesh", empty, coordinatePrecisionOf(format));
  auto file = std::make_unique<AtomicFile>(path);
  switch (format) {
  case MeshFormat::Obj: writeObj(mesh, *file); break;
  case MeshFormat::Ply:
  case MeshFormat::Off:
  case MeshFormat::Stl: writeWithOpenMesh(mesh, format, *file); break;
  case MeshFormat::Gltf:
  case MeshFormat::Glb: writeGltf(mesh, format, *file, compression); break;
  }
  return file;
}

void commitMesh(AtomicFile& file, size_t vertices, size_t triangles)
{
  file.commit();
  log::verbose("wrote " + file.target().string() + ": " + std::to_string(vertices) + " vertices, " +
               std::to_string(triangles) + " triangles");
}

void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& path, EmptyMesh empty,
               GltfCompression compression)
{
  commitMesh(*writeMeshUncommitted(mesh, path, empty, compression), mesh.vertexCount(), mesh.triangleCount());
}

}  // namespace lbmshape
