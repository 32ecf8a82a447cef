#include "lbmshape/mesh/gltf_file_access.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "lbmshape/core/mapped_file.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

int hexValue(char c)
{
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The URI as tinygltf decodes it before it looks for the file ('+' is a
// space, %XY a byte), or nothing when an escape is malformed.
std::optional<std::string> decoded(const std::string& uri)
{
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%') {
      if (i + 2 >= uri.size() || hexValue(uri[i + 1]) < 0 || hexValue(uri[i + 2]) < 0) return std::nullopt;
      out += char(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// "http:", "file:", "C:": a letter, then letters, digits, + - . and a colon.
bool hasScheme(const std::string& uri)
{
  const size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
  return std::all_of(uri.begin(), uri.begin() + std::ptrdiff_t(colon), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
  });
}

std::string normal(const std::string& path) { return fs::path(path).lexically_normal().string(); }

}  // namespace

GltfFileAccess::GltfFileAccess(const MeshSource& source, const std::vector<GltfBufferEntry>& buffers) : source_(source)
{
  for (size_t b = 0; b < buffers.size(); ++b) {
    const std::string& uri = buffers[b].uri;
    if (uri.empty() || uri.starts_with("data:")) continue;  // the GLB chunk, or embedded data
    const std::string name = "buffer " + std::to_string(b) + " (uri " + text::quotedName(uri) + ")";
    const std::string only = "; lbmshape reads only data: URIs and files beside the glTF file";
    if (hasScheme(uri)) source.refuse(name + " names a scheme other than data:" + only);
    const auto file = decoded(uri);
    if (!file) source.refuse(name + " has a malformed %-escape");
    if (file->empty() || file->front() == '/' || file->front() == '\\')
      source.refuse(name + " is an absolute path" + only);
    for (const auto& part : fs::path(*file))
      if (part == ".." || part.string().find('\\') != std::string::npos)
        source.refuse(name + " leaves the glTF file's folder" + only);
    if (file->find('\0') != std::string::npos) source.refuse(name + " holds a NUL character");
    if (!source.folder)
      source.refuse(name + " names a file, but the glTF was not read from a folder (use a .glb or data: URIs)");
    const fs::path folder = source.folder->empty() ? fs::path(".") : *source.folder;
    allowed_[normal((folder / *file).string())] = Allowed{buffers[b].byteLength};
  }
}

std::string GltfFileAccess::baseDirectory() const
{
  return source_.folder && !source_.folder->empty() ? source_.folder->string() : std::string(".");
}

tinygltf::FsCallbacks GltfFileAccess::callbacks()
{
  return tinygltf::FsCallbacks{&GltfFileAccess::fileExists, &GltfFileAccess::expandFilePath,
                               &GltfFileAccess::readWholeFile, &GltfFileAccess::writeWholeFile, this};
}

bool GltfFileAccess::fileExists(const std::string& path, void* self)
{
  const auto& allowed = static_cast<GltfFileAccess*>(self)->allowed_;
  const auto found = allowed.find(normal(path));
  return found != allowed.end() && !found->second.read;
}

std::string GltfFileAccess::expandFilePath(const std::string& path, void*) { return path; }  // no ~ or $VAR

bool GltfFileAccess::readWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                                   void* self)
{
  auto& access = *static_cast<GltfFileAccess*>(self);
  const auto allowed = access.allowed_.find(normal(path));
  if (allowed == access.allowed_.end() || allowed->second.read) {
    if (error) *error = "not a buffer of this file";
    return false;
  }
  allowed->second.read = true;
  auto refuse = [&](const std::string& why) {
    access.refusal_ = "the buffer file " + text::quotedName(path) + (why.starts_with(":") ? "" : " ") + why;
    if (error) *error = access.refusal_.value();
    return false;
  };
  try {
    // A symbolic link inside the folder must not lead out of it.
    const std::string folder = fs::weakly_canonical(access.baseDirectory()).string();
    const std::string target = fs::weakly_canonical(path).string();
    if (!target.starts_with(folder + "/")) return refuse("leads out of the glTF file's folder (a symbolic link)");
    // Refuses anything but a regular file before reading a byte of it.
    const MappedFile file(path);
    // Longer is allowed (the glTF validator accepts it: some writers pad the
    // file to 4 bytes); the buffer is its first byteLength bytes.
    const uint64_t declared = allowed->second.byteLength;
    if (file.bytes().size() < declared)
      return refuse("has " + std::to_string(file.bytes().size()) + " bytes, fewer than the " +
                    std::to_string(declared) + " its buffer declares");
    out->assign(file.bytes().begin(), file.bytes().begin() + std::ptrdiff_t(declared));
    return true;
  } catch (const InputError& e) {
    // "cannot read PATH: why" -> "the buffer file 'PATH': why"
    const std::string message = e.what(), prefix = "cannot read " + path + ": ";
    return refuse(message.starts_with(prefix) ? ": " + message.substr(prefix.size()) : ": " + message);
  } catch (const fs::filesystem_error& e) {
    return refuse(std::string(": ") + e.code().message());
  }
}

bool GltfFileAccess::writeWholeFile(std::string* error, const std::string&, const std::vector<unsigned char>&, void*)
{
  if (error) *error = "lbmshape does not write through its glTF reader";
  return false;
}

}  // namespace lbmshape
