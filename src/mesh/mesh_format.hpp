// The mesh file formats lbmshape reads and writes, told apart by the file
// name's extension (in any letter case).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace lbmshape {

enum class MeshFormat { Obj, Ply, Off, Stl, Gltf, Glb };

// Empty when the extension is none of .obj .ply .off .stl .gltf .glb.
std::optional<MeshFormat> meshFormatOf(const std::filesystem::path& path);

std::string formatName(MeshFormat format);  // "OBJ", "PLY", ...

// ".obj, .ply, .off, .stl, .gltf, .glb": for messages that list the choices.
std::string supportedExtensions();

}  // namespace lbmshape
