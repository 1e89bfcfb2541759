// The registry of lighting models: THE one list of them (XVAL_LIGHTING_MODELS),
// from which the scene's LightingModel variant, the ModelId enum, the
// models' names and their numbering (the GLSL model ids) all derive.
//
// A model is one file, shading/model/<name>.h: a plain struct with its
// scene-file name (kName), its parameters as fields with their defaults,
// params() (shading/model/params.h) and its documentation. To add one:
// write that file, add one line below, and add its case to each backend;
// every backend dispatches exhaustively (std::visit over overloads, or a
// switch over ModelId without a default, which -Werror=switch checks), so
// the compiler names every backend that lacks it. A backend that cannot
// express the model refuses it with a reason (ExportError, the renderers'
// cannot_express / "not expressible" verdict).
//
// The order is the scene format's: the loader's message lists the names so,
// and a model's id (ModelId, its index in the variant, the gl renderer's
// k_model) is its position.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <variant>

#include "shading/model/bidirectional.h"
#include "shading/model/classic_phong.h"
#include "shading/model/cook_torrance.h"
#include "shading/model/hemispherical.h"
#include "shading/model/lambert.h"
#include "shading/model/trilight.h"
#include "shading/model/wrap_around.h"
#include "shading/model/yiq_luma.h"
// issue #33: Minnaert, Blinn-Phong, Oren-Nayar
#include "shading/model/blinn_phong.h"
#include "shading/model/minnaert.h"
#include "shading/model/oren_nayar.h"

#define XVAL_LIGHTING_MODELS(X) \
  X(ClassicPhong)               \
  X(YiqLuma)                    \
  X(Lambert)                    \
  X(WrapAround)                 \
  X(Hemispherical)              \
  X(BiDirectional)              \
  X(Trilight)                   \
  X(Minnaert)                   \
  X(BlinnPhong)                 \
  X(OrenNayar)                  \
  X(CookTorrance)

namespace xval {

namespace model_detail {
template <class Ignored, class... Ms> struct VariantOf {
  using type = std::variant<Ms...>;
};
}  // namespace model_detail

#define XVAL_MODEL_AS_ALTERNATIVE(M) , M
using LightingModel = model_detail::VariantOf<void XVAL_LIGHTING_MODELS(XVAL_MODEL_AS_ALTERNATIVE)>::type;
#undef XVAL_MODEL_AS_ALTERNATIVE

// A model's id: its position in the list (switch over it without a default).
enum class ModelId {
#define XVAL_MODEL_AS_ENUMERATOR(M) M,
  XVAL_LIGHTING_MODELS(XVAL_MODEL_AS_ENUMERATOR)
#undef XVAL_MODEL_AS_ENUMERATOR
};

inline constexpr std::size_t kModelCount = std::variant_size_v<LightingModel>;

// Each enumerator is its struct's index in the variant (by construction;
// checked here so that neither can be reordered alone).
#define XVAL_MODEL_CHECK_ID(M) \
  static_assert(std::is_same_v<std::variant_alternative_t<std::size_t(ModelId::M), LightingModel>, M>);
XVAL_LIGHTING_MODELS(XVAL_MODEL_CHECK_ID)
#undef XVAL_MODEL_CHECK_ID

// The scene-file names ("classic_phong", ...), by id.
inline constexpr std::array<std::string_view, kModelCount> kModelNames = {
#define XVAL_MODEL_NAME(M) std::string_view(M::kName),
    XVAL_LIGHTING_MODELS(XVAL_MODEL_NAME)
#undef XVAL_MODEL_NAME
};

inline ModelId modelId(const LightingModel& m) { return ModelId(m.index()); }
template <class M> constexpr ModelId modelIdOf() {
  ModelId id{};
#define XVAL_MODEL_MATCH(A) \
  if constexpr (std::is_same_v<M, A>) id = ModelId::A;
  XVAL_LIGHTING_MODELS(XVAL_MODEL_MATCH)
#undef XVAL_MODEL_MATCH
  return id;
}
inline const char* modelName(const LightingModel& m) { return kModelNames[m.index()].data(); }

// The model of that id with every parameter at its default.
inline LightingModel defaultModel(ModelId id) {
  LightingModel out;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((std::size_t(id) == I ? (out.emplace<I>(), 0) : 0), ...);
  }(std::make_index_sequence<kModelCount>{});
  return out;
}

}  // namespace xval
