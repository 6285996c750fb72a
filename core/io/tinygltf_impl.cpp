// The project's one TINYGLTF_IMPLEMENTATION (configured by io/tinygltf.h); nothing else.
#define TINYGLTF_IMPLEMENTATION
#include "io/tinygltf.h"
