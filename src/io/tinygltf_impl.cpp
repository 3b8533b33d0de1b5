// The one translation unit that compiles tinygltf's implementation. It is built without the
// project's warning flags (see CMakeLists.txt): the warnings are tinygltf's, not ours.
// Images are never decoded (TINYGLTF_NO_STB_IMAGE and friends, set for the whole library so
// every TU sees the same tinygltf configuration); gltf.cpp installs a loader that skips them.

#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
