// An image as the bytes xval-shader-draw hands back (shader_draw_main.cpp):
// width and height (two native ints), the RGBA floats, the raw RGB floats.
#pragma once

#include <string>

#include "image/image.h"

namespace xval::shaderfile {

std::string imageBytes(const Image& img);
// The image of `bytes`, which must be a w x h image with raw colour; throws
// std::runtime_error saying what arrived otherwise.
Image imageFromBytes(const std::string& bytes, int w, int h);

}  // namespace xval::shaderfile
