// tinygltf's implementation, for the fuzz build only (see CMakeLists.txt,
// which also leaves stb_image out).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
