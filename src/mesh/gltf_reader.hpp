// glTF 2.0 files (.gltf with its buffers, or .glb), read by tinygltf.
#pragma once

#include <filesystem>

#include "mesh/mesh_format.hpp"
#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

// Every triangle primitive (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; indexed
// or not) of every node of the scene to show (the default scene, else scene
// 0, else every root node), each placed by its node's world transform, in
// one soup. Points and lines are skipped; skins and morph targets are not
// applied (the rest pose is read); normals are not read. Throws InputError when the file
// cannot be parsed or its accessors point outside their buffers. No further
// checks: readMesh() validates.
TriangleMesh readGltf(const std::filesystem::path& path, MeshFormat format);

}  // namespace lbmshape
