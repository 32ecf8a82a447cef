// glTF 2.0 files (.gltf with its buffers, or .glb), parsed by tinygltf and
// read defensively: a glTF file is untrusted input.
#pragma once

#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/mesh_source.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Every triangle primitive (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; indexed
// or not) of every node of the scene to show (the default scene, else scene
// 0, else every root node), each placed by its node's world transform, in
// one soup. Points and lines are skipped; skins and morph targets are not
// applied (the rest pose is read); normals are not read.
//
// Throws InputError naming the file and the part at fault: malformed or
// too deeply nested JSON, a buffer URI outside the file's folder (see
// gltf_file_access.hpp), an accessor that reaches outside its data, nodes
// that do not form a tree (a cycle, or a node with two parents), or a scene
// that would instance more geometry than a file of its size can sensibly
// hold. `format` is Gltf (JSON) or Glb (binary container).
TriangleMesh readGltf(const MeshSource& source, MeshFormat format);

}  // namespace lbmshape
