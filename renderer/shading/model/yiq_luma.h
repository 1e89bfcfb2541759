// Lighting model `yiq_luma`: the paper's YIQ luma model, its Table 1
// listing, generalised to several lights by summing before the listing's
// outer saturate (docs/models.md).
//
//   Parameters (scene file: material.model)
//   | name        | type  | default | range | meaning                               |
//   | kd          | float | 1       | >= 0  | diffuse weight                        |
//   | ks          | float | 1       | >= 0  | specular weight (0: no specular term) |
//   | shininess   | float | 55      | >= 0  | specular exponent n                   |
//   | luma_offset | float | 0.1     | any   | the listing's literal "- 0.1"         |
//
//   Dl = saturate(A_Y + kd sum att Y(Lc) saturate(N.L))
//   S  = ks sum att Y(Lc) saturate(R.V)^n
//   F  = C + (Y Dl + S - luma_offset - Y) (1,1,1)
//   Math: models::yiqLuma, models::lightLuma, models::phongSpecular
//   (shading/models.h); summed over the lights by Shader (shading/shader.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct YiqLuma {
  static constexpr const char* kName = "yiq_luma";
  double kd = 1.0, ks = 1.0;
  double shininess = 55.0;
  double luma_offset = 0.1;

  static auto params() {
    using namespace model;
    using M = YiqLuma;
    return std::tuple{NumberParam<M>{"kd", &M::kd, Unit::Weight, kNonNegative, Role::Coefficient},
                      NumberParam<M>{"ks", &M::ks, Unit::Weight, kNonNegative, Role::Specular},
                      NumberParam<M>{"shininess", &M::shininess, Unit::Exponent, kNonNegative, Role::None},
                      NumberParam<M>{"luma_offset", &M::luma_offset, Unit::Luma, kAnyNumber, Role::Coefficient}};
  }
};

}  // namespace xval
