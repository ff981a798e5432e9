// tinygltf's implementation for the browser build (the desktop links Debian's libtinygltf).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
