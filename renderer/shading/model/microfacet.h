// The choices of cook_torrance's microfacet terms (shading/model/
// cook_torrance.h; their math: models::cookTorranceSpecular in
// shading/models.h): the distribution D, the geometry term G and the
// Fresnel factor F. Below the models' math, so that the model's parameter
// struct needs none of it. The gl renderer's u_ct_* uniforms are these
// values.
#pragma once

namespace xval::models {

enum class MicrofacetD { Beckmann = 0, Ggx = 1 };
enum class MicrofacetG { VGroove = 0, Smith = 1 };
enum class MicrofacetF { None = 0, Schlick = 1 };

}  // namespace xval::models
