// Writing a surface mesh to a file, in any format lbmshape knows.
#pragma once

#include <filesystem>
#include <memory>

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/mesh/gltf_compression.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/mesh/writable_mesh.hpp"

namespace lbmshape {

// Writes `mesh` in the format its extension names (in any letter case):
//   .obj         text, coordinates exact (shortest round-trip doubles)
//   .ply, .stl   binary, single precision
//   .off         text, single precision
//   .gltf, .glb  glTF 2.0: one mesh, one node; float positions, unit
//                normals (computed, area-weighted, when the mesh has none),
//                uint32 indices; a .gltf carries its data inside (data URI);
//                with GltfCompression::Meshopt (.glb only, else UsageError)
//                quantized and meshopt-encoded (gltf_compression.hpp)
// The file appears complete or not at all (see AtomicFile): an existing file
// of that name is replaced only once the new one is fully written.
// Throws UsageError for an unknown extension, before anything is written,
// and OutputError naming the path when the folder is missing or unwritable,
// the disk is full, or the mesh cannot be written (NaN; no triangles unless
// `empty` allows it).
// A mesh without triangles, where allowed, is a valid file of no surface in
// every format: glTF has no empty meshes, so there it is one node without a
// mesh.
void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& path, EmptyMesh empty = EmptyMesh::Refused,
               GltfCompression compression = GltfCompression::None);

// writeMesh in two steps, for a writer that leaves the last to another
// thread: the mesh written to the returned file's temporary, not yet under
// its name; commitMesh() forces it to disk and renames it (as writeMesh
// does), and dropping the file instead removes it. A morph's frames are
// committed beside the making of the next: forcing a frame to disk took
// 17 ms on the H100's host, more than the frame took to make.
std::unique_ptr<AtomicFile> writeMeshUncommitted(const TriangleMesh& mesh, const std::filesystem::path& path,
                                                 EmptyMesh empty = EmptyMesh::Refused,
                                                 GltfCompression compression = GltfCompression::None);
void commitMesh(AtomicFile& file, size_t vertices, size_t triangles);

// The checks writeMesh makes before writing, for commands to make before
// their work: UsageError for an unknown extension (or compression of a file
// that is not .glb), OutputError for a missing or unwritable folder (tested
// by creating and removing a temporary file).
void checkMeshDestination(const std::filesystem::path& path, GltfCompression compression = GltfCompression::None);
// Its UsageErrors alone, which need no folder: for `run --check`.
void checkMeshFormat(const std::filesystem::path& path, GltfCompression compression = GltfCompression::None);

// UsageError when `output` is the file `input` (the same path, a link to it,
// or a hard link): writing the result there would replace the input, which
// a command does only when asked to (`replaceInput`, --force).
void checkNotTheInput(const std::filesystem::path& output, const std::filesystem::path& input, bool replaceInput);

}  // namespace lbmshape
