#include "lbmshape/mesh/mesh_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

namespace lbmshape {
namespace {

constexpr std::array<std::pair<const char*, MeshFormat>, 6> extensions{{
    {".obj", MeshFormat::Obj},
    {".ply", MeshFormat::Ply},
    {".off", MeshFormat::Off},
    {".stl", MeshFormat::Stl},
    {".gltf", MeshFormat::Gltf},
    {".glb", MeshFormat::Glb},
}};

}  // namespace

std::optional<MeshFormat> meshFormatOf(const std::filesystem::path& path)
{
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  for (const auto& [name, format] : extensions)
    if (extension == name) return format;
  return std::nullopt;
}

std::string formatName(MeshFormat format)
{
  switch (format) {
  case MeshFormat::Obj: return "OBJ";
  case MeshFormat::Ply: return "PLY";
  case MeshFormat::Off: return "OFF";
  case MeshFormat::Stl: return "STL";
  case MeshFormat::Gltf: return "glTF";
  case MeshFormat::Glb: return "GLB";
  }
  return "unknown";
}

std::string supportedExtensions()
{
  std::string list;
  for (const auto& [name, format] : extensions) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
}

}  // namespace lbmshape
