// The only files a glTF file can make lbmshape read: its buffers, named by
// relative URIs, inside the glTF file's own folder. tinygltf's own file
// access would follow "../../etc/passwd" or an absolute path, search the
// current folder too, open a FIFO and wait on it, and read every image a
// file names; these callbacks allow exactly the buffers checked here, each
// a regular file of the size its buffer declares, inside the folder also
// after following symbolic links, and each read at most once.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "lbmshape/mesh/gltf_json_check.hpp"
#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

class GltfFileAccess {
public:
  // Throws InputError naming the buffer for a URI with a scheme other than
  // data:, an absolute path, a ".." component, or any file at all when the
  // source has no folder.
  GltfFileAccess(const MeshSource& source, const std::vector<GltfBufferEntry>& buffers);

  GltfFileAccess(const GltfFileAccess&) = delete;
  GltfFileAccess& operator=(const GltfFileAccess&) = delete;

  // For tinygltf's loaders: the callbacks (which refer to this object) and
  // the folder to pass as their base directory.
  tinygltf::FsCallbacks callbacks();
  std::string baseDirectory() const;

  // Why a read during loading was refused (a FIFO, a folder, a size other
  // than declared): more precise than tinygltf's "File not found".
  const std::optional<std::string>& refusal() const { return refusal_; }

private:
  static bool fileExists(const std::string& path, void* self);
  static std::string expandFilePath(const std::string& path, void* self);
  static bool readWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* self);
  static bool writeWholeFile(std::string* error, const std::string& path, const std::vector<unsigned char>&,
                             void* self);

  const MeshSource& source_;
  struct Allowed {
    uint64_t byteLength;  // what its buffer declares
    bool read = false;    // tinygltf may ask again for an image naming the same file: it gets nothing
  };
  std::map<std::string, Allowed> allowed_;  // by lexically normal path
  std::optional<std::string> refusal_;
};

}  // namespace lbmshape
