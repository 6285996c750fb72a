// The project's one way to include tinygltf: the same configuration macros in every translation
// unit (they change TinyGLTF's members, so mixing them breaks the one-definition rule). The
// implementation is compiled once, in io/tinygltf_impl.cpp.
// Does not: decode or encode images. tinygltf is built without stb (image/png.h owns stb); a reader
// of glTF files with images sets TinyGLTF::SetImageLoader (e.g. keeping the bytes, or decoding them
// with image::DecodeRgba8Png).
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#ifndef TINYGLTF_USE_CPP14
#define TINYGLTF_USE_CPP14
#endif
#include <tiny_gltf.h>
